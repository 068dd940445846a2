/* terrain_apron.c — the flat apron beyond the terrain's edge (see terrain_apron.h). */
#include "geometry/terrain_apron.h"

#include <math.h>
#include <stdlib.h>

#include "geometry/terrain_mesh.h"

double terrain_apron_reach(const sylva_heightfield *hf, const double eye[3])
{
    double lowest = INFINITY;
    for (uint32_t i = 0; i < hf->nx; i++)
        lowest = fmin(lowest, fmin(hf->z[i], hf->z[(size_t)(hf->ny - 1) * hf->nx + i]));
    for (uint32_t j = 0; j < hf->ny; j++)
        lowest = fmin(lowest, fmin(hf->z[(size_t)j * hf->nx], hf->z[(size_t)j * hf->nx + hf->nx - 1]));
    double h = isfinite(eye[2]) ? eye[2] - lowest : 0.0;
    double size = fmax((hf->nx - 1) * hf->dx, (hf->ny - 1) * hf->dy);
    double reach = fmax(1e4 * fmax(h, 1.0), 10.0 * size);
    return fmin(reach, 5e7);
}

/* The material most of the edge cells have (the first of them on a tie; up to 64 different
 * ones are counted, a later one is not). */
static int32_t edge_material(const terrain_grid *g, int32_t fallback)
{
    int32_t id[64];
    uint64_t count[64] = {0};
    uint32_t n = 0, cx = g->nx - 1, cy = g->ny - 1, best = 0;
    uint64_t cells = 2 * (uint64_t)(cx + cy);
    for (uint64_t k = 0; k < cells; k++) { /* south, north, west, east */
        uint32_t i = k < 2 * cx ? (uint32_t)(k % cx) : (k - 2 * cx < cy ? 0 : cx - 1);
        uint32_t j = k < cx ? 0 : k < 2 * cx ? cy - 1 : (uint32_t)((k - 2 * cx) % cy);
        int32_t m = terrain_triangle_material(g, terrain_triangle_of_cell(g, i, j, 0), fallback);
        uint32_t q = 0;
        while (q < n && id[q] != m) q++;
        if (q == n && n < 64) id[n++] = m;
        if (q < n && ++count[q] > count[best]) best = q;
    }
    return n ? id[best] : fallback;
}

/* One edge's strips: the n nodes along it (node k at grid node (i0 + k di, j0 + k dj)) moved by
 * (ox, oy); vertices from *v, triangles from *t. */
static void edge_strips(const sylva_heightfield *hf, const terrain_grid *g, int32_t material, uint32_t i0,
                        uint32_t j0, int di, int dj, uint32_t n, double ox, double oy, float *pos, uint32_t *tri,
                        int32_t *mat, uint32_t *v, uint32_t *t)
{
    uint32_t first = *v;
    for (uint32_t k = 0; k < n; k++) {
        uint32_t i = i0 + (uint32_t)((int)k * di), j = j0 + (uint32_t)((int)k * dj);
        float *p = pos + (size_t)(*v) * 3;
        terrain_node_vertex(g, i, j, p, NULL, NULL);
        p[3] = (float)(hf->x0 + i * hf->dx + ox), p[4] = (float)(hf->y0 + j * hf->dy + oy), p[5] = p[2];
        *v += 2;
    }
    for (uint32_t k = 0; k + 1 < n; k++) {
        uint32_t a = first + 2 * k, b = a + 2; /* inner k, inner k + 1; outer at + 1 */
        /* wound so that the normal points up whichever edge (ox, oy) leaves */
        int flip = (di * oy - dj * ox) < 0;
        uint32_t q[6] = {a, b, a + 1, b, b + 1, a + 1};
        if (flip) q[1] = a + 1, q[2] = b, q[4] = a + 1, q[5] = b + 1;
        for (int c = 0; c < 6; c++) tri[(size_t)(*t) * 3 + c] = q[c];
        mat[*t] = mat[*t + 1] = material;
        *t += 2;
    }
}

