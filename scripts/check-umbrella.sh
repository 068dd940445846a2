#!/usr/bin/env bash
# check-umbrella.sh HEADER — an umbrella header (one that includes the rest of its folder, such as
# src/core/geometry/geometry.h) includes every other header of its folder and names each in its
# comment; lists each one it misses and exits 1, else exits 0.
header=${1:?usage: check-umbrella.sh HEADER}
dir=$(dirname "$header") folder=$(basename "$(dirname "$header")") self=$(basename "$header")
bad=0
for h in "$dir"/*.h; do
  name=$(basename "$h")
  [ "$name" = "$self" ] && continue
  grep -q "^#include \"$folder/$name\"" "$header" || { echo "$header: does not include $folder/$name"; bad=1; }
  grep -qE "^ \*.*\b${name//./\\.}\b" "$header" || { echo "$header: its comment does not name $name"; bad=1; }
done
[ $bad = 0 ] && echo "$header: includes and names every header of $folder/"
exit $bad
