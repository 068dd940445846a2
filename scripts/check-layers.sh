#!/usr/bin/env bash
# check-layers.sh [ROOT] — lists every #include in src/core that reaches a folder above the
# including file's own layer (or a sibling in the same layer); exit 0 when there is none.
# The layers, lowest first: util, io, params, plugin, scene, geometry, render and pov (side by
# side), crosscheck, ztv and montage (side by side), cli.
cd "${1:-$(dirname "$0")/..}/src/core" || exit 2
# folders in layers, lowest first; render and pov share a layer: neither includes the other
rank() { case $1 in util) echo 0;; io) echo 1;; params) echo 2;; plugin) echo 3;; scene) echo 4;;
  geometry) echo 5;; render|pov) echo 6;; crosscheck|ztv|montage) echo 7;; cli) echo 8;; *) echo -1;; esac; }
bad=0
for f in $(find . -name '*.[ch]' -o -name '*.cpp' | sed 's|^\./||'); do
  d=${f%%/*}; rd=$(rank $d)
  while IFS= read -r inc; do
    t=${inc%%/*}; [ "$t" = "$inc" ] && continue
    rt=$(rank $t); [ $rt -lt 0 ] && continue
    if [ $rt -gt $rd ] || { [ $rt -eq $rd ] && [ "$t" != "$d" ]; }; then echo "UP: $f includes $inc"; bad=1; fi
  done < <(grep -oE '^#include "[^"]+"' "$f" | sed 's/#include "//;s/"$//')
done
[ $bad = 0 ] && echo "layering: no include reaches a folder above its own"
exit $bad
