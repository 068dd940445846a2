#!/usr/bin/env bash
# ztv_layers_test.sh SYLVA SCENE — the GeoPackage and QGIS styles beside a visibility map
# (tests/scenes/ztv/layers_site.yaml): read back through OGR, the viewpoints, the distance rings
# and the structures stand where the scene puts them, with their numbers, heights and CRS; QGIS's
# layer_styles table holds a default style per layer; every .qml parses as XML; the same map
# twice gives the same GeoPackage bytes; with QGIS's Python bindings, QGIS opens every layer
# and the GeoTIFF styled.
set -uo pipefail
sylva=$1 scene=$2
command -v ogrinfo >/dev/null || { echo "ogrinfo (gdal-bin) is not installed: skipped"; exit 77; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

"$sylva" ztv "$scene" -o "$out/a" -q >/dev/null || fail "ztv exited with $?"
"$sylva" ztv "$scene" -o "$out/b" -q --threads 1 >/dev/null || fail "second ztv exited with $?"
for f in ztv_layers.gpkg ztv_viewpoints.qml ztv_distance_rings.qml ztv_developments.qml ztv_bare.qml; do
  [ -f "$out/a/$f" ] || fail "$f is missing"
done
cmp -s "$out/a/ztv_layers.gpkg" "$out/b/ztv_layers.gpkg" || fail "ztv_layers.gpkg differs between two runs"
gpkg=$out/a/ztv_layers.gpkg

# sql QUERY: the rows of an OGR SQL query, as ogrinfo prints them
sql() { ogrinfo -ro -q "$gpkg" -sql "$1" 2>&1; }
expect() { # expect WHAT TEXT OUTPUT
  grep -qF -- "$2" <<<"$3" || { fail "$1: no '$2' in:"; printf '%s\n' "$3" | head -40 >&2; }
}

layers=$(ogrinfo -ro -q "$gpkg" 2>&1)
for l in "viewpoints (Point)" "distance_rings (Multi Polygon)" "developments (Point)"; do
  expect "layers" "$l" "$layers"
done
v=$(ogrinfo -ro -al "$gpkg" viewpoints 2>&1)
expect "viewpoints CRS" 'WGS 84 / UTM zone 14N' "$v"
expect "viewpoints count" 'Feature Count: 2' "$v"
expect "viewpoint 1" 'POINT (649400 3600000)' "$v"
expect "viewpoint 2" 'POINT (650100 3599300)' "$v"
w=$(sql "SELECT number, name, eye_height, heading, ground_level FROM viewpoints WHERE name = 'west'")
expect "west's number" 'number (Integer) = 1' "$w"
expect "west's eye" 'eye_height (Real) = 1.5' "$w"
expect "west's heading" 'heading (Real) = 90' "$w"
expect "west's ground" 'ground_level (Real) = 100' "$w"
s=$(sql "SELECT number, heading, eye_height FROM viewpoints WHERE name = 'south'")
expect "south's number" 'number (Integer) = 2' "$s"
expect "south's heading (looking north)" 'heading (Real) = 0' "$s"
expect "south's eye" 'eye_height (Real) = 2' "$s"

d=$(ogrinfo -ro -al "$gpkg" developments 2>&1)
expect "structures" 'Feature Count: 2' "$d"
expect "mast_a" 'POINT (650000 3600000)' "$d"
expect "mast_b" 'POINT (650200 3600000)' "$d"
a=$(sql "SELECT development, base_level, top_level, height FROM developments WHERE name = 'mast_b'")
expect "mast_b's development" 'development (String) = North' "$a"
expect "mast_b's base" 'base_level (Real) = 100' "$a"
expect "mast_b's top" 'top_level (Real) = 140' "$a"
expect "mast_b's height" 'height (Real) = 40' "$a"

r=$(ogrinfo -ro -so "$gpkg" distance_rings 2>&1)
expect "rings" 'Feature Count: 2' "$r"
# the radius's ring reaches 1.5 km past the outer masts: its extent is the layer's
expect "rings' extent" 'Extent: (648500.000000, 3598500.000000) - (651700.000000, 3601500.000000)' "$r"
one=$(sql "SELECT label, ST_MinX(geom) AS w, ST_MaxX(geom) AS e, ST_MinY(geom) AS s FROM distance_rings WHERE distance = 1000")
expect "1 km ring" 'label (String) = 1 km' "$one"
expect "1 km ring's west" 'w (Real) = 649000' "$one"
expect "1 km ring's east" 'e (Real) = 651200' "$one"
expect "1 km ring's south" 's (Real) = 3599000' "$one"
expect "radius ring" 'label (String) = radius 1.5 km' "$(sql "SELECT label FROM distance_rings WHERE distance = 1500")"

styles=$(sql "SELECT f_table_name, f_geometry_column, useAsDefault, styleName FROM layer_styles")
for t in viewpoints distance_rings developments; do
  expect "layer_styles" "f_table_name (String) = $t" "$styles"
done
expect "layer_styles default" 'useAsDefault (Integer(Boolean)) = 1' "$styles"
expect "layer_styles geometry" 'f_geometry_column (String) = geom' "$styles"

if command -v python3 >/dev/null; then
  for q in "$out"/a/*.qml; do
    python3 -c 'import sys, xml.etree.ElementTree as E; r = E.parse(sys.argv[1]).getroot(); sys.exit(r.tag != "qgis")' "$q" ||
      fail "$(basename "$q") does not parse as a QGIS style"
  done
  python3 - "$gpkg" <<'PY' || fail "a style in layer_styles does not parse as XML"
import sqlite3, sys, xml.etree.ElementTree as E
for name, qml in sqlite3.connect(sys.argv[1]).execute("SELECT f_table_name, styleQML FROM layer_styles"):
    if E.fromstring(qml.split("\n", 1)[1]).tag != "qgis": sys.exit(1)
PY
fi

# where QGIS's Python bindings are installed (python3-qgis, optional): QGIS opens each layer with
# its style from layer_styles and the GeoTIFF with ztv_bare.qml, as a reader's QGIS would
qgis_python=
for p in python3 /usr/bin/python3; do
  if "$p" -c 'import qgis.core' 2>/dev/null; then qgis_python=$p; break; fi
done
if [ -n "$qgis_python" ]; then
  QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR=$out "$qgis_python" - "$gpkg" "$out/a/ztv_bare.tif" <<'PY' 2>"$out/qgis.log" ||
import sys
from qgis.core import QgsApplication, QgsRasterLayer, QgsVectorLayer
app = QgsApplication([], False)
app.initQgis()
want = {"viewpoints": ("SimpleMarker", "circle", 2), "distance_rings": ("SimpleFill", None, 2),
        "developments": ("SimpleMarker", "triangle", 2)}
for name, (kind, shape, count) in want.items():
    layer = QgsVectorLayer(sys.argv[1] + "|layername=" + name, name, "ogr")
    message, loaded = layer.loadDefaultStyle()  # what QGIS does when it adds the layer
    symbol = layer.renderer().symbol().symbolLayer(0)
    props = symbol.properties()
    ok = (layer.isValid() and loaded and layer.featureCount() == count and symbol.layerType() == kind
          and (shape is None or props.get("name") == shape) and layer.labelsEnabled())
    print(name, "styled" if ok else "NOT styled", message, symbol.layerType(), props.get("name"))
    if not ok: sys.exit(1)
raster = QgsRasterLayer(sys.argv[2], "ztv")
message, loaded = raster.loadDefaultStyle()
shader = raster.renderer().shader().rasterShaderFunction()
values = [round(item.value, 5) for item in shader.colorRampItemList()]
print("raster", raster.renderer().type(), values)
sys.exit(0 if loaded and raster.renderer().type() == "singlebandpseudocolor" and raster.renderer().band() == 2
         and values == [0, 0.25, 0.5, 0.75, 0.99999, 1] else 1)
PY
    { fail "QGIS does not open the layers styled"; cat "$out/qgis.log" >&2; }
else
  echo "QGIS's Python bindings (python3-qgis) are not installed: the styles not opened in QGIS"
fi

[ $fails -eq 0 ] && echo "ztv layers: viewpoints, rings, structures and styles as expected"
exit $((fails > 0))
