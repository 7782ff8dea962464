#!/usr/bin/env bash
# Conformance vectors are frozen (spec section 10.1): qmc-make-vectors must
# still write exactly the committed files and MANIFEST. A difference means
# the encoder's output changed under an existing vector's name.
# Usage: vectors_reproducible.sh QMC_MAKE_VECTORS CONFORMANCE_DIR
set -u
gen=$1 committed=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/vectors"
"$gen" "$work" || { echo "qmc-make-vectors failed"; exit 1; }
if diff -r "$work/vectors" "$committed/vectors" && diff "$work/MANIFEST" "$committed/MANIFEST"; then
  echo "vectors: $(ls "$work/vectors" | wc -l) reproduced byte for byte"
else
  echo "FAIL: regenerated vectors differ from the committed ones"
  exit 1
fi
