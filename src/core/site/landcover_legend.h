/* landcover_legend.h — the legends sylva ships for land-cover maps (NLCD 2011 and the CORINE
 * Land Cover raster's grid codes), and the reading of a class name ("Evergreen Forest",
 * "Shrubland") as a kind. A legend gives each code of a map a name and a land_kind
 * (scene/land_cover.h); codes a map uses as no data are marked so.
 *
 * Tables are static const data; nothing here allocates. */
#ifndef SYLVA_LANDCOVER_LEGEND_H
#define SYLVA_LANDCOVER_LEGEND_H

#include <stdint.h>

#include "scene/land_cover.h"

/* The legends a landcover: section may name; LEGEND_NONE is what `auto` falls back to when no
 * shipped legend fits (every code then unknown unless `classes:` names it). */
typedef enum landcover_legend {
    LEGEND_AUTO = 0,
    LEGEND_NLCD2011,
    LEGEND_CORINE,
    LEGEND_NAMES,
    LEGEND_NONE
} landcover_legend;

/* "auto", "nlcd2011", "corine", "names" (the choices of the landcover: legend key, in enum
 * order), NULL-terminated. */
extern const char *const landcover_legend_choices[];
/* The name of any legend, "none" included. */
const char *landcover_legend_name(landcover_legend l);

typedef struct legend_class {
    int64_t code;
    const char *name;
    land_kind kind;
    int no_data;       /* 1: the map's way of saying "no data here" (CORINE 48 and 255) */
} legend_class;

/* The class of `code` in the shipped legend l (LEGEND_NLCD2011 or LEGEND_CORINE), or NULL. */
const legend_class *landcover_legend_class(landcover_legend l, int64_t code);

/* 1 when every one of the n codes is a class (or a no-data code) of legend l. */
int landcover_legend_fits(landcover_legend l, const int64_t *codes, uint32_t n);

/* The kind a class name says, by case-insensitive keywords ("deciduous", "evergreen" or
 * "conifer", "mixed", "forest", "shrub", "grass" or "herbaceous", "water", "snow" or "ice",
 * "developed" or "urban", "barren" or "rock", "cultivated" or "crop" or "pasture", "wetland"
 * or "marsh"); LAND_UNKNOWN when none is found. *no_data is set to 1 for "NA", "no data",
 * "nodata", "unclassified" and an empty name. */
land_kind landcover_kind_of_name(const char *name, int *no_data);

#endif
