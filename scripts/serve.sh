#!/usr/bin/env bash
# Serves the qmc viewer (web/viewer/) on 127.0.0.1 only:
#   scripts/serve.sh [--port 8080] [--data DIR] [--throttle BYTES_PER_SECOND]
# then open http://127.0.0.1:8080/web/viewer/?url=/data/FILE.qmc (files of
# DIR), or drop a .qmc on the page. Builds the WebAssembly decoder first if
# web/dist/ does not have it (scripts/build-wasm.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f web/dist/qmc_decoder.wasm ] || scripts/build-wasm.sh
exec node web/tools/serve.mjs "$@"
