/* ztv_raster.h — what a visibility map (zone of theoretical visibility, ZTV) is made of: the
 * output grid, the screening modes, the class of each cell, and the rows of results the tracer
 * (ztv/ztv_trace.h) hands, a block at a time from north to south, to the writers (GeoTIFF,
 * map PNG, summary). Nothing here allocates; the tracer owns every array a block points to and
 * keeps it only for the duration of the call.
 *
 * The grid is north up: cell (i, j) has its centre at local (x0 + i cell, y0 - j cell), row 0 the
 * northernmost; local = map - site origin (docs/sites.md). Its GeoTIFF geotransform is
 * (origin[0] + x0 - cell/2, cell, 0, origin[1] + y0 + cell/2, 0, -cell).
 */
#ifndef SYLVA_ZTV_RASTER_H
#define SYLVA_ZTV_RASTER_H

#include <stdint.h>

/* What stands between a viewpoint and the development. Each of the first three screens with what
 * the one before it does, and more; the canopy mode screens with bare earth and the canopy's
 * surface from the site's canopy heights (ztv/ztv_canopy.h). */
typedef enum ztv_mode {
    ZTV_BARE = 0,        /* bare earth: the terrain (and water surfaces) only */
    ZTV_VEGETATION = 1,  /* the terrain and the plants (alpha-masked leaves let rays through) */
    ZTV_ALL = 2,         /* the terrain, the plants and every object that is not the development */
    ZTV_CANOPY = 3,      /* the terrain and the canopy surface: ground plus the measured canopy height */
    ZTV_MODES = 4
} ztv_mode;

/* What a cell's observer stands in. Only ZTV_OPEN cells are viewpoints; the others carry no
 * count. In bare-earth mode every cell on the terrain is open. */
typedef enum ztv_class {
    ZTV_OPEN = 0,         /* a viewpoint */
    ZTV_UNDER_CROWN = 1,  /* the observer stands under a tree crown (vegetation and all modes), or
                           * under the canopy surface (canopy mode) */
    ZTV_IN_OBJECT = 2,    /* the observer stands inside an object (all mode) */
    ZTV_OUTSIDE = 3,      /* beyond the radius (or off the terrain of a map without one): not computed */
    ZTV_NO_TERRAIN = 4,   /* within the radius but past the terrain's edge: no ground to stand on */
    ZTV_CLASSES = 5
} ztv_class;

/* 1 when a cell of class cls has ground and is within the radius (open, under a crown or
 * inside an object); 0 when nothing was computed there (GeoTIFF nodata). */
static inline int ztv_class_on_ground(uint8_t cls) { return cls < ZTV_OUTSIDE; }

#define ZTV_MAX_DEVELOPMENTS 24u /* developments in one map: bits of a float-exact mask */

/* The kinds of file a map writes (docs/ztv.md, "Outputs"); ztv_info.products holds a set of them. */
enum {
    ZTV_PRODUCT_RASTER = 1,   /* ztv_MODE.tif, ztv_hidden_MODE.tif and ztv_MODE.qml, the GeoTIFFs' styles */
    ZTV_PRODUCT_MAPS = 2,     /* the pages: ztv_*.png with their .pgw, ztv_*.pdf */
    ZTV_PRODUCT_SUMMARY = 4,  /* ztv_summary.csv and ztv_summary.json */
    ZTV_PRODUCT_LAYERS = 8,   /* ztv_layers.gpkg and its styles as .qml files */
    ZTV_PRODUCTS_ALL = 15
};

/* The terrain's edges, in the order of ztv_grid.past_edge. */
enum { ZTV_WEST, ZTV_EAST, ZTV_SOUTH, ZTV_NORTH, ZTV_EDGES };

typedef struct ztv_grid {
    uint32_t nx, ny;         /* cells west to east, north to south */
    double x0, y0;           /* local centre of cell (0, 0), the north-west one */
    double cell;             /* metres */
    double past_edge[ZTV_EDGES]; /* metres the radius reaches past the terrain's west, east, south
                                  * and north edge (0: it stays within); the grid covers the whole
                                  * radius, its cells past the edge ZTV_NO_TERRAIN */
} ztv_grid;

