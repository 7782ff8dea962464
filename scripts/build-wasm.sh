#!/usr/bin/env bash
# Builds the WebAssembly decoder into web/dist/ with Debian's emscripten
# (web/CMakeLists.txt), in build-wasm/. Extra arguments go to the configure
# step, e.g. -DQMC_WASM_OPT=-Oz.
set -euo pipefail
cd "$(dirname "$0")/.."
# Debian's emscripten needs its own node modules (acorn) on NODE_PATH.
export NODE_PATH=/usr/share/nodejs
if [ ! -f build-wasm/build.ninja ] || [ $# -gt 0 ]; then
  emcmake cmake -S . -B build-wasm -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" > /dev/null
fi
nice cmake --build build-wasm --target qmc_wasm -j 1
