#!/usr/bin/env bash
# docs/results/decode_profile.md, "What each format's methods cost to
# decode": the corpus meshes of more than 10k vertices encoded with
# `qmc encode -q 14 --format F` for each F below (each version's best
# methods, section 14's selectors by version), and with Draco cl10 at
# -qp 14 from the OBJ the 1.15 file decodes to; each decoded REPEAT times in
# one process by bench/decode_once.cc or bench/draco_decode_once.cc, every
# file in turn in each of ROUNDS rounds (default 7), with the allocator
# keeping its memory (as the benchmark's process does; see the page-fault
# note of stop 45). Prints bytes and the median over the rounds of each
# process's median decode time, and Draco cl10's time over qmc's.
#   scripts/decode-by-format.sh          (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${ROUNDS:-7} repeat=${REPEAT:-10}
corpus=${QMC_CORPUS_DIR:-../shared/corpus}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
formats=(1.15 1.12 1.10 1.9 1.7 1.5 1.4)
meshes=(tri/armadillo.obj tri/beetle.off tri/camelhead.off tri/face.obj tri/stanford-bunny.obj)
name() { basename "${1%.*}"; }
for m in "${meshes[@]}"; do
  for f in "${formats[@]}"; do
    build/tools/qmc encode --quiet -q 14 --format "$f" "$corpus/$m" "$work/$(name "$m").$f.qmc"
  done
  build/tools/qmc decode --quiet "$work/$(name "$m").1.15.qmc" "$work/$(name "$m").obj"
  draco_encoder -i "$work/$(name "$m").obj" -o "$work/$(name "$m").drc" -qp 14 -cl 10 >/dev/null
done
export GLIBC_TUNABLES=glibc.malloc.trim_threshold=1073741824:glibc.malloc.mmap_threshold=1073741824
median_ms() { sed 's/.*repeats median \([0-9.]*\) ms.*/\1/'; }
for r in $(seq "$rounds"); do
  for m in "${meshes[@]}"; do
    n=$(name "$m")
    echo "$n draco $(build/bench/qmc_draco_decode_once "$work/$n.drc" "$repeat" | median_ms)"
    for f in "${formats[@]}"; do echo "$n $f $(build/bench/qmc_decode_once "$work/$n.$f.qmc" "$repeat" | median_ms)"; done
  done
done >"$work/runs"
median() {
  awk -v n="$1" -v f="$2" '$1 == n && $2 == f {print $3}' "$work/runs" | sort -g |
    awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'
}
header="| mesh | Draco cl10 bytes, ms |" rule="| --- | ---: |"
for f in "${formats[@]}"; do header="$header qmc --format $f |" rule="$rule ---: |"; done
echo "$header"
echo "$rule"
for m in "${meshes[@]}"; do
  n=$(name "$m")
  draco=$(median "$n" draco)
  row="| $m | $(stat -c %s "$work/$n.drc"), $draco"
  for f in "${formats[@]}"; do
    ms=$(median "$n" "$f")
    row="$row | $(stat -c %s "$work/$n.$f.qmc"), $ms ($(awk -v d="$draco" -v q="$ms" 'BEGIN {printf "%.2f", d / q}'))"
  done
  echo "$row |"
done
