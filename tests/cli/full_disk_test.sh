#!/usr/bin/env bash
# full_disk_test.sh SYLVA DIR SITE_SCENE MONTAGE_SCENE — outputs that cannot be written, as on a
# full disk: every file is limited to 1 KiB (ulimit -f, with SIGXFSZ ignored so that a write past
# it fails with an error instead of ending the process). render of a scene with a site (its
# EXR header, with the CRS, is larger than 1 KiB) and montage must end within seconds with exit
# status 3, naming the file that could not be written, and leave no temporary behind.
set -uo pipefail
sylva=$1 dir=$2 site=$3 scene=$4
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
fail() { echo "$*" >&2; exit 1; }

# limited CMD...: runs CMD with files limited to 1 KiB and a 20 s bound; sets status, err, ms
limited() {
  local t0
  t0=$(date +%s%N)
  err=$( (trap '' XFSZ; ulimit -f 1; exec timeout 20 "$@") 2>&1 >/dev/null)
  status=$?
  ms=$(( ($(date +%s%N) - t0) / 1000000 ))
  echo "$err"
  echo "exit status $status after $ms ms"
}
expect_written_nothing() { # CASE FOLDER
  local left
  left=$(find "$2" -name '*.tmp-*')
  [ -z "$left" ] || fail "$1: temporaries left behind: $left"
}

limited "$sylva" render "$site" --size 16x12 --spp 1 -q -o "$dir/out.png"
[ "$status" -ne 124 ] || fail "render: still writing after 20 s (it hangs)"
[ "$status" -eq 3 ] || fail "render: exit status $status, expected 3"
grep -qF "out.exr" <<<"$err" || fail "render: the message does not name out.exr"
[ "$ms" -lt 5000 ] || fail "render: took $ms ms to give up"
[ ! -e out.exr ] && [ ! -e out.png ] || fail "render: an output was written"
expect_written_nothing render .

# montage: its photograph is the scene rendered without the limit
mkdir -p m && cp "$scene" m/scene.yaml && echo "photo: {file: plate.png}" >> m/scene.yaml || exit 1
"$sylva" render m/scene.yaml -q -o m/plate.png >/dev/null || fail "montage: the plate could not be rendered"
limited "$sylva" montage m/scene.yaml -q -o m/out
[ "$status" -ne 124 ] || fail "montage: still writing after 20 s (it hangs)"
[ "$status" -eq 3 ] || fail "montage: exit status $status, expected 3"
grep -qE "m/out/[a-z]+\.(png|exr)" <<<"$err" || fail "montage: the message does not name the file"
expect_written_nothing montage m/out
exit 0
