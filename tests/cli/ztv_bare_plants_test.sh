#!/usr/bin/env bash
# ztv_bare_plants_test.sh SYLVA SCENE — a bare-earth map is built without the scene's plants and is
# the same map: `sylva ztv` on tests/scenes/ztv/deciduous_screen.yaml (a double row of beech before
# a mast) screened by vegetation, then with --screening none, which must say that the plants are
# not built, build no tree variants, and write the screened run's bare-earth GeoTIFF byte for byte
# and its bare-earth rows of the summary.
set -uo pipefail
sylva=$1 scene=$2 fails=0 out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

"$sylva" ztv "$scene" -o "$out/screened" -q >/dev/null || fail "ztv (vegetation) exited with $?"
"$sylva" ztv "$scene" -o "$out/bare" --screening none >/dev/null 2>"$out/bare.log" || fail "ztv (none) exited with $?"
grep -q "^ztv: bare earth only: the scene's plants are not built$" "$out/bare.log" ||
  fail "ztv --screening none does not say that the plants are not built: $(cat "$out/bare.log")"
grep -q "^phases: " "$out/bare.log" || fail "ztv --screening none printed no phases line"
grep "^phases: " "$out/bare.log" | grep -q "tree variants" && fail "ztv --screening none built tree variants"
cmp -s "$out/screened/ztv_bare.tif" "$out/bare/ztv_bare.tif" ||
  fail "the bare-earth map without the plants differs from the screened run's"
diff <(grep ',bare,' "$out/screened/ztv_summary.csv") <(grep ',bare,' "$out/bare/ztv_summary.csv") >&2 ||
  fail "the summary's bare-earth rows differ"

[ $fails -eq 0 ] && echo "ztv: the bare-earth map without the plants is the screened run's bare-earth map"
exit $((fails > 0))
