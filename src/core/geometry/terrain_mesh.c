/* terrain_mesh.c — tessellating a heightfield (see terrain_mesh.h). */
#include "geometry/terrain_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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
            pos[k * 3] = (float)(hf->x0 + i * hf->dx);
            pos[k * 3 + 1] = (float)(hf->y0 + j * hf->dy);
            pos[k * 3 + 2] = hf->z[k];
            /* central differences (one-sided at the border) */
            uint32_t i0 = i ? i - 1 : i, i1 = i + 1 < nx ? i + 1 : i;
            uint32_t j0 = j ? j - 1 : j, j1 = j + 1 < ny ? j + 1 : j;
            double dzdx = (hf->z[(size_t)j * nx + i1] - hf->z[(size_t)j * nx + i0]) / ((i1 - i0) * hf->dx);
            double dzdy = (hf->z[(size_t)j1 * nx + i] - hf->z[(size_t)j0 * nx + i]) / ((j1 - j0) * hf->dy);
            double l = sqrt(dzdx * dzdx + dzdy * dzdy + 1.0);
            nrm[k * 3] = (float)(-dzdx / l), nrm[k * 3 + 1] = (float)(-dzdy / l), nrm[k * 3 + 2] = (float)(1.0 / l);
            uv[k * 2] = (float)i / (nx - 1), uv[k * 2 + 1] = (float)j / (ny - 1);
        }
    size_t t = 0;
    for (uint32_t j = 0; j + 1 < ny; j++)
        for (uint32_t i = 0; i + 1 < nx; i++) {
            uint32_t a = j * nx + i, b = a + 1, c = a + nx, d = c + 1;
            int32_t ma = hf->material && hf->material[a] >= 0 ? hf->material[a] : fallback;
            uint32_t q[6] = {a, b, d, a, d, c};
            memcpy(tri + t * 3, q, sizeof q);
            mat[t] = mat[t + 1] = ma;
            t += 2;
        }
    if (mesh_append(m, pos, nrm, uv, (uint32_t)nv, tri, mat, fallback, (uint32_t)nt, err)) goto fail;
    free(pos), free(nrm), free(uv), free(tri), free(mat);
    return m;
fail:
    free(pos), free(nrm), free(uv), free(tri), free(mat);
    mesh_free(m);
    return NULL;
}
