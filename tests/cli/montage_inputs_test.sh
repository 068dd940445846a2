#!/usr/bin/env bash
# montage_inputs_test.sh SYLVA DIR SCENE — montage refuses a photograph it cannot trust before
# anything is rendered: a JPEG cut short (libjpeg would fill the rest in grey), and control points
# whose pixels lie outside the photograph (picked on another image). Each ends with exit status 2,
# a sentence naming the file and what is wrong, and no montage written.
set -uo pipefail
sylva=$1 dir=$2 scene=$3
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
fail() { echo "$*" >&2; exit 1; }
refused() { # CASE FRAGMENT SCENE
  local err status
  err=$("$sylva" montage "$3" -q -o "out_$1" 2>&1 >/dev/null)
  status=$?
  echo "$1: $err"
  [ "$status" -eq 2 ] || fail "$1: exit status $status, expected 2"
  grep -qF -- "$2" <<<"$err" || fail "$1: the message lacks: $2"
  [ ! -e "out_$1/montage.png" ] || fail "$1: a montage was written"
}

# a photograph cut short: the scene rendered, as JPEG, cut to 60 % of its bytes
"$sylva" render "$scene" --size 64x48 -q -o plate.png >/dev/null || fail "the plate could not be rendered"
if command -v oiiotool >/dev/null; then
  oiiotool plate.png -o plate.jpg || fail "oiiotool cannot write plate.jpg"
  head -c $(( $(stat -c %s plate.jpg) * 6 / 10 )) plate.jpg > cut.jpg
  cp "$scene" cut.yaml && echo "photo: {file: cut.jpg}" >> cut.yaml
  refused cut_photograph "cut.jpg: cannot read the photograph: it is damaged or cut short" cut.yaml
else
  echo "oiiotool is not installed: the cut JPEG is not tried"
fi

# a 1 x 1 photograph with control points at pixel (429, 286) and beyond
"$sylva" render "$scene" --size 1x1 -q -o tiny.png >/dev/null || fail "the 1 x 1 photograph could not be rendered"
printf 'id,u,v,x,y,z\nmast foot,0.5,0.5,20,20,0\nmast top,429,286,20,20,60\nhill,300,400,0,0,30\n' > points.csv
cp "$scene" tiny.yaml && echo "photo: {file: tiny.png, control_points: points.csv}" >> tiny.yaml
refused points_off_the_photograph \
  "points.csv:3:10: control point 'mast top' is at pixel (429, 286), outside the photograph" tiny.yaml
refused points_off_the_photograph "of 1 x 1 pixels" tiny.yaml
exit 0
