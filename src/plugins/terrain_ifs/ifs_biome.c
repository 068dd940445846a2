/* ifs_biome.c — picking a biome and the snow and scree heights of a latitude (ifs_biome.h). */
#include "ifs_biome.h"

#include <math.h>
#include <string.h>

#include "sylva/plugin.h"

#define REFERENCE_LATITUDE 46.0 /* the Alps: the lines of a scene without a site */
#define DRY_SNOW_RAISE 600.0    /* m: the snow line of a dry climate stands this much higher */
#define DRY_SNOW_FLOOR 3000.0   /* m: a dry biome has no snow below this */
#define GRASS_ABOVE_TREES 300.0 /* m: closed alpine grassland ends this far above the tree line */

typedef struct line_point {
    double latitude, height;
} line_point;

/* The regional summer snow line by latitude (m); docs/models/terrain_ifs.md gives the sources. */
static const line_point snow_line[] = {{0, 4800},  {10, 4900}, {20, 5200}, {25, 5300}, {30, 5000},
                                       {35, 4200}, {40, 3500}, {46, 2800}, {50, 2400}, {55, 1900},
                                       {60, 1400}, {65, 900},  {70, 500},  {75, 250},  {80, 0},
                                       {90, 0}};
/* The upper limit of trees by latitude (m). */
static const line_point tree_line[] = {{0, 3900},  {10, 3900}, {20, 4000}, {25, 4000}, {30, 3700},
                                       {35, 3400}, {40, 2800}, {46, 2000}, {50, 1700}, {55, 1300},
                                       {60, 900},  {65, 600},  {70, 200},  {75, 0},    {90, 0}};

static double line_at(const line_point *t, unsigned n, double latitude_deg)
{
    double a = isfinite(latitude_deg) ? fmin(fabs(latitude_deg), 90.0) : REFERENCE_LATITUDE;
    unsigned k = 1;
    while (k + 1 < n && t[k].latitude < a) k++;
    double f = (a - t[k - 1].latitude) / (t[k].latitude - t[k - 1].latitude);
    return t[k - 1].height + f * (t[k].height - t[k - 1].height);
}

double ifs_snow_line(double latitude_deg)
{
    return line_at(snow_line, sizeof snow_line / sizeof snow_line[0], latitude_deg);
}

double ifs_tree_line(double latitude_deg)
{
    return line_at(tree_line, sizeof tree_line / sizeof tree_line[0], latitude_deg);
}

void ifs_biome_heights(ifs_biome b, double latitude_deg, double *snow_z, double *scree_z)
{
    double snow = ifs_snow_line(latitude_deg);
    if (ifs_biome_preset_of(b)->dry) snow = fmax(snow + DRY_SNOW_RAISE, DRY_SNOW_FLOOR);
    *snow_z = snow;
    *scree_z = fmin(ifs_tree_line(latitude_deg) + GRASS_ABOVE_TREES, snow);
}

int ifs_biome_by_name(const char *name)
{
    for (int b = 0; b < IFS_BIOMES; b++)
        if (name && !strcmp(name, ifs_biome_preset_of((ifs_biome)b)->name)) return b;
    return -1;
}

/* The biome of a latitude band alone. */
static ifs_biome by_latitude(double a)
{
    if (a < 30) return IFS_BIOME_SEMI_ARID;
    if (a < 40) return IFS_BIOME_MEDITERRANEAN;
    if (a < 55) return IFS_BIOME_TEMPERATE;
    if (a < 66.5) return IFS_BIOME_BOREAL;
    return IFS_BIOME_ALPINE;
}

/* The biome of the land cover within the latitude's band (a: |latitude|, NaN when unknown):
 * snow, then a dry site (scrub and bare ground below 45 degrees: semi-arid where bare ground
 * shows through, Mediterranean where the scrub closes), then the largest of forest, scrub and
 * open land (grass and fields). */
static ifs_biome by_cover(const ifs_cover_shares *c, double a)
{
    int cold = isfinite(a) && a >= 66.5, boreal = isfinite(a) && a >= 55 && !cold;
    int warm = !isfinite(a) || a < 45;
    if (c->snow >= 0.5 || (cold && c->barren + c->snow >= 0.3)) return IFS_BIOME_ALPINE;
    if (c->barren >= 0.4) return IFS_BIOME_SEMI_ARID;
    if (warm && c->shrub + c->barren >= 0.3)
        return c->barren >= 0.05 ? IFS_BIOME_SEMI_ARID : IFS_BIOME_MEDITERRANEAN;
    double open = c->grass + c->cultivated;
    double largest = fmax(fmax(c->forest, c->shrub), open);
    if (!(largest > 0)) return isfinite(a) ? by_latitude(a) : IFS_BIOME_TEMPERATE;
    if (cold) return IFS_BIOME_ALPINE;
    if (boreal) return IFS_BIOME_BOREAL;
    return largest == open ? IFS_BIOME_PRAIRIE : IFS_BIOME_TEMPERATE;
}

ifs_cover_shares ifs_cover_shares_of(const double *r)
{
    return (ifs_cover_shares){.forest = r[SYLVA_COVER_FOREST], .shrub = r[SYLVA_COVER_SHRUB],
                              .grass = r[SYLVA_COVER_GRASS], .cultivated = r[SYLVA_COVER_CULTIVATED],
                              .barren = r[SYLVA_COVER_BARREN], .snow = r[SYLVA_COVER_SNOW],
                              .water = r[SYLVA_COVER_WATER]};
}

ifs_biome ifs_biome_choose(double latitude_deg, const ifs_cover_shares *shares)
{
    double a = fabs(latitude_deg);
    if (shares) return by_cover(shares, a);
    return isfinite(a) ? by_latitude(a) : IFS_BIOME_TEMPERATE;
}
