#!/usr/bin/env bash
# Builds with AddressSanitizer + UndefinedBehaviorSanitizer (no visualizer: llvmpipe under ASan
# is slow and reports the driver's own leaks) and runs the core, CLI and family tests.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build-asan -DSW_SANITIZE=ON -DSW_VISUALIZER=OFF -DSW_BENCH=OFF
cd build-asan
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j"$(nproc)"
