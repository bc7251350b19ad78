#!/usr/bin/env bash
# Sets everything up and runs the main job: the visualizer on the first lesson. With a display it
# opens the window (stepwise-gui); without one it renders frames of the first lesson into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --app build
mkdir -p out
build/stepwise trace dda-line --input '{"p0":[1.25,2.5],"p1":[12.75,7.25]}' --numeric exact --out out/dda-line.jsonl
build/stepwise check out/dda-line.jsonl
first=lessons/$(grep -v '^#' lessons/manifest.txt | grep -m1 .)
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -x build/visualizer/stepwise-gui ]; then
  echo "run: opening $first in stepwise-gui"
  exec build/visualizer/stepwise-gui --lesson "$first"
fi
name=$(basename "$first" .md)
build/stepwise render --lesson "$first" --out "out/$name.png"
build/stepwise render --lesson "$first" --gif "out/$name.gif" --size 960x600 --delay 400
echo "run: no display; wrote frames of $first to out/$name.png and out/$name.gif (stepwise-gui needs a display, or xvfb-run)"
