#!/usr/bin/env bash
# Installs the Debian packages qmc needs to build, test and benchmark.
# Idempotent: installs only what is missing, and touches nothing else.
#   scripts/install-deps.sh [PACKAGE...]
set -euo pipefail
packages=(
  cmake ninja-build g++ pkg-config      # build
  libgtest-dev python3                  # tests (python3: conformance/run.py)
  clang-14 libfuzzer-14-dev libclang-rt-14-dev   # fuzzing (ASan, UBSan, libFuzzer)
  libopenmesh-dev libeigen3-dev libzstd-dev      # encoder-side tools
  libdraco-dev draco                    # baseline comparison only (bench/)
  libmeshoptimizer-dev                  # bench/: meshoptimizer + zstd in compression.md
  libpng-dev                            # tools: geometry-image planes and pictures
)
# Given package names, installs those instead (scripts/install-web-deps.sh).
[ $# -eq 0 ] || packages=("$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
