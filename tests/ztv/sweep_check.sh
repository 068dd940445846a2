#!/usr/bin/env bash
# sweep_check.sh SYLVA WORK SCENE... — the bare-earth sweep (src/core/ztv/ztv_sweep.h) against the
# sightlines it spares: each scene's bare-earth ZTV made twice, by default (the sweep settles the
# pairs it is sure of, the sightlines decide the rest) and with --sightlines (every pair by its
# Embree sightline), must be the same bytes. The disagreement allowed is none: the sweep declares a
# pair seen or hidden only with a margin that bounds its difference from the sightline (the ray's
# offset times the ground's steepness, and ZTV_SWEEP_SLACK for the chords and single precision),
# and leaves every other pair to the sightline. Prints the share of pairs the sweep settled; the
# run with --sightlines must say why the sweep did not run, the default one must not.
# Exit 0 when every scene agrees, 1 when one does not, 77 (skipped) without the shared data.
set -uo pipefail
sylva=$1 work=$2
shift 2
rm -rf "$work" && mkdir -p "$work" || exit 1
status=0
for scene in "$@"; do
  name=$(basename "$scene" .yaml)
  dtm=$(sed -n 's/^[[:space:]]*dtm:[[:space:]]*\([^ #]*\).*/\1/p' "$scene" | head -n 1)
  case $dtm in /*) ;; *) dtm=$(dirname "$scene")/$dtm ;; esac
  [ -f "$dtm" ] || { echo "skipped: $dtm is not there (the shared data beside the clone)"; exit 77; }
  for way in sweep sightlines; do
    flag=()
    [ $way = sightlines ] && flag=(--sightlines)
    "$sylva" ztv "$scene" -o "$work/$name.$way" "${flag[@]}" --threads 2 2>"$work/$name.$way.log" >/dev/null ||
      { echo "$name: sylva ztv ($way) failed:"; tail -n 3 "$work/$name.$way.log"; status=1; continue 2; }
  done
  settled=$(sed -n 's/.*, \([0-9.]*\) % of the pairs settled.*/\1/p' "$work/$name.sweep.log")
  # the line says why the sweep did not run, and only then
  if grep -q "settled by the bare-earth sweep (not run" "$work/$name.sweep.log"; then
    echo "$name: the sweep did not run: $(grep -o '(not run.*' "$work/$name.sweep.log")"
    status=1
  fi
  if ! grep -q "settled by the bare-earth sweep (not run: --sightlines asks" "$work/$name.sightlines.log"; then
    echo "$name: with --sightlines the line does not say why the sweep did not run"
    status=1
  fi
  if cmp -s "$work/$name.sweep/ztv_bare.tif" "$work/$name.sightlines/ztv_bare.tif"; then
    echo "$name: the same map (${settled:-?} % of the pairs settled by the sweep)"
  else
    echo "$name: the sweep's bare-earth map differs from the sightlines'"
    status=1
  fi
done
exit $status
