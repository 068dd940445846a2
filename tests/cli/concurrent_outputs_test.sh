#!/usr/bin/env bash
# concurrent_outputs_test.sh SYLVA DIR SCENE — two renders to the same -o at once leave the PNG
# and the EXR of one of them: a render renames its pair into place only while it holds the lock
# file beside them (.out.lock), waiting while another holds it; five pairs of renders of two
# sizes into one name always leave a PNG and an EXR of the same size; no lock file or temporary
# is left behind.
set -uo pipefail
sylva=$1 dir=$2 scene=$3
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
fail() { echo "$*" >&2; exit 1; }

# while the lock is held elsewhere, the outputs wait for it
flock .out.lock -c "sleep 2" &
holder=$!
sleep 0.3
"$sylva" render "$scene" --size 8x6 --spp 1 -q -o out.png >/dev/null &
render=$!
sleep 1.2
[ ! -e out.png ] && [ ! -e out.exr ] || fail "the render wrote out.png or out.exr while another run held .out.lock"
wait "$holder"
wait "$render" || fail "the render failed after the lock was let go"
[ -f out.png ] && [ -f out.exr ] || fail "out.png and out.exr were not written once the lock was let go"

# a pair of renders of two sizes into one name: the PNG and the EXR come from the same run
if command -v iinfo >/dev/null; then
  for i in $(seq 5); do
    "$sylva" render "$scene" --size 24x18 --spp 1 -q -o same.png >/dev/null &
    a=$!
    "$sylva" render "$scene" --size 16x12 --spp 1 -q -o same.png >/dev/null &
    b=$!
    wait "$a" || fail "render a failed"
    wait "$b" || fail "render b failed"
    png=$(iinfo same.png | grep -o '[0-9]* x *[0-9]*' | head -1)
    exr=$(iinfo same.exr | grep -o '[0-9]* x *[0-9]*' | head -1)
    [ "$png" = "$exr" ] || fail "round $i: same.png is $png, same.exr is $exr: they come from different runs"
  done
  echo "5 pairs of concurrent renders: PNG and EXR of one run each time"
else
  echo "iinfo is not installed: the concurrent pairs are not compared"
fi
left=$(find . -name '*.tmp-*' -o -name '*.lock')
[ -z "$left" ] || fail "left behind: $left"
exit 0
