/* water_surface.c — the water rectangle over a terrain (see water_surface.h). */
#include "geometry/water_surface.h"

void water_surface_extent(const sylva_heightfield *hf, double lo[3], double hi[3])
{
    lo[0] = hf->x0, lo[1] = hf->y0, lo[2] = hf->water_level;
    hi[0] = hf->x0 + (hf->nx - 1) * hf->dx, hi[1] = hf->y0 + (hf->ny - 1) * hf->dy, hi[2] = hf->water_level;
}

int water_surface_build(const scene *s, mesh **out, err_buf *err)
{
    *out = NULL;
    const sylva_heightfield *hf = s->terrain;
    if (!hf || !hf->has_water) return 0;
    double lo[3], hi[3];
    water_surface_extent(hf, lo, hi);
    float x0 = (float)lo[0], y0 = (float)lo[1], x1 = (float)hi[0], y1 = (float)hi[1], z = (float)lo[2];
    float pos[12] = {x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z};
    float uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    int32_t water_material = hf->water_material >= 0 ? hf->water_material : s->water_material;
    mesh *m = mesh_new();
    if (!m) return err_nomem(err, "out of memory for the water surface");
    if (mesh_append(m, pos, NULL, uv, 4, tri, NULL, water_material, 2, err)) {
        mesh_free(m);
        return -1;
    }
    *out = m;
    return 0;
}
