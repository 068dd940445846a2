#!/usr/bin/env bash
# main.sh — the main job: installs dependencies, builds sylva and renders scenes/default.yaml
# into out/default.png and out/default.exr. Prints where the images are.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$root/build"
mkdir -p "$root/out"
"$root/build/sylva" render "$root/scenes/default.yaml" -o "$root/out/default.png" >/dev/null
echo "image: $root/out/default.png"
echo "linear EXR with depth, normal, albedo and id layers: $root/out/default.exr"
