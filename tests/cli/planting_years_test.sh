#!/usr/bin/env bash
# planting_years_test.sh SYLVA SCENE — a planting plan over the years (tests/scenes/planting/belt.yaml):
# a planted tree's height at --year N is the height of its species' age variant at the matching
# age (the row of `sylva tree-stats` for that age, within 5 %), the same tree stands in the same place every year, and
# `sylva ztv --years` writes each year's maps, what the planting hides (a map page with a world file)
# and the visible area
# against the years (a chart on a page of 190 x 105 mm at 200 dpi): nothing hidden at year 1 (whips
# below every sightline), the mast hidden from
# some place by year 30, and the visible area never growing from one year to the next.
set -uo pipefail
sylva=$1 scene=$2 fails=0 out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

# The post oak of the plan is planted at the height of its species' youngest variant (age 0.25 of
# 60 years: 15 years old), so at --year 15 it is 30 years old (age 0.5) and at --year 45 full grown.
probe_oak() { "$sylva" probe "$scene" -50 5 --year "$1" -q | awk '$1 == "post_oak" {print $2, $4, $5}'; }
stats() { "$sylva" tree-stats "$scene" post_oak 2>/dev/null | awk -v a="$1" '$2 + 0 == a + 0 {print $10}'; }
for pair in "0 0.25" "15 0.5" "45 1"; do
  set -- $pair
  got=$(probe_oak "$1") want=$(stats "$2")
  read -r height x y <<<"$got"
  echo "year $1: the oak is ${height:-?} m tall at ($x, $y); tree-stats at age $2: ${want:-?} m"
  awk -v g="$height" -v w="$want" 'BEGIN {exit !(w > 0 && g > 0.95 * w && g < 1.05 * w)}' ||
    fail "year $1: the oak is ${height:-?} m, the model at age $2 ${want:-?} m"
  [ "$x $y" = "-50.000 5.000" ] || fail "year $1: the oak stands at ($x, $y), not (-50, 5)"
done

# The belt alone for the maps (the plan's single trees, standing taller, and their species left out).
sed -e '/^  trees:/,$d' -e '/^  include:/d' "$scene" > "$out/belt.yaml"
grep -q '^  belts:' "$out/belt.yaml" && ! grep -q '^  trees:' "$out/belt.yaml" || fail "the belt's scene is not cut as expected"
"$sylva" ztv "$out/belt.yaml" -o "$out/ztv" --years 1,10,20,30,40 -q > "$out/stdout" || fail "ztv --years exited with $?"
for f in before/ztv_summary.csv year_1/ztv_vegetation.tif year_1/ztv_hidden_by_planting.tif year_40/ztv_hidden_by_planting.png \
         visible_area.csv visible_area.png; do
  [ -s "$out/ztv/$f" ] || fail "no $f"
done
# what the planting hides is a map page like the others: A3 at 150 dpi, its title saying the year
file "$out/ztv/year_40/ztv_hidden_by_planting.png" | grep -q "2480 x 1754" ||
  fail "year 40's hidden map is not an A3 page at 150 dpi: $(file "$out/ztv/year_40/ztv_hidden_by_planting.png")"
pdftotext "$out/ztv/year_40/ztv_hidden_by_planting.pdf" - 2>/dev/null | grep -q "hidden by the planting, 40 years after planting" ||
  fail "year 40's hidden map (PDF) does not say what it shows"
[ -s "$out/ztv/year_40/ztv_hidden_by_planting.pgw" ] || fail "year 40's hidden map has no world file"
file "$out/ztv/visible_area.png" | grep -q "1496 x 827" ||
  fail "visible_area.png is not the 190 x 95 mm page at 200 dpi: $(file "$out/ztv/visible_area.png")"
cat "$out/ztv/visible_area.csv"
awk -F, 'NR == 3 && $3 != 0 {exit 1}' "$out/ztv/visible_area.csv" || fail "year 1 hides the mast from somewhere"
awk -F, 'NR == 7 && !($3 > 0) {exit 1}' "$out/ztv/visible_area.csv" || fail "year 40 hides the mast from nowhere"
awk -F, 'NR > 2 {if (NR > 3 && $2 > last + 1e-12) bad = 1; last = $2} END {exit bad}' "$out/ztv/visible_area.csv" ||
  fail "the visible area grows from one year to the next"

"$sylva" ztv "$out/belt.yaml" -o "$out/bad" --years 10,5 -q 2>"$out/err"; rc=$?
[ "$rc" = 1 ] && grep -q "increasing" "$out/err" || fail "--years 10,5: exit $rc, $(cat "$out/err")"
exit $((fails > 0))
