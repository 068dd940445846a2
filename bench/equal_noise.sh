#!/usr/bin/env bash
# equal_noise.sh — the path tracer's time to reach a given noise, against a baseline build of
# sylva: for each scene the baseline renders at BASE_SPP and the current build at a ladder of
# sample counts around it; the current build's time at the baseline's noise (log-log
# interpolation between the two rungs that bracket it) over the baseline's time is the
# equal-noise time ratio (below 1: the current build is faster to the same picture).
#
# Noise and time come from bench_distance_noise (tests/image/patch_noise.h), the current one in
# both builds (the baseline is built with the current measuring code over its renderer): the
# per-pixel standard deviation of the luminance over SEEDS renders, relative to the image's mean
# luminance, over the whole image, at the scene's max_depth; the time is the processor time of
# the render phase alone (all threads; the scene is built once per run), which a machine shared
# with other work disturbs less than the wall clock. Same sizes, depths and threads (all cores)
# for both; the two builds' runs alternate, REPS times, and times and noises are averaged over
# the repetitions.
#
# usage: bench/equal_noise.sh [--baseline BUILD_DIR] [--seeds K] [--reps R]
#   BUILD_DIR: a build folder of the baseline (holding bench/bench_distance_noise, printing
#   processor time, and plugins/); default: revision BASE_REV (the renderer with independent
#   random numbers past the first vertex and multi-jittered pixel positions) exported with git
#   archive, given the current measuring code, and built (core and plugins) under $TMPDIR.
# Cycles: then bench/cycles_noise.sh compares sylva with Blender Cycles on the same scenes, or
# says that blender is not installed (scripts/install-deps.sh --bench installs it).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
BASE_REV=${BASE_REV:-826c449}
baseline="" seeds=4 reps=2
while [ $# -gt 0 ]; do
    case $1 in
    --baseline) baseline=$2; shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    *) echo "usage: $0 [--baseline BUILD_DIR] [--seeds K] [--reps R]" >&2; exit 1 ;;
    esac
done
current=${CURRENT_BUILD:-$root/build}
[ -x "$current/bench/bench_distance_noise" ] || { echo "$current/bench/bench_distance_noise: build sylva first (scripts/build.sh)" >&2; exit 1; }
if [ -z "$baseline" ]; then
    src=${TMPDIR:-/tmp}/sylva-baseline-$BASE_REV
    baseline=$src/build
    if [ ! -x "$baseline/bench/bench_distance_noise" ]; then
        echo "building the baseline $BASE_REV in $src ..." >&2
        mkdir -p "$src"
        git -C "$root" archive "$BASE_REV" | tar -x -C "$src"
        cp "$root/tests/image/patch_noise.h" "$src/tests/image/"
        cp "$root/bench/bench_distance_noise.c" "$src/bench/"
        cmake -S "$src" -B "$baseline" -DCMAKE_BUILD_TYPE=Release >/dev/null
        cmake --build "$baseline" -j"$(nproc)" --target bench_distance_noise ecology terrain_ifs tree_aono_kunii \
            tree_lsystem tree_vessel >/dev/null
    fi
fi

# one run: BUILD SCENE WxH SPP... -> lines "spp noise seconds" at the scene's max_depth
run() {
    local build=$1 scene=$2 size=$3
    shift 3
    local w=${size%x*} h=${size#*x}
    SYLVA_PLUGIN_PATH=$build/plugins "$build/bench/bench_distance_noise" --patch 0,0,$w,$h "$scene" "$size" "$seeds" "$@" |
        awk '{spp = $2; d = $4 + 0; t = $(NF - 2)
              for (i = 1; i <= NF; i++) if ($i == "noise") n = $(i + 1)
              if (d >= best[spp]) { best[spp] = d; line[spp] = spp " " n " " t } }
             END { for (s in line) print line[s] }' | sort -n
}

# SCENE LABEL WxH BASE_SPP SPP...
measure() {
    local scene=$1 label=$2 size=$3 base_spp=$4
    shift 4
    local tmp
    tmp=$(mktemp -d)
    for r in $(seq "$reps"); do
        run "$baseline" "$scene" "$size" "$base_spp" >>"$tmp/base"
        run "$current" "$scene" "$size" "$@" >>"$tmp/cur"
    done
    awk -v label="$label" -v size="$size" -v reps="$reps" -v seeds="$seeds" '
        FNR == 1 { file++ }
        file == 1 { bn += $2; bt += $3; bs = $1; nb++ }
        file == 2 { n[$1] += $2; t[$1] += $3; c[$1]++ }
        END {
            bn /= nb; bt /= nb
            k = 0
            for (s in n) { sp[k++] = s + 0 }
            for (i = 0; i < k; i++) for (j = i + 1; j < k; j++) if (sp[j] < sp[i]) { x = sp[i]; sp[i] = sp[j]; sp[j] = x }
            printf "%s (%s, %d seeds, %d reps): baseline %d spp noise %.4f in %.2f s CPU\n", label, size, seeds, reps, bs, bn, bt
            for (i = 0; i < k; i++) {
                s = sp[i]; nn[i] = n[s] / c[s]; tt[i] = t[s] / c[s]
                printf "  current %4d spp: noise %.4f in %.2f s CPU\n", s, nn[i], tt[i]
            }
            for (i = 0; i + 1 < k; i++)
                if (nn[i] >= bn && nn[i + 1] <= bn) {
                    f = (log(bn) - log(nn[i])) / (log(nn[i + 1]) - log(nn[i]))
                    te = exp(log(tt[i]) + f * (log(tt[i + 1]) - log(tt[i])))
                    se = exp(log(sp[i]) + f * (log(sp[i + 1]) - log(sp[i])))
                    printf "  equal noise: current %.1f spp in %.2f s CPU; time ratio current/baseline %.2f\n", se, te, te / bt
                    found = 1
                }
            if (!found) printf "  equal noise: outside the ladder of sample counts (widen it)\n"
        }' "$tmp/base" "$tmp/cur"
    rm -rf "$tmp"
}

measure "$root/bench/sunlit_ground.yaml" "sunlit ground" 64x64 16 4 8 16 32
measure "$root/tests/scenes/image/sphere_on_plane.yaml" "sphere on plane" 96x64 16 4 8 16 32
measure "$root/scenes/default.yaml" "default forest" 160x90 8 2 4 8 16

CURRENT_BUILD=$current "$root/bench/cycles_noise.sh"
