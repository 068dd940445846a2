#!/usr/bin/env bash
# image_test.sh SYLVA IMGDIFF SCENE REF OUTDIR [imgdiff bounds...] — renders SCENE with sylva
# and compares its linear EXR with the reference REF (refimages/) within the stated bounds.
set -euo pipefail
sylva=$1 imgdiff=$2 scene=$3 ref=$4 outdir=$5
shift 5
name=$(basename "$scene" .yaml)
mkdir -p "$outdir"
if [ ! -f "$ref" ]; then
  echo "missing reference $ref; regenerate with scripts/update-refimages.sh" >&2
  exit 1
fi
"$sylva" render "$scene" -o "$outdir/$name.exr" --quiet >/dev/null
"$imgdiff" "$ref" "$outdir/$name.exr" --diff "$outdir/$name.diff.png" "$@"
