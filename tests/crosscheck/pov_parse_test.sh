#!/usr/bin/env bash
# pov_parse_test.sh SYLVA SCENE OUTDIR [EXPORT-OPTIONS...] — exports SCENE with
# `sylva export-pov` (options such as --species NAME pass through) and renders the export with
# POV-Ray at 32 x 24 from its folder: POV-Ray must exit 0 and report no error. The output is
# named "<scene> export.pov", with a space, as users' names have them (POV-Ray takes such a
# name quoted: +I"a b.pov").
set -euo pipefail
sylva=$1 scene=$2 outdir=$3
shift 3
povray=${SYLVA_POVRAY:-povray}
if ! command -v "$povray" >/dev/null; then
  echo "POV-Ray ($povray) is not installed: skipped" >&2
  exit 77
fi
name=$(basename "$scene" .yaml)
dir="$outdir/$name.parse${1:+$(printf '%s' "$*" | tr -c 'A-Za-z0-9' '_')}"
rm -rf "$dir"
mkdir -p "$dir"
main="$name export.pov"
"$sylva" export-pov "$scene" -o "$dir/$main" --quiet "$@" >/dev/null
cd "$dir"
set +e
"$povray" "+I\"$main\"" +Otest.png +W32 +H24 -D -P >povray.log 2>&1
rc=$?
set -e
if [ "$rc" -ne 0 ] || grep -q "Error" povray.log; then
  echo "POV-Ray failed on $dir/$main (exit $rc):" >&2
  grep -n -B2 -A2 "Error" povray.log >&2 || tail -20 povray.log >&2
  exit 1
fi
[ -s test.png ] || { echo "POV-Ray wrote no image" >&2; exit 1; }
