#!/usr/bin/env bash
# sheet_test.sh SYLVA SCENE — the study's sheets (docs/study.md, Sheets) on
# tests/scenes/study/sheet_study.yaml (a 60 m mast seen from south_west, the sun at
# 2026-06-21T14:30:00-07:00), read back with poppler's tools:
#   fields     pdftotext finds every field, and these right: focal length 50.0 mm, sensor 36.0 mm,
#              35 mm equivalent 50.0 mm, horizontal field of view 39.60 (2 atan(18/50)), the local
#              time with its zone, the grid reference, the distance and bearing to the mast to 1 m
#              and 0.1 degree (computed here from the scene's coordinates), Type 2, the cross-check
#              "not run", and that the mast's top is out of the level frame;
#   page       the PDF's page is A3 landscape (420 x 297 mm), the PNG 420 and 297 mm at the dpi, and
#              every picture in the PDF is embedded at the dpi; the proposed view's pixels span the
#              printed width the sheet states;
#   wireline   the wireline is stroked as vector paths (a red path of several segments in the PDF's
#              content), not embedded as a picture;
#   panorama   the cylindrical frame's sheet gives no focal length and 90.00 degrees across;
#   print      --print-width 297 makes an A4 landscape page;
#   resume     a rerun writes nothing; a changed dpi writes the sheets anew and keeps the views.
. "$(dirname "$0")/sheet_lib.sh"
sylva=$1 scene=$2

"$sylva" study "$scene" -o "$out/s" --only south_west --frames single,cylindrical_90 --dpi 100 -q >/dev/null \
  || fail "study exited with $?"
