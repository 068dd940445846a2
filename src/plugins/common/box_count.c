/* box_count.c — rasterising projected branches and counting boxes (002 eq. 1–3). */
#include "box_count.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int box_raster_init(box_raster *r, uint32_t level, double x0, double y0, double size)
{
    memset(r, 0, sizeof *r);
    if (level > BOX_RASTER_MAX_LEVEL || !(size > 0) || !isfinite(size) || !isfinite(x0) || !isfinite(y0)) return -1;
    r->level = level;
    r->n = 1u << level;
    r->px = calloc((size_t)r->n * r->n, 1);
    if (!r->px) return -1;
    r->x0 = x0, r->y0 = y0;
    r->pixel = size / r->n;
    return 0;
}

void box_raster_free(box_raster *r)
{
    free(r->px);
    r->px = NULL;
}

void box_raster_line(box_raster *r, double ax, double ay, double bx, double by, double hw)
{
    /* To pixel units. */
    ax = (ax - r->x0) / r->pixel, ay = (ay - r->y0) / r->pixel;
    bx = (bx - r->x0) / r->pixel, by = (by - r->y0) / r->pixel;
    hw /= r->pixel;
    if (hw < 0.51) hw = 0.51; /* at least one pixel wide: every row and column it crosses */
    double dx = bx - ax, dy = by - ay, len = sqrt(dx * dx + dy * dy);
    double ux, uy;
    if (len > 1e-9) ux = dx / len, uy = dy / len;
    else ux = 1.0, uy = 0.0;
    /* The covered quad: the segment widened by hw on both sides and at both ends. */
    double px = -uy * hw, py = ux * hw, ex = ux * hw, ey = uy * hw;
    double q[4][2] = {{ax - ex + px, ay - ey + py}, {bx + ex + px, by + ey + py},
                      {bx + ex - px, by + ey - py}, {ax - ex - px, ay - ey - py}};
    double ylo = q[0][1], yhi = q[0][1];
    for (int k = 1; k < 4; k++) ylo = fmin(ylo, q[k][1]), yhi = fmax(yhi, q[k][1]);
    /* rows clamped to the raster while still doubles: a branch at 1e308 m (or NaN) is no long */
    double jlo = fmax(floor(ylo), 0.0), jhi = fmin(ceil(yhi), (double)r->n - 1);
    if (!(jlo <= jhi)) return;
    for (long j = (long)jlo; j <= (long)jhi; j++) {
        double yc = j + 0.5, xlo = INFINITY, xhi = -INFINITY;
        for (int k = 0; k < 4; k++) {
            const double *p = q[k], *s = q[(k + 1) % 4];
            if ((p[1] <= yc && s[1] >= yc) || (s[1] <= yc && p[1] >= yc)) {
                double x = p[1] == s[1] ? p[0] : p[0] + (yc - p[1]) * (s[0] - p[0]) / (s[1] - p[1]);
                if (p[1] == s[1]) xlo = fmin(xlo, fmin(p[0], s[0])), xhi = fmax(xhi, fmax(p[0], s[0]));
                xlo = fmin(xlo, x), xhi = fmax(xhi, x);
            }
        }
        if (!(xlo <= xhi)) continue;
        double ilo = fmax(ceil(xlo - 0.5), 0.0), ihi = fmin(floor(xhi - 0.5), (double)r->n - 1);
        if (ilo <= ihi) memset(r->px + (size_t)j * r->n + (size_t)ilo, 1, (size_t)(ihi - ilo + 1));
    }
}

/* Sets the pixel holding (x, y), pixel units, when it lies on the raster. */
static void cover_point(box_raster *r, double x, double y)
{
    if (x >= 0 && y >= 0 && x < r->n && y < r->n) r->px[(size_t)y * r->n + (size_t)x] = 1;
}

