#!/usr/bin/env bash
# Builds the browser page, out/web/stepwise.html: the whole app compiled to WebAssembly with Debian's
# emscripten, lessons, scenes and fonts embedded, one file that opens from file:// (docs/web.md).
# The wasm libraries come from scripts/web-deps.sh (built once, then cached outside the repository).
# Usage: scripts/web.sh [build-dir]   (default build-web)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/web-deps.sh
bash scripts/meshes.sh out/meshes >/dev/null  # the meshes lessons and scenes name
BUILD=${1:-build-web}
start=$SECONDS
emcmake cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DSW_WEB_CACHE="${STEPWISE_WEB_CACHE:-/var/cache/stepwise-web}" >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target stepwise-web
mkdir -p out/web
cp "$BUILD/visualizer/stepwise.html" out/web/stepwise.html
echo "web: out/web/stepwise.html, $(du -k out/web/stepwise.html | cut -f1) KiB, built in $((SECONDS - start)) s"
