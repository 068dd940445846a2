#!/usr/bin/env bash
# ztv_test.sh SYLVA SCENE — `sylva ztv` end to end on tests/scenes/ztv/small_site.yaml: the files
# it promises appear (GeoTIFFs on the site's CRS, maps as PNG with its world file and PDF, summary) and nothing else; the summary
# finds the area the trees and the barn hide and the cells inside them; the maps and GeoTIFFs
# are byte for byte the same from one thread and from two; a second run replaces the files;
# --products raster writes the GeoTIFFs and their styles alone, the same bytes, and a bad list is refused.
set -uo pipefail
sylva=$1 scene=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

"$sylva" ztv "$scene" -o "$out/a" --threads 1 -q >/dev/null || fail "ztv exited with $?"
"$sylva" ztv "$scene" -o "$out/b" --threads 2 -q >/dev/null || fail "ztv --threads 2 exited with $?"
want="ztv_all.pdf ztv_all.pgw ztv_all.png ztv_all.qml ztv_all.tif ztv_bare.pdf ztv_bare.pgw ztv_bare.png ztv_bare.qml ztv_bare.tif ztv_developments.qml ztv_distance_rings.qml ztv_hidden_all.pdf ztv_hidden_all.pgw ztv_hidden_all.png ztv_hidden_all.tif ztv_layers.gpkg ztv_summary.csv ztv_summary.json ztv_viewpoints.qml"
got=$(cd "$out/a" && ls -A | tr '\n' ' ' | sed 's/ $//')
[ "$got" = "$want" ] || fail "files: '$got', expected '$want'"
for f in $want; do
  cmp -s "$out/a/$f" "$out/b/$f" || fail "$f differs between one thread and two"
done

# value QUANTITY MODE: the summary's number for it
value() { awk -F, -v q="$1" -v m="$2" '$1 == q && $2 == m {print $4}' "$out/a/ztv_summary.csv"; }
positive() { awk -v v="$1" 'BEGIN {exit !(v > 0)}'; }
for q in "area_hidden_by_screening all" "area_partly_hidden_by_screening all" "area_under_crown all" \
         "area_in_object all" "area_visible_0 bare" "area_visible_100 bare"; do
  v=$(value $q)
  positive "${v:-0}" || fail "summary: $q is '${v}', expected more than 0"
done
for q in "area_under_crown bare" "area_in_object bare" "area_not_computed bare"; do
  v=$(value $q)
  [ "$v" = "0" ] || fail "summary: $q is '${v}', expected 0"
done
# the 61 x 61 cells of 5 m add up to the grid's area in every mode
for m in bare all; do
  sum=$(awk -F, -v m=$m '$2 == m && $1 ~ /^area_(visible|under|in_obj|not_comp)/ {s += $4} END {printf "%.6f", s}' "$out/a/ztv_summary.csv")
  [ "$sum" = "0.093025" ] || fail "summary: the $m areas add up to $sum km2, expected 0.093025"
done

if command -v gdalinfo >/dev/null; then
  info=$(gdalinfo "$out/a/ztv_all.tif")
  grep -q 'WGS 84 / UTM zone 14N' <<<"$info" || fail "ztv_all.tif: no UTM zone 14N CRS"
  grep -q 'Pixel Size = (5.000000000000000,-5.000000000000000)' <<<"$info" || fail "ztv_all.tif: pixel size"
  grep -q 'Origin = (649847.500000000000000,3600152.500000000000000)' <<<"$info" || fail "ztv_all.tif: origin"
  grep -q 'Size is 61, 61' <<<"$info" || fail "ztv_all.tif: size"
fi

# a second run into the same folder replaces what is there
"$sylva" ztv "$scene" -o "$out/a" --screening none -q >/dev/null || fail "second run exited with $?"
[ -f "$out/a/ztv_bare.tif" ] && cmp -s "$out/a/ztv_bare.tif" "$out/b/ztv_bare.tif" || fail "rerun: ztv_bare.tif changed"

# --products raster: the GeoTIFFs and their styles, nothing else, the same bytes as with every product
"$sylva" ztv "$scene" -o "$out/r" --products raster --threads 1 -q >/dev/null || fail "--products raster exited with $?"
want="ztv_all.qml ztv_all.tif ztv_bare.qml ztv_bare.tif ztv_hidden_all.tif"
got=$(cd "$out/r" 2>/dev/null && ls -A | tr '\n' ' ' | sed 's/ $//')
[ "$got" = "$want" ] || fail "--products raster: files '$got', expected '$want'"
for f in $want; do cmp -s "$out/r/$f" "$out/b/$f" || fail "--products raster: $f differs from the full run's"; done
"$sylva" ztv "$scene" -o "$out/s" --products summary,raster -q >/dev/null || fail "--products summary,raster exited with $?"
[ -f "$out/s/ztv_summary.csv" ] && [ ! -e "$out/s/ztv_bare.png" ] || fail "--products summary,raster: wrong files"
"$sylva" ztv "$scene" -o "$out/x" --products raster,pictures -q >/dev/null 2>"$out/err"
rc=$?
[ $rc -eq 1 ] && grep -q "'pictures' is not a product" "$out/err" || fail "--products raster,pictures: exit $rc, $(cat "$out/err")"

[ $fails -eq 0 ] && echo "ztv: files, summary, thread count and rerun as expected"
exit $((fails > 0))
