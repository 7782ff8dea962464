#!/usr/bin/env bash
# Spec 6.4 / Appendix A: the decoder's exact arithmetic must not rest on our
# CMake flags. Compiles src/decoder and src/common the way an embedder might
# (their compiler and flags, none of our options; by default -O2
# -march=native -ffp-contract=fast, or $QMC_EMBEDDER_FLAGS) and checks every
# conformance vector.
# Usage: run.sh SOURCE_DIR WORK_DIR COMPILER...
set -euo pipefail
src=$1 work=$2
shift 2
flags=${QMC_EMBEDDER_FLAGS:--O2 -march=native -ffp-contract=fast}
mkdir -p "$work"
for cxx in "$@"; do
  if ! command -v "$cxx" >/dev/null; then
    echo "embedder_flags: $cxx not installed" >&2
    exit 1
  fi
  bin="$work/check_vectors_$(basename "$cxx")"
  # shellcheck disable=SC2086  # the flags are words
  "$cxx" -std=c++17 $flags -I"$src/include" -I"$src/src" -I"$src/tools/lib" \
    "$src"/src/decoder/*.cc "$src"/src/common/*.cc "$src/tools/lib/sha256.cc" \
    "$src/tests/embedder_flags/check_vectors.cc" -o "$bin"
  echo "== $cxx $flags"
  "$bin" "$src/conformance"
done
