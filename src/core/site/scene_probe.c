/* scene_probe.c — the terrain, water, plants and objects at one point (scene_probe.h). */
#include "site/scene_probe.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/heightfield.h"
#include "site/terrain_extent.h"

static int by_distance(const void *a, const void *b)
{
    const probe_plant *p = a, *q = b;
    if (p->distance != q->distance) return p->distance < q->distance ? -1 : 1;
    return p->instance < q->instance ? -1 : p->instance > q->instance;
}

static int probe_plants(const scene *s, double x, double y, double radius, probe_result *r, err_buf *err)
{
    for (int pass = 0; pass < 2; pass++) { /* count, then fill */
        uint32_t n = 0;
        for (uint32_t i = 0; i < s->n_instances; i++) {
            const xform3x4 *xf = &s->instances[i].xf;
            double dx = xf->m[0][3] - x, dy = xf->m[1][3] - y, d = sqrt(dx * dx + dy * dy);
            if (!(d <= radius)) continue;
            if (pass) {
                const prototype *pt = &s->prototypes[s->instances[i].prototype];
                /* The plant's scale is that of its transform's z column. */
                double sz = sqrt((double)xf->m[0][2] * xf->m[0][2] + (double)xf->m[1][2] * xf->m[1][2] +
                                 (double)xf->m[2][2] * xf->m[2][2]);
                r->plants[n] = (probe_plant){.instance = i, .species = pt->species,
                                             .position = {xf->m[0][3], xf->m[1][3], xf->m[2][3]},
                                             .height = pt->height * sz, .distance = d};
            }
            n++;
        }
        if (!pass) {
            if (!n) return 0;
            if (!(r->plants = malloc((size_t)n * sizeof *r->plants)))
                return err_nomem(err, "out of memory listing %u plants", n);
        }
        r->n_plants = n;
    }
    qsort(r->plants, r->n_plants, sizeof *r->plants, by_distance);
    return 0;
}

/* The height of triangle (a, b, c) above (x, y), or NAN when (x, y) lies outside its outline
 * seen from above (or the triangle stands edge-on to that view). Edges count as inside. */
static double height_above(vec3 a, vec3 b, vec3 c, double x, double y)
{
    double d = ((double)b.y - c.y) * ((double)a.x - c.x) + ((double)c.x - b.x) * ((double)a.y - c.y);
    if (d == 0.0) return NAN;
    double l0 = (((double)b.y - c.y) * (x - c.x) + ((double)c.x - b.x) * (y - c.y)) / d;
    double l1 = (((double)c.y - a.y) * (x - c.x) + ((double)a.x - c.x) * (y - c.y)) / d;
    double l2 = 1.0 - l0 - l1;
    if (l0 < 0.0 || l1 < 0.0 || l2 < 0.0) return NAN;
    return l0 * a.z + l1 * b.z + l2 * c.z;
}

/* Vertex k of m in world space: an object's own mesh is already there; a placed model's mesh
 * goes through the object's transform. */
static vec3 world_vertex(const mesh *m, const xform3x4 *xf, uint32_t k)
{
    const float *p = m->pos + (size_t)k * 3;
    vec3 v = v3(p[0], p[1], p[2]);
    return xf ? xf_point(xf, v) : v;
}

static int probe_objects(const scene *s, double x, double y, probe_result *r, err_buf *err)
{
    if (!s->n_objects) return 0;
    if (!(r->objects = malloc((size_t)s->n_objects * sizeof *r->objects)))
        return err_nomem(err, "out of memory listing %u objects", s->n_objects);
    for (uint32_t o = 0; o < s->n_objects; o++) {
        const xform3x4 *xf;
        const mesh *m = scene_object_mesh(s, o, &xf);
        double top = -INFINITY;
        for (uint32_t t = 0; t < m->nt; t++) {
            const uint32_t *k = m->tri + (size_t)t * 3;
            double z = height_above(world_vertex(m, xf, k[0]), world_vertex(m, xf, k[1]), world_vertex(m, xf, k[2]), x, y);
            if (z > top) top = z;
        }
        if (top > -INFINITY) r->objects[r->n_objects++] = (probe_object){.object = o, .top = top};
    }
    return 0;
}

int scene_probe(const scene *s, double x, double y, double radius, probe_result *r, err_buf *err)
{
    memset(r, 0, sizeof *r);
    r->x = x, r->y = y;
    r->land_class = land_cover_at(s->land_cover, x, y);
    const sylva_heightfield *hf = s->terrain;
    if (!hf) return err_fail(err, ERR_INPUT, "the scene has no terrain to probe; add a 'terrain:' section");
    double n[3];
    if (heightfield_height(hf, x, y, &r->ground) || heightfield_normal(hf, x, y, n)) {
        char where[512];
        terrain_extent_text(s, x, y, where, sizeof where);
        return err_fail(err, ERR_INPUT, "(%.3f, %.3f) lies outside the terrain%s", x, y, where);
    }
    double level = sqrt(n[0] * n[0] + n[1] * n[1]);
    r->slope_deg = atan2(level, n[2]) * 180.0 / M_PI;
    /* The normal leans toward where the ground falls. */
    r->aspect_deg = level > 1e-12 ? atan2(n[0], n[1]) * 180.0 / M_PI : NAN;
    if (r->aspect_deg < 0.0) r->aspect_deg += 360.0;
    if (hf->has_water && r->ground < hf->water_level) {
        r->water = 1;
        r->water_level = hf->water_level;
        r->water_depth = hf->water_level - r->ground;
    }
    return probe_plants(s, x, y, radius, r, err) || probe_objects(s, x, y, r, err) ? -1 : 0;
}

void probe_result_free(probe_result *r)
{
    free(r->plants);
    free(r->objects);
    r->plants = NULL, r->objects = NULL;
    r->n_plants = r->n_objects = 0;
}
