#!/usr/bin/env bash
# planting_study_test.sh SYLVA SCENE — `sylva study` of a planting plan (tests/scenes/planting/belt.yaml
# with a viewpoint, the mast as the development and a study: section added): at each of study.years it writes the viewpoint's
# sheet into DIR/year_N_SEASON/, and each sheet says in its title and its table which year since
# planting, calendar year and season it shows.
set -uo pipefail
sylva=$1 scene=$2 fails=0 out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

sed -e '/^  include:/d' -e '/^  trees:/,$d' "$scene" > "$out/plan.yaml"
sed -i -e 's|^ztv:|image: {width: 64, height: 36, spp: 1}\nviewpoints:\n  west: {position: [-60, 0, 1.6], look_at: [100, 0, 3], focal_length: 35}\nobjects:\n  - {name: mast, shape: box, size: [1, 1, 10], position: [100, 0, 5], development: true}\nstudy: {viewpoints: [west], products: [sheet], years: "1 winter, 15 summer"}\nztv:|' \
  "$out/plan.yaml"
"$sylva" study "$out/plan.yaml" -o "$out/study" --threads 2 -q 2>"$out/err" || fail "study exited with $?: $(cat "$out/err")"
for y in "1 winter 2028" "15 summer 2042"; do
  set -- $y
  dir="$out/study/year_$1_$2/west"
  for f in sheet_single.pdf sheet_single.png; do [ -s "$dir/$f" ] || fail "no year_$1_$2/west/$f"; done
  text=$(pdftotext "$dir/sheet_single.pdf" - 2>/dev/null | tr '\n' ' ')
  grep -q "year $1 after planting ($3), $2" <<<"$text" || fail "the sheet of year $1 does not say 'year $1 after planting ($3), $2'"
  grep -q "Mitigation planting" <<<"$text" || fail "the sheet of year $1 has no row for the planting"
done
exit $((fails > 0))
