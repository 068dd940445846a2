/* scene_view.c — the steps of a scene drawn from its camera (scene_view.h). */
#include "geometry/scene_view.h"

#include <stdio.h>

#include "geometry/ground_cover_place.h"

int scene_view_prepare(scene *s, const ground_cover_settings *gc, const scene_view *v, phase_times *times, err_buf *err)
{
    if (!v->picture) return 0;
    uint32_t width = v->width, height = v->height;
    if (!width || !height) width = s->image.width, height = s->image.height;
    ground_cover_report rep;
    phase_mark t0 = phase_start();
    if (ground_cover_add(s, gc, width, height, v->threads, &rep, err)) return err_default(err, ERR_INTERNAL);
    phase_stop(times, PHASE_GROUND_COVER, t0);
    if (!v->quiet && rep.instances)
        fprintf(stderr, "ground cover: %u tufts within %.0f m (a blade spans a pixel at %.0f m)%s\n", rep.instances,
                rep.radius, rep.pixel_radius, rep.capped ? ", the radius shrunk to max_instances" : "");
    return 0;
}