void box_raster_triangle(box_raster *r, double ax, double ay, double bx, double by, double cx, double cy)
{
    double q[3][2] = {{(ax - r->x0) / r->pixel, (ay - r->y0) / r->pixel},
                      {(bx - r->x0) / r->pixel, (by - r->y0) / r->pixel},
                      {(cx - r->x0) / r->pixel, (cy - r->y0) / r->pixel}};
    for (int k = 0; k < 3; k++) cover_point(r, q[k][0], q[k][1]);
    double ylo = fmin(q[0][1], fmin(q[1][1], q[2][1])), yhi = fmax(q[0][1], fmax(q[1][1], q[2][1]));
    double jlo = fmax(ceil(ylo - 0.5), 0.0), jhi = fmin(floor(yhi - 0.5), (double)r->n - 1);
    if (!(jlo <= jhi)) return;
    for (long j = (long)jlo; j <= (long)jhi; j++) {
        double yc = j + 0.5, xlo = INFINITY, xhi = -INFINITY;
        for (int k = 0; k < 3; k++) {
            const double *p = q[k], *s = q[(k + 1) % 3];
            if (!((p[1] <= yc && s[1] >= yc) || (s[1] <= yc && p[1] >= yc))) continue;
            if (p[1] == s[1]) {
                xlo = fmin(xlo, fmin(p[0], s[0])), xhi = fmax(xhi, fmax(p[0], s[0]));
                continue;
            }
            double x = p[0] + (yc - p[1]) * (s[0] - p[0]) / (s[1] - p[1]);
            xlo = fmin(xlo, x), xhi = fmax(xhi, x);
        }
        double ilo = fmax(ceil(xlo - 0.5), 0.0), ihi = fmin(floor(xhi - 0.5), (double)r->n - 1);
        if (ilo <= ihi) memset(r->px + (size_t)j * r->n + (size_t)ilo, 1, (size_t)(ihi - ilo + 1));
    }
}

void box_count(const box_raster *r, uint64_t *counts)
{
    /* Occupancy at the finest grid, then each coarser grid ORs 2 x 2 blocks of the finer one. */
    uint32_t n = r->n;
    uint8_t *grid = malloc((size_t)n * n); /* owned here */
    if (!grid) {
        for (uint32_t i = 0; i <= r->level; i++) counts[i] = 0;
        return;
    }
    memcpy(grid, r->px, (size_t)n * n);
    for (uint32_t level = r->level;; level--) {
        uint64_t c = 0;
        for (size_t k = 0; k < (size_t)n * n; k++) c += grid[k] != 0;
        counts[level] = c;
        if (!level) break;
        uint32_t h = n / 2;
        for (uint32_t j = 0; j < h; j++)
            for (uint32_t i = 0; i < h; i++)
                grid[(size_t)j * h + i] = grid[(size_t)(2 * j) * n + 2 * i] | grid[(size_t)(2 * j) * n + 2 * i + 1] |
                                          grid[(size_t)(2 * j + 1) * n + 2 * i] |
                                          grid[(size_t)(2 * j + 1) * n + 2 * i + 1];
        n = h;
    }
    free(grid);
}

double box_dimension_fit(const double *eps, const double *counts, int m)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int k = 0;
    for (int i = 0; i < m; i++) {
        if (!(counts[i] > 0) || !(eps[i] > 0)) continue;
        double x = log(eps[i]), y = log(counts[i]);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
        k++;
    }
    double den = k * sxx - sx * sx;
    if (k < 2 || !(fabs(den) > 0)) return 0.0;
    /* Eq. 3 is the slope of log N against log eps; N = C eps^-D makes it -D. */
    return -(k * sxy - sx * sy) / den;
}

double box_dimension(const box_raster *r, uint32_t level_min, uint32_t level_max)
{
    uint64_t counts[BOX_RASTER_MAX_LEVEL + 1];
    double eps[BOX_RASTER_MAX_LEVEL + 1], n[BOX_RASTER_MAX_LEVEL + 1];
    if (level_max > r->level) level_max = r->level;
    if (level_min > level_max) return 0.0;
    box_count(r, counts);
    int m = 0;
    for (uint32_t i = level_min; i <= level_max; i++, m++) {
        eps[m] = ldexp(1.0, -(int)i);
        n[m] = (double)counts[i];
    }
    return box_dimension_fit(eps, n, m);
}

int box_silhouette_init(box_raster *r, double x0, double z0, double w, double h)
{
    double size = (w > h ? w : h) * 1.0001;
    if (!(size > 0)) {
        *r = (box_raster){0};
        return -1;
    }
    return box_raster_init(r, BOX_SILHOUETTE_LEVEL, x0, z0, size);
}

double box_silhouette_dimension(const box_raster *r)
{
    return box_dimension(r, BOX_SILHOUETTE_FIT_MIN, BOX_SILHOUETTE_FIT_MAX);
}
