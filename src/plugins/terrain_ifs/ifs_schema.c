/* ifs_schema.c — the terrain_ifs parameter table. */
#include "ifs_schema.h"

#include "dtm_file.h"
#include "ifs_chaos.h"
#include "ifs_eval.h"

#define RANGE (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX)
#define OPEN_RANGE (RANGE | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_MAX_EXCLUSIVE)

static const char *const mode_choices[] = {"bilinear", "affine", NULL};
static const char *const method_choices[] = {"random", "deterministic", NULL};
static const char *const units_choices[] = {"auto", "metres", "degrees", NULL};
static const char *const surface_choices[] = {"classes", "scene", NULL};
static const char *const beyond_edge_choices[] = {"flat", "void", NULL};
/* auto, then the biomes in ifs_biome order */
static const char *const biome_choices[] = {"auto", "temperate", "mediterranean", "semi_arid", "prairie",
                                            "boreal", "alpine", NULL};

static const double def_generated_nodes[] = {17, 17};
static const double def_centre[] = {0, 0};
static const double def_height_range[] = {IFS_DTM_HEIGHT_MIN, IFS_DTM_HEIGHT_MAX};
static const double def_grass[] = {0.07, 0.10, 0.04};
static const double def_dry_grass[] = {0.30, 0.26, 0.12};
static const double def_scree[] = {0.34, 0.32, 0.29};
static const double def_rock[] = {0.21, 0.19, 0.17};
static const double def_snow[] = {0.85, 0.87, 0.90};
static const double def_water[] = {0.02, 0.05, 0.08};

static const sylva_param_spec generated_members[] = {
    {.name = "nodes", .type = SYLVA_P_LIST, .flags = RANGE, .min = 3, .max = 1025,
     .def_list = def_generated_nodes, .def_len = 2, .min_len = 2, .max_len = 2,
     .help = "Nodes of the generated DTM along x and y (whole numbers)."},
    {.name = "relief", .type = SYLVA_P_REAL, .flags = RANGE, .def = 60, .min = 0, .max = 10000,
     .unit = "m", .help = "Height difference between the lowest and the highest generated node."},
    {.name = "smoothness", .type = SYLVA_P_REAL,
     .flags = RANGE | SYLVA_PARAM_MIN_EXCLUSIVE, .def = 0.8, .min = 0, .max = 1,
     .help = "Hurst exponent of the generated relief: 1 is rolling, near 0 is jagged."},
};

