#!/usr/bin/env bash
# check-layers.sh [ROOT] — lists every #include in src/core that reaches a folder above the
# including file's own layer (or a sibling in the same layer), and every back end's include of
# the scene file's reader; exit 0 when there is none.
# The layers, lowest first: util, io, params and page (side by side: the printed page's drawing),
# plugin, scene (the graph and its settings), then site, season and model (side by side),
# scene_file (the reader), scene_build, geometry, render and pov (side by side), sheet (a study's
# printed sheet), crosscheck, ztv, montage and study (side by side), cli.
cd "${1:-$(dirname "$0")/..}/src/core" || exit 2
# folders in layers, lowest first; folders that share a layer include none of each other
rank() { case $1 in util) echo 0;; io) echo 1;; params|page) echo 2;; plugin) echo 3;; scene) echo 4;;
  site|season|model) echo 5;; scene_file) echo 6;; scene_build) echo 7;; geometry) echo 8;;
  render|pov) echo 9;; sheet) echo 10;; crosscheck|ztv|montage|study) echo 11;; cli) echo 12;; *) echo -1;; esac; }
# The back ends read the scene and its settings (scene/scene_settings.h), never the file format
# (scene_file/, nor scene_build/, whose headers bring it). The files that read their product's
# own sections of the file (ztv: its settings, targets and developments, and the names its maps
# print; photo:, read by the montage and its sheet) are the exceptions, named here. study/ is no back end: like the command line it
# drives the build (scene_build) and reads its own study: section, then hands the built scene to
# the renderer; sheet/ sets out what the study made with the scene file's viewpoints and objects.
backend() { case $1 in geometry|render|pov|ztv|montage) return 0;; *) return 1;; esac; }
reads_file() { case $1 in ztv/ztv_study.c|ztv/ztv_targets.c|ztv/ztv_features.c|ztv/ztv_labels.[ch]|montage/montage_run.c|montage/verification_sheet.[ch]) return 0;; *) return 1;; esac; }
bad=0
for f in $(find . -name '*.[ch]' -o -name '*.cpp' | sed 's|^\./||'); do
  d=${f%%/*}; rd=$(rank $d)
  while IFS= read -r inc; do
    t=${inc%%/*}; [ "$t" = "$inc" ] && continue
    rt=$(rank $t); [ $rt -lt 0 ] && continue
    if [ $rt -gt $rd ] || { [ $rt -eq $rd ] && [ "$t" != "$d" ]; }; then echo "UP: $f includes $inc"; bad=1; fi
    if backend $d && { [ $t = scene_file ] || [ $t = scene_build ]; } && ! { [ "$inc" = scene_file/scene_file.h ] && reads_file $f; }; then
      echo "FORMAT: $f includes $inc (a back end reads scene/scene_settings.h, not the scene file)"; bad=1
    fi
  done < <(grep -oE '^#include "[^"]+"' "$f" | sed 's/#include "//;s/"$//')
done
[ $bad = 0 ] && echo "layering: no include reaches a folder above its own, and no back end the scene file"
exit $bad
