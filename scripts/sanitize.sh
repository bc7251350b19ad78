#!/usr/bin/env bash
# The sanitizer job: a clang build with AddressSanitizer + UndefinedBehaviorSanitizer (no visualizer:
# llvmpipe under ASan is slow and reports the driver's own leaks; no benchmarks) runs the tests, then
# each libFuzzer harness for a short fixed time on its seed corpus (FUZZ_SECONDS, default 30; the
# run harness spends its first 20 s replaying its seeds).
set -euo pipefail
cd "$(dirname "$0")/.."
CC=clang CXX=clang++ scripts/setup.sh build-asan -DSW_SANITIZE=ON -DSW_FUZZ=ON -DSW_VISUALIZER=OFF -DSW_BENCH=OFF
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j"$(nproc)")
scripts/fuzz.sh build-asan -time "${FUZZ_SECONDS:-30}"
