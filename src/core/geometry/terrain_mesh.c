/* terrain_mesh.c — tessellating a heightfield and its levels of detail (see terrain_mesh.h). */
#include "geometry/terrain_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

uint32_t terrain_grid_count(const sylva_heightfield *hf)
{
    return 1 + (SYLVA_HAS_FIELD(hf, sylva_heightfield, levels) ? hf->n_levels : 0);
}

terrain_grid terrain_grid_of(const sylva_heightfield *hf, uint32_t g)
{
    terrain_grid t = {.hf = hf, .z = hf->z, .material = hf->material, .nx = hf->nx, .ny = hf->ny,
                      .refine = 1};
    if (g > 0) {
        const sylva_terrain_level *l = &hf->levels[g - 1];
        t.z = l->z, t.material = l->material, t.nx = l->nx, t.ny = l->ny;
        t.i0 = l->i0, t.j0 = l->j0, t.refine = l->refine;
    }
    if (g + 1 < terrain_grid_count(hf)) { /* the next level's window, in this grid's cells */
        const sylva_terrain_level *f = &hf->levels[g];
        t.hole_i0 = (f->i0 - t.i0) * t.refine, t.hole_j0 = (f->j0 - t.j0) * t.refine;
        t.hole_i1 = t.hole_i0 + f->cells_x * t.refine, t.hole_j1 = t.hole_j0 + f->cells_y * t.refine;
    }
    return t;
}

void terrain_node_vertex(const terrain_grid *g, uint32_t i, uint32_t j, float pos[3], float nrm[3],
                         float uv[2])
{
    const sylva_heightfield *hf = g->hf;
    uint32_t nx = g->nx, ny = g->ny;
    size_t k = (size_t)j * nx + i;
    /* in heightfield cells: exact, so a node shared by two grids has one position */
    double ci = g->i0 + (double)i / g->refine, cj = g->j0 + (double)j / g->refine;
    if (pos) {
        pos[0] = (float)(hf->x0 + ci * hf->dx);
        pos[1] = (float)(hf->y0 + cj * hf->dy);
        pos[2] = g->z[k];
    }
    if (nrm) { /* central differences (one-sided at the border) */
        double dx = hf->dx / g->refine, dy = hf->dy / g->refine;
        uint32_t i0 = i ? i - 1 : i, i1 = i + 1 < nx ? i + 1 : i;
        uint32_t j0 = j ? j - 1 : j, j1 = j + 1 < ny ? j + 1 : j;
        double dzdx = (g->z[(size_t)j * nx + i1] - g->z[(size_t)j * nx + i0]) / ((i1 - i0) * dx);
        double dzdy = (g->z[(size_t)j1 * nx + i] - g->z[(size_t)j0 * nx + i]) / ((j1 - j0) * dy);
        double l = sqrt(dzdx * dzdx + dzdy * dzdy + 1.0);
        nrm[0] = (float)(-dzdx / l), nrm[1] = (float)(-dzdy / l), nrm[2] = (float)(1.0 / l);
    }
    if (uv) uv[0] = (float)ci / (hf->nx - 1), uv[1] = (float)cj / (hf->ny - 1);
}

void terrain_triangle_nodes(const terrain_grid *g, uint32_t t, uint32_t k[3])
{
    uint32_t cell = t / 2, cols = g->nx - 1;
    uint32_t a = (cell / cols) * g->nx + cell % cols, b = a + 1, c = a + g->nx, d = c + 1;
    if (t & 1) k[0] = a, k[1] = d, k[2] = c;
    else k[0] = a, k[1] = b, k[2] = d;
}

int32_t terrain_triangle_material(const terrain_grid *g, uint32_t t, int32_t fallback)
{
    if (!g->material) return fallback;
    uint32_t cell = t / 2, cols = g->nx - 1;
    int32_t m = g->material[(size_t)(cell / cols) * g->nx + cell % cols];
    return m >= 0 ? m : fallback;
}

mesh *terrain_mesh_build(const sylva_heightfield *hf, int32_t fallback, err_buf *err)
{
    uint32_t grids = terrain_grid_count(hf);
    uint64_t nv = 0, nt = 0;
    for (uint32_t g = 0; g < grids; g++) {
        terrain_grid t = terrain_grid_of(hf, g);
        nv += (uint64_t)t.nx * t.ny;
        nt += 2 * ((uint64_t)(t.nx - 1) * (t.ny - 1) - (uint64_t)(t.hole_i1 - t.hole_i0) * (t.hole_j1 - t.hole_j0));
    }
    if (nv > UINT32_MAX || nt > UINT32_MAX) {
        err_set(err, "the terrain has %llu vertices and %llu triangles; a mesh holds 2^32 at most",
                (unsigned long long)nv, (unsigned long long)nt);
        return NULL;
    }
    float *pos = malloc(nv * 3 * sizeof(float)), *nrm = malloc(nv * 3 * sizeof(float));
    float *uv = malloc(nv * 2 * sizeof(float));
    uint32_t *tri = malloc(nt * 3 * sizeof(uint32_t));
    int32_t *mat = malloc(nt * sizeof(int32_t));
    mesh *m = mesh_new();
    if (!pos || !nrm || !uv || !tri || !mat || !m) {
        err_nomem(err, "out of memory tessellating a %u x %u terrain", hf->nx, hf->ny);
        goto fail;
    }
    size_t v0 = 0, t = 0;
    for (uint32_t g = 0; g < grids; g++) {
        terrain_grid gr = terrain_grid_of(hf, g);
        for (uint32_t j = 0; j < gr.ny; j++)
            for (uint32_t i = 0; i < gr.nx; i++) {
                size_t k = v0 + (size_t)j * gr.nx + i;
                terrain_node_vertex(&gr, i, j, pos + k * 3, nrm + k * 3, uv + k * 2);
            }
        for (uint32_t j = 0; j + 1 < gr.ny; j++)
            for (uint32_t i = 0; i + 1 < gr.nx; i++) {
                if (!terrain_cell_drawn(&gr, i, j)) continue;
                for (uint32_t half = 0; half < 2; half++, t++) {
                    uint32_t c = terrain_triangle_of_cell(&gr, i, j, half), k[3];
                    terrain_triangle_nodes(&gr, c, k);
                    for (int q = 0; q < 3; q++) tri[t * 3 + q] = (uint32_t)(v0 + k[q]);
                    mat[t] = terrain_triangle_material(&gr, c, fallback);
                }
            }
        v0 += (size_t)gr.nx * gr.ny;
    }
    if (mesh_append(m, pos, nrm, uv, (uint32_t)nv, tri, mat, fallback, (uint32_t)nt, err)) goto fail;
    free(pos), free(nrm), free(uv), free(tri), free(mat);
    return m;
fail:
    free(pos), free(nrm), free(uv), free(tri), free(mat);
    mesh_free(m);
    return NULL;
}
