#!/usr/bin/env bash
# Regenerates docs/results/baseline.md: qmc against Draco on every corpus mesh
# (../shared/corpus) and the bundled demo mesh. RUNS (default 7) runs per
# measurement; medians are reported. Run on an otherwise idle machine.
set -euo pipefail
cd "$(dirname "$0")/.."
corpus=${QMC_CORPUS_DIR:-../shared/corpus}
[ -d "$corpus" ] || { echo "bench: corpus not found at $corpus (set QMC_CORPUS_DIR)" >&2; exit 1; }
scripts/install-deps.sh >/dev/null
scripts/build.sh >/dev/null
out=docs/results/baseline.md
tmp=$(mktemp)
build/bench/qmc_baseline --runs "${RUNS:-7}" --bits 12 --out "$tmp" data/demo/torus.obj "$corpus"/quad/* "$corpus"/tri/*
{
  echo "# Baseline: qmc 0.1 (format 1.0) against Draco"
  echo
  echo "Made by \`scripts/bench.sh\` (\`build/bench/qmc_baseline --runs ${RUNS:-7} --bits 12 ...\`)."
  echo
  cat "$tmp"
} >"$out"
rm -f "$tmp"
echo "bench: wrote $out"
