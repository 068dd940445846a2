#!/usr/bin/env bash
# study_bench.sh — `sylva study` against separate `sylva render` runs on a real site: the wind
# farm of scenes/wind_farm.yaml (five 15 MW turbines, the development, on the DTM of the
# Dallas-Fort Worth area, its prairie trees grown by the ecology over 120 years) seen from 20
# viewpoints: the scene's three and 17 more the bench adds to a copy of the scene, on rings
# 2.5, 4 and 6 km round the turbines, each eye 1.5 m above the ground looking at the turbines'
# middle at hub height with a 50 mm lens.
#
# The study renders every viewpoint's existing view, proposed view and wireline in the single
# frame and the 90 degree panorama (120 products, 80 frames traced; not the scene's sheets and
# ZTV) from one build; the
# separate runs are what a practitioner runs today, one `sylva render --viewpoint NAME` per
# viewpoint (20 proposed single frames, each building the scene anew). The frames are WIDTH
# pixels wide, each as high as its page (480: the single frame 480 x 320, the panorama
# 480 x 152), the separate renders the single frame's size; all at SPP samples per pixel.
# Prints each side's wall and CPU time, the time per product and per render, and the ratio of
# the 20 separate renders' wall time to the whole study's (the goal: at least 3). On a machine
# shared with other work the CPU times are the steadier measure; the load is printed after each side.
#
# The separate renders refine the ground around each camera, the study around the development
# (docs/study.md), so their images are not compared here; tests/cli/study_test.sh checks the
# study's proposed view against render byte for byte on a scene whose ground follows no camera.
#
# usage: [BUILD=dir] [WORKDIR=dir] [WIDTH=n] [SPP=n] [THREADS=n] [RENDERS=n] bench/study_bench.sh
#   BUILD: the build folder (default build/); WORKDIR: the scene's copy and the outputs (default
#   $TMPDIR/sylva_study_bench); WIDTH (default 480), SPP (default 2); THREADS (default one
#   per processor); RENDERS: how many of the 20 separate renders to run (default 20; the rest
#   are counted at the mean of those run). Needs ../shared/data beside the clone.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build} workdir=${WORKDIR:-${TMPDIR:-/tmp}/sylva_study_bench}
width=${WIDTH:-480} spp=${SPP:-2} threads=${THREADS:-$(nproc)} renders=${RENDERS:-20}
sylva=$build/sylva
[ -f "$root/../shared/data/dem/pysheds/dem.tif" ] || { echo "no ../shared/data beside the clone" >&2; exit 77; }
rm -rf "$workdir"
mkdir -p "$workdir/renders"
scene=$workdir/wind_farm_study.yaml
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $(nproc) processors," \
     "$threads threads; load $(cut -d' ' -f1-3 /proc/loadavg)"

# The scene's copy: its files by absolute paths, 17 viewpoints more after its first.
centre_e=648970 centre_n=3606580 # the turbines' mean position (scenes/wind_farm_layout.csv)
awk -v ce=$centre_e -v cn=$centre_n 'BEGIN {
  for (k = 0; k < 17; k++) {
    d = k % 3 == 0 ? 2500 : k % 3 == 1 ? 4000 : 6000; a = (k * 360 / 17 + 10) * atan2(0, -1) / 180
    printf "  v%02d: {position: {easting: %.0f, northing: %.0f}, height_above_ground: 1.5, focal_length: 50,\n", \
           k + 1, ce + d * sin(a), cn + d * cos(a)
    printf "        look_at: {easting: %d, northing: %d, height_above_ground: 150}}\n", ce, cn
  } }' > "$workdir/viewpoints.yaml"
sed -e "s|\.\./\.\./shared/data|$root/scenes/../../shared/data|g" -e "s|species/prairie.yaml|$root/scenes/species/prairie.yaml|" \
    -e "s|wind_farm_layout.csv|$root/scenes/wind_farm_layout.csv|" "$root/scenes/wind_farm.yaml" |
  awk -v extra="$workdir/viewpoints.yaml" '{ print } /^              pitch: 2, focal_length: 50}/ && !done {
    while ((getline line < extra) > 0) print line; done = 1 }' > "$scene"
