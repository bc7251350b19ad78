#!/usr/bin/env bash
# The visibility identity at full size: every example scene a rasterizer takes (perspective
# cameras), at its own resolution, drawn in float, double, filtered and exact by `stepwise scene
# raster --identity`, each pixel against the exact ray cast (docs/pipeline/semantics.md#scene-raster).
# Prints one table per scene. Usage: bench/scene_raster_identity.sh [build-dir] [--size WxH]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
shift || true
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for scene in scenes/*.json; do
  if ! "$BUILD/stepwise" scene raster "$scene" "$@" --out "$out/x.png" --quiet 2>/dev/null; then
    echo "== $scene: not drawn ($("$BUILD/stepwise" scene raster "$scene" "$@" --out "$out/x.png" 2>&1 | head -1))"
    continue
  fi
  echo "== $scene"
  "$BUILD/stepwise" scene raster "$scene" "$@" --out "$out/x.png" --identity | sed -n '1p;3,8p'
done
