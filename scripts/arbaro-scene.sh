#!/usr/bin/env bash
# arbaro-scene.sh SPECIES.xml HEIGHT OUT.png [BUILD_DIR] — sylva's tree of an Arbaro species file
# (tree_weber_penn, seed 13, leaf: own), written by `sylva export-pov --species` and rendered by
# POV-Ray in the scene Arbaro's POVSceneExporter writes for its renders: orthographic camera on a
# picture 1.3 HEIGHT high and 2/3 as wide, centred 0.45 of it above the base, the tree turned 90
# degrees about POV-Ray's y, the two lights and the pale background, grey stems and white leaves
# (ambient 0.15, diffuse 0.8), 400 x 600 pixels. Its leafless preview is left out. HEIGHT is the
# top of the tree's stems in metres (Arbaro's tree height). The picture shows the tree sylva grows
# as Arbaro's own renders show theirs, so the two can be laid side by side
# (docs/models/tree_weber_penn.md, "Seen beside Arbaro's renders"). Needs povray.
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: arbaro-scene.sh SPECIES.xml HEIGHT OUT.png [BUILD_DIR]" >&2; exit 1; }
root=$(cd "$(dirname "$0")/.." && pwd)
species=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
height=$2
out=$(cd "$(dirname "$3")" && pwd)/$(basename "$3")
build=${4:-"$root/build"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Grey as Arbaro's scene: its stems `rgb 0.9`, its leaves `rgb 1` (the most leaf_color allows).
cat >"$work/tree.yaml" <<EOY
camera: {position: [100, 0, 10], look_at: [0, 0, 10]}
species:
  tree: {plugin: tree_weber_penn, file: "$species", leaf: own, variants: 1, seed: 13,
         bark_color: [0.9, 0.9, 0.9], leaf_color: [1, 1, 1], leaf_transmittance: [0, 0, 0]}
EOY
"$build/sylva" export-pov "$work/tree.yaml" --species tree -o "$work/tree.pov" --quiet >/dev/null
cat >"$work/arbaro.pov" <<EOP
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.15 }
#include "tree.inc"
background { rgb <0.95, 0.95, 0.9> }
light_source { <5000, 5000, -3000>, rgb 1.2 }
light_source { <-5000, 2000, 3000>, rgb 0.5 shadowless }
#declare HEIGHT = $height * 1.3;
#declare WIDTH = HEIGHT * 400 / 600;
camera { orthographic location <0, HEIGHT * 0.45, -100>
         right <WIDTH, 0, 0> up <0, HEIGHT, 0>
         look_at <0, HEIGHT * 0.45, -80> }
object { Tree_0 transform { Sylva_to_y_up } rotate 90 * y }
EOP
(cd "$work" && povray +Iarbaro.pov +O"$out" +W400 +H600 -D +A0.1 Display_Gamma=1 File_Gamma=1 >/dev/null 2>&1) ||
  { echo "arbaro-scene.sh: povray failed on $work/arbaro.pov" >&2; exit 3; }
echo "$out"
