#!/usr/bin/env bash
# biome_check.sh SYLVA WORK SRC — the ground terrain_ifs gives a site by its climate
# (docs/models/terrain_ifs.md, Biomes), read from the plugin's class counts:
#   - a steep dry DTM at 34.3 N (steep_dry_dtm.py, like the San Gabriel front) picks the
#     Mediterranean biome by itself: no snow, and scree on under 5 % of the ground (30 % of its
#     slopes lie at 30 to 40 degrees, which shrubs cover there);
#   - the same DTM with an explicit snow_altitude of 1,500 m has snow (the scene's key wins);
#   - a scene without a site stays temperate;
#   - the shared Zion DTM (37.2 N, top 2,892 m) has no snow in summer, its biome from the latitude
#     alone is a warning, and with its NLCD land cover it is semi-arid (skipped without the data).
# Exit 0 when all hold, 1 when one does not.
set -uo pipefail
sylva=$1 work=$2 src=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
python3 "$src/steep_dry_dtm.py" "$work/steep.asc" || exit 1
status=0

# The share (%) of class $2 in the "ground:" line of log $1.
share() { sed -n "s/.*ground: .* \([0-9.]*\)% $2\b.*/\1/p; s/.*ground: \([0-9.]*\)% $2,.*/\1/p" "$1" | head -n 1; }
render() { # name, then the scene text
  printf '%s\n' "$2" > "$work/$1.yaml"
  "$sylva" render "$work/$1.yaml" -o "$work/$1.png" --size 64x48 --spp 1 --threads 2 > "$work/$1.log" 2>&1 ||
    { echo "FAIL: $1 did not render:"; cat "$work/$1.log"; status=1; }
}
expect() { # what, condition (awk), value
  if awk "BEGIN { exit !($2) }"; then echo "ok: $1 ($3)"; else echo "FAIL: $1 ($3)"; status=1; fi
}

steep="terrain: {plugin: terrain_ifs, dtm: $work/steep.asc, refine: 1}"
render steep_auto "site: {}
camera: {position: [0, -2500, 2200], look_at: [0, 0, 1200]}
$steep"
grep -q "biome mediterranean (auto" "$work/steep_auto.log" && echo "ok: the steep dry site is Mediterranean" ||
  { echo "FAIL: the steep dry site's biome:"; grep biome "$work/steep_auto.log"; status=1; }
snow=$(share "$work/steep_auto.log" snow) scree=$(share "$work/steep_auto.log" scree)
expect "no snow on the steep dry site" "${snow:-1} == 0" "snow ${snow:-?} %"
expect "little scree on the steep dry site" "${scree:-100} < 5" "scree ${scree:-?} %"

render steep_snow "site: {}
camera: {position: [0, -2500, 2200], look_at: [0, 0, 1200]}
terrain: {plugin: terrain_ifs, dtm: $work/steep.asc, refine: 1, snow_altitude: 1500}"
snow=$(share "$work/steep_snow.log" snow)
expect "an explicit snow_altitude wins" "${snow:-0} > 5" "snow ${snow:-?} %"

render no_site "camera: {position: [0, -2500, 2200], look_at: [0, 0, 1200]}
$steep"
grep -q "biome temperate (auto: the scene has no site)" "$work/no_site.log" && echo "ok: no site, temperate" ||
  { echo "FAIL: a scene without a site:"; grep biome "$work/no_site.log"; status=1; }
scree=$(share "$work/no_site.log" scree)
expect "the temperate rules put scree on the steep slopes" "${scree:-0} > 15" "scree ${scree:-?} %"

zion=${SYLVA_SHARED_DATA_DIR:-$src/../../../shared/data}/sites/zion/srtm.tif
if [ -f "$zion" ]; then
  render zion "site: {}
camera: {position: [-2000, -8000, 2300], look_at: [-1700, 10900, 2700]}
terrain: {plugin: terrain_ifs, dtm: $zion, refine: 1}"
  snow=$(share "$work/zion.log" snow)
  grep "biome" "$work/zion.log" | sed 's/^/   /'
  expect "no snow on Zion in summer" "${snow:-1} == 0" "snow ${snow:-?} %"
  grep -q "picked from the site's latitude" "$work/zion.log" && echo "ok: latitude alone is a warning" ||
    { echo "FAIL: no warning that the biome rests on the latitude alone"; status=1; }
  render zion_cover "site: {}
camera: {position: [-2000, -8000, 2300], look_at: [-1700, 10900, 2700]}
terrain: {plugin: terrain_ifs, dtm: $zion, refine: 1}
landcover: {raster: $(dirname "$zion")/nlcd2011.tif}"
  grep "biome" "$work/zion_cover.log" | sed 's/^/   /'
  grep -q "biome semi_arid (auto, from the land cover" "$work/zion_cover.log" &&
    ! grep -q "picked from the site's latitude" "$work/zion_cover.log" &&
    echo "ok: Zion's land cover (pinyon-juniper, scrub, bare rock) makes it semi-arid" ||
    { echo "FAIL: Zion with its land cover:"; grep -i "biome\|landcover" "$work/zion_cover.log"; status=1; }
else
  echo "skipped the Zion case: $zion is not there"
fi
exit $status
