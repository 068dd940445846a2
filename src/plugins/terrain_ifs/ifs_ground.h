/* ifs_ground.h — the ground rules and colours terrain_ifs classes and hands over by: the
 * scene's keys where it gives them, else its biome's (given, or picked by `biome: auto` from the
 * site's latitude), with the snow and scree heights of the site's climate. */
#ifndef IFS_GROUND_H
#define IFS_GROUND_H

#include "ifs_biome.h"
#include "plugin_params.h"
#include "surface_classes.h"
#include "sylva/plugin.h"

typedef struct ifs_ground {
    ifs_biome biome;
    int biome_auto;            /* 1: picked by `biome: auto` */
    ifs_surface_rules rules;   /* heights in the DTM's metres */
    float albedo[IFS_SURFACE_CLASSES][3];
    sylva_ground_palette palette;
} ifs_ground;

/* The ground for the terrain block read through `params` at latitude_deg (NaN: no site) with
 * the land cover's shares near the site (NULL: none) over a DTM whose
 * heights span [zmin, zmax] (for the older fractions snow_line and scree_line). */
void ifs_ground_resolve(plugin_params *params, double latitude_deg, const ifs_cover_shares *cover,
                        double zmin, double zmax, ifs_ground *out);

/* The biome's name and how it was picked, for the log: "mediterranean (auto, latitude 34.30)". */
void ifs_ground_describe(const ifs_ground *g, double latitude_deg, int by_cover, char *buf, unsigned size);

#endif
