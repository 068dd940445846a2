#!/usr/bin/env bash
# study_index_test.sh SYLVA SCENE — the study's index.html (tests/scenes/study/hill_study.yaml):
# it needs no network (no script, no file from elsewhere), every link and picture in it is a
# file of the study, each viewpoint's row lists its images and sheets there are, the marks stand
# where the map's world file places the viewpoints (the study's own world file puts a mark on the
# viewpoint's dot of the map page; a world file put by hand moves them), and headless Chromium draws
# it (a screenshot that is not blank). Without chromium the test is skipped (exit 77).
set -uo pipefail
sylva=$1 scene=$2
browser=$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)
[ -n "$browser" ] || { echo "chromium is not installed: skipped"; exit 77; }
command -v python3 >/dev/null || { echo "python3 is not installed: skipped"; exit 77; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

study() { "$sylva" study "$scene" -o "$out/s" --products existing,proposed,wireline,ztv --size 48x32 --spp 1 -q \
            >/dev/null 2>&1 || fail "study exited with $?"; }
study
index=$out/s/index.html
[ -f "$index" ] || { echo "FAIL: no index.html" >&2; exit 1; }

# links CHECKS: every href and src is a file of the study (or a mark of the page), none elsewhere
links() {
  python3 - "$index" <<'PY'
import html.parser, os, sys, urllib.parse
page = sys.argv[1]
root = os.path.dirname(page)
class P(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(); self.refs = []; self.ids = set(); self.bad = []
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "script": self.bad.append("a script")
        if tag == "link": self.bad.append("a linked file: %s" % a.get("href"))
        if "id" in a: self.ids.add(a["id"])
        for k in ("href", "src", "xlink:href"):
            if a.get(k) is not None: self.refs.append(a[k])
p = P(); p.feed(open(page, encoding="utf-8").read())
bad = p.bad
for r in p.refs:
    u = urllib.parse.urlsplit(r)
    if u.scheme or u.netloc: bad.append("a link elsewhere: " + r); continue
    if not u.path:
        if u.fragment not in p.ids: bad.append("a mark the page lacks: " + r)
        continue
    if not os.path.isfile(os.path.join(root, urllib.parse.unquote(u.path))): bad.append("no file " + r)
for b in bad: print(b)
print("links %d" % len(p.refs))
sys.exit(1 if bad else 0)
PY
}
res=$(links) || fail "index.html: $res"
n=$(sed -n 's/^links //p' <<<"$res")
[ "${n:-0}" -ge 13 ] || fail "index.html has ${n:-0} links; expected the map, 3 marks and 9 images at least"
for v in south_west south south_east; do
  for p in existing proposed wireline; do
    grep -q "href=\"$v/${p}_single.png\"" "$index" || fail "no link to $v/${p}_single.png"
  done
done
grep -q '<td>mast</td><td>115</td><td>0.0</td>' "$index" || fail "south's nearest structure, distance, bearing"

# the map page's own world file (ztv_vegetation.pgw, written by the study) places each mark on the
# picture: south_west's mark stands on the red dot the page draws for it
map=$(ls "$out"/s/ztv/ztv_vegetation.png)
[ -f "${map%.png}.pgw" ] || fail "the study wrote no world file beside $map"
grep -q '<image href="ztv/ztv_vegetation.png"' "$index" || fail "the index does not show the map page under its marks"
read -r cx cy < <(sed -n 's/.*<title>south_west<\/title><circle cx="\([0-9.]*\)" cy="\([0-9.]*\)".*/\1 \2/p' "$index")
[ -n "${cx:-}" ] || fail "no mark for south_west on the map picture"
if [ -n "${cx:-}" ] && command -v oiiotool >/dev/null; then
  # the 13 x 13 pixels round the mark's centre: most of them the page's red dot (a 2 mm disc)
  oiiotool "$map" --cut "13x13+$((${cx%.*} - 6))+$((${cy%.*} - 6))" -o "$out/mark.ppm" 2>/dev/null ||
    fail "oiiotool cannot cut $map"
  red=$(python3 -c 'import sys; d = open(sys.argv[1], "rb").read()[-13 * 13 * 3:]
print(sum(d[k] > 150 and d[k + 1] < 90 and d[k + 2] < 90 for k in range(0, len(d), 3)))' "$out/mark.ppm")
  echo "south_west's mark at ($cx, $cy): ${red:-0} of 169 pixels round it the page's red dot"
  [ "${red:-0}" -ge 40 ] || fail "south_west's mark at ($cx, $cy) is not on its dot on the map picture"
fi

# a sheet appears in its viewpoint's row; a world file places the marks on the map picture
: >"$out/s/south/sheet_single.pdf"
printf '1\n0\n0\n-1\n440000\n3760300\n' >"${map%.png}.pgw"
study
grep -q 'href="south/sheet_single.pdf"' "$index" || fail "the sheet of south is not linked"
grep -q '<image href="ztv/ztv_vegetation.png"' "$index" || fail "the map picture is not under the marks"
grep -q 'cx="60.5" cy="260.5"' "$index" || fail "south_west's mark is not at (60.5, 260.5) of the map"
res=$(links) || fail "index.html with a sheet and a world file: $res"

# headless Chromium draws it: a screenshot, not blank
shot=$out/shot.png
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --no-first-run --user-data-dir="$out/profile" \
  --window-size=1200,1600 --screenshot="$shot" "file://$index" >"$out/chromium.log" 2>&1
[ -s "$shot" ] || { fail "chromium wrote no screenshot"; tail -5 "$out/chromium.log" >&2; }
if [ -s "$shot" ]; then
  # gdalinfo's statistics of the picture: a page drawn has its text, table and map, not one colour
  stats=$(cp "$shot" "$out/stats.png" && gdalinfo -stats "$out/stats.png" 2>/dev/null)
  sd=$(sed -n 's/.*STATISTICS_STDDEV=//p' <<<"$stats" | head -1)
  lo=$(sed -n 's/.*STATISTICS_MINIMUM=//p' <<<"$stats" | head -1)
  echo "screenshot: band 1 stddev ${sd:-?}, minimum ${lo:-?}"
  awk -v s="${sd:-0}" -v m="${lo:-255}" 'BEGIN {exit !(s > 10 && m < 100)}' || fail "the screenshot is blank"
fi

[ $fails -eq 0 ] && echo "study index: links resolve, no network, marks placed, drawn by Chromium"
exit $((fails > 0))
