/* scene_ground.c — heights above ground against the built terrain (scene_ground.h), measured
 * from the surface as it is drawn (the triangulated heightfield), so a camera 1.6 m above
 * ground stands 1.6 m above the rendered ground. */
#include "scene_build/scene_ground.h"

#include <math.h>

#include "scene/heightfield.h"

int scene_ground_point(const scene *s, const scene_file *sf, const char *what, const ground_height *g,
                       double p[3], err_buf *err)
{
    if (!g->given) return 0;
    double z;
    if (s->terrain && !heightfield_surface_height(s->terrain, p[0], p[1], &z)) {
        p[2] = z + g->above;
        return 0;
    }
    const sylva_heightfield *t = s->terrain;
    if (!t)
        return err_at(err, ERR_INPUT, sf->path, g->line, g->column,
                      "%s stands on or above the ground, but the scene has no terrain; give its "
                      "height instead", what);
    const double *o = sf->site.origin;
    if (sf->site.crs_wkt)
        return err_at(err, ERR_INPUT, sf->path, g->line, g->column,
                      "%s (easting %.2f, northing %.2f) lies outside the terrain (easting %.2f to "
                      "%.2f, northing %.2f to %.2f); height_above_ground needs ground under it",
                      what, p[0] + o[0], p[1] + o[1], t->x0 + o[0], t->x0 + (t->nx - 1) * t->dx + o[0],
                      t->y0 + o[1], t->y0 + (t->ny - 1) * t->dy + o[1]);
    return err_at(err, ERR_INPUT, sf->path, g->line, g->column,
                  "%s (%.2f, %.2f) lies outside the terrain (x %.2f to %.2f, y %.2f to %.2f); "
                  "height_above_ground needs ground under it",
                  what, p[0], p[1], t->x0, t->x0 + (t->nx - 1) * t->dx, t->y0, t->y0 + (t->ny - 1) * t->dy);
}

int scene_ground_camera(scene *s, const scene_file *sf, err_buf *err)
{
    camera_settings *c = &s->camera;
    if (!c->eye_ground.given && !c->look_at_ground.given) return 0;
    if (scene_ground_point(s, sf, "the camera 'position'", &c->eye_ground, c->position, err)) return -1;
    if (!c->has_look_at) return 0;
    if (scene_ground_point(s, sf, "the camera's 'look_at'", &c->look_at_ground, c->look_at, err)) return -1;
    double d[3] = {c->look_at[0] - c->position[0], c->look_at[1] - c->position[1],
                   c->look_at[2] - c->position[2]};
    double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double ul = sqrt(c->up[0] * c->up[0] + c->up[1] * c->up[1] + c->up[2] * c->up[2]);
    double cr[3] = {d[1] * c->up[2] - d[2] * c->up[1], d[2] * c->up[0] - d[0] * c->up[2],
                    d[0] * c->up[1] - d[1] * c->up[0]};
    const ground_height *at = c->look_at_ground.given ? &c->look_at_ground : &c->eye_ground;
    if (!(l > 0.0) || !isfinite(l))
        return err_at(err, ERR_INPUT, sf->path, at->line, at->column,
                      "the camera stands at its 'look_at' once placed above the ground; give "
                      "another 'look_at' or height");
    if (sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]) < 1e-9 * l * ul)
        return err_at(err, ERR_INPUT, sf->path, at->line, at->column,
                      "once placed above the ground, the camera looks along 'up'; give another "
                      "'up' or turn the view");
    for (int k = 0; k < 3; k++) c->direction[k] = d[k] / l;
    return 0;
}
