#!/usr/bin/env bash
# Builds everything (encoder, tools and tests too, not only the decoder the
# fuzz targets cover) with AddressSanitizer and UndefinedBehaviorSanitizer
# (GCC) into build-sanitize/ and runs the ctest suite there: any
# use-after-free, overflow or undefined behaviour fails the test that hit it.
# Not part of scripts/test.sh: the build and the run take about 16 minutes on
# 2 cores.
#
# Left out of the run, as they cannot pass in such a build whatever the code:
# EncoderComplexity.* bound the encoder's CPU time (tests/encoder_test.cc),
# which the sanitizers triple; find_package_consumer links the installed,
# instrumented libraries into a program built without the sanitizers'
# runtime.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-sanitize
flags="-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" > /dev/null
cmake --build "$build" -j "$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 1800 \
  -E '^(EncoderComplexity\.|find_package_consumer$)'
