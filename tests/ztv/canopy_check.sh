#!/usr/bin/env bash
# canopy_check.sh SYLVA GROUND COMPARE WORK — the ZTV of masts screened by the canopy surface
# (`sylva ztv`, screening canopy) on the shared ForestTools canopy height models, against
# gdal_viewshed run on the surface model and against exact sightlines (ztv_canopy_compare.c).
#
# Each CHM gets a synthetic ground on its own grid and CRS and the surface model DSM = DTM + CHM
# (GROUND: canopy_ground.c, which also picks the masts' open cells). The scene reads the DTM
# unrefined through the terrain plugin (its nodes are the CHM's pixels, so the map's cells are
# too) and the canopy as the CHM itself (CHM_test.tif) or as the DSM less the DTM
# (kootenayCHM.tif); MASTS masts of H metres, each its own development, on a flat Earth, eyes EYE
# metres above the ground. gdal_viewshed: its observer at the mast, -oz H less the CHM at the mast
# (its DSM stands that much above the ground), -cc 0, in its output mode GROUND (each cell's least
# target height above the DSM from which the mast is in sight), so that the comparison can put its
# eye EYE above the ground as sylva's, below the open cells' low vegetation (-tz EYE would put it
# EYE above the DSM).
#
# Exit 0 when both models pass, 1 when one does not, 77 (skipped) without the shared data.
set -uo pipefail
sylva=$1 ground=$2 compare=$3 work=$4
data=${SYLVA_SHARED_DATA_DIR:-}/canopy/foresttools
[ -f "$data/CHM_test.tif" ] && [ -f "$data/kootenayCHM.tif" ] ||
  { echo "skipped: $data is not there (the shared data beside the clone)"; exit 77; }
command -v gdal_viewshed >/dev/null || { echo "gdal_viewshed not found: install gdal-bin (scripts/install-deps.sh)" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work" || exit 1
MASTS=5 H=20 EYE=2

# The scene of one case into $w/scene.yaml: the canopy: line is $2.
scene() {
  local w=$1 canopy=$2 i=0
  {
    echo "site: {}"
    echo "terrain: {plugin: terrain_ifs, dtm: dtm.tif, refine: 1, method: deterministic, alpha: 0, biome: boreal}"
    echo "canopy: $canopy"
    echo "earth: {curvature: false}"
    echo "ztv:"
    echo "  observer_height: $EYE"
    echo "  screening: canopy"
    echo "  targets:"
    while read -r e n _; do
      i=$((i + 1))
      echo "    - {position: {easting: $e, northing: $n}, height_above_ground: $H, development: M$i}"
    done <"$w/masts.txt"
  } >"$w/scene.yaml"
}

status=0
for case in "CHM_test {chm: $data/CHM_test.tif}" "kootenayCHM {dsm: dsm.tif, dtm: dtm.tif}"; do
  name=${case%% *} canopy=${case#* }
  w=$work/$name && mkdir -p "$w"
  "$ground" "$data/$name.tif" "$w" "$MASTS" >"$w/masts.txt" || { echo "$name: canopy_ground failed" >&2; exit 1; }
  scene "$w" "$canopy"
  t0=$(date +%s.%N)
  (cd "$w" && "$sylva" ztv scene.yaml -o ztv --threads 2 -q >/dev/null) || { echo "$name: sylva ztv failed" >&2; status=1; continue; }
  t1=$(date +%s.%N)
  maps=()
  while read -r e n c; do
    t=${#maps[@]}
    oz=$(awk -v h="$H" -v c="$c" 'BEGIN { printf "%.4f", h - c }')
    gdal_viewshed -q -ox "$e" -oy "$n" -oz "$oz" -cc 0 -om GROUND "$w/dsm.tif" "$w/gdal_$t.tif" ||
      { echo "$name: gdal_viewshed failed" >&2; exit 1; }
    maps+=("$w/gdal_$t.tif")
  done <"$w/masts.txt"
  t2=$(date +%s.%N)
  echo "== $name: $MASTS masts of $H m, eyes $EYE m, canopy: $canopy; sylva ztv $(awk -v a="$t0" -v b="$t1" \
    'BEGIN { printf "%.2f", b - a }') s (bare earth and canopy), gdal_viewshed $(awk -v a="$t1" -v b="$t2" \
    'BEGIN { printf "%.2f", b - a }') s"
  "$compare" "$w/ztv/ztv_canopy.tif" "$w/ztv/ztv_bare.tif" "$data/$name.tif" "$w/dtm.tif" "$w/dsm.tif" "$EYE" "$H" \
    "$w/masts.txt" "${maps[@]}" || status=1
done
exit $status
