#!/usr/bin/env bash
# describe_presets.sh SYLVA — `sylva plugins --describe tree_vessel` prints every preset with
# the values the plugin starts from (vessel_presets.c), each under its own preset.
set -uo pipefail
sylva=$1
out=$("$sylva" plugins --describe tree_vessel) || { echo "FAIL: --describe tree_vessel failed" >&2; exit 1; }
# The lines of one preset: from "  NAME:" to the next preset or the end of the section.
preset() { awk -v p="  $1:" 'index($0, p) == 1 {on = 1; next} /^  [a-z_]+:/ {on = 0} /^$/ {on = 0} on' <<<"$out"; }
want() { # PRESET KEY VALUE
    preset "$1" | awk -v k="$2" -v v="$3" '{ sub(/^ +/, ""); if (index($0, k " ") == 1) {
        rest = substr($0, length(k) + 1); sub(/^ +/, "", rest); if (rest == v) found = 1 } }
        END { exit !found }' ||
        { echo "FAIL: preset $1 does not show $2 $3" >&2; preset "$1" >&2; exit 1; }
}
grep -q "^presets (chosen with \`preset\`" <<<"$out" || { echo "FAIL: no presets section" >&2; exit 1; }
want beech vessels 4000
want beech trunk_length "5 m"
want beech length_min_g "[[0, 1], [7.5, 0.45], [15, 1]]"
want spruce vessels 6000
want spruce sides 6
want spruce split_w "[[0, 1], [42.89, 1.005], [42.89, 0.654], [50, 0.6256]]"
want spruce leaf "\"spruce\""
want weeping_willow leaf_size "0.3452 m"
want weeping_willow gravimorphism_g "[[0, 84.45], [1.746, 94.69], [15, 110]] deg"
want maple leaf_type stacked
want maple bark_color "[0.2, 0.18, 0.15]"
for p in beech spruce weeping_willow maple; do
    [ "$(preset $p | wc -l)" -ge 15 ] || { echo "FAIL: preset $p shows fewer than 15 values" >&2; exit 1; }
done
echo "presets: described with their values"
