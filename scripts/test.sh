#!/usr/bin/env bash
# Sets everything up and runs all the tests: the native build (every target), the browser page
# (scripts/web.sh: the wasm libraries from Debian's source packages, cached, then the page), and ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
scripts/setup.sh build -DSW_REQUIRE_PEERS=ON
echo "test: native build done in $((SECONDS - start)) s"
scripts/web.sh
echo "test: browser page done in $((SECONDS - start)) s"
cd build
ctest --output-on-failure -j"$(nproc)"
echo "test: all done in $((SECONDS - start)) s"
