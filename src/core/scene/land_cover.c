/* land_cover.c — the kinds' names and the lookup of a node's class (land_cover.h). */
#include "scene/land_cover.h"

#include <math.h>
#include <stdlib.h>

const char *const land_kind_names[] = {
    "unknown", "water", "snow_ice", "developed", "barren", "forest", "forest_deciduous",
    "forest_evergreen", "forest_mixed", "shrub", "grass", "cultivated", "wetland", "wetland_woody",
    "wetland_herbaceous", NULL};

land_kind land_kind_broad(land_kind k)
{
    if (k >= LAND_FOREST && k <= LAND_FOREST_MIXED) return LAND_FOREST;
    if (k >= LAND_WETLAND && k <= LAND_WETLAND_HERBACEOUS) return LAND_WETLAND;
    return k;
}

void land_cover_free(land_cover *lc)
{
    if (!lc) return;
    for (uint32_t c = 0; c < lc->n_classes; c++) free(lc->classes[c].name);
    free(lc->classes);
    free(lc->node_class);
    free(lc->source);
    free(lc->legend);
    free(lc);
}

int32_t land_cover_at(const land_cover *lc, double x, double y)
{
    if (!lc || !lc->node_class) return -1;
    double fi = round((x - lc->x0) / lc->dx), fj = round((y - lc->y0) / lc->dy);
    if (!(fi >= 0 && fj >= 0 && fi < lc->nx && fj < lc->ny)) return -1;
    uint16_t c = lc->node_class[(size_t)fj * lc->nx + (size_t)fi];
    return c == LAND_COVER_NONE ? -1 : (int32_t)c;
}

double land_cover_herb_share(const land_cover *lc, double x, double y)
{
    int32_t c = land_cover_at(lc, x, y);
    if (c < 0) return 1;
    switch (land_kind_broad(lc->classes[c].kind)) {
    case LAND_WATER:
    case LAND_SNOW_ICE: return 0;
    case LAND_BARREN: return 0.05;
    case LAND_DEVELOPED: return 0.15;
    case LAND_SHRUB: return 0.35;
    case LAND_FOREST: return 0.5;
    default: return 1;
    }
}