/* One mode's results over a block's cells (rows * nx, row by row). */
typedef struct ztv_layer {
    const uint16_t *visible;      /* targets visible from the cell (0 where not ZTV_OPEN) */
    const float *fraction;        /* visible targets / all targets, 0..1 (0 where not ZTV_OPEN) */
    const uint8_t *cls;           /* a ztv_class */
    const uint32_t *developments; /* bit d set: some target of development d is visible */
} ztv_layer;

/* Grid rows [j0, j0 + rows) of every mode computed. */
typedef struct ztv_block {
    uint32_t j0, rows;
    const float *ground;                /* rows * nx terrain heights at cell centres, local metres
                                        * (map = local + origin[2]); NAN where ZTV_OUTSIDE
                                        * or ZTV_NO_TERRAIN */
    const ztv_layer *layer[ZTV_MODES];  /* NULL for a mode not computed */
} ztv_block;

/* A viewpoint of the study, as the GeoPackage beside the map lists it (ztv/ztv_layers.h). */
typedef struct ztv_viewpoint {
    const char *name;            /* borrowed from the scene file */
    uint32_t number;             /* 1, 2, ...: scene_file_viewpoint_number, as the sheets number it */
    double xy[2];                /* local horizontal position */
    double eye_height;           /* metres above the ground */
    double heading;              /* degrees clockwise from grid north, 0 to 360; NAN: straight up or down */
    double ground;               /* local height of the ground under it; NAN off the terrain */
} ztv_viewpoint;

/* A structure of a development (an object marked development: true, a layout's row), as placed. */
typedef struct ztv_structure {
    const char *name;            /* borrowed from the scene file */
    const char *development;     /* the development it belongs to; borrowed */
    double xy[2];                /* local horizontal position */
    double base, top;            /* local heights of its lowest and highest point */
} ztv_structure;

/* What the writers need to know of the map besides its cells. */
typedef struct ztv_info {
    ztv_grid grid;
    const char *crs_wkt;         /* the site's CRS, or NULL (a scene in local metres) */
    const char *crs_name;        /* its short name, or NULL */
    double origin[3];            /* map coordinates of the local origin (0 without a site) */
    int computed[ZTV_MODES];     /* 1: the blocks carry this mode's layer */
    double observer_height;      /* metres above the ground */
    const char *ground;          /* the ground the sightlines traced, a phrase for the summary
                                    ("the DTM as surveyed: ..."), or NULL */
    double radius;               /* metres from the nearest target; INFINITY: the whole grid */
    int curvature;               /* 1: Earth curvature and refraction applied */
    double refraction;           /* k */
    uint32_t n_targets;
    uint32_t n_developments;
    const char *const *development_names;  /* n_developments */
    const double (*development_xy)[2];     /* n_developments: local position to mark on the map
                                            * (the centre of its targets) */
    const double (*target_xy)[2];          /* n_targets: local horizontal positions */
    const uint32_t *target_development;    /* n_targets: development index */
    const ztv_viewpoint *study_views;      /* n_study_views, the viewpoints the maps mark and the
                                            * GeoPackage lists, in the study's order (may be 0) */
    uint32_t n_study_views;
    const ztv_structure *structures;       /* n_structures (may be 0: targets given by hand) */
    uint32_t n_structures;
    /* for the maps' title block and marks (ztv_map.h); any may be NULL or 0 */
    const char *project;                   /* the scene file's name */
    const char *dtm;                       /* the DTM's file name */
    const char *date;                      /* the day the map is made, "YYYY-MM-DD" */
    const double *target_heights;          /* metres above the ground, n_target_heights */
    uint32_t n_target_heights;
    /* a planting plan's map at a year (`ztv --years`): the output folder of the map made before the
     * plan on the same grid, for the map of what the plan hides (ztv_map_write_planting), and the
     * years since planting; NULL otherwise */
    const char *planting_before;
    double planting_year;
    unsigned products;                     /* ZTV_PRODUCT_* bits: the files written; 0: all of them */
} ztv_info;

#endif
