#!/usr/bin/env bash
# Sets everything up and runs all the tests: the packages, then the native build (every target) and
# the browser page (scripts/web.sh: the wasm libraries from Debian's source packages, cached, then
# the page) side by side, then ctest. The two builds share the cores: each has one-core stretches
# (configure scripts, links) that the other fills. The page's output goes to out/web-build.log.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
scripts/setup.sh --packages
mkdir -p out
setsid scripts/web.sh >out/web-build.log 2>&1 &  # its own process group, so that it can be stopped whole
web=$!
trap 'kill -- -"$web" 2>/dev/null || true' EXIT  # a failed native build stops the page's too
scripts/setup.sh build -DSW_REQUIRE_PEERS=ON
echo "test: native build done in $((SECONDS - start)) s"
if ! wait "$web"; then
  tail -40 out/web-build.log
  echo "test: the browser page did not build (scripts/web.sh; its log: out/web-build.log)" >&2
  exit 1
fi
tail -1 out/web-build.log
echo "test: browser page done in $((SECONDS - start)) s"
cd build
ctest --output-on-failure -j"$(nproc)"
echo "test: all done in $((SECONDS - start)) s"
