/* cutout.c — cut-out triangles, the alpha test at a point, and a mesh's split (see cutout.h). */
#include "geometry/cutout.h"

#include <stdlib.h>
#include <string.h>

#include "geometry/texture_lookup.h"

int cutout_triangle(const scene *s, const mesh *m, uint32_t t)
{
    return cutout_material(s, &s->materials[scene_triangle_material(s, m, t)]);
}

int cutout_point_kept(const scene *s, const mesh *m, uint32_t t, float bu, float bv)
{
    const material *mt = &s->materials[scene_triangle_material(s, m, t)];
    const uint32_t *k = m->tri + (size_t)t * 3;
    float w = 1.0f - bu - bv;
    float u = w * m->uv[k[0] * 2] + bu * m->uv[k[1] * 2] + bv * m->uv[k[2] * 2];
    float v = w * m->uv[k[0] * 2 + 1] + bu * m->uv[k[1] * 2 + 1] + bv * m->uv[k[2] * 2 + 1];
    return cutout_texel_kept(texture_texel(&s->textures[mt->texture], u, v)[3]);
}

int cutout_part_build(const scene *s, const mesh *m, int cutouts, cutout_part *p, err_buf *err)
{
    memset(p, 0, sizeof *p);
    uint32_t n = 0;
    for (uint32_t t = 0; t < m->nt; t++) n += cutout_triangle(s, m, t) == cutouts;
    if (!n) return 0;
    p->tri = malloc((size_t)n * 3 * sizeof *p->tri);
    p->to_mesh = malloc((size_t)n * sizeof *p->to_mesh);
    if (!p->tri || !p->to_mesh) {
        cutout_part_free(p);
        return err_nomem(err, "out of memory splitting a mesh of %u triangles into opaque and cut-out parts", m->nt);
    }
    for (uint32_t t = 0; t < m->nt; t++)
        if (cutout_triangle(s, m, t) == cutouts) {
            memcpy(p->tri + (size_t)p->n * 3, m->tri + (size_t)t * 3, 3 * sizeof *p->tri);
            p->to_mesh[p->n++] = t;
        }
    return 0;
}

void cutout_part_free(cutout_part *p)
{
    free(p->tri);
    free(p->to_mesh);
    memset(p, 0, sizeof *p);
}
