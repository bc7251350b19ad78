#!/usr/bin/env bash
# Renders the screenshot beside each lesson (lessons/<name>.png) with the headless renderer, at a
# step that shows the lesson's point, as a small palette PNG. Usage: lessons/screenshots.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
STEPWISE=${1:-build}/stepwise
shot() {  # lesson [step]; without a step, the lesson's own start step
  "$STEPWISE" render --lesson "lessons/$1.md" ${2:+--step "$2"} --out "lessons/$1.png" --size 1280x800
  if [ -x /usr/bin/convert ]; then /usr/bin/convert "lessons/$1.png" -strip +dither -colors 255 "PNG8:lessons/$1.png"; fi
}
shot 01-dda-line 14        # pixels so far, with dp0 in the state panel
shot 02-grid-walk 6        # the second cell of the two-pixel corner case
shot 03-bresenham 14       # the decision variable e after a minor step
shot 04-float-drift 3939   # the first pixel where float and exact differ
shot 05-triangle-crack 10  # float: v < 0 in triangle 1, the ray falls through
shot 06-far-sphere         # (ray family) the lesson's start step
shot 07-midpoint-circle        # the decision after the first rows
shot 08-forward-difference-drift  # the first pixel where float and exact differ
shot 09-implicit-node           # the move past the node onto the other branch
shot 10-triangle-start-offset   # a plot in the lower half, the colour from the plane
shot 11-triangle-no-offset      # the plot of (12, 5), outside the triangle
shot 12-even-odd-nonzero        # w = 2 in the star's centre: even-odd leaves it out
shot 13-cohen-sutherland 7      # the accepted piece after three cuts
shot 14-perspective-checkerboard  # the whole textured floor, exact beside float
shot 15-affine-checkerboard       # the same floor without the divide: equal rows of squares
shot 16-kd-sah                  # node 2's x cut at 8: an empty side is cheaper than halving
shot 17-bsp-painter             # half painted, back to front
shot 18-kd-ray-mesh             # (needs out/meshes) the hit beyond the leaf, on the tree
shot 19-gouraud-phong           # the largest difference: Phong's highlight that Gouraud misses
shot 20-minnaert-moon           # the full-moon disc, nearly flat (the Sweep tab)
shot 21-fresnel-grazing         # F = 0.573 at 84.3 degrees
shot 22-phong-blinn             # 0.985^20 = 0.736 against Blinn-Phong's 0.927
shot 23-shadow-acne             # the scene with its acne specks, the traced pixel's blocked shadow ray
shot 24-glass-tir               # (3D) TIR on the slab's far face: tir = 1, guide_tir = 0
shot 25-planner-skips           # the planner's decisions beside the image
