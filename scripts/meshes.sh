#!/usr/bin/env bash
# Extracts the real triangle meshes of CGAL's data set (Debian's libcgal-demo ships it as
# /usr/share/doc/libcgal-dev/data.tar.gz: data/meshes/*.off, e.g. bunny00, armadillo, elephant,
# ChineseDragon-10kv) into a directory: $1, else $SW_MESH_DIR, else out/meshes (git-ignored).
# Idempotent: files already extracted (same size) are left alone. Prints the directory.
set -euo pipefail
cd "$(dirname "$0")/.."
DIR=${1:-${SW_MESH_DIR:-out/meshes}}
TARBALL=/usr/share/doc/libcgal-dev/data.tar.gz
if [ ! -f "$TARBALL" ]; then
  echo "meshes: $TARBALL not found (install libcgal-demo: scripts/setup.sh)" >&2
  exit 1
fi
mkdir -p "$DIR"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
tar -xzf "$TARBALL" -C "$tmp" --wildcards 'data/meshes/*.off'
n=0
for f in "$tmp"/data/meshes/*.off; do
  dest="$DIR/$(basename "$f")"
  if [ ! -f "$dest" ] || [ "$(stat -c %s "$f")" != "$(stat -c %s "$dest")" ]; then
    cp "$f" "$dest"
    n=$((n + 1))
  fi
done
echo "meshes: $(ls "$DIR"/*.off | wc -l) meshes in $DIR ($n new)" >&2
echo "$DIR"
