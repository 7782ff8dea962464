#!/usr/bin/env bash
# Encodes the corpus meshes of more than 10k vertices for web/bench/decode.mjs:
# NAME.qmc (qmc encode -q 14), NAME.obj (its decoded mesh, positions only, so
# that every codec gets the same mesh) and NAME.drc (draco_encoder -qp 14 of
# that OBJ, default compression level); bunny_progressive.qmc (3 Loop levels)
# for first_level.mjs.
#   web/bench/prepare.sh OUT_DIR [QMC_BINARY]
set -euo pipefail
out=$1
qmc=${2:-build/tools/qmc}
corpus=../shared/corpus
mkdir -p "$out"
for mesh in tri/camelhead.off tri/armadillo.obj tri/beetle.off tri/face.obj tri/stanford-bunny.obj \
            attr/human_neutral.obj attr/boat.obj; do
  name=$(basename "${mesh%.*}")
  # Positions only, as every codec here: a first encoding names the
  # attributes (spec 15) that the second leaves out.
  "$qmc" encode "$corpus/$mesh" "$out/$name.qmc" -q 14 --quiet --drop-unsupported
  drops=$("$qmc" info --json "$out/$name.qmc" |
    python3 -c 'import json, sys; print(" ".join("--drop " + a["name"] for a in json.load(sys.stdin)["attributes"]))')
  # shellcheck disable=SC2086  # one word per flag and name
  "$qmc" encode "$corpus/$mesh" "$out/$name.qmc" -q 14 --quiet --drop-unsupported $drops
  "$qmc" decode "$out/$name.qmc" "$out/$name.obj" > /dev/null
  draco_encoder -i "$out/$name.obj" -o "$out/$name.drc" -qp 14 > /dev/null
done
"$qmc" encode "$corpus/tri/stanford-bunny.obj" "$out/bunny_progressive.qmc" --progressive --levels 3 --quiet
ls -l "$out"
