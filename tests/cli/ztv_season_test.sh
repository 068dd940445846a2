#!/usr/bin/env bash
# ztv_season_test.sh SYLVA SCENE — screening by deciduous trees falls in winter: `sylva ztv` on
# tests/scenes/ztv/deciduous_screen.yaml (a double row of beech before a mast) as written
# (season: summer) and with season: winter. The area from which the row hides the mast (all of
# it or part of it) must shrink (to at most 95 % of summer's: the bare crowns' 4000 twigs a tree
# still hide part of the mast from most places), the area from which it hides the whole mast to
# at most half; the bare-earth map must not change.
set -uo pipefail
sylva=$1 scene=$2 fails=0 out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

grep -q '^season: summer$' "$scene" || { echo "FAIL: $scene has no 'season: summer' line" >&2; exit 1; }
sed 's/^season: summer$/season: winter/' "$scene" > "$out/winter.yaml"
cp "$scene" "$out/summer.yaml"
for s in summer winter; do
  "$sylva" ztv "$out/$s.yaml" -o "$out/$s" -q >/dev/null || fail "ztv ($s) exited with $?"
done

# value SEASON QUANTITY MODE: the summary's number (km2)
value() { awk -F, -v q="$2" -v m="$3" '$1 == q && $2 == m {print $4}' "$out/$1/ztv_summary.csv"; }
screened() { awk -v a="$(value "$1" area_hidden_by_screening vegetation)" \
                 -v b="$(value "$1" area_partly_hidden_by_screening vegetation)" 'BEGIN {printf "%.6f", a + b}'; }
summer=$(screened summer) winter=$(screened winter)
summer_full=$(value summer area_hidden_by_screening vegetation) winter_full=$(value winter area_hidden_by_screening vegetation)
echo "screened: summer $summer km2, winter $winter km2; wholly hidden: summer $summer_full km2, winter $winter_full km2"
awk -v s="$summer" 'BEGIN {exit !(s > 0.01)}' || fail "summer: the row screens only $summer km2, expected more than 0.01"
awk -v s="$summer" -v w="$winter" 'BEGIN {exit !(w <= 0.95 * s)}' ||
  fail "winter screens $winter km2, more than 95 % of summer's $summer km2"
awk -v s="$summer_full" -v w="$winter_full" 'BEGIN {exit !(w <= 0.5 * s)}' ||
  fail "winter hides the whole mast from $winter_full km2, more than half of summer's $summer_full km2"
cmp -s "$out/summer/ztv_bare.tif" "$out/winter/ztv_bare.tif" || fail "the bare-earth map differs between seasons"

[ $fails -eq 0 ] && echo "ztv: screening by the deciduous row falls in winter"
exit $((fails > 0))