const sylva_param_spec terrain_ifs_params[] = {
    /* --- the DTM ------------------------------------------------------------------------ */
    {.name = "dtm", .type = SYLVA_P_PATH,
     .help = "Raster file with the DTM heights (GeoTIFF, ESRI ASCII grid or any raster GDAL "
             "reads); leave out to use heights or the generated DTM."},
    {.name = "band", .type = SYLVA_P_INT, .flags = RANGE, .def = 1, .min = 1, .max = 65535,
     .help = "Band of the dtm file that holds the heights (1 is the first)."},
    {.name = "crop", .type = SYLVA_P_LIST, .flags = SYLVA_PARAM_HAS_MIN, .min = 0, .max_len = 4,
     .help = "Window of the dtm file [first column, first row, columns, rows] in pixels, row 0 "
             "at the top (north), as gdal_translate -srcwin; empty: the whole file."},
    {.name = "step", .type = SYLVA_P_INT, .flags = RANGE, .def = 1, .min = 1, .max = 4096,
     .help = "Resampling step: keep every step-th node of the dtm window along both axes."},
    {.name = "height_range", .type = SYLVA_P_LIST, .def_list = def_height_range, .def_len = 2,
     .min_len = 2, .max_len = 2, .unit = "m",
     .help = "Lowest and highest plausible height [low, high] in the dtm file (before z_scale "
             "and z_offset); a height outside it stops loading as a damaged file. The default "
             "spans the Dead Sea shore to Everest; widen it for heights in feet."},
    {.name = "units", .type = SYLVA_P_ENUM, .def_str = "auto", .choices = units_choices,
     .help = "Horizontal units of the dtm file: auto (from its coordinate system), metres, or "
             "degrees (converted to metres at the window's centre latitude)."},
    {.name = "heights", .type = SYLVA_P_GRID, .unit = "m",
     .help = "Inline DTM heights, rows from south to north and columns from west to east (at "
             "least 3 x 3)."},
    {.name = "generated", .type = SYLVA_P_GROUP, .group = generated_members,
     .n_group = sizeof generated_members / sizeof generated_members[0],
     .help = "The coarse DTM made up from the scene seed when neither dtm nor heights is "
             "given."},
    {.name = "cell_size", .type = SYLVA_P_LIST,
     .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE, .min = 0, .max_len = 2, .unit = "m",
     .help = "DTM node spacing [dx, dy] or [d]; empty: the dtm file's own spacing, or 25 m for "
             "heights and the generated DTM."},
    {.name = "z_scale", .type = SYLVA_P_REAL, .flags = RANGE | SYLVA_PARAM_MIN_EXCLUSIVE,
     .def = 1, .min = 0, .max = 1000,
     .help = "Factor on every DTM height (vertical exaggeration or a unit conversion)."},
    {.name = "z_offset", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = -100000,
     .max = 100000, .unit = "m", .help = "Added to every DTM height after z_scale."},
    {.name = "beyond_edge", .type = SYLVA_P_ENUM, .def_str = "flat", .choices = beyond_edge_choices,
     .help = "flat: past the DTM's edge the ground goes on, flat at the edge's heights, to the "
             "horizon; void: nothing past the edge (the sky shows under the horizon)."},
    {.name = "centre", .type = SYLVA_P_LIST, .def_list = def_centre, .def_len = 2, .min_len = 2,
     .max_len = 2, .unit = "m",
     .help = "Where the centre of the DTM's footprint stands in the scene, [x, y]."},
    /* --- the maps (8)-(12) -------------------------------------------------------------- */
    {.name = "mode", .type = SYLVA_P_ENUM, .def_str = "bilinear", .choices = mode_choices,
     .help = "bilinear: four corner conditions, the surface passes through every DTM node; "
             "affine: the paper's three-corner map (9)-(11)."},
    {.name = "alpha", .type = SYLVA_P_REAL, .flags = OPEN_RANGE, .def = 0, .min = -1, .max = 1,
     .help = "Vertical scaling alpha of every map (9), an override: 0 gives the bilinear surface, "
             "a larger |alpha| a rougher one (alpha times the whole DTM's departure from its "
             "corners' surface per cell). Leave out: chosen from the DTM's own roughness (detail)."},
    {.name = "detail", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = 0, .max = 1000,
     .unit = "m",
     .help = "RMS height of the relief the refinement adds within the DTM's cells; alpha is chosen "
             "to give it. Leave out (and alpha too): the DTM's own roughness at its two finest "
             "scales, continued one scale down."},
    {.name = "alpha_field", .type = SYLVA_P_GRID, .flags = OPEN_RANGE, .min = -1, .max = 1,
     .help = "Per-cell alpha instead of alpha: one row per row of DTM cells from south to north, "
             "one value per cell from west to east."},
    {.name = "probability_field", .type = SYLVA_P_GRID, .flags = SYLVA_PARAM_HAS_MIN, .min = 0,
     .help = "Per-cell weights R for picking the maps, laid out as alpha_field and normalised; "
             "empty: proportional to the cell area."},
    /* --- evaluation ----------------------------------------------------------------------- */
    {.name = "method", .type = SYLVA_P_ENUM, .def_str = "deterministic", .choices = method_choices,
     .help = "deterministic: f_K evaluated at every output node, so the surface passes through "
             "every DTM node (bilinear mode); random: the random iteration of Fig. 1, points "
             "averaged onto the output grid (near, not on, the DTM's nodes)."},
    {.name = "iterations", .type = SYLVA_P_INT, .flags = RANGE, .def = 4000000, .min = 1,
     .max = (double)IFS_MAX_POINTS,
     .help = "Number of iterations NK of the random iteration (one surface point each); "
             "method: random only."},
    {.name = "start", .type = SYLVA_P_LIST, .max_len = 3, .unit = "m",
     .help = "Starting point [x, y, z] of the random iteration in scene coordinates; empty: "
             "the DTM's origin (its south-west node); method: random only."},
    {.name = "depth", .type = SYLVA_P_INT, .flags = RANGE, .def = 0, .min = 0,
     .max = IFS_MAX_DEPTH,
     .help = "Levels K of the deterministic evaluation (also for nodes no random point "
             "reached); 0: enough for the output spacing and for alpha^K <= 1e-4."},
    {.name = "refine", .type = SYLVA_P_INT, .flags = RANGE, .def = 4, .min = 1, .max = 1024,
     .help = "Output nodes per DTM cell along each axis: (N - 1) refine + 1 nodes along x."},
    {.name = "detail_radius", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = 0,
     .max = 1e7, .unit = "m",
     .help = "Levels of detail: refine only within this distance of the camera (ring by ring "
             "coarser beyond, halving the refine, the DTM's own nodes everywhere); 0: uniform "
             "refinement unless it passes 4097 x 4097 nodes, then 1024 output cells around the "
             "camera."},
    {.name = "output_nodes", .type = SYLVA_P_LIST, .flags = RANGE, .min = 2, .max = 65536,
     .max_len = 2, .help = "Output grid size [nx, ny] in nodes, instead of refine."},
    {.name = "threads", .type = SYLVA_P_INT, .flags = RANGE, .def = 0, .min = 0,
     .max = PLUGIN_MAX_THREADS,
     .help = "Worker threads; 0: the run's --threads, else one per processor. The heights do not depend on it."},
    /* --- ground cover and water ----------------------------------------------------------- */
    {.name = "surface", .type = SYLVA_P_ENUM, .def_str = "classes", .choices = surface_choices,
     .help = "classes: grass, dry grass, scree, rock and snow by slope, altitude and humidity; "
             "scene: the terrain's material from the scene everywhere."},
    {.name = "biome", .type = SYLVA_P_ENUM, .def_str = "auto", .choices = biome_choices,
     .help = "The ground's colours, scree and rock slopes and the dryness of its snow line: "
             "temperate meadow, Mediterranean scrub, semi-arid shrubland, prairie, boreal forest or "
             "alpine tundra; auto: by the site's latitude (temperate without a site). Any key "
             "below that the scene gives wins over the biome's."},
    {.name = "water_altitude", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = -100000,
     .max = 100000, .unit = "m",
     .help = "Height of a water surface in metres of the DTM's heights (after z_scale and "
             "z_offset); leave out for no water (or give water_level)."},
    {.name = "water_level", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0, .min = 0, .max = 1,
     .help = "Older form of water_altitude: the normalised altitude y_w of the water surface over "
             "the DTM's height range; 0: no water."},
    {.name = "snow_altitude", .type = SYLVA_P_REAL, .flags = RANGE,
     .def = TERRAIN_IFS_DEFAULT_SNOW_ALTITUDE, .min = -100000, .max = 100000, .unit = "m",
     .help = "Height above which snow lies (on slopes below rock_slope), metres of the DTM's "
             "heights; leave out: the summer snow line at the site's latitude (the Alps' 2800 m "
             "without a site), higher in a dry biome."},
    {.name = "scree_altitude", .type = SYLVA_P_REAL, .flags = RANGE,
     .def = TERRAIN_IFS_DEFAULT_SCREE_ALTITUDE, .min = -100000, .max = 100000, .unit = "m",
     .help = "Height above which grass gives way to scree, metres of the DTM's heights; leave "
             "out: the upper limit of closed alpine grassland, 300 m above the tree line at the "
             "site's latitude (the Alps' 2300 m without a site)."},
    {.name = "snow_line", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0.8, .min = 0, .max = 2,
     .help = "Older form of snow_altitude: a normalised altitude over the DTM's height range "
             "(used only when given)."},
    {.name = "scree_line", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0.6, .min = 0, .max = 2,
     .help = "Older form of scree_altitude: a normalised altitude over the DTM's height range "
             "(used only when given)."},
    {.name = "scree_slope", .type = SYLVA_P_REAL, .flags = RANGE, .def = 30, .min = 0, .max = 90,
     .unit = "deg", .help = "Slope from which the ground is scree; the default is the biome's (30 "
     "temperate, 40 Mediterranean, 38 semi-arid)."},
    {.name = "rock_slope", .type = SYLVA_P_REAL, .flags = RANGE, .def = 42, .min = 0, .max = 90,
     .unit = "deg", .help = "Slope from which the ground is bare rock; the default is the biome's "
     "(42 temperate)."},
    {.name = "humidity_map", .type = SYLVA_P_PATH,
     .help = "Raster of humidity whose pixels tile the terrain's footprint, north up (e.g. the "
             "humidity.png of sylva factors); grass below dry_humidity is dry."},
    {.name = "humidity_band", .type = SYLVA_P_INT, .flags = RANGE, .def = 1, .min = 1,
     .max = 65535, .help = "Band of humidity_map that holds the humidity (1 is the first)."},
    {.name = "humidity_range", .type = SYLVA_P_LIST, .max_len = 2,
     .help = "Raw values of humidity 0 and 1 in humidity_map, mapped linearly; empty: integer "
             "samples over their type's largest value, floating samples as they are."},
    {.name = "dry_humidity", .type = SYLVA_P_REAL, .flags = RANGE, .def = 0.3, .min = 0, .max = 1,
     .help = "Humidity below which grass is dry grass (with humidity_map)."},
    {.name = "grass_albedo", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1,
     .def_list = def_grass, .def_len = 3, .help = "Linear RGB albedo of grass."},
    {.name = "dry_grass_albedo", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1,
     .def_list = def_dry_grass, .def_len = 3, .help = "Linear RGB albedo of dry grass."},
    {.name = "scree_albedo", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1,
     .def_list = def_scree, .def_len = 3, .help = "Linear RGB albedo of scree."},
    {.name = "rock_albedo", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1,
     .def_list = def_rock, .def_len = 3, .help = "Linear RGB albedo of rock."},
    {.name = "snow_albedo", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1,
     .def_list = def_snow, .def_len = 3, .help = "Linear RGB albedo of snow."},
    {.name = "water_albedo", .type = SYLVA_P_VEC3, .flags = RANGE, .min = 0, .max = 1,
     .def_list = def_water, .def_len = 3, .help = "Linear RGB albedo of the water surface."},
};
