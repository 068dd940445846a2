/* crown_hull.c — a crown's star-shaped envelope (crown_hull.h). */
#include "geometry/crown_hull.h"

#include <math.h>
#include <stdlib.h>

#include "geometry/cutout.h"
#include "scene/mesh.h"

#define NA CROWN_HULL_AZIMUTHS
#define NR CROWN_HULL_RINGS

/* 1 when triangle t of m belongs to the crown. */
static int crown_triangle(const scene *s, const mesh *m, uint32_t t)
{
    const material *mt = &s->materials[scene_triangle_material(s, m, t)];
    return mt->bsdf == SYLVA_BSDF_LEAF || cutout_material(s, mt);
}

/* The cell of direction (dx, dy, dz) (not zero). */
static uint32_t cell_of(double dx, double dy, double dz)
{
    double az = atan2(dy, dx), el = atan2(dz, hypot(dx, dy));
    int a = (int)floor((az + M_PI) / (2 * M_PI) * NA), r = (int)floor((el + M_PI / 2) / M_PI * NR);
    a = a < 0 ? 0 : a >= NA ? NA - 1 : a;
    r = r < 0 ? 0 : r >= NR ? NR - 1 : r;
    return (uint32_t)r * NA + (uint32_t)a;
}

/* Fills the cells no leaf fell in with the mean of their filled neighbours, ring by ring
 * outward from the filled ones. Returns 0, or -1 when no cell is filled. */
static int fill_cells(double *radius)
{
    int any = 0;
    for (uint32_t c = 0; c < NA * NR; c++) any |= radius[c] > 0;
    if (!any) return -1;
    for (int pass = 0; pass < NA + NR; pass++) {
        double next[NA * NR];
        int empty = 0;
        for (uint32_t r = 0; r < NR; r++)
            for (uint32_t a = 0; a < NA; a++) {
                uint32_t c = r * NA + a;
                next[c] = radius[c];
                if (radius[c] > 0) continue;
                double sum = 0;
                int n = 0;
                const int nb[4][2] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};
                for (int k = 0; k < 4; k++) {
                    int rr = (int)r + nb[k][0], aa = ((int)a + nb[k][1] + NA) % NA;
                    if (rr < 0 || rr >= NR || !(radius[rr * NA + aa] > 0)) continue;
                    sum += radius[rr * NA + aa], n++;
                }
                if (n) next[c] = sum / n;
                else empty = 1;
            }
        for (uint32_t c = 0; c < NA * NR; c++) radius[c] = next[c];
        if (!empty) break;
    }
    return 0;
}

/* Rounds the envelope off: a few passes of a weighted mean of each cell and its four neighbours,
 * so that a crown a few pixels across shows no facets or spikes smaller than a pixel. */
static void smooth_cells(double *radius)
{
    for (int pass = 0; pass < 8; pass++) {
        double next[NA * NR];
        for (uint32_t r = 0; r < NR; r++)
            for (uint32_t a = 0; a < NA; a++) {
                double sum = 2 * radius[r * NA + a], w = 2;
                const int nb[4][2] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};
                for (int k = 0; k < 4; k++) {
                    int rr = (int)r + nb[k][0], aa = ((int)a + nb[k][1] + NA) % NA;
                    if (rr < 0 || rr >= NR) continue;
                    sum += radius[rr * NA + aa], w++;
                }
                next[r * NA + a] = sum / w;
            }
        for (uint32_t c = 0; c < NA * NR; c++) radius[c] = next[c];
    }
}

double crown_leaf_size(const scene *s, const mesh *m)
{
    double area = 0;
    uint32_t n = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
        if (!crown_triangle(s, m, t)) continue;
        const uint32_t *k = m->tri + (size_t)t * 3;
        const float *a = m->pos + (size_t)k[0] * 3, *b = m->pos + (size_t)k[1] * 3, *c = m->pos + (size_t)k[2] * 3;
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
        area += 0.5 * sqrt(x * x + y * y + z * z), n++;
    }
    return n ? sqrt(2 * area / n) : 0;
}

