#!/usr/bin/env bash
# ground_check.sh SYLVA WORK SCENE... — the ground a ZTV traces, on real DTMs (tests/ztv/*_default.yaml,
# the terrain plugin's defaults). For each scene, with its camera as given and moved 6 km:
#   - the default map (the DTM as surveyed) is the same bytes for both cameras, and so is `probe`
#     at three points;
#   - the map on the refined ground (`--ground refined`, levels of detail around the development)
#     is the same bytes for both cameras;
#   - the refinement's texture (alpha from the DTM's own roughness) changes the visible area by
#     less than 1 % against the surveyed ground;
#   - each summary says which ground it traced.
# Exit 0 when all hold, 1 when one does not, 77 (skipped) without the shared data.
set -uo pipefail
sylva=$1 work=$2
shift 2
rm -rf "$work" && mkdir -p "$work" || exit 1

# The area from which at least one target is seen (km2), from a ztv summary: every bare band but 0.
visible() { awk -F, '$1 ~ /^area_visible_/ && $1 != "area_visible_0" && $2 == "bare" { s += $4 } END { printf "%.9f", s }' "$1"; }

status=0
for scene in "$@"; do
  name=$(basename "$scene" .yaml)
  dir=$(cd "$(dirname "$scene")" && pwd)
  w=$work/$name && mkdir -p "$w"
  dtm=$(sed -n 's/^[[:space:]]*dtm:[[:space:]]*\([^#[:space:]]*\).*/\1/p' "$scene" | head -n 1)
  case $dtm in /*) ;; *) dtm=$dir/$dtm ;; esac
  [ -f "$dtm" ] || { echo "skipped: $dtm is not there (the shared data beside the clone)"; exit 77; }
  # the scene twice, with the DTM's path made absolute: as given, and its camera 6 km east
  sed "s#^\([[:space:]]*dtm:[[:space:]]*\)[^#[:space:]]*#\1$dtm#" "$scene" > "$w/a.yaml"
  awk '/^camera: \{position: \[/ { match($0, /\[[-0-9.]+,/)
                                    $0 = substr($0, 1, RSTART) (substr($0, RSTART + 1, RLENGTH - 2) + 6000) \
                                         substr($0, RSTART + RLENGTH - 1) } { print }' "$w/a.yaml" > "$w/b.yaml"
  cmp -s "$w/a.yaml" "$w/b.yaml" && { echo "$name: the camera line was not moved" >&2; exit 1; }
  for v in a b; do
    "$sylva" ztv "$w/$v.yaml" -o "$w/surveyed_$v" -q >/dev/null 2>"$w/surveyed_$v.err" &&
      "$sylva" ztv "$w/$v.yaml" -o "$w/refined_$v" --ground refined -q >/dev/null 2>"$w/refined_$v.err" ||
      { echo "$name: sylva ztv failed:" >&2; cat "$w"/*_"$v".err >&2; status=1; continue 2; }
    for p in "0 0" "-3000 2500" "4100 -3700"; do
      # shellcheck disable=SC2086 # the point's two numbers are words
      "$sylva" probe "$w/$v.yaml" $p --local 2>/dev/null >> "$w/probe_$v.txt"
    done
  done
  for g in surveyed refined; do
    for f in ztv_bare.tif ztv_summary.csv; do
      cmp -s "$w/${g}_a/$f" "$w/${g}_b/$f" || { echo "FAIL $name: $g $f changes with the camera"; status=1; }
    done
  done
  cmp -s "$w/probe_a.txt" "$w/probe_b.txt" || { echo "FAIL $name: probe changes with the camera"; status=1; }
  grep -q '^ground,,,"the DTM as surveyed' "$w/surveyed_a/ztv_summary.csv" &&
    grep -q '^ground,,,"the terrain refined around the development' "$w/refined_a/ztv_summary.csv" ||
    { echo "FAIL $name: a summary does not say which ground it traced"; status=1; }
  s=$(visible "$w/surveyed_a/ztv_summary.csv") r=$(visible "$w/refined_a/ztv_summary.csv")
  change=$(awk -v s="$s" -v r="$r" 'BEGIN { printf "%.3f", 100 * (r - s) / s }')
  echo "== $name: visible area on the DTM as surveyed $s km2, on the refined ground $r km2 ($change %)"
  grep -h "roughness\|adds" "$w/refined_a.err" | sed 's/^sylva: terrain plugin .terrain_ifs.: /   /' | cut -c1-220
  awk -v c="$change" 'BEGIN { exit !(c < 1 && c > -1) }' ||
    { echo "FAIL $name: the refinement changes the visible area by $change %, 1 % at most"; status=1; }
done
exit $status