int terrain_apron_build(const sylva_heightfield *hf, int32_t fallback, double reach, mesh **out,
                        err_buf *err)
{
    *out = NULL;
    if (!SYLVA_HAS_FIELD(hf, sylva_heightfield, beyond_edge) || !hf->beyond_edge) return 0;
    uint32_t nx = hf->nx, ny = hf->ny;
    uint64_t nv = 4 * (uint64_t)(nx + ny) + 16, nt = 4 * (uint64_t)(nx + ny) + 8;
    float *pos = malloc(nv * 3 * sizeof(float)), *nrm = malloc(nv * 3 * sizeof(float));
    uint32_t *tri = malloc(nt * 3 * sizeof(uint32_t));
    int32_t *mat = malloc(nt * sizeof(int32_t));
    mesh *m = mesh_new();
    if (!pos || !nrm || !tri || !mat || !m) {
        err_nomem(err, "out of memory for the terrain's apron");
        goto fail;
    }
    terrain_grid g = terrain_grid_of(hf, 0);
    int32_t ground = edge_material(&g, fallback);
    uint32_t v = 0, t = 0;
    double d = reach;
    edge_strips(hf, &g, ground, 0, 0, 1, 0, nx, 0, -d, pos, tri, mat, &v, &t);           /* south */
    edge_strips(hf, &g, ground, 0, ny - 1, 1, 0, nx, 0, d, pos, tri, mat, &v, &t);      /* north */
    edge_strips(hf, &g, ground, 0, 0, 0, 1, ny, -d, 0, pos, tri, mat, &v, &t);          /* west */
    edge_strips(hf, &g, ground, nx - 1, 0, 0, 1, ny, d, 0, pos, tri, mat, &v, &t);      /* east */
    /* the corners: flat squares at the corner nodes' heights */
    const uint32_t ci[4] = {0, nx - 1, 0, nx - 1}, cj[4] = {0, 0, ny - 1, ny - 1};
    for (int c = 0; c < 4; c++) {
        double sx = ci[c] ? d : -d, sy = cj[c] ? d : -d;
        float p[3];
        terrain_node_vertex(&g, ci[c], cj[c], p, NULL, NULL);
        double x = hf->x0 + ci[c] * hf->dx, y = hf->y0 + cj[c] * hf->dy;
        float q[4][3] = {{p[0], p[1], p[2]}, {(float)(x + sx), p[1], p[2]}, {(float)(x + sx), (float)(y + sy), p[2]},
                         {p[0], (float)(y + sy), p[2]}};
        for (int k = 0; k < 4; k++)
            for (int e = 0; e < 3; e++) pos[(size_t)(v + k) * 3 + e] = q[k][e];
        int up = (sx > 0) == (sy > 0); /* counter-clockwise seen from above */
        uint32_t o[6] = {v, v + 1, v + 2, v, v + 2, v + 3};
        if (!up) o[1] = v + 2, o[2] = v + 1, o[4] = v + 3, o[5] = v + 2;
        for (int e = 0; e < 6; e++) tri[(size_t)t * 3 + e] = o[e];
        mat[t] = mat[t + 1] = ground;
        v += 4, t += 2;
    }
    for (uint32_t k = 0; k < v; k++) nrm[k * 3] = 0, nrm[k * 3 + 1] = 0, nrm[k * 3 + 2] = 1;
    if (mesh_append(m, pos, nrm, NULL, v, tri, mat, fallback, t, err)) goto fail;
    free(pos), free(nrm), free(tri), free(mat);
    *out = m;
    return 0;
fail:
    free(pos), free(nrm), free(tri), free(mat);
    mesh_free(m);
    return -1;
}

mesh *terrain_mesh_with_apron(const sylva_heightfield *hf, int32_t material, const double eye[3], err_buf *err)
{
    mesh *terrain = terrain_mesh_build(hf, material, err);
    mesh *apron = NULL;
    if (!terrain || terrain_apron_build(hf, material, terrain_apron_reach(hf, eye), &apron, err) ||
        (apron && mesh_append(terrain, apron->pos, apron->nrm, apron->uv, apron->nv, apron->tri, apron->mat, material,
                              apron->nt, err))) {
        mesh_free(apron);
        mesh_free(terrain);
        return NULL;
    }
    mesh_free(apron);
    return terrain;
}
