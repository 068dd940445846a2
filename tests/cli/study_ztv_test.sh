#!/usr/bin/env bash
# study_ztv_test.sh SYLVA HILL_SCENE LAYERS_SCENE — the study's visibility map: `sylva study
# --products ...,ztv` maps it once from the study's build (refined around the development for the
# views) into DIR/ztv/, byte for byte the files of `sylva ztv` (the ground as surveyed, the plants
# on it); a rerun keeps it, and with one of its files deleted maps it alone again; a scene with
# a ztv: section gets its map without asking.
set -uo pipefail
sylva=$1 hill=$2 layers=$3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

"$sylva" study "$hill" -o "$out/s" --products proposed,ztv --size 48x32 --spp 1 -q >/dev/null ||
  fail "study exited with $?"
"$sylva" ztv "$hill" -o "$out/z" -q >/dev/null 2>&1 || fail "ztv exited with $?"
n=0
for f in "$out"/z/*; do
  name=$(basename "$f")
  n=$((n + 1))
  cmp -s "$f" "$out/s/ztv/$name" || fail "ztv/$name differs from sylva ztv's"
done
[ $n -ge 10 ] || fail "sylva ztv wrote $n files"
[ -f "$out/s/ztv/ztv.manifest" ] || fail "no ztv/ztv.manifest"
[ -f "$out/s/index.html" ] || fail "no index.html"

# a rerun keeps the map; without its GeoPackage it maps it again, and renders nothing
touch -d '2001-01-01' "$out"/s/ztv/*
log=$("$sylva" study "$hill" -o "$out/s" --products proposed,ztv --size 48x32 --spp 1 2>&1)
grep -q "the ZTV up to date" <<<"$log" || fail "rerun: the ZTV not up to date: $log"
grep -q "0 scene builds" <<<"$log" || fail "rerun: a scene was built: $log"
[ -z "$(find "$out/s/ztv" -type f -newermt '2002-01-01')" ] || fail "rerun: the map's files were rewritten"
rm "$out/s/ztv/ztv_layers.gpkg"
log=$("$sylva" study "$hill" -o "$out/s" --products proposed,ztv --size 48x32 --spp 1 2>&1)
grep -q "0 to render, 3 up to date; the ZTV to map" <<<"$log" || fail "after a deletion: $log"
grep -q "0 frames rendered" <<<"$log" || fail "after a deletion, frames were rendered: $log"
cmp -s "$out/z/ztv_layers.gpkg" "$out/s/ztv/ztv_layers.gpkg" || fail "the GeoPackage made again differs"

# the scene's ztv: section asks for the map; --products without ztv leaves it out
"$sylva" study "$layers" -o "$out/l" --products proposed --size 24x16 --spp 1 -q >/dev/null 2>&1 ||
  fail "study of the layers site exited with $?"
[ ! -e "$out/l/ztv" ] || fail "--products proposed made the map"
"$sylva" study "$layers" -o "$out/l" --size 24x16 --spp 1 -q >/dev/null 2>&1 || fail "second study exited with $?"
[ -f "$out/l/ztv/ztv_layers.gpkg" ] || fail "the ztv: section did not make the map"

[ $fails -eq 0 ] && echo "study ztv: the map of sylva ztv, kept, remade alone, asked for by the scene"
exit $((fails > 0))
