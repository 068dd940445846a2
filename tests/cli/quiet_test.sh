#!/usr/bin/env bash
# quiet_test.sh SYLVA DIR SCENE GEO_SCENE — with -q a command prints only warnings and errors:
# every command that takes -q, run on SCENE (whose terrain plugin logs information lines while
# it builds), must leave stderr empty; without -q, render shows the plugin's information lines.
# GEO_SCENE's DTM is in degrees and its site left to the DTM: the loader's line saying which UTM
# zone it chose is shown by probe, and left out by probe -q.
set -uo pipefail
sylva=$1 dir=$2 scene=$3 geo_scene=$4
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
cp "$scene" scene.yaml && echo "photo: {file: plate.png}" >> scene.yaml || exit 1
echo "viewpoints: {south: {position: [0, -260, 90], look_at: [0, 0, 20], fov: 55}}" >> scene.yaml || exit 1
fail() { echo "$*" >&2; exit 1; }

err=$("$sylva" render scene.yaml -o plate.png 2>&1 >/dev/null) || fail "render without -q failed: $err"
grep -q "^sylva: terrain plugin 'terrain_ifs': " <<<"$err" ||
  fail "render without -q shows no information line of the terrain plugin: $err"

quiet() { # NAME COMMAND...: the command succeeds with nothing on stderr
  local name=$1 out
  shift
  out=$("$sylva" "$@" 2>&1 >/dev/null) || fail "$name -q failed: $out"
  [ -z "$out" ] || fail "$name -q printed on stderr: $out"
  echo "$name -q: stderr empty"
}
quiet render render scene.yaml -q -o r.png
quiet simulate simulate scene.yaml --years 2 -q -o plants.csv
quiet factors factors scene.yaml -q -o factors
quiet export-pov export-pov scene.yaml -q -o x.pov
quiet probe probe scene.yaml 0 0 -q
quiet ztv ztv scene.yaml -q -o ztv --cell 20
quiet montage montage scene.yaml -q -o montage
quiet study study scene.yaml -q -o study --width 32
err=$("$sylva" probe "$geo_scene" 499660 3762300 2>&1 >/dev/null) || fail "probe on a geographic DTM failed: $err"
grep -q "the site CRS is the UTM zone of its centre" <<<"$err" ||
  fail "probe without -q does not say which UTM zone the site took: $err"
quiet probe-geographic probe "$geo_scene" 499660 3762300 -q
if command -v povray >/dev/null; then
  quiet crosscheck crosscheck scene.yaml -q -o crosscheck --size 16x12 --spp 1
fi
exit 0
