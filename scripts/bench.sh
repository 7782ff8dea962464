#!/usr/bin/env bash
# Regenerates the benchmark results in docs/results/:
#   baseline.md      qmc against Draco on every corpus mesh (../shared/corpus)
#                    and the bundled demo mesh;
#   seed001.md       seed 001's chapter 5 tables (spheres, cow) rerun with qmc,
#                    beside the thesis's figures;
#   quad_vs_draco.md qmc's quad coder against Draco with polygons preserved;
#   topology.md      connectivity bits per vertex of qmc's structured coders
#                    (auto, polygon coder forced) against Draco and against
#                    qmc's indexed fallback on every corpus mesh, with the
#                    topology the polygon coder records;
#   seed003.md       seed 003's tables 2 and 3 rerun with qmc's progressive
#                    Loop levels, and their rate-distortion against Draco
#                    8-14 bits, plotted in seed003_rd.svg;
#   progressive.md   issue 17: every level of a progressive file nearer the
#                    input than the one before, every corpus mesh, K = 2..6;
#   gim.md           geometry images: seed 000 table 1 and seed 002 tables 1-2
#                    rerun, lossless planes against zstd -19 and 16-bit PNG,
#                    pictures in docs/results/gim/;
#   compression.md   issue 13: qmc's positions and whole files against Draco
#                    cl10 / cl7 and meshoptimizer + zstd -19 at 12, 14 and 16
#                    bits, decode and encode times, with the issue's targets.
#   attributes.md    issue 16: texture coordinates and normals (spec 15)
#                    against Draco cl10 at the same bits, on every corpus
#                    mesh with attributes.
#   surface_lattice.md  POSN method 14 (--surface-lattice, spec 14.15)
#                    against Draco cl10 at the same distance between the
#                    surfaces, corpus triangle meshes at 12, 14, 16 bits.
#   start_faces.md   --start-faces N (the polygon coder's first faces, spec
#                    5.4.2): bytes and encode time on every corpus mesh.
#   large_meshes.md  decode time of generated meshes of about a million
#                    vertices against Draco cl10 (with BEFORE=PROGRAM, a
#                    qmc_decode_once built at another revision, beside it).
# ONLY=compression, ONLY=topology, ONLY=seed003, ONLY=progressive,
# ONLY=attributes, ONLY=lattice, ONLY=starts, ONLY=large or ONLY=gim
# regenerates that one file.
# RUNS (default 7) runs per measurement, LARGE_RUNS (default 3) for the
# ~1M-quad sphere; medians are reported. Run on an otherwise idle machine.
set -euo pipefail
cd "$(dirname "$0")/.."
corpus=${QMC_CORPUS_DIR:-../shared/corpus}
[ -d "$corpus" ] || { echo "bench: corpus not found at $corpus (set QMC_CORPUS_DIR)" >&2; exit 1; }
runs=${RUNS:-7}
large_runs=${LARGE_RUNS:-3}
scripts/install-deps.sh >/dev/null
if [ "${ONLY:-}" = compression ] || [ "${ONLY:-}" = topology ] || [ "${ONLY:-}" = seed003 ] ||
   [ "${ONLY:-}" = progressive ]; then
  # One program: build just it (and what it links), not the whole tree.
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  target=qmc_${ONLY/compression/compression_bench}
  target=${target/topology/topology_bench}
  cmake --build build --target "${target/progressive/progressive_levels}" >/dev/null
else
  scripts/build.sh >/dev/null
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

machine() {
  local cpu
  cpu=$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')
  echo "${cpu:-unknown CPU}, $(nproc) cores"
}

# write_result FILE TITLE COMMAND...: runs COMMAND, which prints Markdown, and
# writes FILE: the title, the command itself, machine and date, then its output.
write_result() {
  local file=$1 title=$2
  shift 2
  "$@" >"$work/result"
  {
    echo "# $title"
    echo
    echo "Made by \`scripts/bench.sh\`, which ran: \`$*\`"
    echo
    echo "Machine: $(machine). Date: $(date -u '+%Y-%m-%d %H:%M UTC')."
    echo
    cat "$work/result"
  } >"$file"
  echo "bench: wrote $file"
}

