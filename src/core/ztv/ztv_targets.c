/* ztv_targets.c — the targets of a visibility map: given by hand, above the development
 * objects' footprints, or sampled on their surfaces. */
#include "ztv/ztv_targets.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/heightfield.h"
#include "scene_file/scene_file.h"
#include "util/rng.h"

int ztv_ground(const scene *s, double x, double y, double *z)
{
    if (!s->terrain || heightfield_surface_height(s->terrain, x, y, z)) return -1;
    if (s->terrain->has_water && *z < s->terrain->water_level) *z = s->terrain->water_level;
    return 0;
}

int ztv_within_radius(const ztv_targets *t, double radius, double x, double y)
{
    if (!isfinite(radius)) return 1;
    double r2 = radius * radius;
    for (uint32_t k = 0; k < t->n; k++) {
        double dx = t->p[k][0] - x, dy = t->p[k][1] - y;
        if (dx * dx + dy * dy <= r2) return 1;
    }
    return 0;
}

static int reserve(ztv_targets *t, uint64_t n, err_buf *err)
{
    if (n > ZTV_MAX_TARGETS)
        return err_set(err, "the map would have %llu targets; at most %u (fewer samples, heights or targets)",
                       (unsigned long long)n, ZTV_MAX_TARGETS);
    t->p = calloc(n ? n : 1, sizeof *t->p);
    t->development = calloc(n ? n : 1, sizeof *t->development);
    if (!t->p || !t->development) return err_nomem(err, "out of memory for %llu targets", (unsigned long long)n);
    return 0;
}

static void add(ztv_targets *t, double x, double y, double z, uint32_t development)
{
    t->p[t->n][0] = x, t->p[t->n][1] = y, t->p[t->n][2] = z;
    t->development[t->n++] = development;
}

static int from_given(ztv_targets *t, const scene_file *sf, const scene *s, err_buf *err)
{
    const ztv_settings *z = &sf->ztv;
    if (reserve(t, z->n_targets, err)) return -1;
    for (uint32_t i = 0; i < z->n_targets; i++) {
        const ztv_target_spec *g = &z->targets[i];
        double ground = 0;
        if (!g->has_height && ztv_ground(s, g->position[0], g->position[1], &ground)) {
            err_set(err, "ztv.targets[%u] stands at local (%.1f, %.1f), off the terrain; a height above "
                         "ground needs the terrain under it", i, g->position[0], g->position[1]);
            return err_locate(err, sf->path, g->line, g->column);
        }
        add(t, g->position[0], g->position[1], g->has_height ? g->position[2] : ground + g->above_ground,
            g->development);
    }
    return 0;
}

/* One target per height above the base of each development entry as placed (the z of its lowest
 * point: on a slope, the lowest ground under its footprint it was snapped to), at its position:
 * the targets stand on the object whatever the ground does under it. */
static int from_heights(ztv_targets *t, const scene_file *sf, const scene *s, err_buf *err)
{
    const ztv_settings *z = &sf->ztv;
    uint64_t placements = 0;
    for (uint32_t o = 0; o < sf->n_objects; o++) placements += sf->objects[o].development != 0;
    if (reserve(t, placements * z->n_target_heights, err)) return -1;
    for (uint32_t o = 0; o < s->n_objects; o++) {
        const object *ob = &s->objects[o];
        if (!ob->development || (o > 0 && s->objects[o - 1].entry == ob->entry)) continue; /* a group's parts */
        const object_spec *entry = &sf->objects[ob->entry];
        for (uint32_t h = 0; h < z->n_target_heights; h++)
            add(t, entry->position[0], entry->position[1], ob->base + z->target_heights[h], (uint32_t)ob->development - 1);
    }
    return 0;
}

/* Twice the area of triangle k of m, in world space (xf applied when not NULL). */
static double triangle_area2(const mesh *m, const xform3x4 *xf, uint32_t k, vec3 v[3])
{
    for (int c = 0; c < 3; c++) {
        const float *p = &m->pos[3 * m->tri[3 * k + c]];
        v[c] = v3(p[0], p[1], p[2]);
        if (xf) v[c] = xf_point(xf, v[c]);
    }
    vec3 e1 = v3_sub(v[1], v[0]), e2 = v3_sub(v[2], v[0]);
    double cx = (double)e1.y * e2.z - (double)e1.z * e2.y, cy = (double)e1.z * e2.x - (double)e1.x * e2.z,
           cz = (double)e1.x * e2.y - (double)e1.y * e2.x;
    return sqrt(cx * cx + cy * cy + cz * cz);
}

/* `samples` points on object o's surface, spread by area: a triangle drawn in proportion to its
 * area, a point uniform on it; the random numbers keyed by (seed, object, sample). */
