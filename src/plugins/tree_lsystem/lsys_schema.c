/* lsys_schema.c — the tree_lsystem plugin's parameter table: the keys a species block may hold
 * next to `plugin: tree_lsystem`, with types, defaults, ranges, units and help
 * (docs/models/tree_lsystem.md lists them). Static const data. */
#include "lsys_schema.h"

#include "lsys_mesh.h"
#include "lsys_system.h"
#include "lsys_texture.h"

static const char *const shape_choices[] = {"auto", "prism", "cylinder", NULL};
static const double default_height_by_age[] = {0.0, 0.0, 1.0, 1.0};

static const sylva_param_spec palette_members[] = {
    {.name = "index", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_REQUIRED | SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .min = 0, .max = 65535, .help = "Colour index as c(x) sets it."},
    {.name = "albedo", .type = SYLVA_P_VEC3, .flags = SYLVA_PARAM_REQUIRED | SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .min = 0, .max = 1, .help = "Linear RGB reflectance of wood and leaves drawn in this colour."},
    {.name = "transmittance", .type = SYLVA_P_VEC3, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = 0,
     .max = 1, .help = "Linear RGB transmittance of leaves (polygons) in this colour; default half the albedo."},
};

const sylva_param_spec lsys_schema[LSYS_SCHEMA_COUNT] = {
    {.name = "source", .type = SYLVA_P_STRING,
     .help = "The L-system text itself, numeric (Lparser 4) or keyword (Lparser 2.1) dialect; give source or file."},
    {.name = "file", .type = SYLVA_P_PATH,
     .help = "An L-parser .ls file in either dialect, relative to the scene file; give source or file."},
    {.name = "recursion", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = 0,
     .max = LSYS_MAX_RECURSION, .help = "Derivation steps of the full-grown tree (default: the file's)."},
    {.name = "angle", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = -360,
     .max = 360, .unit = "deg", .help = "Standard turning angle (default: the file's)."},
    {.name = "thickness", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = 0,
     .max = 1e6, .unit = "%", .help = "Width of a segment in percent of its length at the start (default: the file's)."},
    {.name = "min_thickness", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = 0,
     .max = 1e6, .help = "Smallest width of a segment in hundredths of a file unit, as Lparser reads it (default: the file's, else 0)."},
    {.name = "base_length", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = 0,
     .max = 1e9, .help = "Length of F at the start in the file's units; 0 takes the dialect's (numeric 100, keyword 1)."},
    {.name = "height", .type = SYLVA_P_REAL,
     .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_HAS_MAX, .def = 10, .min = 0,
     .max = 10000, .unit = "m", .help = "Height of the full-grown tree (age 1); each variant is scaled to its own height."},
    {.name = "unit_length", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = 0,
     .max = 1e6, .unit = "m", .help = "Metres per file unit; when positive the models keep the L-system's own size and height is not used."},
    {.name = "segment_shape", .type = SYLVA_P_ENUM, .def_str = "auto", .choices = shape_choices,
     .help = "Segments as prisms (Lparser's blocks) or joined cylinders; auto follows the file's shape line, else cylinders."},
    {.name = "sides", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .def = 8, .min = 5,
     .max = LSYS_MESH_MAX_SIDES, .help = "Corners of a cylinder's cross-section (prisms have 4)."},
    {.name = "lenient", .type = SYLVA_P_BOOL, .def = 0,
     .help = "Drop unknown symbols and ignore unsupported keywords with a warning instead of failing."},
    {.name = "max_string", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .def = 33554432,
     .min = 1, .max = 1e9, .unit = "bytes", .help = "Longest derived string; a derivation that would grow past it fails."},
    {.name = "max_segments", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .def = 2000000,
     .min = 1, .max = 1e8, .help = "Most segments (F, Z) a model may draw."},
    {.name = "max_polygons", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .def = 2000000,
     .min = 1, .max = 1e8, .help = "Most polygons (leaves) a model may draw."},
    {.name = "max_polygon_vertices", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .def = 4096, .min = 3, .max = 65536, .help = "Most vertices open polygons may hold at once."},
    {.name = "height_by_age", .type = SYLVA_P_POLYLINE, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = 0,
     .max = 1, .def_list = default_height_by_age, .def_len = 2, .min_len = 1,
     .help = "Height as a fraction of height against the normalised age, points [age, fraction] with age in [0, 1]."},
    {.name = "branch_law", .type = SYLVA_P_BOOL, .def = 1,
     .help = "Choose each age variant's recursion level by the branch-number law N2 = N1 (H1/H2)^(-D/2)."},
    {.name = "law_height", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = 0,
     .max = 10000, .unit = "m",
     .help = "H1 of the branch-number law: the height of a measured tree with law_branches branches, from which "
             "eq. 6 gives every variant's count (002's direction, young to old); 0: the full-grown tree."},
    {.name = "law_branches", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = 0,
     .max = 1e12, .help = "N1 of the branch-number law: the branches of the measured tree law_height high; 0: "
                          "counted on the full-grown tree."},
    {.name = "box_dimension", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = 0,
     .max = 3, .help = "D of the branch-number law; 0 measures it from the full-grown tree's silhouette."},
    {.name = "bark", .type = SYLVA_P_ENUM, .def_str = "furrowed", .choices = lsys_bark_texture_names,
     .help = "Fractal bark on the segments (smooth, scaly, furrowed, fissured), multiplied by the colour's albedo; "
             "off: plain colour."},
    {.name = "bark_tile_length", .type = SYLVA_P_REAL,
     .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_HAS_MAX, .def = 0.5, .min = 0, .max = 100,
     .unit = "m", .help = "Length of branch over which the bark texture repeats once (it goes once round every branch)."},
    {.name = "leaf", .type = SYLVA_P_ENUM, .def_str = "beech", .choices = lsys_leaf_texture_names,
     .help = "Affine-map leaf colour (blade, midrib, veins) on the leaf polygons, whose outline stays the grammar's "
             "(beech, maple, spruce, shrub, willow); off: plain colour."},
    {.name = "palette", .type = SYLVA_P_GROUP_LIST, .group = palette_members,
     .n_group = sizeof palette_members / sizeof palette_members[0],
     .help = "Colours for colour indices, overriding the file's color lines and the default palette."},
};