# compression_result: docs/results/compression.md (RUNS rounds, interleaved).
compression_result() {
  write_result docs/results/compression.md "Compression: qmc against Draco and meshoptimizer on Draco's grid (issue 13)" \
    build/bench/qmc_compression_bench --runs "$runs" --bits 12,14,16 "$corpus"/tri/* "$corpus"/quad/*
}

# seed003_result: docs/results/seed003.md and its plot (progressive files).
seed003_result() {
  write_result docs/results/seed003.md "Seed 003 (Loop progressive geometry compression) rerun with qmc's progressive levels" \
    build/bench/qmc_seed003 --runs "$runs" --plot docs/results/seed003_rd.svg "$corpus"/tri/stanford-bunny.obj \
    "$corpus"/tri/armadillo.obj "$corpus"/tri/fertility.off "$corpus"/tri/camelhead.off
}

# progressive_result: docs/results/progressive.md (issue 17's levels criterion).
progressive_result() {
  write_result docs/results/progressive.md "Progressive files: every level nearer the input than the one before (issue 17)" \
    build/bench/qmc_progressive_levels "$corpus"/tri/* "$corpus"/quad/* "$corpus"/attr/*.obj
}

# topology_result: docs/results/topology.md (connectivity alone, issue 14).
topology_result() {
  write_result docs/results/topology.md "Connectivity: qmc's structured coders against Draco and the indexed fallback" \
    build/bench/qmc_topology_bench --runs "$runs" --large-runs "$large_runs" --bits 12 "$corpus"/quad/* "$corpus"/tri/*
}

# attributes_result: docs/results/attributes.md (issue 16): sizes, errors, decode times.
attributes_result() {
  write_result docs/results/attributes.md "Attributes: qmc's aTTR chunks against Draco cl10" \
    python3 bench/attribute_sizes.py build/tools/qmc build/bench/qmc_file_decode_bench "$runs" "$work" "$corpus"/attr/*.obj "$corpus"/tri/cathead.obj \
    "$corpus"/quad/cylinder_ngon_caps.obj "$corpus"/quad/fish_control_mesh.obj "$corpus"/quad/spot_control_mesh.obj \
    "$corpus"/quad/suzanne.obj
}

# lattice_result: docs/results/surface_lattice.md (sizes and distances only, no times).
lattice_result() {
  write_result docs/results/surface_lattice.md "The surface lattice (POSN method 14) against Draco cl10 at the same L2" \
    python3 bench/surface_lattice.py build/tools/qmc "$work" 12,14,16 "$corpus"/tri/*
}

# starts_result: docs/results/start_faces.md.
starts_result() {
  write_result docs/results/start_faces.md "--start-faces: the polygon coder's first faces (spec 5.4.2)" \
    python3 bench/start_faces.py build/tools/qmc build/bench/qmc_encode_once "$work" 12 "$corpus"/tri/* \
    "$corpus"/quad/* "$corpus"/attr/*.obj
}

# large_result: docs/results/large_meshes.md.
large_result() {
  write_result docs/results/large_meshes.md "Meshes of a million vertices: decode time against Draco cl10" \
    python3 bench/large_meshes.py build/tools/qmc build/tools/qmc-meshgen build/bench/qmc_decode_once \
    build/bench/qmc_draco_decode_once "$work" "$runs" 12 "$corpus"/tri/stanford-bunny.obj ${BEFORE:-}
}

if [ "${ONLY:-}" = starts ]; then
  starts_result
  exit 0
fi
if [ "${ONLY:-}" = large ]; then
  large_result
  exit 0
fi
if [ "${ONLY:-}" = compression ]; then
  compression_result
  exit 0
fi
if [ "${ONLY:-}" = lattice ]; then
  lattice_result
  exit 0
fi
if [ "${ONLY:-}" = attributes ]; then
  attributes_result
  exit 0
fi
if [ "${ONLY:-}" = topology ]; then
  topology_result
  exit 0
fi
if [ "${ONLY:-}" = seed003 ]; then
  seed003_result
  exit 0
fi
if [ "${ONLY:-}" = progressive ]; then
  progressive_result
  exit 0
fi

# ONLY=gim regenerates docs/results/gim.md alone.
if [ "${ONLY:-}" != gim ]; then
out=docs/results/baseline.md
build/bench/qmc_baseline --runs "$runs" --bits 12 --out "$work/baseline" data/demo/torus.obj "$corpus"/quad/* "$corpus"/tri/*
{
  echo "# Baseline: qmc 0.1 (format 1.1) against Draco"
  echo
  echo "Made by \`scripts/bench.sh\` (\`build/bench/qmc_baseline --runs $runs --bits 12 ...\`)."
  echo
  cat "$work/baseline"
} >"$out"
echo "bench: wrote $out"


write_result docs/results/seed001.md "Seed 001 (Q. Jing's thesis), chapter 5, rerun with qmc" \
  build/bench/qmc_seed001 --runs "$runs" --bits 8 "$corpus"/tri/cow.obj
write_result docs/results/quad_vs_draco.md "Quad meshes: qmc's quad coder against Draco with polygons preserved" \
  build/bench/qmc_quad_bench --runs "$runs" --large-runs "$large_runs" --bits 12 --sphere-levels 7 "$corpus"/quad/*
topology_result
compression_result
seed003_result
progressive_result
attributes_result
lattice_result
starts_result
large_result
fi
mkdir -p docs/results/gim
write_result docs/results/gim.md "Geometry images: seeds 000 and 002 rerun with qmc, and lossless planes against zstd and PNG" \
  build/bench/qmc_gim_bench "$corpus" docs/results/gim "$runs"