static int sample_object(ztv_targets *t, const scene *s, uint32_t o, uint32_t samples, uint64_t seed, err_buf *err)
{
    const xform3x4 *xf;
    const mesh *m = scene_object_mesh(s, o, &xf);
    if (!m || !m->nt) return 0;
    double *cum = malloc((size_t)m->nt * sizeof *cum); /* running sum of twice the areas; freed below */
    if (!cum) return err_nomem(err, "out of memory sampling object '%s'", s->objects[o].name);
    double total = 0;
    vec3 v[3];
    for (uint32_t k = 0; k < m->nt; k++) cum[k] = total += triangle_area2(m, xf, k, v);
    for (uint32_t i = 0; i < samples && total > 0; i++) {
        sylva_rng r;
        rng_stream(&r, seed, "ztv target", ((uint64_t)o << 32) | i);
        double pick = rng_next_double(&r) * total;
        uint32_t lo = 0, hi = m->nt - 1;
        while (lo < hi) {
            uint32_t mid = lo + (hi - lo) / 2;
            if (cum[mid] > pick) hi = mid; else lo = mid + 1;
        }
        triangle_area2(m, xf, lo, v);
        double a = rng_next_double(&r), b = rng_next_double(&r);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        add(t, v[0].x + a * (v[1].x - v[0].x) + b * (v[2].x - v[0].x),
            v[0].y + a * (v[1].y - v[0].y) + b * (v[2].y - v[0].y),
            v[0].z + a * (v[1].z - v[0].z) + b * (v[2].z - v[0].z), (uint32_t)s->objects[o].development - 1);
    }
    free(cum);
    return 0;
}

static int from_samples(ztv_targets *t, const scene_file *sf, const scene *s, uint64_t seed, err_buf *err)
{
    uint64_t n = 0;
    for (uint32_t o = 0; o < s->n_objects; o++) n += s->objects[o].development ? sf->ztv.samples : 0;
    if (reserve(t, n, err)) return -1;
    for (uint32_t o = 0; o < s->n_objects; o++)
        if (s->objects[o].development && sample_object(t, s, o, sf->ztv.samples, seed, err)) return -1;
    return 0;
}

/* Keeps the developments that have targets, renumbered in order, with their centres. */
static int gather_developments(ztv_targets *t, const scene_file *sf, err_buf *err)
{
    uint32_t map[SCENE_MAX_DEVELOPMENTS], count[SCENE_MAX_DEVELOPMENTS] = {0};
    for (uint32_t i = 0; i < t->n; i++) count[t->development[i]]++;
    t->names = calloc(SCENE_MAX_DEVELOPMENTS, sizeof *t->names);
    t->centre = calloc(SCENE_MAX_DEVELOPMENTS, sizeof *t->centre);
    t->xy = calloc(t->n ? t->n : 1, sizeof *t->xy);
    if (!t->names || !t->centre || !t->xy) return err_nomem(err, "out of memory for the targets");
    for (uint32_t d = 0; d < sf->n_developments; d++)
        if (count[d]) map[d] = t->n_developments, t->names[t->n_developments++] = sf->developments[d];
    for (uint32_t i = 0; i < t->n; i++) {
        uint32_t old = t->development[i], d = t->development[i] = map[old];
        t->xy[i][0] = t->p[i][0], t->xy[i][1] = t->p[i][1];
        t->centre[d][0] += t->p[i][0] / count[old], t->centre[d][1] += t->p[i][1] / count[old];
    }
    return 0;
}

int ztv_targets_build(ztv_targets *t, const scene_file *sf, const scene *s, uint64_t seed, err_buf *err)
{
    memset(t, 0, sizeof *t);
    const ztv_settings *z = &sf->ztv;
    int rc;
    if (z->n_targets) t->source = ZTV_TARGETS_GIVEN, rc = from_given(t, sf, s, err);
    else if (z->n_target_heights) t->source = ZTV_TARGETS_HEIGHTS, rc = from_heights(t, sf, s, err);
    else t->source = ZTV_TARGETS_SAMPLED, rc = from_samples(t, sf, s, seed, err);
    if (!rc && !t->n)
        rc = err_set(err, "nothing to look for: no object is marked 'development: true' and ztv: gives no "
                          "targets (docs/ztv.md)");
    if (!rc) rc = gather_developments(t, sf, err);
    if (rc) ztv_targets_free(t);
    return rc;
}

void ztv_targets_free(ztv_targets *t)
{
    free(t->p), free(t->xy), free(t->development), free(t->names), free(t->centre);
    memset(t, 0, sizeof *t);
}
