/* lsys_silhouette.c — segments onto the silhouette raster. */
#include "lsys_silhouette.h"

static int raster_segment(void *ctx, const lsys_segment *s)
{
    box_raster *r = ctx;
    box_raster_line(r, s->p0[0], s->p0[2], s->p1[0], s->p1[2], s->radius);
    return 0;
}

lsys_sink lsys_silhouette_sink(box_raster *r)
{
    return (lsys_sink){.ctx = r, .segment = raster_segment};
}
