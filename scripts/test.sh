#!/usr/bin/env bash
# Quick start 2: install what is missing, build, and run every test: the
# GoogleTest suite, the conformance vectors, the CLI checks, the
# find_package consumer (all through ctest), the web package (WebAssembly,
# JS, the viewer in headless Chromium: scripts/web-test.sh), then a short run
# of every fuzz target (FUZZ_SECONDS, default 20).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/install-web-deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
scripts/web-test.sh
scripts/fuzz.sh "${FUZZ_SECONDS:-20}"