int crown_hull_build(const scene *s, const mesh *m, mesh **out, err_buf *err)
{
    *out = NULL;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    uint32_t n = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
        if (!crown_triangle(s, m, t)) continue;
        n++;
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 3; i++) {
                double v = m->pos[(size_t)m->tri[(size_t)t * 3 + k] * 3 + i];
                lo[i] = fmin(lo[i], v), hi[i] = fmax(hi[i], v);
            }
    }
    if (!n) return 0;
    double c[3] = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
    double radius[NA * NR] = {0};
    for (uint32_t t = 0; t < m->nt; t++) {
        if (!crown_triangle(s, m, t)) continue;
        for (int k = 0; k < 3; k++) {
            const float *p = m->pos + (size_t)m->tri[(size_t)t * 3 + k] * 3;
            double d[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]}, r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (!(r > 0)) continue;
            uint32_t cell = cell_of(d[0], d[1], d[2]);
            radius[cell] = fmax(radius[cell], r);
        }
    }
    if (fill_cells(radius)) return 0;
    smooth_cells(radius);

    /* Vertices: the cells' centre directions at their radii, then the two poles. */
    enum { NV = NA * NR + 2, NT = 2 * NA * (NR - 1) + 2 * NA };
    float *pos = malloc(sizeof(float) * 3 * NV);       /* owned here */
    uint32_t *tri = malloc(sizeof(uint32_t) * 3 * NT); /* owned here */
    mesh *hull = mesh_new();
    int rc = -1;
    if (!pos || !tri || !hull) {
        err_nomem(err, "out of memory building a crown's envelope");
        goto done;
    }
    double bottom = 0, top = 0;
    for (uint32_t r = 0; r < NR; r++) {
        double el = -M_PI / 2 + (r + 0.5) * M_PI / NR;
        for (uint32_t a = 0; a < NA; a++) {
            double az = -M_PI + (a + 0.5) * 2 * M_PI / NA, rad = radius[r * NA + a];
            float *p = pos + 3 * (r * NA + a);
            p[0] = (float)(c[0] + rad * cos(el) * cos(az));
            p[1] = (float)(c[1] + rad * cos(el) * sin(az));
            p[2] = (float)(c[2] + rad * sin(el));
            if (r == 0) bottom += rad / NA;
            if (r == NR - 1) top += rad / NA;
        }
    }
    const uint32_t south = NA * NR, north = NA * NR + 1;
    pos[3 * south] = (float)c[0], pos[3 * south + 1] = (float)c[1], pos[3 * south + 2] = (float)(c[2] - bottom);
    pos[3 * north] = (float)c[0], pos[3 * north + 1] = (float)c[1], pos[3 * north + 2] = (float)(c[2] + top);
    uint32_t k = 0;
    for (uint32_t a = 0; a < NA; a++) {
        uint32_t b = (a + 1) % NA;
        for (uint32_t r = 0; r + 1 < NR; r++) { /* counter-clockwise seen from outside */
            uint32_t p00 = r * NA + a, p01 = r * NA + b, p10 = (r + 1) * NA + a, p11 = (r + 1) * NA + b;
            tri[k++] = p00, tri[k++] = p01, tri[k++] = p11;
            tri[k++] = p00, tri[k++] = p11, tri[k++] = p10;
        }
        tri[k++] = south, tri[k++] = b, tri[k++] = a;
        tri[k++] = north, tri[k++] = (NR - 1) * NA + a, tri[k++] = (NR - 1) * NA + b;
    }
    if (mesh_append(hull, pos, NULL, NULL, NV, tri, NULL, -1, NT, err)) goto done;
    *out = hull;
    hull = NULL;
    rc = 0;
done:
    mesh_free(hull);
    free(pos);
    free(tri);
    return rc;
}