names=$(sed -n '/^viewpoints:/,/^[a-z]/p' "$scene" | grep -oE '^  [a-z0-9_]+:' | tr -d ' :')
[ "$(echo $names | wc -w)" = 20 ] || { echo "the scene's copy has $(echo $names | wc -w) viewpoints, not 20" >&2; exit 2; }

# timed LOG COMMAND...: runs it, stderr into LOG, and prints "wall user sys" seconds.
timed() { local log=$1; shift; /usr/bin/time -f "%e %U %S" -o "$log.time" "$@" >/dev/null 2>"$log"; cat "$log.time"; }
sum() { awk '{w += $1; c += $2 + $3} END {printf "%.1f %.1f", w, c}'; }

size=${width}x$(awk -v w="$width" 'BEGIN {printf "%d", w * 24 / 36 + 0.5}') # the single frame's
echo "study: 20 viewpoints x (existing, proposed, wireline) x (single, cylindrical_90), $width wide, spp $spp ..."
read -r s_wall s_user s_sys <<<"$(timed "$workdir/study.log" "$sylva" study "$scene" -o "$workdir/study" \
    --products existing,proposed,wireline --frames single,cylindrical_90 --width "$width" --spp "$spp" --threads "$threads")"
grep -E '^study: the scene built|products written|^phases:' "$workdir/study.log" | sed 's/^/  /'
echo "  load after the study: $(cut -d' ' -f1-3 /proc/loadavg)"
s_cpu=$(awk -v u="$s_user" -v s="$s_sys" 'BEGIN {printf "%.1f", u + s}')
s_products=$(grep -oE '[0-9]+ products written' "$workdir/study.log" | grep -oE '^[0-9]+')
s_frames=$(grep -oE '[0-9]+ frames rendered' "$workdir/study.log" | grep -oE '^[0-9]+')

echo "separate: sylva render --viewpoint NAME --size $size --spp $spp, $renders of 20 ..."
: > "$workdir/renders.times"
k=0
for v in $names; do
  [ "$k" -lt "$renders" ] || break
  timed "$workdir/renders/$v.log" "$sylva" render "$scene" --viewpoint "$v" --size "$size" --spp "$spp" \
      --threads "$threads" -o "$workdir/renders/$v.png" >> "$workdir/renders.times"
  k=$((k + 1))
done
read -r r_wall r_cpu <<<"$(sum < "$workdir/renders.times")"
r_wall20=$(awk -v w="$r_wall" -v k="$k" 'BEGIN {printf "%.1f", w / k * 20}')
r_cpu20=$(awk -v c="$r_cpu" -v k="$k" 'BEGIN {printf "%.1f", c / k * 20}')
grep -h '^phases:' "$workdir/renders/"*.log | head -1 | sed 's/^/  one render: /'
echo "  load after the renders: $(cut -d' ' -f1-3 /proc/loadavg)"

awk -v sw="$s_wall" -v sc="$s_cpu" -v sp="$s_products" -v sf="$s_frames" -v rw="$r_wall20" -v rc="$r_cpu20" -v k="$k" \
    -v mw="$r_wall" 'BEGIN {
  printf "study:    %6.1f s wall, %6.1f s CPU for %d products (%d frames traced): %.2f s wall a product, %.2f s a frame\n", sw, sc, sp, sf, sw / sp, sw / sf
  printf "separate: %6.1f s wall, %6.1f s CPU for 20 renders%s: %.2f s wall a render\n", rw, rc, k < 20 ? sprintf(" (%d run, %.1f s)", k, mw) : "", rw / 20
  printf "20 separate renders / the whole study, wall: %.2fx (goal >= 3x); CPU: %.2fx\n", rw / sw, rc / sc
  printf "the %d frames of the study as separate renders (at the same pace): %.0f s wall, %.1fx the study\n", sf, rw / 20 * sf, rw / 20 * sf / sw
}'
