#!/usr/bin/env bash
# Quick start 1: install what is missing, build, and send the bundled mesh
# through encode, info, decode and verify.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh >/dev/null
qmc=build/tools/qmc
out=build/demo
mkdir -p "$out"
mesh=data/demo/torus.obj
echo "== qmc encode $mesh $out/torus.qmc"
$qmc encode "$mesh" "$out/torus.qmc"
echo
echo "== qmc info $out/torus.qmc"
$qmc info "$out/torus.qmc"
echo
echo "== qmc decode $out/torus.qmc $out/torus_decoded.obj"
$qmc decode "$out/torus.qmc" "$out/torus_decoded.obj"
echo
echo "== qmc verify $mesh $out/torus.qmc"
$qmc verify "$mesh" "$out/torus.qmc"
