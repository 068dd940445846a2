/* ztv_features.c — the viewpoints and structures the GeoPackage beside a map lists
 * (ztv_features.h). */
#include "ztv/ztv_features.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene_file/scene_file.h"
#include "ztv/ztv_targets.h"

/* Degrees clockwise from grid north of the horizontal part of (dx, dy); NAN when there is none. */
static double compass(double dx, double dy)
{
    if (hypot(dx, dy) < 1e-12) return NAN;
    double h = atan2(dx, dy) * 180.0 / M_PI;
    return h < 0 ? h + 360.0 : h;
}

static ztv_viewpoint viewpoint_of(const scene_viewpoint *v, uint32_t number, const scene *s)
{
    const camera_settings *c = &v->camera;
    ztv_viewpoint out = {.name = v->name, .number = number, .xy = {c->position[0], c->position[1]}};
    out.heading = c->has_look_at ? compass(c->look_at[0] - c->position[0], c->look_at[1] - c->position[1])
                                 : compass(c->direction[0], c->direction[1]);
    double ground;
    out.ground = ztv_ground(s, out.xy[0], out.xy[1], &ground) ? NAN : ground;
    out.eye_height = c->eye_ground.given ? c->eye_ground.above : c->position[2] - out.ground;
    return out;
}

static int gather_viewpoints(ztv_features *f, const scene_file *sf, const scene *s,
                             const scene_viewpoint *const *views, uint32_t n_views, err_buf *err)
{
    uint32_t n = views ? n_views : sf->n_viewpoints + sf->study.n_points;
    f->viewpoints = calloc(n ? n : 1, sizeof *f->viewpoints);
    if (!f->viewpoints) return err_nomem(err, "out of memory for %u viewpoints of the map", n);
    for (uint32_t i = 0; i < n; i++) {
        const scene_viewpoint *v = views ? views[i]
                                 : i < sf->n_viewpoints ? &sf->viewpoints[i] : &sf->study.points[i - sf->n_viewpoints];
        f->viewpoints[f->n_viewpoints++] = viewpoint_of(v, scene_file_viewpoint_number(sf, v), s);
    }
    return 0;
}

/* The highest point of object o (its own mesh, or its model's placed by its transform). */
static double object_top(const scene *s, const object *o)
{
    const mesh *m = o->mesh ? o->mesh : o->model >= 0 ? s->models[o->model].mesh : NULL;
    double top = -INFINITY;
    for (uint32_t k = 0; m && k < m->nv; k++) {
        vec3 p = v3(m->pos[3 * k], m->pos[3 * k + 1], m->pos[3 * k + 2]);
        if (!o->mesh) p = xf_point(&o->xf, p);
        top = fmax(top, p.z);
    }
    return top;
}

/* One structure per objects: entry marked development (a group's parts are one structure). */
static int gather_structures(ztv_features *f, const scene_file *sf, const scene *s, err_buf *err)
{
    f->structures = calloc(s->n_objects ? s->n_objects : 1, sizeof *f->structures);
    if (!f->structures) return err_nomem(err, "out of memory for %u structures of the map", s->n_objects);
    for (uint32_t k = 0; k < s->n_objects; k++) {
        const object *o = &s->objects[k];
        if (!o->development || o->entry >= sf->n_objects) continue;
        double top = object_top(s, o);
        if (k > 0 && s->objects[k - 1].development && s->objects[k - 1].entry == o->entry && f->n_structures) {
            ztv_structure *last = &f->structures[f->n_structures - 1];
            last->top = fmax(last->top, top);
            continue;
        }
        const object_spec *entry = &sf->objects[o->entry];
        uint32_t d = (uint32_t)o->development - 1;
        f->structures[f->n_structures++] = (ztv_structure){
            .name = entry->name, .development = d < sf->n_developments ? sf->developments[d] : NULL,
            .xy = {entry->position[0], entry->position[1]}, .base = o->base, .top = top};
    }
    return 0;
}

int ztv_features_gather(ztv_features *f, const scene_file *sf, const scene *s, const scene_viewpoint *const *views,
                        uint32_t n_views, err_buf *err)
{
    memset(f, 0, sizeof *f);
    if (gather_viewpoints(f, sf, s, views, n_views, err) || gather_structures(f, sf, s, err)) {
        ztv_features_free(f);
        return -1;
    }
    return 0;
}

void ztv_features_free(ztv_features *f)
{
    free(f->viewpoints), free(f->structures);
    memset(f, 0, sizeof *f);
}
