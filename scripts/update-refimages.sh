#!/usr/bin/env bash
# update-refimages.sh [BUILD_DIR] — deliberately re-renders every image-diff test scene
# (tests/scenes/image/*.yaml) into refimages/<name>.exr. Run it only when a change to the
# renderer is meant to change the pictures, look at the new images, and commit them.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$root/build"}
for scene in "$root"/tests/scenes/image/*.yaml; do
  name=$(basename "$scene" .yaml)
  "$build/sylva" render "$scene" -o "$root/refimages/$name.exr" --quiet >/dev/null
  echo "refimages/$name.exr (and .png for viewing)"
done
