/* terrain_mesh.c — tessellating a heightfield (see terrain_mesh.h). */
#include "geometry/terrain_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void terrain_node_vertex(const sylva_heightfield *hf, uint32_t i, uint32_t j, float pos[3],
                         float nrm[3], float uv[2])
{
    uint32_t nx = hf->nx, ny = hf->ny;
    size_t k = (size_t)j * nx + i;
    if (pos) {
        pos[0] = (float)(hf->x0 + i * hf->dx);
        pos[1] = (float)(hf->y0 + j * hf->dy);
        pos[2] = hf->z[k];
    }
    if (nrm) { /* central differences (one-sided at the border) */
        uint32_t i0 = i ? i - 1 : i, i1 = i + 1 < nx ? i + 1 : i;
        uint32_t j0 = j ? j - 1 : j, j1 = j + 1 < ny ? j + 1 : j;
        double dzdx = (hf->z[(size_t)j * nx + i1] - hf->z[(size_t)j * nx + i0]) / ((i1 - i0) * hf->dx);
        double dzdy = (hf->z[(size_t)j1 * nx + i] - hf->z[(size_t)j0 * nx + i]) / ((j1 - j0) * hf->dy);
        double l = sqrt(dzdx * dzdx + dzdy * dzdy + 1.0);
        nrm[0] = (float)(-dzdx / l), nrm[1] = (float)(-dzdy / l), nrm[2] = (float)(1.0 / l);
    }
    if (uv) uv[0] = (float)i / (nx - 1), uv[1] = (float)j / (ny - 1);
}

void terrain_triangle_nodes(const sylva_heightfield *hf, uint32_t t, uint32_t k[3])
{
    uint32_t cell = t / 2, cols = hf->nx - 1;
    uint32_t a = (cell / cols) * hf->nx + cell % cols, b = a + 1, c = a + hf->nx, d = c + 1;
    if (t & 1) k[0] = a, k[1] = d, k[2] = c;
    else k[0] = a, k[1] = b, k[2] = d;
}

int32_t terrain_triangle_material(const sylva_heightfield *hf, uint32_t t, int32_t fallback)
{
    if (!hf->material) return fallback;
    uint32_t cell = t / 2, cols = hf->nx - 1;
    int32_t m = hf->material[(size_t)(cell / cols) * hf->nx + cell % cols];
    return m >= 0 ? m : fallback;
}

mesh *terrain_mesh_build(const sylva_heightfield *hf, int32_t fallback, err_buf *err)
{
    uint32_t nx = hf->nx, ny = hf->ny;
    size_t nv = (size_t)nx * ny, nt = (size_t)(nx - 1) * (ny - 1) * 2;
    float *pos = malloc(nv * 3 * sizeof(float)), *nrm = malloc(nv * 3 * sizeof(float));
    float *uv = malloc(nv * 2 * sizeof(float));
    uint32_t *tri = malloc(nt * 3 * sizeof(uint32_t));
    int32_t *mat = malloc(nt * sizeof(int32_t));
    mesh *m = mesh_new();
    if (!pos || !nrm || !uv || !tri || !mat || !m) {
        err_nomem(err, "out of memory tessellating a %u x %u terrain", nx, ny);
        goto fail;
    }
    for (uint32_t j = 0; j < ny; j++)
        for (uint32_t i = 0; i < nx; i++) {
            size_t k = (size_t)j * nx + i;
            terrain_node_vertex(hf, i, j, pos + k * 3, nrm + k * 3, uv + k * 2);
        }
    for (uint32_t t = 0; t < nt; t++) {
        terrain_triangle_nodes(hf, t, tri + (size_t)t * 3);
        mat[t] = terrain_triangle_material(hf, t, fallback);
    }
    if (mesh_append(m, pos, nrm, uv, (uint32_t)nv, tri, mat, fallback, (uint32_t)nt, err)) goto fail;
    free(pos), free(nrm), free(uv), free(tri), free(mat);
    return m;
fail:
    free(pos), free(nrm), free(uv), free(tri), free(mat);
    mesh_free(m);
    return NULL;
}
