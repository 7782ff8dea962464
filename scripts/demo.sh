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
# The sphere (genus 0, all quads: qmc-meshgen sphere-series 3) goes through
# the quad coder; the torus (genus 1) through the polygon coder, and encode
# says why the quad coder could not take it.
for mesh in data/demo/sphere.obj data/demo/torus.obj; do
  name=$(basename "$mesh" .obj)
  echo "== qmc encode $mesh $out/$name.qmc"
  $qmc encode "$mesh" "$out/$name.qmc"
  echo
done
echo "== qmc info $out/sphere.qmc"
$qmc info "$out/sphere.qmc"
echo
echo "== qmc decode $out/sphere.qmc $out/sphere_decoded.obj"
$qmc decode "$out/sphere.qmc" "$out/sphere_decoded.obj"
echo
echo "== qmc verify data/demo/sphere.obj $out/sphere.qmc"
$qmc verify data/demo/sphere.obj "$out/sphere.qmc"
echo
# Progressive Loop levels (seed 003, spec 12): the torus's quads split into
# triangles, a base mesh of about 1/16 of them, and two levels on top.
echo "== qmc encode data/demo/torus.obj $out/torus_progressive.qmc --progressive --levels 2"
$qmc encode data/demo/torus.obj "$out/torus_progressive.qmc" --progressive --levels 2
echo
echo "== qmc decode $out/torus_progressive.qmc $out/torus_base.obj --level 0"
$qmc decode "$out/torus_progressive.qmc" "$out/torus_base.obj" --level 0
echo
# Geometry image (seeds 000 and 002, spec 13): the torus cut open along its
# two handle loops, sampled on a 64 x 64 grid, exported as 16-bit PNG planes.
echo "== qmc encode data/demo/torus.obj $out/torus_gim.qmc --gim 64 --sampling adaptive"
$qmc encode data/demo/torus.obj "$out/torus_gim.qmc" --gim 64 --sampling adaptive
echo
mkdir -p "$out/torus_gim"
echo "== qmc gim export $out/torus_gim.qmc $out/torus_gim"
$qmc gim export "$out/torus_gim.qmc" "$out/torus_gim"
