#!/usr/bin/env bash
# montage_sheet_test.sh SYLVA SCENE — the photomontage's verification sheet (docs/photomontage.md,
# Verification sheet) on tests/scenes/study/sheet_study.yaml's mast: the scene rendered at
# 240 x 160 stands in for the photograph, its camera set at a surveyed height (653 m, E 440060,
# N 3760040, heading 45, 39.60 degrees across); eight control points in map coordinates are
# projected through that camera here (each pixel nudged by up to 0.1 px) and the montage matches
# the camera to them from a 35 mm lens on a 24 mm sensor. Read back with poppler's tools:
#   matched    sheet.pdf (no sheet.html) says Type 4, the RMSE the run printed and the largest
#              residual of residuals.csv, the matched focal length 33.3 mm (50 mm on 36 mm is
#              33.3 on 24), the 35 mm equivalent 50.0 mm, the sensor 24.00 mm given, 39.60
#              degrees across (to 0.01: the points are nudged), the camera's height, the time the
#              sun was placed for, and no capture time (a PNG has none);
#   page       the page is A3 landscape at --dpi 100 (1190.55 x 841.89 pts, PNG 1654 x 1169), the
#              photomontage, the photograph twice and the map embedded;
#   unmatched  without control points the sheet says Type 3 and no residuals.
. "$(dirname "$0")/sheet_lib.sh"
sylva=$1 scene=$2

# the scene with its camera at a surveyed height, the DTM's path made absolute
python3 - "$scene" "$out" <<'PY' || exit 1
import math, os, re, sys
scene, out = sys.argv[1], sys.argv[2]
text = open(scene).read().replace("../site/", os.path.join(os.path.dirname(os.path.abspath(scene)), "../site/"))
text = re.sub(r"camera:\n(  .*\n)+", "camera: {position: {easting: 440060, northing: 3760040, height: 653}, heading: 45, "
              "focal_length: 50}\n", text, count=1)
open(os.path.join(out, "base.yaml"), "w").write(text)
for name, points in (("matched", ", control_points: points.csv"), ("unmatched", "")):
    open(os.path.join(out, name + ".yaml"), "w").write(text + "photo: {file: plate.png%s, exposure: 1, sensor_width: 24, "
                                                       "focal_length: 35}\n" % points)
# the camera: heading 45, level, 2 atan(18 / 50) across 240 pixels
h = math.radians(45)
f, r, u = (math.sin(h), math.cos(h), 0), (math.cos(h), -math.sin(h), 0), (0, 0, 1)
eye, F = (440060, 3760040, 653), 120 / (18 / 50)
rows = ["id,u,v,easting,northing,height"]
for k, (d, a, b) in enumerate([(80, -0.25, -0.1), (150, 0.2, 0.05), (250, 0.05, 0.15), (400, -0.1, -0.05),
                               (120, 0.28, -0.15), (300, -0.3, 0.1), (200, -0.05, -0.2), (500, 0.15, 0.02)]):
    p = [eye[i] + d * (f[i] + a * r[i] + b * u[i]) for i in range(3)]
    nudge = 0.1 * math.sin(7 * k + 1)
    rows.append("cp%d,%.4f,%.4f,%.3f,%.3f,%.3f" % (k + 1, 120 + F * a + nudge, 80 - F * b - nudge, *p))
open(os.path.join(out, "points.csv"), "w").write("\n".join(rows) + "\n")
PY
cd "$out" || exit 1
"$sylva" render base.yaml --size 240x160 -q -o plate.png >/dev/null || fail "the plate could not be rendered"

"$sylva" montage matched.yaml -o m --dpi 100 >/dev/null 2>m.log || fail "montage exited with $? ($(tail -1 m.log))"
for f in sheet.pdf sheet.png residuals.csv; do [ -s "m/$f" ] || fail "no $f"; done
[ ! -e m/sheet.html ] || fail "sheet.html is still written"
pdftotext -layout m/sheet.pdf m.txt || fail "pdftotext failed"
field() { # FILE LABEL TEXT: the label, then its text, on one line
  grep -qE "$2 +$3" "$1" || fail "$1: no '$2  $3' (got: $(grep -E "$2" "$1" | sed 's/  */ /g'))"
}
rmse=$(grep -oE "RMSE [0-9]+\.[0-9]+ px" m.log | grep -oE "[0-9]+\.[0-9]+")
largest=$(awk -F, 'NR > 1 && $6 > m { m = $6 } END { printf "%.2f", m }' m/residuals.csv)
[ "$(wc -l < m/residuals.csv)" -eq 9 ] || fail "residuals.csv does not hold the 8 points"
field m.txt "Visualisation type" "Type 4 \(TGN 06/19\): photomontage, survey verifiable"
grep -qE "Visualisation Type 4 \(LI TGN 06/19\)" m.txt || fail "the title does not say Type 4"
field m.txt "Camera match" "8 control points, RMSE ${rmse//./\\.} px \([0-9.]+°\); largest residual ${largest//./\\.} px"
field m.txt "Lens \(focal length\)" "33\.3 mm matched"
field m.txt "35 mm equivalent" "50\.0 mm"
field m.txt "Sensor width" "24\.00 mm \(given in photo:\)"
field m.txt "Horizontal field of view" "39\.(59|60)°"
field m.txt "Camera position" "surveyed"
field m.txt "Camera height" "653\.0 m"
field m.txt "Sun placed for" "2026-06-21 14:30:00 \(UTC-07:00\)"
field m.txt "Photograph taken" "not in the EXIF"
field m.txt "Print size" "A3 landscape, 420 × 297 mm at 100 dpi"
grep -qE "Photomontage printed +[0-9]+ × [0-9]+ mm; view it from [0-9]+ mm" m.txt || fail "no viewing distance"

pdfinfo m/sheet.pdf | grep -qE "Page size: +1190\.55 x 841\.89 pts" \
  || fail "the page is not A3 landscape: $(pdfinfo m/sheet.pdf | grep 'Page size')"
png_size=$(python3 -c 'import struct, sys; print(*struct.unpack(">II", open(sys.argv[1], "rb").read(24)[16:24]))' m/sheet.png)
[ "$png_size" = "1654 1169" ] || fail "the PNG page is $png_size pixels, not 1654 1169 (A3 at 100 dpi)"
[ "$(pdfimages -list m/sheet.pdf | awk 'NR > 2' | wc -l)" -ge 4 ] || fail "fewer than four pictures on the sheet"

"$sylva" montage unmatched.yaml -o u --dpi 50 -q >/dev/null || fail "montage without points exited with $?"
pdftotext -layout u/sheet.pdf u.txt || fail "pdftotext failed on the unmatched sheet"
field u.txt "Visualisation type" "Type 3 \(TGN 06/19\)"
field u.txt "Camera match" "none"
[ ! -e u/residuals.csv ] || fail "residuals.csv written without a match"

[ $fails -eq 0 ] && echo "montage sheet: all checks passed"
exit $((fails > 0))
