#!/usr/bin/env bash
# update-refimages.sh [BUILD_DIR [NAME...]] — deliberately re-renders the image-diff test scenes
# (tests/scenes/image/*.yaml, or only tests/scenes/image/NAME.yaml for each NAME given) into
# refimages/<name>.exr. Run it only when a change to the renderer is meant to change the
# pictures, look at the new images, and commit them.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$root/build"}
shift || true
scenes=("$root"/tests/scenes/image/*.yaml)
if [ $# -gt 0 ]; then
  scenes=()
  for name in "$@"; do
    scene="$root/tests/scenes/image/$name.yaml"
    [ -f "$scene" ] || { echo "update-refimages.sh: no scene $scene" >&2; exit 1; }
    scenes+=("$scene")
  done
fi
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .yaml)
  "$build/sylva" render "$scene" -o "$root/refimages/$name.exr" --quiet >/dev/null
  echo "refimages/$name.exr (and .png for viewing)"
done
