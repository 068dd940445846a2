/* canopy.c — the canopy's lookup by position (canopy.h). */
#include "scene/canopy.h"

#include <math.h>
#include <stdlib.h>

void canopy_free(canopy *c)
{
    if (!c) return;
    free(c->height);
    free(c->source);
    free(c);
}

double canopy_height_at(const canopy *c, double x, double y)
{
    if (!c || !c->height) return NAN;
    double fi = round((x - c->x0) / c->dx), fj = round((y - c->y0) / c->dy);
    if (!(fi >= 0 && fj >= 0 && fi < c->nx && fj < c->ny)) return NAN;
    return c->height[(size_t)fj * c->nx + (size_t)fi];
}
