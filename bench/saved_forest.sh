#!/usr/bin/env bash
# saved_forest.sh — re-rendering a saved forest of about a million plants: the scene build of
# `sylva render` when the plants come from `plants: {file: STATE}` (docs/scene-file.md, "A forest
# kept between renders"), against the goal of no simulation and a build of at most 3 s.
#
# The first run grows bench/forest_1m.yaml's forest with `sylva simulate --save` into WORKDIR
# (minutes; kept for later runs); every run then renders WORKDIR/forest_1m_saved.yaml, the same
# scene with the saved run as its plants, at a small size, and prints the phases of `sylva
# render`: ecology (here loading and placing the saved run: no year is simulated) and the
# scene build (terrain, tree variants, plants, BVH; then lights and crown proxies), everything
# before the pixels.
#
# usage: [BUILD=dir] [WORKDIR=dir] [THREADS=n] bench/saved_forest.sh
#   BUILD: the build folder (default build/), WORKDIR: where the saved run and the render go
#   (default $TMPDIR/sylva_saved_forest), THREADS: for every phase (default: one per processor)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build} workdir=${WORKDIR:-${TMPDIR:-/tmp}/sylva_saved_forest} threads=${THREADS:-$(nproc)}
sylva=$build/sylva
mkdir -p "$workdir"
state=$workdir/forest_1m.state
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $(nproc) processors, $threads threads"
if [ ! -s "$state" ]; then
    echo "simulating bench/forest_1m.yaml once (sylva simulate --save $state) ..."
    t0=$(date +%s.%N)
    "$sylva" simulate "$root/bench/forest_1m.yaml" --threads "$threads" --save "$state" -q
    echo "  simulated in $(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }') s"
fi
# The same scene with the saved run as its plants; the species file by its absolute path.
sed "s|\.\./scenes/species/forest.yaml|$root/scenes/species/forest.yaml|" "$root/bench/forest_1m.yaml" \
    > "$workdir/forest_1m_saved.yaml"
echo "plants: {file: forest_1m.state}" >> "$workdir/forest_1m_saved.yaml"
log=$workdir/render.log
"$sylva" render "$workdir/forest_1m_saved.yaml" -o "$workdir/forest_1m_saved.png" --size 160x90 --spp 1 \
    --threads "$threads" > /dev/null 2> "$log"
grep -E '^plants: ' "$log" || { echo "sylva render did not reuse the saved run" >&2; exit 2; }
grep -E '^scene: ' "$log"
phases=$(grep -E '^phases:' "$log")
echo "$phases"
# Seconds of one phase from the phases line (phases under 5 ms are not printed: 0).
phase() { echo "$phases" | grep -oE "$1 [0-9.]+s" | grep -oE '[0-9.]+' || echo 0; }
sim=$(phase ecology) # loading and placing the saved run: no year is simulated
scene_s=$(awk -v a="$(phase terrain)" -v b="$(phase 'tree variants')" -v c="$sim" -v d="$(phase 'rest of the scene')" \
    -v e="$(phase 'ground cover')" -v f="$(phase BVH)" 'BEGIN { printf "%.2f", a + b + c + d + e + f }')
setup_s=$(awk -v a="$scene_s" -v b="$(phase 'lights and proxies')" 'BEGIN { printf "%.2f", a + b }')
echo "saved forest re-render: no year simulated (loading and placing the saved run ${sim} s); scene build" \
    "(terrain, variants, plants, BVH) ${scene_s} s (goal <= 3 s); with lights and crown proxies ${setup_s} s"
