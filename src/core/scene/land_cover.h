/* land_cover.h — the land cover of a site as the scene holds it: a class per node of the ground
 * as surveyed (scene.surveyed), and the table of those classes (the map's code, a name and a
 * kind sylva understands). Built once from a land-cover map (site/landcover.h); read by the probe
 * and, later, by what grows on the ground.
 *
 * Ownership: a land_cover owns its node array, its class table and the strings in it;
 * land_cover_free releases them all. */
#ifndef SYLVA_LAND_COVER_H
#define SYLVA_LAND_COVER_H

#include <stdint.h>

/* The kinds of ground sylva tells apart. A map whose legend says only "forest" (no leaf habit)
 * or "wetland" (no woody or herbaceous) gets the broad kind. Order fixed: land_kind_names. */
typedef enum land_kind {
    LAND_UNKNOWN = 0,
    LAND_WATER,
    LAND_SNOW_ICE,
    LAND_DEVELOPED,
    LAND_BARREN,
    LAND_FOREST,
    LAND_FOREST_DECIDUOUS,
    LAND_FOREST_EVERGREEN,
    LAND_FOREST_MIXED,
    LAND_SHRUB,
    LAND_GRASS,
    LAND_CULTIVATED,
    LAND_WETLAND,
    LAND_WETLAND_WOODY,
    LAND_WETLAND_HERBACEOUS,
    LAND_KIND_COUNT
} land_kind;

/* "unknown", "water", "snow_ice", ... in land_kind order; NULL-terminated. */
extern const char *const land_kind_names[];
/* The broad kind: every forest_* is forest, every wetland_* wetland, the others themselves. */
land_kind land_kind_broad(land_kind k);

#define LAND_COVER_NONE UINT16_MAX /* a node the map does not cover (no data) */
#define LAND_COVER_MAX_CLASSES 4096u

typedef struct land_class {
    int64_t code;      /* the map's code (or the number given to a class name) */
    char *name;        /* owned */
    land_kind kind;
    uint64_t nodes;    /* nodes of the grid in this class */
} land_class;

typedef struct land_cover {
    uint32_t nx, ny;         /* the grid of scene.surveyed: node (i, j) at (x0 + i dx, y0 + j dy) */
    double x0, y0, dx, dy;
    uint16_t *node_class;    /* nx * ny, row j = 0 south: an index into classes, or
                                LAND_COVER_NONE; owned */
    land_class *classes;     /* owned */
    uint32_t n_classes;
    uint64_t no_data;        /* nodes off the map or on its no-data cells */
    char *source;            /* the map's file name, for messages; owned */
    char *legend;            /* the legend used ("nlcd2011", "corine", "names", "none"); owned */
} land_cover;

void land_cover_free(land_cover *lc); /* accepts NULL */

/* The class at the node nearest (x, y) (local metres): an index into classes, or -1 where the
 * map has no data or (x, y) lies off the grid by more than half a spacing. */
int32_t land_cover_at(const land_cover *lc, double x, double y);

/* The share of the ground cover's full density (grass and herb tufts) that the class at (x, y)
 * holds: none on water and snow, a few tufts on barren and built land, about a third under
 * shrubs, half on a forest floor, all of it on grass, fields and wetland, and where the map has
 * no class (1) or there is no map (lc NULL). */
double land_cover_herb_share(const land_cover *lc, double x, double y);

/* The bare ground the land cover shows at (x, y): the least share of rock, and of bare soil in
 * what the rock leaves, that the ground has there (docs/models/ground.md, "Land cover"): barren
 * land mostly rock and soil, built land and shrubland much bare soil, the other kinds none. Blended
 * bilinearly between the nodes, so continuous; 0 and 0 without a map (lc NULL) or off it. */
void land_cover_bare_ground(const land_cover *lc, double x, double y, double *rock, double *soil);

#endif
