#!/usr/bin/env bash
# planted_links_test.sh SYLVA DIR RENDER_SCENE ECOLOGY_SCENE — symbolic links planted beside an
# output, under every name a temporary of that output could predictably take (the process id
# and a counter), must neither be followed nor block the run: render -o out.png and
# simulate -o plants.csv write their files, and the file the links point to keeps its content.
set -uo pipefail
sylva=$1 dir=$2 render_scene=$3 eco_scene=$4
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
printf 'precious\n' > victim.txt
# after exec the run's process id is this shell's $$
plant='for n in 0 1 2 3 4 5 6 7; do
         ln -s victim.txt ".out.tmp-$$-$n.png"; ln -s victim.txt "plants.csv.tmp-$$-$n"
       done; exec "$@"'
bash -c "$plant" planter "$sylva" render "$render_scene" --size 8x8 --spp 1 -o out.png ||
  { echo "render failed" >&2; exit 1; }
bash -c "$plant" planter "$sylva" simulate "$eco_scene" --years 1 -q -o plants.csv ||
  { echo "simulate failed" >&2; exit 1; }
[ "$(cat victim.txt)" = precious ] || { echo "victim.txt was overwritten through a link" >&2; exit 1; }
for f in out.png out.exr plants.csv; do
  [ -f "$f" ] && [ ! -L "$f" ] || { echo "$f is not a regular file" >&2; exit 1; }
done
left=$(find . -name '*.tmp-*' ! -type l)
[ -z "$left" ] || { echo "temporaries left behind: $left" >&2; exit 1; }
exit 0
