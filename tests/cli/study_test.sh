#!/usr/bin/env bash
# study_test.sh SYLVA SCENE POINTS LOD_SCENE — `sylva study` end to end on
# tests/scenes/study/hill_study.yaml:
#   identical   each viewpoint's proposed view is byte for byte `sylva render --viewpoint NAME
#               --size WxH` (PNG and EXR), the ground cover near each camera included;
#   built_once  the scene is built once for the three viewpoints: the terrain plugin's
#               evaluation line appears as often in the study's messages as in one render's;
#   resume      a rerun keeps every product; with one output deleted it renders that product
#               alone, every other file left untouched (by their times), and a study with
#               nothing left builds nothing;
#   settings    --only with --force renders one viewpoint anew; another spp renders everything,
#               and so does another season;
#   points      a points file (POINTS, longitude and latitude) adds its viewpoints;
#   ground      on LOD_SCENE, whose ground is refined in levels of detail, the study's view is
#               `render --ground development`'s (its ground refined around the development),
#               not that of a render refining it around the camera.
set -uo pipefail
sylva=$1 scene=$2 points=$3 lod=$4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }
views="south_west south south_east"

"$sylva" study "$scene" -o "$out/s" --threads 2 >/dev/null 2>"$out/first.log" || fail "study exited with $?"
for v in $views; do
  for p in existing proposed wireline; do
    for e in png exr manifest; do [ -f "$out/s/$v/${p}_single.$e" ] || fail "no $v/${p}_single.$e"; done
  done
done

# identical: the single frame of the 72-pixel image is 72 x 48
for v in $views; do
  "$sylva" render "$scene" --viewpoint "$v" --size 72x48 -o "$out/r_$v.png" >/dev/null 2>"$out/render_$v.log" ||
    fail "render --viewpoint $v exited with $?"
  cmp -s "$out/r_$v.png" "$out/s/$v/proposed_single.png" || fail "$v: proposed_single.png differs from render's"
  cmp -s "$out/r_$v.exr" "$out/s/$v/proposed_single.exr" || fail "$v: proposed_single.exr differs from render's"
done
grep -q "ground cover: [0-9]* tufts" "$out/render_south_west.log" || fail "the render of south_west placed no ground cover"
cmp -s "$out/s/south/existing_single.png" "$out/s/south/proposed_single.png" &&
  fail "south: the existing view is the proposed one (the mast is in view)"

# built_once: one terrain evaluation in the study, as in one render
evals() { grep -c 'deterministic evaluation' "$1"; }
[ "$(evals "$out/first.log")" = "$(evals "$out/render_south.log")" ] && [ "$(evals "$out/first.log")" -ge 1 ] ||
  fail "terrain evaluated $(evals "$out/first.log") times in the study, $(evals "$out/render_south.log") in a render"
grep -q '9 products written, 0 up to date; 1 scene build, 6 frames rendered' "$out/first.log" ||
  fail "study summary: $(grep 'products written' "$out/first.log")"

# resume: delete one output, rerun: that product alone is rendered
sleep 1
touch "$out/mark"
rm "$out/s/south/existing_single.png"
"$sylva" study "$scene" -o "$out/s" >/dev/null 2>"$out/second.log" || fail "rerun exited with $?"
grep -q '9 products in .*; 1 to render, 8 up to date' "$out/second.log" || fail "rerun plan: $(grep 'to render' "$out/second.log")"
grep -q 'south single 72x48: existing in' "$out/second.log" || fail "rerun did not render south's existing view alone"
newer=$(cd "$out/s" && find . -type f -newer "$out/mark" | sort | tr '\n' ' ')
[ "$newer" = "./south/existing_single.exr ./south/existing_single.manifest ./south/existing_single.png " ] ||
  fail "rerun rewrote '$newer', expected south's existing view alone"
cmp -s "$out/s/south/proposed_single.png" "$out/r_south.png" || fail "rerun changed south's proposed view"
"$sylva" study "$scene" -o "$out/s" >/dev/null 2>"$out/third.log" || fail "third run exited with $?"
grep -q '0 products written, 9 up to date; 0 scene builds, 0 frames rendered' "$out/third.log" ||
  fail "a study with nothing to render: $(grep 'products written' "$out/third.log")"

# settings: --only with --force renders one viewpoint; another spp renders everything
"$sylva" study "$scene" -o "$out/s" --only south_east --force >/dev/null 2>"$out/only.log" || fail "--only exited with $?"
grep -q '3 products in .*; 3 to render' "$out/only.log" && grep -q '\[1/1\] south_east single' "$out/only.log" ||
  fail "--only south_east --force: $(grep 'to render' "$out/only.log")"
"$sylva" study "$scene" -o "$out/s" --spp 3 -q >/dev/null || fail "--spp 3 exited with $?"
grep -q '^spp 3$' "$out/s/south_west/wireline_single.manifest" || fail "--spp 3 did not render south_west anew"
"$sylva" study "$scene" -o "$out/s" --spp 3 --season winter --only south >/dev/null 2>"$out/winter.log" ||
  fail "--season winter exited with $?"
grep -q '3 products in .*; 3 to render' "$out/winter.log" && grep -q '^season_day 15$' "$out/s/south/proposed_single.manifest" ||
  fail "--season winter did not render south anew: $(grep 'to render' "$out/winter.log")"

# points: two more viewpoints by longitude and latitude
"$sylva" study "$scene" -o "$out/p" --points "$points" --viewpoints gate,south --products proposed -q >/dev/null ||
  fail "--points exited with $?"
got=$(cd "$out/p" && ls | tr '\n' ' ')
[ "$got" = "gate index.html south " ] || fail "--points --viewpoints gate,south wrote '$got'"
cmp -s "$out/p/south/proposed_single.png" "$out/r_south.png" || fail "south differs beside the points"

# ground: levels of detail around the development
"$sylva" study "$lod" -o "$out/lod" --products proposed -q >/dev/null || fail "study of $lod exited with $?"
"$sylva" render "$lod" --viewpoint south --size 72x48 --ground development -o "$out/lod_dev.png" -q >/dev/null &&
  "$sylva" render "$lod" --viewpoint south --size 72x48 -o "$out/lod_camera.png" -q >/dev/null || fail "LOD renders failed"
cmp -s "$out/lod/south/proposed_single.png" "$out/lod_dev.png" && cmp -s "$out/lod/south/proposed_single.exr" "$out/lod_dev.exr" ||
  fail "the study's view of $lod differs from render --ground development's"
cmp -s "$out/lod/south/proposed_single.png" "$out/lod_camera.png" &&
  fail "the study's view of $lod is the render's refined around the camera"

[ $fails -eq 0 ] && echo "study: identical to render, built once, resumed, settings, points and ground as expected"
exit $((fails > 0))
