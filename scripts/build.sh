#!/usr/bin/env bash
# Configures and builds qmc (Release) into ${QMC_BUILD_DIR:-build}.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${QMC_BUILD_DIR:-build}
# CI (CI=true) treats compiler warnings as errors; a user's newer compiler
# may warn where ours does not, so elsewhere warnings stay warnings.
werror=OFF
[ "${CI:-}" = true ] && werror=ON
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DQMC_WERROR=$werror >/dev/null
cmake --build "$build" -j "$(nproc)"
