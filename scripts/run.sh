#!/usr/bin/env bash
# Sets everything up and runs the main job: traces the default DDA example.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
mkdir -p out
build/stepwise trace dda-line --input '{"p0":[1.25,2.5],"p1":[12.75,7.25]}' --numeric exact --out out/dda-line.jsonl
build/stepwise check out/dda-line.jsonl
