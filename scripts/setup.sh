#!/usr/bin/env bash
# Installs the Debian packages stepwise needs (only those missing), then configures and builds.
# Idempotent: a second run installs nothing and rebuilds only what changed.
# Usage: scripts/setup.sh [build-dir] [extra cmake args...]
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  build-essential cmake pkg-config git
  libgmp-dev libmpfr-dev libcgal-dev libglm-dev
  catch2 nlohmann-json3-dev libcli11-dev libbenchmark-dev
  libimgui-dev libstb-dev libglfw3-dev libgl-dev libosmesa6-dev libgif-dev
  xvfb xauth libembree-dev fonts-dejavu-core libtinyobjloader-dev libnanoflann-dev
  libcgal-demo clang libclang-rt-14-dev llvm-14
  libmd4c-dev libmd4c-html0-dev chromium chromium-driver python3 python3-jsonschema
  povray
)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" = 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The real meshes of CGAL's data set, for the bench and the mesh lessons (out/meshes).
bash scripts/meshes.sh out/meshes >/dev/null

BUILD=${1:-build}
shift || true
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$BUILD" -j"$(nproc)"
