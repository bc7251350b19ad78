#!/usr/bin/env bash
# Installs the Debian packages stepwise needs (only those missing), then configures and builds.
# Idempotent: a second run installs nothing and rebuilds only what changed.
# Usage: scripts/setup.sh [--app | --packages] [build-dir] [extra cmake args...]
#   --app       only what the app and the CLI need: their packages, and the targets stepwise (which
#               brings stepwise-gl, its renderer) and stepwise-gui (scripts/run.sh, the fast first picture). Without it: every package (tests,
#               peers, benches, the sanitizer job's clang) and every target.
#   --packages  every package and the meshes, no build (scripts/test.sh, before its two builds).
set -euo pipefail
cd "$(dirname "$0")/.."
APP=0 PACKAGES_ONLY=0
if [ "${1:-}" = --app ]; then APP=1; shift; fi
if [ "${1:-}" = --packages ]; then PACKAGES_ONLY=1; shift; fi

# The app and the CLI: compilers, GMP/MPFR, CGAL (the exact oracle inside the runtime), JSON and
# CLI parsing, ImGui with GLFW and OSMesa, GIF and Markdown, the fonts, and CGAL's meshes.
PACKAGES=(
  build-essential cmake pkg-config
  libgmp-dev libmpfr-dev libcgal-dev libglm-dev nlohmann-json3-dev libcli11-dev
  libimgui-dev libstb-dev libglfw3-dev libgl-dev libosmesa6-dev libgif-dev libmd4c-dev libmd4c-html0-dev
  fonts-dejavu-core libcgal-demo
)
# The tests, their peers (POV-Ray, xvfb, Chromium, Embree, nanoflann) and the benches; clang and
# LLVM for the sanitizer and fuzz build; `file` for CPack's .deb (its dependencies from dpkg-shlibdeps);
# ccache for scripts/mutate.sh, whose every revert would otherwise recompile what the mutant touched;
# emscripten and what fetches and builds Debian's source packages for the browser page (scripts/web.sh).
((APP)) || PACKAGES+=(
  git ccache catch2 libbenchmark-dev xvfb xauth libembree-dev libtinyobjloader-dev libnanoflann-dev
  clang libclang-rt-14-dev llvm-14 chromium chromium-driver python3 python3-jsonschema povray file
  emscripten nodejs dpkg-dev xz-utils m4 libboost-dev
)
source scripts/packages.sh
install_missing "${PACKAGES[@]}"

# The real meshes of CGAL's data set, for the bench and the mesh lessons (out/meshes).
bash scripts/meshes.sh out/meshes >/dev/null
((PACKAGES_ONLY)) && exit 0

BUILD=${1:-build}
shift || true
if ((APP)); then
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DSW_TESTS=OFF -DSW_BENCH=OFF "$@" >/dev/null
  cmake --build "$BUILD" -j"$(nproc)" --target stepwise stepwise-gui
else
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DSW_TESTS=ON -DSW_BENCH=ON "$@" >/dev/null
  cmake --build "$BUILD" -j"$(nproc)"
fi
