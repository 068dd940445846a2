#!/usr/bin/env bash
# wireline_lattice_test.sh SYLVA — the wireline of an open structure is its silhouette: the shared
# lattice tower (../shared/data/models/pylon/gazebo-radio-tower, the mast of
# scenes/engabreen_montage.yaml) seen whole, 120 m away, in a study's wireline product: its
# outline (red) is one closed contour, where the members' own edges (yellow, inside it) are many
# pieces, and with `study: {inner_edges: false}` the outline is drawn alone; on the sheet the
# outline is one closed vector path, the edges vector paths too. Skipped (exit 77)
# without the shared data or oiiotool.
set -uo pipefail
sylva=$1
data=${SYLVA_SHARED_DATA_DIR:-}
model=$data/models/pylon/gazebo-radio-tower/radio_tower.dae
[ -n "$data" ] && [ -f "$model" ] || { echo "the shared data (${model}) is absent: skipped"; exit 77; }
command -v oiiotool >/dev/null || { echo "oiiotool is not installed: skipped"; exit 77; }
command -v python3 >/dev/null || { echo "python3 is not installed: skipped"; exit 77; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

cat >"$out/lattice.yaml" <<YAML
image: {width: 240, height: 160, spp: 1, seed: 1, max_depth: 2}
camera: {position: [-120, 0, 22], look_at: [0, 0, 22], focal_length: 50}
viewpoints:
  west: {position: [-120, 0, 22], look_at: [0, 0, 22], focal_length: 50}
  south_west: {position: [-85, -85, 22], look_at: [0, 0, 22], focal_length: 50}
sun: {azimuth: 200, elevation: 40}
terrain:
  grid: [[0, 0, 0], [0, 0, 0], [0, 0, 0]]
  origin: [-300, -300]
  spacing: [300, 300]
objects:
  - {name: tower, model: "$model", position: [0, 0, 0], development: true}
YAML
"$sylva" study "$out/lattice.yaml" -o "$out/s" --products wireline -q >/dev/null 2>&1 || fail "study exited with $?"
# the same with the outline alone
{ cat "$out/lattice.yaml"; echo "study: {inner_edges: false}"; } >"$out/outline.yaml"
"$sylva" study "$out/outline.yaml" -o "$out/o" --products wireline --only west -q >/dev/null 2>&1 ||
  fail "study with inner_edges: false exited with $?"
for v in west south_west west_outline; do
  png=$out/s/$v/wireline_single.png
  [ $v = west_outline ] && png=$out/o/west/wireline_single.png
  [ -f "$png" ] || { fail "no $v/wireline_single.png"; continue; }
  oiiotool "$png" -o "$out/$v.ppm" || { fail "oiiotool cannot read $png"; continue; }
  counts=$(python3 - "$out/$v.ppm" <<'PY'
import sys
data = open(sys.argv[1], "rb").read()
fields, pos = [], 0
while len(fields) < 4:  # P6, width, height, maxval
    while data[pos:pos + 1].isspace(): pos += 1
    start = pos
    while not data[pos:pos + 1].isspace(): pos += 1
    fields.append(data[start:pos])
w, h = int(fields[1]), int(fields[2])
px = data[pos + 1:]
def mask(rgb):
    return [[px[3 * (y * w + x):3 * (y * w + x) + 3] == rgb for x in range(w)] for y in range(h)]
def contours(m):  # 8-connected pieces
    seen, n = [[False] * w for _ in range(h)], 0
    for y in range(h):
        for x in range(w):
            if not m[y][x] or seen[y][x]: continue
            n += 1; stack = [(x, y)]; seen[y][x] = True
            while stack:
                cx, cy = stack.pop()
                for dy in (-1, 0, 1):
                    for dx in (-1, 0, 1):
                        nx, ny = cx + dx, cy + dy
                        if 0 <= nx < w and 0 <= ny < h and m[ny][nx] and not seen[ny][nx]:
                            seen[ny][nx] = True; stack.append((nx, ny))
    return n
red, yellow = mask(b"\xff\x00\x00"), mask(b"\xff\xdc\x00")
print(contours(red), sum(map(sum, red)), contours(yellow), sum(map(sum, yellow)))
PY
)
  read -r outline outline_px inner inner_px <<<"$counts"
  echo "$v: outline $outline contour(s) of $outline_px pixels; inner edges $inner pieces of $inner_px pixels"
  [ "$outline" = 1 ] || fail "$v: the outline is $outline contours, not one"
  [ "${outline_px:-0}" -ge 150 ] || fail "$v: the outline has $outline_px pixels; the tower is not in view"
  if [ $v = west_outline ]; then
    [ "${inner_px:-1}" = 0 ] || fail "$v: inner_edges: false drew $inner_px pixels of inner edges"
    [ "$outline_px" = "$west_outline_px" ] || fail "$v: the outline alone has $outline_px pixels, with the edges $west_outline_px"
  else
    [ "${inner:-0}" -ge 2 ] || fail "$v: the members' edges are $inner pieces; the tower is not open"
  fi
  [ $v = west ] && west_outline_px=$outline_px
done

# on the sheet the wireline is vector paths: the outline one closed red path (one "h" in the stroke
# that sets red), the members' edges yellow paths
"$sylva" study "$out/lattice.yaml" -o "$out/sheet" --products sheet --only west --dpi 50 -q >/dev/null 2>&1 ||
  fail "study --products sheet exited with $?"
pdf=$out/sheet/west/sheet_single.pdf
if [ -f "$pdf" ]; then
  paths=$(python3 - "$pdf" <<'PY'
import re, sys, zlib
pdf = open(sys.argv[1], "rb").read()
content = b""
for m in re.finditer(rb"stream\r?\n(.*?)\r?\nendstream", pdf, re.S):
    try: content += zlib.decompress(m.group(1)) + b"\n"
    except zlib.error: pass
def stroke(colour):  # the path stroked after colour is set: its closed subpaths and its points
    m = re.search(colour, content)
    if not m: return 0, 0
    end = content.find(b" S", m.end())
    body = content[m.end():end if end > 0 else None]
    return len(re.findall(rb"\bh\b", body)), len(re.findall(rb"[0-9.-]+ [0-9.-]+ [ml]\b", body))
print(*stroke(rb"1 0 0 RG"), *stroke(rb"1 0\.86 0 RG"))
PY
)
  read -r closed points edge_closed edge_points <<<"$paths"
  echo "sheet: outline $closed closed path(s) of $points points; inner edges $edge_points points"
  [ "$closed" = 1 ] || fail "the sheet's outline is $closed closed paths, not one"
  [ "${points:-0}" -ge 8 ] || fail "the sheet's outline has ${points:-0} points"
  [ "${edge_points:-0}" -ge 4 ] || fail "the sheet's inner edges have ${edge_points:-0} points"
else
  fail "no sheet_single.pdf"
fi

[ $fails -eq 0 ] && echo "wireline of the lattice tower: one closed contour per view, on the sheet one closed path"
exit $((fails > 0))