d=$out/s/south_west
for e in pdf png manifest; do [ -f "$d/sheet_single.$e" ] || fail "no sheet_single.$e"; done
pdftotext -layout "$d/sheet_single.pdf" "$out/single.txt" || fail "pdftotext failed"
# one field: its label, then its text, on one line of the text
field() {
  grep -qE "$1 +$2" "$out/single.txt" || fail "sheet_single.pdf: no '$1  $2' (got: $(grep -E "$1" "$out/single.txt" | sed 's/  */ /g'))"
}
field "Viewpoint" "1 south_west"
field "Grid reference" "E 440060\.0 N 3760040\.0 \(WGS 84 / UTM zone 11N\)"
field "Ground level" "[0-9]+\.[0-9] m"
field "Eye height" "1\.60 m above ground"
field "Lens \(focal length\)" "50\.0 mm"
field "Sensor width" "36\.0 mm"
field "35 mm equivalent" "50\.0 mm"
hfov=$(python3 -c 'import math; print("%.2f" % (2 * math.degrees(math.atan(18 / 50))))')
field "Horizontal field of view" "${hfov//./\\.}°"
field "Date and local time" "2026-06-21 14:30:00 \(UTC-07:00\)"
read -r dist bearing < <(python3 -c 'import math; dx, dy = 440135 - 440060, 3760135 - 3760040
print("%.0f %.1f" % (math.hypot(dx, dy), math.degrees(math.atan2(dx, dy)) % 360))')
field "Nearest development" "mast \(development\): $dist m at bearing ${bearing//./\\.}°"
field "Visualisation type" "Type 2"
field "Print size" "A3 landscape, 420 × 297 mm at 100 dpi"
field "Camera match" "none"
field "POV-Ray cross-check" "not run"
field "Development in frame" "NOT whole"

# the page and the pictures at the print size
pdfinfo "$d/sheet_single.pdf" > "$out/info.txt"
grep -qE "Page size: +1190\.55 x 841\.89 pts" "$out/info.txt" || fail "the page is not A3 landscape: $(grep 'Page size' "$out/info.txt")"
png_size=$(python3 -c 'import struct, sys; b = open(sys.argv[1], "rb").read(24); print(*struct.unpack(">II", b[16:24]))' "$d/sheet_single.png")
[ "$png_size" = "1654 1169" ] || fail "the PNG page is $png_size pixels, not 1654 1169 (A3 at 100 dpi)"
pdfimages -list "$d/sheet_single.pdf" | awk 'NR > 2 { n++; if ($13 < 99 || $13 > 101 || $14 < 99 || $14 > 101) bad++ }
  END { exit !(n >= 4 && !bad) }' || fail "a picture is not embedded at 100 dpi: $(pdfimages -list "$d/sheet_single.pdf")"
printed=$(grep -oE "Proposed view printed +[0-9]+" "$out/single.txt" | grep -oE "[0-9]+$")
main_px=$(pdfimages -list "$d/sheet_single.pdf" | awk 'NR == 3 { print $4 }')
python3 -c "import sys; sys.exit(abs($main_px / 100 * 25.4 - $printed) > 1)" \
  || fail "the proposed view is $main_px pixels at 100 dpi, not the $printed mm the sheet states"

# the wireline as vector paths: in the page's content, a red stroke (the outline) made of a closed
# path of several segments, over the existing view's picture
python3 - "$d/sheet_single.pdf" <<'PY' || fail "sheet_single.pdf holds no vector outline for the wireline"
import re, sys, zlib
pdf = open(sys.argv[1], "rb").read()
content = b""
for m in re.finditer(rb"stream\r?\n(.*?)\r?\nendstream", pdf, re.S):
    try: content += zlib.decompress(m.group(1)) + b"\n"
    except zlib.error: pass
best = 0
for m in re.finditer(rb"1 0 0 RG", content):
    end = content.find(b" S", m.end())
    ops = re.findall(rb"[0-9.-]+ [0-9.-]+ ([ml])\b", content[m.end():end if end > 0 else None])
    best = max(best, len(ops))
print("the wireline's outline: %d path points stroked in red" % best)
sys.exit(0 if best >= 4 else 1)
PY

# the panorama
pdftotext -layout "$d/sheet_cylindrical_90.pdf" "$out/pano.txt" || fail "no cylindrical sheet"
grep -qE "Lens \(focal length\) +none" "$out/pano.txt" || fail "the panorama's sheet gives a focal length"
grep -qE "Horizontal field of view +90\.00°" "$out/pano.txt" || fail "the panorama's sheet is not 90.00 degrees across"

# another print width
"$sylva" study "$scene" -o "$out/a4" --only south_west --products sheet --print-width 297 --dpi 50 -q >/dev/null \
  || fail "study --print-width exited with $?"
pdfinfo "$out/a4/south_west/sheet_single.pdf" | grep -qE "Page size: +841\.89 x 595\.[0-9]+ pts" \
  || fail "--print-width 297 is not an A4 landscape page: $(pdfinfo "$out/a4/south_west/sheet_single.pdf" | grep 'Page size')"

# resuming
"$sylva" study "$scene" -o "$out/s" --only south_west --frames single,cylindrical_90 --dpi 100 >/dev/null 2>"$out/again.log" \
  || fail "rerun exited with $?"
grep -q "0 to render, 8 up to date" "$out/again.log" || fail "the rerun rendered again: $(head -1 "$out/again.log")"
touch -d '2000-01-01' "$d"/existing_single.png
"$sylva" study "$scene" -o "$out/s" --only south_west --frames single --size 72x48 --dpi 90 >/dev/null 2>"$out/dpi.log" \
  || fail "the run at 90 dpi exited with $?"
grep -q "1 to render, 3 up to date" "$out/dpi.log" || fail "another dpi did not render the sheet alone: $(head -1 "$out/dpi.log")"
[ "$(stat -c %Y "$d/existing_single.png")" = "$(date -d '2000-01-01' +%s)" ] || fail "another dpi rewrote the existing view"

[ $fails -eq 0 ] && echo "sheet: all checks passed"
exit $((fails > 0))
