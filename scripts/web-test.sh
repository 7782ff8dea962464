#!/usr/bin/env bash
# Builds the WebAssembly decoder with Debian's emscripten (web/CMakeLists.txt)
# and runs the web tests with node's test runner: the JS package over every
# conformance vector, and the viewer in headless Chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build-wasm.sh
cd web
node --test test/
