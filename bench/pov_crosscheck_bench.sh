#!/usr/bin/env bash
# pov_crosscheck_bench.sh — the whole POV-Ray cross-check (`sylva crosscheck`: export, POV-Ray,
# sylva's verification render, comparison, report) of the main scene (scenes/default.yaml) and
# the wind farm (scenes/wind_farm.yaml), in one run. For each it prints the export's time and
# size, POV-Ray's parse and trace CPU time for the picture and for the coverage render (the
# second render a scene with air takes for its alpha), sylva's verification render (BVH and
# render), the whole command's wall and CPU time, the load average after it, and the verdict.
# On a machine shared with other work the CPU times are the steadier measure.
#
# usage: [BUILD=dir] [WORKDIR=dir] [SIZE=WxH] [SPP=n] [THREADS=n] [LEAVES=auto|mask|outline]
#        bench/pov_crosscheck_bench.sh [SCENE...]
#   BUILD: the build folder (default build/); WORKDIR: the outputs (default
#   $TMPDIR/sylva_pov_crosscheck_bench); SIZE (default 320x180) and SPP (default 9): the
#   documented cross-check of the main scene; THREADS (default 2); LEAVES: crosscheck's
#   --leaves (default auto). SCENE: the scenes (default the two above; the wind farm needs
#   ../shared/data beside the clone and is left out without it).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build} workdir=${WORKDIR:-${TMPDIR:-/tmp}/sylva_pov_crosscheck_bench}
size=${SIZE:-320x180} spp=${SPP:-9} threads=${THREADS:-2} leaves=${LEAVES:-auto}
sylva=$build/sylva
export SYLVA_PLUGIN_PATH=${SYLVA_PLUGIN_PATH:-$build/plugins}
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
  scenes=("$root/scenes/default.yaml")
  if [ -d "$root/../shared/data" ]; then
    scenes+=("$root/scenes/wind_farm.yaml")
  else
    echo "../shared/data is missing: the wind farm is left out" >&2
  fi
fi
mkdir -p "$workdir"

# field JSON NAME: the number after "NAME": in metrics.json (null when POV-Ray gave none).
field() { grep -o "\"$2\": [-0-9.e+a-z]*" "$1" | head -1 | awk '{print $2}'; }

printf '%-16s %9s %9s %9s %9s %9s %9s %9s %9s %9s  %s\n' scene "export s" "export MB" "pov parse" \
  "pov trace" "pov cover" "sylva bvh" "sylva rnd" "wall s" "cpu s" "load, verdict"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .yaml)
  out="$workdir/$name"
  rm -rf "$out"
  set +e
  /usr/bin/time -f "%e %U %S" -o "$workdir/$name.time" "$sylva" crosscheck "$scene" -o "$out" --size "$size" \
    --spp "$spp" --threads "$threads" --leaves "$leaves" >"$workdir/$name.out" 2>"$workdir/$name.log"
  status=$?
  set -e
  load=$(awk '{print $1}' /proc/loadavg)
  # the last line: /usr/bin/time puts "Command exited with non-zero status N" before it
  read -r wall user sys < <(tail -1 "$workdir/$name.time") || true
  m="$out/metrics.json"
  if [ ! -s "$m" ]; then
    echo "$name: crosscheck failed (exit $status); see $workdir/$name.log" >&2
    continue
  fi
  bytes=$(find "$out" -maxdepth 1 -name "$name*" ! -name "*-povray*" ! -name "*-noair*" -printf '%s\n' |
          awk '{s += $1} END {print s}')
  cover=$(field "$m" povray_coverage_cpu_seconds)
  printf '%-16s %9.1f %9.1f %9.1f %9.1f %9.1f %9.1f %9.1f %9.1f %9.1f  %s, %s\n' "$name" "$(field "$m" export_seconds)" \
    "$(awk -v b="$bytes" 'BEGIN {print b / 1e6}')" "$(field "$m" povray_parse_cpu_seconds)" \
    "$(field "$m" povray_trace_cpu_seconds)" "$cover" "$(field "$m" sylva_bvh_seconds)" \
    "$(field "$m" sylva_render_seconds)" "$wall" "$(awk -v u="$user" -v s="$sys" 'BEGIN {print u + s}')" \
    "$load" "$(head -1 "$workdir/$name.out" | cut -d: -f1)"
done
echo "pov parse and trace: POV-Ray's CPU seconds for the picture (its log); pov cover: the whole" \
     "coverage render's CPU seconds; export, sylva bvh and render: wall seconds; cpu: the command's" \
     "user + system time, POV-Ray's included; load: the 1-minute load average after each."
