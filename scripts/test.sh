#!/usr/bin/env bash
# Sets everything up and runs all the tests.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build -DSW_REQUIRE_PEERS=ON
cd build
ctest --output-on-failure -j"$(nproc)"
