#!/usr/bin/env bash
# ztv_edges_test.sh SYLVA SCENE — `sylva ztv` and `sylva probe` on a scene without a camera:
# section (tests/scenes/ztv/no_camera.yaml), which `sylva render` still refuses; the map's
# radius running 20 m past the terrain's east edge is said on stderr and in the summary, and the
# cells there are mapped as no terrain (their own class in the summary, nodata in the GeoTIFF).
set -uo pipefail
sylva=$1 scene=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

"$sylva" ztv "$scene" -o "$out/map" -q 2>"$out/stderr" >/dev/null || fail "ztv without a camera exited with $?"
cat "$out/stderr"
grep -qF "the radius of 40 m reaches 20.0 m past the terrain's east edge" "$out/stderr" ||
  fail "stderr does not say how far the radius runs past the east edge"
"$sylva" probe "$scene" 0 0 >"$out/probe" 2>&1 || fail "probe without a camera exited with $?"
grep -q "ground" "$out/probe" || fail "probe printed no ground: $(cat "$out/probe")"
"$sylva" render "$scene" -o "$out/r.png" --size 8x8 --spp 1 2>"$out/render" && fail "render without a camera succeeded"
grep -qF "missing required section 'camera'" "$out/render" || fail "render: $(cat "$out/render")"

csv=$out/map/ztv_summary.csv
value() { awk -F, -v q="$1" -v m="$2" '$1 == q && $2 == m {print $4}' "$csv"; }
[ "$(value radius_past_east_edge '')" = "20" ] || fail "summary: radius_past_east_edge is '$(value radius_past_east_edge '')'"
[ "$(value radius_past_west_edge '')" = "0" ] || fail "summary: radius_past_west_edge is '$(value radius_past_west_edge '')'"
awk -v v="$(value area_no_terrain bare)" 'BEGIN {exit !(v > 0)}' || fail "summary: no area without terrain"
grep -q '"radius_past_terrain_m": {"west": 0, "east": 20, "south": 0, "north": 0}' "$out/map/ztv_summary.json" ||
  fail "ztv_summary.json lacks the radius past the terrain"
grep -q '"no_terrain": {"cells": [1-9]' "$out/map/ztv_summary.json" || fail "ztv_summary.json: no cells without terrain"
# the grid reaches the radius: 17 columns from -10 to 70 m, not cut at the terrain's edge at 50 m
[ "$(value grid_columns '')" = "17" ] || fail "summary: grid_columns is '$(value grid_columns '')', expected 17"
# the areas of a mode add up to the grid's, no terrain included
sum=$(awk -F, '$2 == "bare" && $1 ~ /^area_(visible|under|in_obj|not_comp|no_terrain)/ {s += $4} END {printf "%.6f", s}' "$csv")
want=$(awk -F, '$1 == "grid_columns" {c = $4} $1 == "grid_rows" {r = $4} END {printf "%.6f", c * r * 25e-6}' "$csv")
[ "$sum" = "$want" ] || fail "summary: the bare areas add up to $sum km2, the grid is $want"
if command -v gdallocationinfo >/dev/null; then
  v=$(gdallocationinfo -valonly -geoloc "$out/map/ztv_bare.tif" 60 0 | head -1)
  [ "$v" = "-1" ] || fail "ztv_bare.tif at (60, 0), past the terrain: '$v', expected nodata -1"
  v=$(gdallocationinfo -valonly -geoloc "$out/map/ztv_bare.tif" 40 0 | head -1)
  [ "$v" = "2" ] || fail "ztv_bare.tif at (40, 0), on the terrain: '$v' targets visible, expected 2"
fi

[ $fails -eq 0 ] && echo "ztv edges: no camera needed, the radius past the terrain said and mapped as no terrain"
exit $((fails > 0))
