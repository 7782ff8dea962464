#!/usr/bin/env bash
# Installs what the web package (web/) needs to build and test: Debian's
# emscripten, node and chromium, and web/'s npm packages from its
# package-lock. Idempotent: installs only what is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
packages=(emscripten chromium)
command -v node > /dev/null || packages+=(nodejs)
command -v npm > /dev/null || packages+=(npm)
scripts/install-deps.sh "${packages[@]}"
# puppeteer-core drives Debian's chromium: it must not fetch a browser.
if [ ! -f web/node_modules/.package-lock.json ] || [ web/package-lock.json -nt web/node_modules/.package-lock.json ]; then
  echo "install-web-deps: npm ci in web/"
  (cd web && PUPPETEER_SKIP_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
else
  echo "install-web-deps: web/node_modules up to date"
fi
