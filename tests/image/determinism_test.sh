#!/usr/bin/env bash
# determinism_test.sh SYLVA SCENE OUTDIR — renders SCENE with 1 and with 2 threads and checks
# that the EXR files are identical byte for byte.
set -euo pipefail
sylva=$1 scene=$2 outdir=$3
mkdir -p "$outdir"
"$sylva" render "$scene" -o "$outdir/t1.exr" --threads 1 --quiet >/dev/null
"$sylva" render "$scene" -o "$outdir/t2.exr" --threads 2 --quiet >/dev/null
if cmp "$outdir/t1.exr" "$outdir/t2.exr"; then
  echo "1 and 2 threads: identical ($(stat -c %s "$outdir/t1.exr") bytes)"
else
  echo "1 and 2 threads gave different EXR bytes" >&2
  exit 1
fi
