#!/usr/bin/env bash
# Builds the WebAssembly decoder with Debian's emscripten (web/CMakeLists.txt)
# and runs the web tests with node's test runner: the JS package over every
# conformance vector, and the viewer in headless Chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
# Debian's emscripten needs its own node modules (acorn) on NODE_PATH.
export NODE_PATH=/usr/share/nodejs
[ -f build-wasm/build.ninja ] || emcmake cmake -S . -B build-wasm -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
nice cmake --build build-wasm --target qmc_wasm -j 1
cd web
node --test test/
