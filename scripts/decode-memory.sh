#!/usr/bin/env bash
# docs/results/decode_memory.md: the first decode of a fresh process, by two
# builds of bench/decode_once.cc (e.g. before and after a change), on the
# corpus meshes of more than 10k vertices encoded with `qmc encode -q 14`.
# Each round runs every build on every file in turn, each in a new process;
# medians over ROUNDS (default 9) rounds.
#   scripts/decode-memory.sh OLD_DECODE_ONCE NEW_DECODE_ONCE
set -euo pipefail
cd "$(dirname "$0")/.."
old=$1 new=$2 rounds=${ROUNDS:-9}
corpus=${QMC_CORPUS_DIR:-../shared/corpus}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
meshes=(tri/armadillo.obj tri/beetle.off tri/camelhead.off tri/face.obj tri/stanford-bunny.obj)
for m in "${meshes[@]}"; do build/tools/qmc encode -q 14 --quiet "$corpus/$m" "$work/$(basename "${m%.*}").qmc"; done
for r in $(seq "$rounds"); do
  for m in "${meshes[@]}"; do
    f="$work/$(basename "${m%.*}").qmc"
    for b in old new; do
      bin=$old; [ "$b" = new ] && bin=$new
      echo "$m $b $("$bin" "$f" 5)"
    done
  done
done >"$work/runs"
echo "| mesh | first decode ms, before | after | minor faults, before | after | 5 more decodes in the process, median ms, before | after |"
echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
for m in "${meshes[@]}"; do
  row="| $m"
  for field in 4 6 11; do  # "first X ms, F minor faults; repeats median R ms"
    for b in old new; do
      row="$row | $(awk -v m="$m" -v b="$b" -v f="$field" '$1 == m && $2 == b {print $(f)}' "$work/runs" | sort -g |
        awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}')"
    done
  done
  echo "$row |"
done
