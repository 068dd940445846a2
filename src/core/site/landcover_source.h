/* landcover_source.h — what a land-cover map is and where it is read onto: the map named by a
 * scene's landcover: section (its form, file, layer and class field, legend and the classes the
 * scene names) and the site grid it is sampled on. Plain values (site/landcover.h reads them).
 *
 * Ownership: a landcover_source points to strings and classes its caller keeps. */
#ifndef SYLVA_LANDCOVER_SOURCE_H
#define SYLVA_LANDCOVER_SOURCE_H

#include <stdint.h>

#include "site/landcover_legend.h"

typedef enum landcover_form { LANDCOVER_RASTER = 1, LANDCOVER_POLYGONS = 2 } landcover_form;

/* A class the scene names: it replaces the legend's class of that code or adds one. */
typedef struct landcover_class_spec {
    int64_t code;
    const char *name;       /* NULL: the legend's name (or "code N") */
    int kind;               /* a land_kind, or -1: the legend's kind (or unknown) */
} landcover_class_spec;

typedef struct landcover_source {
    landcover_form form;
    const char *path;           /* the map file (resolved) */
    const char *layer;          /* polygons: the layer's name; NULL: the first layer */
    const char *class_field;    /* polygons: the attribute holding the class (a code or a name) */
    landcover_legend legend;
    const landcover_class_spec *classes;
    uint32_t n_classes;
} landcover_source;

/* What landcover_check found wrong, so the caller can place the message at that key. */
typedef enum landcover_fault { LANDCOVER_FAULT_FILE = 0, LANDCOVER_FAULT_LAYER, LANDCOVER_FAULT_FIELD } landcover_fault;

/* The grid the map is sampled on: the ground as surveyed, in the site's local frame. */
typedef struct landcover_grid {
    const char *site_wkt;       /* the site's CRS */
    double origin[2];           /* the site origin's map coordinates */
    uint32_t nx, ny;
    double x0, y0, dx, dy;      /* node (i, j) at local (x0 + i dx, y0 + j dy) */
} landcover_grid;

#endif
