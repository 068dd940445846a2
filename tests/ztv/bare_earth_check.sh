#!/usr/bin/env bash
# bare_earth_check.sh gdal|exact SYLVA TOOL WORK SCENE... — the bare-earth ZTV of each scene
# (`sylva ztv`) against a reference on the same DTM, targets, heights and curvature:
#   gdal   gdal_viewshed, the tool practitioners make ZTVs with; TOOL is ztv_gdal_compare
#          (ztv_gdal_compare.c), which says what agreeing means and prints the figures;
#   exact  exact sightlines over the same ground, computed independently of sylva's tracer;
#          TOOL is ztv_sightline_oracle (ztv_sightline_oracle.c).
# Each scene (tests/ztv/*.yaml) names a DTM file with `dtm:`, optionally `crop:` and
# `cell_size:`, an `earth:` line, the ZTV's `observer_height:` and its targets one per line as
# `{position: [x, y], height_above_ground: H, development: NAME}` in local metres (the scene has no
# site, so the DTM's footprint is centred on the origin).
#
# gdal_viewshed gets a GeoTIFF copy of the DTM cut and sized as sylva reads it, carrying a
# transverse Mercator CRS on a sphere of sylva's Earth radius (6,371 km): gdal_viewshed takes the
# radius from the raster's CRS, and ignores -cc on a raster without one. sylva's observer at
# observer_height above a cell seeing a target H above the ground is gdal_viewshed's observer at
# the target (-oz H) seeing the cell's ground plus -tz observer_height. Curvature: sylva's
# refraction k is gdal_viewshed's -cc 1 - k; a flat Earth (`curvature: false`) is -cc 0.
#
# Exit 0 when every scene agrees, 1 when one does not, 77 (skipped) without the shared data.
set -uo pipefail
mode=$1 sylva=$2 tool=$3 work=$4
shift 4
case $mode in gdal|exact) ;; *) echo "mode must be gdal or exact, not '$mode'" >&2; exit 2 ;; esac
command -v gdal_viewshed >/dev/null && command -v gdal_translate >/dev/null ||
  { echo "gdal_viewshed or gdal_translate not found: install gdal-bin (scripts/install-deps.sh)" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work" || exit 1

# The first value of KEY in the scene (a number, a path or a list's inside), or empty.
value() { sed -n "s/^[[:space:]]*$2:[[:space:]]*\[\{0,1\}\([^]#]*\)\]\{0,1\}[[:space:]]*\(#.*\)\{0,1\}$/\1/p" "$1" | head -n 1; }

status=0
for scene in "$@"; do
  name=$(basename "$scene" .yaml)
  dir=$(cd "$(dirname "$scene")" && pwd)
  w=$work/$name && mkdir -p "$w"
  dtm=$(value "$scene" dtm) crop=$(value "$scene" crop) cell=$(value "$scene" cell_size)
  h=$(value "$scene" observer_height)
  [ -n "$dtm" ] && [ -n "$h" ] || { echo "$scene: no dtm or observer_height" >&2; exit 1; }
  case $dtm in /*) ;; *) dtm=$dir/$dtm ;; esac
  [ -f "$dtm" ] || { echo "skipped: $dtm is not there (the shared data beside the clone)"; exit 77; }
  if grep -q '^earth:.*curvature: true' "$scene"; then
    k=$(sed -n 's/^earth:.*refraction: \([-0-9.]*\).*/\1/p' "$scene")
    cc=$(awk -v k="${k:-0.13}" 'BEGIN { printf "%.10g", 1 - k }')
  else
    cc=0
  fi

  # gdal_viewshed's copy: the crop as sylva takes it, square cells as cell_size makes them.
  opts=(-q -a_srs "+proj=tmerc +R=6371000 +units=m +no_defs")
  [ -n "$crop" ] && opts+=(-srcwin ${crop//,/ })
  gdal_translate "${opts[@]}" "$dtm" "$w/dtm.tif" || { echo "$name: gdal_translate failed" >&2; exit 1; }
  read -r nx ny x0 y0 px <<<"$(gdalinfo "$w/dtm.tif" | sed -n \
    -e 's/^Size is \([0-9]*\), \([0-9]*\)/\1 \2/p' -e 's/^Origin = (\([^,]*\),\([^)]*\))/\1 \2/p' \
    -e 's/^Pixel Size = (\([^,]*\),.*/\1/p' | tr '\n' ' ')"
  if [ -n "$cell" ]; then
    px=$cell
    gdal_translate -q -a_ullr "$x0" "$y0" "$(awk -v a="$x0" -v n="$nx" -v c="$cell" 'BEGIN { printf "%.6f", a + n * c }')" \
      "$(awk -v a="$y0" -v n="$ny" -v c="$cell" 'BEGIN { printf "%.6f", a - n * c }')" "$w/dtm.tif" "$w/dtm_sq.tif" &&
      mv "$w/dtm_sq.tif" "$w/dtm.tif" || exit 1
  fi
  # map = local + the centre of the footprint
  cx=$(awk -v a="$x0" -v n="$nx" -v c="$px" 'BEGIN { printf "%.6f", a + 0.5 * n * c }')
  cy=$(awk -v a="$y0" -v n="$ny" -v c="$px" 'BEGIN { printf "%.6f", a - 0.5 * n * c }')

  t0=$(date +%s.%N)
  "$sylva" ztv "$scene" -o "$w/ztv" -q || { echo "$name: sylva ztv failed" >&2; status=1; continue; }
  t1=$(date +%s.%N)
  targets=$(sed -n 's/.*position: \[\([-0-9.]*\), *\([-0-9.]*\)\], *height_above_ground: *\([0-9.]*\).*/\1 \2 \3/p' "$scene")
  [ -n "$targets" ] || { echo "$scene: no targets" >&2; exit 1; }
  if [ "$mode" = exact ]; then
    curve=$(awk -v c="$cc" 'BEGIN { printf "%.12g", c / (2 * 6371000) }')
    echo "== $name: exact sightlines, observer $h m, (1 - k) / 2R = $curve /m; sylva ztv $(awk -v a="$t0" -v b="$t1" \
      'BEGIN { printf "%.2f", b - a }') s"
    # shellcheck disable=SC2086 # the targets' numbers are words
    "$tool" "$w/ztv/ztv_bare.tif" "$w/dtm.tif" "$h" "$curve" $targets || status=1
    continue
  fi
  maps=()
  while read -r x y H; do
    t=${#maps[@]}
    ox=$(awk -v c="$cx" -v x="$x" 'BEGIN { printf "%.6f", c + x }')
    oy=$(awk -v c="$cy" -v y="$y" 'BEGIN { printf "%.6f", c + y }')
    gdal_viewshed -q -ox "$ox" -oy "$oy" -oz "$H" -tz "$h" -cc "$cc" -vv 1 -iv 0 "$w/dtm.tif" "$w/gdal_$t.tif" ||
      { echo "$name: gdal_viewshed failed" >&2; exit 1; }
    maps+=("$w/gdal_$t.tif")
  done <<<"$targets"
  t2=$(date +%s.%N)
  echo "== $name: ${#maps[@]} targets, observer $h m, gdal_viewshed -cc $cc; sylva ztv $(awk -v a="$t0" -v b="$t1" \
    'BEGIN { printf "%.2f", b - a }') s, gdal_viewshed $(awk -v a="$t1" -v b="$t2" 'BEGIN { printf "%.2f", b - a }') s"
  "$tool" "$w/ztv/ztv_bare.tif" "$w/dtm.tif" "${maps[@]}" | tee "$w/figures.txt"
  [ "${PIPESTATUS[0]}" -eq 0 ] || status=1
done

# The curvature hides cells: in both tools the curved map of the hills sees fewer cell-targets
# than the flat one, and sylva's loss is gdal_viewshed's within a quarter (a wrong sign, or the
# diameter taken for the radius, changes it by all or twice; the agreement alone would not tell).
if [ "$mode" = gdal ] && [ -f "$work/hills_curved/figures.txt" ] && [ -f "$work/hills_flat/figures.txt" ]; then
  loss() { echo $(( $(sed -n "s/^$1 visible cells: //p" "$work/hills_flat/figures.txt") -
                    $(sed -n "s/^$1 visible cells: //p" "$work/hills_curved/figures.txt") )); }
  ls=$(loss sylva) lg=$(loss gdal)
  echo "the curvature hides $ls cell-targets in sylva's map, $lg in gdal_viewshed's"
  [ "$lg" -gt 0 ] && [ "$ls" -gt 0 ] && [ $(( 4 * (ls > lg ? ls - lg : lg - ls) )) -le "$lg" ] ||
    { echo "FAIL: the curvature's effect differs between the two" >&2; status=1; }
fi
exit $status
