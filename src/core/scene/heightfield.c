/* heightfield.c — bilinear height and normal of a heightfield (see heightfield.h). */
#include "scene/heightfield.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

void heightfield_free(sylva_heightfield *h)
{
    if (!h) return;
    for (uint32_t k = 0; k < h->n_levels; k++) free(h->levels[k].z), free(h->levels[k].material);
    free(h->levels), free(h->z), free(h->material), free(h->humidity), free(h);
}

sylva_heightfield heightfield_level_view(const sylva_heightfield *h, uint32_t k)
{
    const sylva_terrain_level *l = &h->levels[k];
    return (sylva_heightfield){.size = sizeof(sylva_heightfield), .nx = l->nx, .ny = l->ny,
                               .x0 = h->x0 + l->i0 * h->dx, .y0 = h->y0 + l->j0 * h->dy,
                               .dx = h->dx / l->refine, .dy = h->dy / l->refine, .z = l->z,
                               .material = l->material};
}

/* The finest grid holding (x, y): h, or a level's view in *view. */
static const sylva_heightfield *finest_at(const sylva_heightfield *h, double x, double y,
                                          sylva_heightfield *view)
{
    for (uint32_t k = h->n_levels; k-- > 0;) {
        const sylva_terrain_level *l = &h->levels[k];
        double gx = (x - h->x0) / h->dx - l->i0, gy = (y - h->y0) / h->dy - l->j0;
        if (gx >= 0 && gy >= 0 && gx <= l->cells_x && gy <= l->cells_y) {
            *view = heightfield_level_view(h, k);
            return view;
        }
    }
    return h;
}

/* The cell (i, j) of a point at grid coordinates (gx, gy) inside the grid, and its fractions
 * (fx, fy) within the cell. */
typedef struct cell {
    uint32_t i, j;
    double fx, fy;
} cell;

static cell cell_at(const sylva_heightfield *h, double gx, double gy)
{
    uint32_t i = (uint32_t)gx, j = (uint32_t)gy;
    if (i > h->nx - 2) i = h->nx - 2;
    if (j > h->ny - 2) j = h->ny - 2;
    return (cell){i, j, gx - i, gy - j};
}

/* The cell of (x, y); -1 outside the grid. */
static int cell_of(const sylva_heightfield *h, double x, double y, cell *c)
{
    double gx = (x - h->x0) / h->dx, gy = (y - h->y0) / h->dy;
    if (!(gx >= 0.0 && gy >= 0.0 && gx <= h->nx - 1 && gy <= h->ny - 1)) return -1;
    *c = cell_at(h, gx, gy);
    return 0;
}

static double bilinear(const sylva_heightfield *h, cell c)
{
    const float *r0 = h->z + (size_t)c.j * h->nx, *r1 = r0 + h->nx;
    double fx = c.fx, fy = c.fy;
    uint32_t i = c.i;
    return (1 - fy) * ((1 - fx) * r0[i] + fx * r0[i + 1]) + fy * ((1 - fx) * r1[i] + fx * r1[i + 1]);
}

int heightfield_height(const sylva_heightfield *h, double x, double y, double *z)
{
    sylva_heightfield view;
    h = finest_at(h, x, y, &view);
    cell c;
    if (cell_of(h, x, y, &c)) return -1;
    *z = bilinear(h, c);
    return 0;
}

int heightfield_surface_height(const sylva_heightfield *h, double x, double y, double *z)
{
    sylva_heightfield view;
    h = finest_at(h, x, y, &view); /* the drawn surface is the finest level there */
    cell c;
    if (cell_of(h, x, y, &c)) return -1;
    const float *r0 = h->z + (size_t)c.j * h->nx, *r1 = r0 + h->nx;
    uint32_t i = c.i;
    if (c.fx >= c.fy) /* the triangle (i, j), (i + 1, j), (i + 1, j + 1) */
        *z = r0[i] + c.fx * ((double)r0[i + 1] - r0[i]) + c.fy * ((double)r1[i + 1] - r0[i + 1]);
    else /* the triangle (i, j), (i + 1, j + 1), (i, j + 1) */
        *z = r0[i] + c.fy * ((double)r1[i] - r0[i]) + c.fx * ((double)r1[i + 1] - r1[i]);
    return 0;
}

double heightfield_height_clamped(const sylva_heightfield *h, double x, double y)
{
    sylva_heightfield view;
    h = finest_at(h, x, y, &view);
    double gx = (x - h->x0) / h->dx, gy = (y - h->y0) / h->dy;
    double mx = h->nx - 1, my = h->ny - 1;
    gx = gx < 0 ? 0 : gx > mx ? mx : gx;
    gy = gy < 0 ? 0 : gy > my ? my : gy;
    return bilinear(h, cell_at(h, gx, gy));
}

int heightfield_normal(const sylva_heightfield *h, double x, double y, double n[3])
{
    sylva_heightfield view;
    h = finest_at(h, x, y, &view);
    cell c;
    if (cell_of(h, x, y, &c)) return -1;
    const float *r0 = h->z + (size_t)c.j * h->nx, *r1 = r0 + h->nx;
    double fx = c.fx, fy = c.fy;
    uint32_t i = c.i;
    double dzdx = ((1 - fy) * (r0[i + 1] - r0[i]) + fy * (r1[i + 1] - r1[i])) / h->dx;
    double dzdy = ((1 - fx) * (r1[i] - r0[i]) + fx * (r1[i + 1] - r0[i + 1])) / h->dy;
    double l = sqrt(dzdx * dzdx + dzdy * dzdy + 1.0);
    n[0] = -dzdx / l, n[1] = -dzdy / l, n[2] = 1.0 / l;
    return 0;
}

const char *heightfield_describe(const sylva_heightfield *h, char *buf, size_t n)
{
    int k = snprintf(buf, n, "%u x %u nodes %.3g x %.3g m apart", h->nx, h->ny, h->dx, h->dy);
    uint32_t levels = SYLVA_HAS_FIELD(h, sylva_heightfield, levels) ? h->n_levels : 0;
    if (levels && k >= 0 && (size_t)k < n) {
        const sylva_terrain_level *f = &h->levels[levels - 1];
        snprintf(buf + k, n - (size_t)k, ", refined in %u level%s of detail down to %.3g m over %.3g x %.3g km",
                 levels, levels == 1 ? "" : "s", h->dx / f->refine, f->cells_x * h->dx / 1000,
                 f->cells_y * h->dy / 1000);
    }
    return buf;
}
