#!/usr/bin/env bash
# cycles_noise.sh — time to a noise level, sylva against Blender Cycles on the same scene
# (docs/rendering.md, "Against Cycles"). Needs `blender` (Debian's, 3.4; scripts/install-deps.sh
# --bench installs it); says "not installed" and exits 0 without it.
#
# For each scene: the built scene is exported for Blender (bench_blender_export), then each
# renderer renders it at a ladder of sample counts and once at REF_SPP samples with another seed,
# its own reference. The noise of a render is the RMS of its per-pixel luminance difference from
# its own renderer's reference, relative to the reference's mean (bench_image_rms; the reference
# has 16 times the top rung's samples, so its own noise adds at most 3 % to the top rung's
# figure, alike for both). The time is the processor time of the pixel phase, both on THREADS
# threads: sylva's render call on a scene built once (bench_time_to_noise); Cycles' render call
# with the scene kept between renders (persistent data, after a first render at 1 sample that
# builds and synchronises it), times Cycles' own render time over the call's wall time, which
# takes out what is left of synchronisation. Both ladders run REPS times, alternating, and
# their times are averaged. sylva's time at each Cycles rung's noise is interpolated (log-log)
# on sylva's ladder; the ratio sylva / Cycles is printed with the goal (at most 0.5).
# The wall-time ratio (sylva's render call, Cycles' own render time) is printed beside it.
#
# usage: [THREADS=2] [REPS=2] [KEEP=DIR] [CURRENT_BUILD=build] bench/cycles_noise.sh
#   KEEP: a folder to keep the exports and renders in (default: a temporary one, removed).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
threads=${THREADS:-2} reps=${REPS:-2} keep=${KEEP:-}
[ $# -eq 0 ] || { echo "usage: [THREADS=N] [REPS=R] [KEEP=DIR] $0" >&2; exit 1; }
if ! command -v blender >/dev/null 2>&1; then
    echo "Cycles: blender not installed; not compared (scripts/install-deps.sh --bench installs it)"
    exit 0
fi
build=${CURRENT_BUILD:-$root/build}
for t in bench_blender_export bench_time_to_noise bench_image_rms; do
    [ -x "$build/bench/$t" ] || { echo "$build/bench/$t: build sylva first (scripts/build.sh)" >&2; exit 1; }
done
export SYLVA_PLUGIN_PATH=$build/plugins
work=${keep:-$(mktemp -d)}
mkdir -p "$work"
[ -n "$keep" ] || trap 'rm -rf "$work"' EXIT
echo "sylva against $(blender --version 2>/dev/null | head -1), $threads threads, $(nproc) cores ($(uptime | sed 's/.*load/load/'))"

# cycles LADDER OUT [--seed S]: Cycles' lines "spp cpu wall render sync file"
cycles() {
    local dir=$1 ladder=$2 out=$3
    shift 3
    blender -b --factory-startup -P "$root/bench/cycles_render.py" -- "$dir/export" "$out" "$ladder" \
        --threads "$threads" "$@" 2>&1 | awk '$1 == "cycles" && $2 == "spp"' || true
}

# SCENE LABEL WxH REF_SPP SPP...
measure() {
    local scene=$1 label=$2 size=$3 ref=$4
    shift 4
    local dir=$work/${label// /_} ladder
    ladder=$(echo "$@" | tr ' ' ',')
    mkdir -p "$dir/sylva_ref" "$dir/sylva"
    "$build/bench/bench_blender_export" "$scene" "$dir/export" "$size" 2>"$dir/export.log" ||
        { cat "$dir/export.log" >&2; return 1; }
    # references: each renderer's own, another seed than its ladder
    "$build/bench/bench_time_to_noise" "$scene" "$size" "$dir/sylva_ref" "$ref" --threads "$threads" \
        --crown-proxy 0 2>"$dir/sylva.log" >/dev/null || { cat "$dir/sylva.log" >&2; return 1; }
    cycles "$dir" "$ref" "$dir/cycles_ref" --seed 9173 >/dev/null
    [ -f "$dir/sylva_ref/sylva_ref.exr" ] && [ -f "$dir/cycles_ref/cycles_$ref.exr" ] ||
        { echo "$label: a reference render failed" >&2; return 1; }
    : >"$dir/sylva.txt"; : >"$dir/cycles.txt"
    for r in $(seq "$reps"); do
        "$build/bench/bench_time_to_noise" "$scene" "$size" "$dir/sylva" 0 "$@" --threads "$threads" \
            --crown-proxy 0 2>>"$dir/sylva.log" | awk '{print $3, $5, $7, $9}' >>"$dir/sylva.txt"
        cycles "$dir" "$ladder" "$dir/cycles" | awk '{print $3, $5 * $9 / $7, $9, $13}' >>"$dir/cycles.txt"
    done
    local s c
    s=$("$build/bench/bench_image_rms" "$dir/sylva_ref/sylva_ref.exr" $(printf "$dir/sylva/sylva_%s.exr " "$@"))
    c=$("$build/bench/bench_image_rms" "$dir/cycles_ref/cycles_$ref.exr" $(printf "$dir/cycles/cycles_%s.exr " "$@"))
    # lines: "S|C spp noise cpu wall mean"
    { echo "$s" | awk '{n = split($1, p, "_"); sub(".exr", "", p[n]); print "S", p[n], $3, $5}'
      echo "$c" | awk '{n = split($1, p, "_"); sub(".exr", "", p[n]); print "C", p[n], $3, $5}'
      awk '{print "TS", $0}' "$dir/sylva.txt"; awk '{print "TC", $0}' "$dir/cycles.txt"; } |
    awk -v label="$label" -v size="$size" -v ref="$ref" -v reps="$reps" '
        $1 == "S" { sn[$2] = $3; smean = $4 }  $1 == "C" { cn[$2] = $3; cmean = $4 }
        $1 == "TS" { st[$2] += $3; sw[$2] += $4; sc[$2]++ }
        $1 == "TC" { ct[$2] += $3; cw[$2] += $4; cc[$2]++ }
        END {
            k = 0
            for (s in sn) sp[k++] = s + 0
            for (i = 0; i < k; i++) for (j = i + 1; j < k; j++) if (sp[j] < sp[i]) { x = sp[i]; sp[i] = sp[j]; sp[j] = x }
            printf "%s (%s, references %d spp, %d reps): mean luminance sylva %.5f, Cycles %.5f (sylva %+.1f %%)\n",
                label, size, ref, reps, smean, cmean, 100 * (smean / cmean - 1)
            for (i = 0; i < k; i++) {
                s = sp[i]
                printf "  %4d spp: sylva noise %.4f in %.3f s CPU (%.3f s wall); Cycles noise %.4f in %.3f s CPU (%.3f s wall)\n",
                    s, sn[s], st[s] / sc[s], sw[s] / sc[s], cn[s], ct[s] / cc[s], cw[s] / cc[s]
            }
            for (c = 0; c < k; c++) {
                target = cn[sp[c]]; tc = ct[sp[c]] / cc[sp[c]]; wc = cw[sp[c]] / cc[sp[c]]
                found = 0
                if (!(tc > 0) || !(wc > 0)) {
                    # Cycles reports its render time in steps of 10 ms
                    printf "  at Cycles %d spp (noise %.4f): Cycles'"'"' time under its 10 ms resolution; not compared\n", sp[c], target
                    continue
                }
                for (i = 0; i + 1 < k && !found; i++) {
                    a = sp[i]; b = sp[i + 1]
                    if (sn[a] >= target && sn[b] <= target) {
                        f = (log(target) - log(sn[a])) / (log(sn[b]) - log(sn[a]))
                        ts = exp(log(st[a] / sc[a]) + f * (log(st[b] / sc[b]) - log(st[a] / sc[a])))
                        ws = exp(log(sw[a] / sc[a]) + f * (log(sw[b] / sc[b]) - log(sw[a] / sc[a])))
                        ss = exp(log(a) + f * (log(b) - log(a)))
                        printf "  at Cycles %d spp (noise %.4f): sylva %.1f spp in %.3f s CPU; sylva / Cycles time %.2f (goal <= 0.5: %s); wall %.2f\n",
                            sp[c], target, ss, ts, ts / tc, ts / tc <= 0.5 ? "met" : "missed", ws / wc
                        found = 1
                    }
                }
                if (!found) printf "  at Cycles %d spp (noise %.4f): outside sylva'"'"'s ladder\n", sp[c], target
            }
        }'
}

measure "$root/bench/sunlit_ground.yaml" "sunlit ground" 64x64 1024 1 2 4 8 16 32 64
measure "$root/tests/scenes/image/sphere_on_plane.yaml" "sphere on plane" 192x128 1024 1 2 4 8 16 32 64
measure "$root/scenes/default.yaml" "default forest" 320x180 256 1 2 4 8 16
