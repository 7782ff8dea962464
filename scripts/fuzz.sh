#!/usr/bin/env bash
# Builds the libFuzzer targets (clang-14, ASan + UBSan) into build-fuzz/,
# replays every committed regression input, then fuzzes each target for
# FUZZ_SECONDS (or the first argument; default 30) from seeds made of the
# conformance vectors. A crash, or an allocation above FUZZ_MALLOC_LIMIT_MB
# (default 64), leaves its input in build-fuzz/crashes/TARGET/: copy it into
# fuzz/regressions/TARGET/ together with the fix.
#
# Why 64 MB: spec 8 ties every allocation to the input size, and the decoder
# must not need more than about 64 MB for the inputs of at most 64 KB fuzzed
# here (-max_len); every conformance vector decodes well below it. A larger
# single allocation is a memory bomb (issue #12 items 1-3) and counts as a
# finding, as does a process above 2 GB in total (-rss_limit_mb).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-${FUZZ_SECONDS:-30}}
malloc_limit_mb=${FUZZ_MALLOC_LIMIT_MB:-64}
build=build-fuzz
CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DQMC_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j 2 >/dev/null
rm -rf "$build/seeds"
"$build/fuzz/make_seeds" conformance/vectors "$build/seeds" >/dev/null
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
limits=(-max_len=65536 -rss_limit_mb=2048 -malloc_limit_mb="$malloc_limit_mb" -timeout=10)
passed=0 failed=0
for bin in "$build"/fuzz/*_fuzzer; do  # every target fuzz/CMakeLists.txt builds
  target=$(basename "$bin" _fuzzer)
  regressions=(fuzz/regressions/$target/*)
  if [ -e "${regressions[0]}" ]; then
    if ! "$bin" "${limits[@]}" "${regressions[@]}" >"$build/$target.replay.log" 2>&1; then
      echo "FAIL $target: a regression input crashes (see $build/$target.replay.log)"
      failed=$((failed + 1)); continue
    fi
  fi
  corpus="$build/corpus/$target"
  crashes="$build/crashes/$target"
  mkdir -p "$corpus" "$crashes"
  if "$bin" "$corpus" "$build/seeds/$target" -max_total_time="$seconds" "${limits[@]}" \
       -artifact_prefix="$crashes/" -print_final_stats=1 >"$build/$target.log" 2>&1; then
    runs=$(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$build/$target.log" | grep -o '[0-9]*$' || echo "?")
    echo "ok   $target: $runs runs in ${seconds}s, no finding"
    passed=$((passed + 1))
  else
    echo "FAIL $target: finding in $crashes (log $build/$target.log);" \
         "reproduce: $bin ${limits[*]} $crashes/<file>"
    failed=$((failed + 1))
  fi
done
echo "fuzz: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
