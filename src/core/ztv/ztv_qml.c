/* ztv_qml.c — the QGIS styles of ztv_qml.h, written out by hand as QGIS 3 reads them: a
 * renderer-v2 with one symbol (its properties as <prop> elements, which every QGIS 3 reads) and
 * simple labels for the vector layers, a discrete colour-ramp shader for the GeoTIFF's fraction
 * band. The colours are the maps' (ztv_map.c, docs/ztv.md "The maps"). */
#include "ztv/ztv_qml.h"

#define QML_HEAD "<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>\n" \
                 "<qgis version=\"3.16.0\" styleCategories=\"Symbology|Labeling\" labelsEnabled=\"1\">\n"
/* A symbol layer's property, in the form every QGIS 3 reads. */
#define OPT(name, value) "     <prop k=\"" name "\" v=\"" value "\"/>\n"

/* Simple labels of `field` (an expression when expr is "1"), size points, dist mm off the feature. */
#define LABELS(field, expr, size, colour, placement) \
    " <labeling type=\"simple\">\n" \
    "  <settings calloutType=\"simple\">\n" \
    "   <text-style fieldName=\"" field "\" isExpression=\"" expr "\" fontFamily=\"Sans Serif\" fontSize=\"" size "\"" \
    " fontSizeUnit=\"Point\" fontWeight=\"75\" textColor=\"" colour "\" textOpacity=\"1\" multilineHeight=\"1\"/>\n" \
    "   <text-buffer bufferDraw=\"1\" bufferSize=\"0.8\" bufferSizeUnits=\"MM\" bufferColor=\"255,255,255,255\"" \
    " bufferOpacity=\"1\"/>\n" \
    "   <placement " placement "/>\n" \
    "   <rendering drawLabels=\"1\" obstacle=\"1\" scaleVisibility=\"0\"/>\n" \
    "  </settings>\n" \
    " </labeling>\n"

/* One symbol of kind (marker, fill) drawn by symbol_class with the options given, for every feature. */
#define SINGLE_SYMBOL(kind, symbol_class, options) \
    " <renderer-v2 type=\"singleSymbol\" symbollevels=\"0\" enableorderby=\"0\" forceraster=\"0\">\n" \
    "  <symbols>\n" \
    "   <symbol type=\"" kind "\" name=\"0\" alpha=\"1\" clip_to_extent=\"1\" force_rhr=\"0\">\n" \
    "    <layer class=\"" symbol_class "\" enabled=\"1\" pass=\"0\" locked=\"0\">\n" options \
    "    </layer>\n" \
    "   </symbol>\n" \
    "  </symbols>\n" \
    " </renderer-v2>\n"

/* A marker of shape, filled and outlined (width and size in millimetres). */
#define MARKER(shape, fill, outline, width, size) \
    SINGLE_SYMBOL("marker", "SimpleMarker", OPT("name", shape) OPT("color", fill) OPT("outline_color", outline) \
                  OPT("outline_style", "solid") OPT("outline_width", width) OPT("outline_width_unit", "MM") \
                  OPT("size", size) OPT("size_unit", "MM"))

static const char viewpoints[] =
    QML_HEAD
    MARKER("circle", "255,255,255,255", "0,0,0,255", "0.5", "4.5")
    LABELS("concat(&quot;number&quot;, ' ', &quot;name&quot;)", "1", "9", "0,0,0,255",
           "placement=\"0\" dist=\"1.2\" distUnits=\"MM\" priority=\"8\"")
    " <layerGeometryType>0</layerGeometryType>\n"
    "</qgis>\n";

static const char rings[] =
    QML_HEAD
    SINGLE_SYMBOL("fill", "SimpleFill",
                  OPT("style", "no") OPT("color", "0,0,0,0") OPT("outline_color", "40,40,40,255")
                  OPT("outline_style", "dash") OPT("outline_width", "0.4") OPT("outline_width_unit", "MM"))
    LABELS("label", "0", "8", "40,40,40,255", "placement=\"7\" placementFlags=\"1\" dist=\"0.5\" distUnits=\"MM\" priority=\"5\"")
    " <layerGeometryType>2</layerGeometryType>\n"
    "</qgis>\n";

static const char developments[] =
    QML_HEAD
    MARKER("triangle", "0,0,0,255", "255,255,255,255", "0.3", "3.5")
    LABELS("name", "0", "8", "0,0,0,255", "placement=\"0\" dist=\"1\" distUnits=\"MM\" priority=\"6\"")
    " <layerGeometryType>0</layerGeometryType>\n"
    "</qgis>\n";

#define RAMP_ITEM(value, rgb, alpha, label) \
    "      <item value=\"" value "\" color=\"" rgb "\" alpha=\"" alpha "\" label=\"" label "\"/>\n"

/* Band 2 of ztv_MODE.tif: a discrete ramp, each item colouring the values up to its own. */
static const char visibility[] =
    "<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>\n"
    "<qgis version=\"3.16.0\" styleCategories=\"Symbology\">\n"
    " <pipe>\n"
    "  <provider>\n"
    "   <resampling enabled=\"false\" zoomedInResamplingMethod=\"nearestNeighbour\""
    " zoomedOutResamplingMethod=\"nearestNeighbour\" maxOversampling=\"2\"/>\n"
    "  </provider>\n"
    "  <rasterrenderer type=\"singlebandpseudocolor\" band=\"2\" opacity=\"0.65\" alphaBand=\"-1\""
    " classificationMin=\"0\" classificationMax=\"1\" nodataColor=\"\">\n"
    "   <rastershader>\n"
    "    <colorrampshader colorRampType=\"DISCRETE\" classificationMode=\"1\" clip=\"0\""
    " minimumValue=\"0\" maximumValue=\"1\" labelPrecision=\"2\">\n"
    RAMP_ITEM("0", "#000000", "0", "0 %")
    RAMP_ITEM("0.25", "#ffe650", "255", "1-25 %")
    RAMP_ITEM("0.5", "#feaa32", "255", "25-50 %")
    RAMP_ITEM("0.75", "#f0641e", "255", "50-75 %")
    RAMP_ITEM("0.99999", "#cd1e1e", "255", "75-&lt;100 %")
    RAMP_ITEM("1", "#780032", "255", "100 %")
    "    </colorrampshader>\n"
    "   </rastershader>\n"
    "  </rasterrenderer>\n"
    "  <brightnesscontrast brightness=\"0\" contrast=\"0\" gamma=\"1\"/>\n"
    "  <huesaturation saturation=\"0\" grayscaleMode=\"0\" colorizeOn=\"0\"/>\n"
    "  <rasterresampler maxOversampling=\"2\"/>\n"
    " </pipe>\n"
    " <blendMode>0</blendMode>\n"
    "</qgis>\n";

const char *ztv_qml_text(ztv_qml_style style)
{
    static const char *const texts[ZTV_QML_STYLES] = {viewpoints, rings, developments, visibility};
    return (unsigned)style < ZTV_QML_STYLES ? texts[style] : "";
}

const char *ztv_qml_name(ztv_qml_style style)
{
    static const char *const names[ZTV_QML_STYLES] = {"sylva viewpoints", "sylva distance rings",
                                                      "sylva developments", "sylva visibility"};
    return (unsigned)style < ZTV_QML_STYLES ? names[style] : "";
}
