#!/usr/bin/env bash
# Renders the screenshot beside each lesson of the manifest (lessons/<name>.png) with the headless
# renderer, at the step its front matter names (screenshot:, else its start step), as a small
# palette PNG. Lesson 18 needs out/meshes (scripts/setup.sh). Usage: lessons/screenshots.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
STEPWISE=${1:-build}/stepwise
grep -v '^\s*\(#\|$\)' lessons/manifest.txt | while read -r file; do
  name=${file%.md}
  "$STEPWISE" render --lesson "lessons/$file" --shot --out "lessons/$name.png" --size 1280x800
  if [ -x /usr/bin/convert ]; then /usr/bin/convert "lessons/$name.png" -strip +dither -colors 255 "PNG8:lessons/$name.png"; fi
done
