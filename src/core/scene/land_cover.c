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

/* The bare ground of a kind: its rock share, and its soil share of what the rock leaves. */
static void kind_bare_ground(land_kind k, double *rock, double *soil)
{
    *rock = *soil = 0;
    switch (land_kind_broad(k)) {
    case LAND_BARREN: *rock = 0.6, *soil = 0.85; break;
    case LAND_DEVELOPED: *soil = 0.6; break;
    case LAND_SHRUB: *soil = 0.6; break;
    default: break;
    }
}

void land_cover_bare_ground(const land_cover *lc, double x, double y, double *rock, double *soil)
{
    *rock = *soil = 0;
    if (!lc || !lc->node_class || lc->nx < 2 || lc->ny < 2) return;
    double fx = (x - lc->x0) / lc->dx, fy = (y - lc->y0) / lc->dy;
    fx = fx < 0 ? 0 : fx > lc->nx - 1 ? lc->nx - 1 : fx;
    fy = fy < 0 ? 0 : fy > lc->ny - 1 ? lc->ny - 1 : fy;
    uint32_t i = (uint32_t)fx < lc->nx - 1 ? (uint32_t)fx : lc->nx - 2;
    uint32_t j = (uint32_t)fy < lc->ny - 1 ? (uint32_t)fy : lc->ny - 2;
    double u = fx - i, v = fy - j;
    for (int c = 0; c < 4; c++) {
        uint16_t k = lc->node_class[(size_t)(j + c / 2) * lc->nx + i + c % 2];
        double r = 0, s = 0, b = (c % 2 ? u : 1 - u) * (c / 2 ? v : 1 - v);
        if (k != LAND_COVER_NONE) kind_bare_ground(lc->classes[k].kind, &r, &s);
        *rock += b * r, *soil += b * s;
    }
}
