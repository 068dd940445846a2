#!/usr/bin/env bash
# simulate_cli_test.sh SYLVA SCENE OUTDIR — `sylva simulate` and `sylva factors` end to end:
# a run saved at year 15 and continued to 40 writes the same plant CSV as a run straight to 40;
# --stats writes the population CSV and chart and the maps; factors writes every map; bad
# options and a state from another scene fail with their exit status and message; --threads 1
# and 3 write the same plants.
set -euo pipefail
sylva=$1 scene=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
fail() { echo "FAIL: $*" >&2; exit 1; }

"$sylva" simulate "$scene" --years 40 -o "$out/whole.csv" -q >/dev/null
"$sylva" simulate "$scene" --years 15 --save "$out/y15.state" -q >/dev/null
"$sylva" simulate "$scene" --load "$out/y15.state" --years 25 -o "$out/continued.csv" \
  --stats "$out/stats" --maps 15,30 -q >/dev/null
cmp -s "$out/whole.csv" "$out/continued.csv" || fail "the continued run differs from the uninterrupted one"
# the species' seedlings, growth and deaths and the dominance search on worker threads: the same
# plants, byte for byte, for any thread count
"$sylva" simulate "$scene" --years 40 --threads 1 -o "$out/t1.csv" -q >/dev/null
"$sylva" simulate "$scene" --years 40 --threads 3 -o "$out/t3.csv" -q >/dev/null
cmp -s "$out/whole.csv" "$out/t1.csv" || fail "--threads 1 differs from the default thread count"
cmp -s "$out/t1.csv" "$out/t3.csv" || fail "--threads 3 differs from --threads 1"
head -1 "$out/whole.csv" | grep -qx 'species,x,y,z,age,height,radius,vigour' || fail "CSV header"
[ "$(wc -l < "$out/whole.csv")" -gt 50 ] || fail "too few plants in the CSV"
for f in population.csv population.png map_0015.png map_0030.png map_0040.png; do
  [ -s "$out/stats/$f" ] || fail "missing stats/$f"
done
[ "$(wc -l < "$out/stats/population.csv")" -eq 27 ] || fail "population.csv should hold years 15 to 40"
head -1 "$out/stats/population.csv" | grep -qx 'year,beech,shrub,crate' || fail "population.csv header"

"$sylva" factors "$scene" -o "$out/factors" -q >/dev/null
for f in altitude slope humidity windiness sunniness water; do
  [ -s "$out/factors/$f.png" ] || fail "missing factors/$f.png"
done
[ "$(wc -l < "$out/factors/factors.csv")" -eq 401 ] || fail "factors.csv should hold 20 x 20 patches"

set +e
msg=$("$sylva" simulate "$scene" --years -3 2>&1); rc=$?
[ $rc -eq 1 ] && echo "$msg" | grep -q -- "--years expects a whole number" || fail "bad --years: $rc $msg"
msg=$("$sylva" simulate "$scene" --load "$out/whole.csv" 2>&1); rc=$?
[ $rc -eq 2 ] && echo "$msg" | grep -q "not a sylva ecology state" || fail "bad --load: $rc $msg"
msg=$("$sylva" factors "$scene" 2>&1); rc=$?
[ $rc -eq 1 ] || fail "factors without -o: $rc"
echo "ok"
