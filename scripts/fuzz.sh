#!/usr/bin/env bash
# Builds the libFuzzer targets (clang-14, ASan + UBSan) into build-fuzz/,
# replays every committed regression input, then fuzzes each target for
# SECONDS (default 60) from seeds made of the conformance vectors.
# A crash leaves its input in build-fuzz/crashes/TARGET/: copy it into
# fuzz/regressions/TARGET/ together with the fix.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
build=build-fuzz
CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DQMC_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j "$(nproc)" >/dev/null
rm -rf "$build/seeds"
"$build/fuzz/make_seeds" conformance/vectors "$build/seeds" >/dev/null
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
passed=0 failed=0
for target in decode_file stream_decoder connectivity quad_connectivity polygon_connectivity positions huffman roundtrip order loop_levels gim_file gim_plane; do
  bin="$build/fuzz/${target}_fuzzer"
  regressions=(fuzz/regressions/$target/*)
  if [ -e "${regressions[0]}" ]; then
    if ! "$bin" "${regressions[@]}" >"$build/$target.replay.log" 2>&1; then
      echo "FAIL $target: a regression input crashes (see $build/$target.replay.log)"
      failed=$((failed + 1)); continue
    fi
  fi
  corpus="$build/corpus/$target"
  crashes="$build/crashes/$target"
  mkdir -p "$corpus" "$crashes"
  if "$bin" "$corpus" "$build/seeds/$target" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 \
       -timeout=10 -artifact_prefix="$crashes/" -print_final_stats=1 >"$build/$target.log" 2>&1; then
    runs=$(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$build/$target.log" | grep -o '[0-9]*$' || echo "?")
    echo "ok   $target: $runs runs in ${seconds}s, no crash"
    passed=$((passed + 1))
  else
    echo "FAIL $target: crash, input in $crashes (log $build/$target.log)"
    failed=$((failed + 1))
  fi
done
echo "fuzz: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
