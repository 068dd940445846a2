/* sky_table.c — a sky tabulated on a lat-long grid for importance sampling: the cells'
 * radiance split into a base (each row's per-channel minimum) and what varies above it, a
 * piecewise-constant distribution proportional to the varying part's luminance times
 * sin(theta) with a small floor, and sampling and pdf lookups that agree with each other.
 * See docs/models/sky.md for the sampling scheme.
 */
#include "render/sky_table.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Importance floor: cells with any radiance get (luminance + floor) as weight, the floor being
 * this fraction of the solid-angle mean luminance. */
#define SKY_TABLE_FLOOR 0.01
/* Samples stay this fraction of a cell's angular size away from its edges in theta and phi, so
 * that a direction rounded to float is found in the cell it was drawn from. */
#define SKY_TABLE_EDGE 1e-3

static double clampd(double v, double lo, double hi) { return v < lo ? lo : (v > hi ? hi : v); }

void sky_table_free(sky_table *t)
{
    if (!t) return;
    free(t->rgb);
    free(t->cdf_rows);
    free(t->cdf_cols);
    free(t->pdf);
    free(t->base);
    memset(t, 0, sizeof *t);
}

static double cell_importance(const float c[3])
{
    double r = isfinite(c[0]) && c[0] > 0.0f ? c[0] : 0.0;
    double g = isfinite(c[1]) && c[1] > 0.0f ? c[1] : 0.0;
    double b = isfinite(c[2]) && c[2] > 0.0f ? c[2] : 0.0;
    return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

int sky_table_build(sky_table *t, uint32_t nt, uint32_t np,
                    void (*radiance)(const double dir[3], double rgb[3], const void *user),
                    const void *user)
{
    memset(t, 0, sizeof *t);
    if (nt == 0 || np == 0 || !radiance) return -1;
    size_t cells = (size_t)nt * np;
    if (cells > SIZE_MAX / (3 * sizeof(float)) / 2) return -1;

    int rc = -1;
    double *weight = malloc(cells * sizeof *weight); /* owned here, freed below */
    double *row_sum = malloc((size_t)nt * sizeof *row_sum); /* owned here, freed below */
    t->nt = nt;
    t->np = np;
    t->rgb = malloc(cells * 3 * sizeof *t->rgb);
    t->cdf_rows = malloc(((size_t)nt + 1) * sizeof *t->cdf_rows);
    t->cdf_cols = malloc((size_t)nt * ((size_t)np + 1) * sizeof *t->cdf_cols);
    t->pdf = malloc(cells * sizeof *t->pdf);
    t->base = malloc((size_t)nt * 3 * sizeof *t->base);
    if (!weight || !row_sum || !t->rgb || !t->cdf_rows || !t->cdf_cols || !t->pdf || !t->base) goto done;

    double dtheta = M_PI / nt, dphi = 2.0 * M_PI / np;
    for (uint32_t i = 0; i < nt; i++) {
        double theta = (i + 0.5) * dtheta;
        float *base = t->base + 3 * (size_t)i;
        base[0] = base[1] = base[2] = INFINITY;
        for (uint32_t j = 0; j < np; j++) {
            double phi = (j + 0.5) * dphi;
            double dir[3] = {sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta)};
            double c[3] = {0.0, 0.0, 0.0};
            radiance(dir, c, user);
            float *cell = t->rgb + 3 * ((size_t)i * np + j);
            for (int k = 0; k < 3; k++) {
                cell[k] = (float)c[k];
                base[k] = fminf(base[k], isfinite(cell[k]) && cell[k] > 0.0f ? cell[k] : 0.0f);
            }
        }
    }
    /* The varying part's luminance, its solid-angle integral and its irradiance on surfaces
     * facing up and down. */
    double lum_area = 0.0, up = 0.0, down = 0.0;
    for (uint32_t i = 0; i < nt; i++) {
        double solid = (cos(i * dtheta) - cos((i + 1) * dtheta)) * dphi, mu = cos((i + 0.5) * dtheta);
        const float *base = t->base + 3 * (size_t)i;
        for (uint32_t j = 0; j < np; j++) {
            const float *cell = t->rgb + 3 * ((size_t)i * np + j);
            float above[3] = {cell[0] - base[0], cell[1] - base[1], cell[2] - base[2]};
            double lum = cell_importance(above);
            weight[(size_t)i * np + j] = lum;
            lum_area += lum * solid;
            if (mu > 0.0)
                up += lum * solid * mu;
            else
                down -= lum * solid * mu;
        }
    }
    t->irradiance_up = (float)up, t->irradiance_down = (float)down;
    double floor_lum = SKY_TABLE_FLOOR * lum_area / (4.0 * M_PI);

    /* Weight of a cell: (luminance + floor) times its solid angle, i.e. luminance times
     * sin(theta) integrated over the cell; 0 where nothing of the cell lies above the base. */
    double total = 0.0;
    for (uint32_t i = 0; i < nt; i++) {
        double solid = (cos(i * dtheta) - cos((i + 1) * dtheta)) * dphi;
        double sum = 0.0;
        const float *base = t->base + 3 * (size_t)i;
        for (uint32_t j = 0; j < np; j++) {
            size_t idx = (size_t)i * np + j;
            const float *cell = t->rgb + 3 * idx;
            int lit = (isfinite(cell[0]) && cell[0] > base[0]) || (isfinite(cell[1]) && cell[1] > base[1]) ||
                      (isfinite(cell[2]) && cell[2] > base[2]);
            weight[idx] = lit ? (weight[idx] + floor_lum) * solid : 0.0;
            sum += weight[idx];
        }
        row_sum[i] = sum;
        total += sum;
    }

    /* CDFs in float with exact 0 and 1 ends; a row of zero weight gets a uniform conditional
     * CDF (never used: its row probability is 0). A sky without variation (a constant or no
     * radiance) leaves every CDF entry at 0, which sampling reports as pdf 0. */
    double acc = 0.0;
    t->cdf_rows[0] = 0.0f;
    for (uint32_t i = 0; i < nt; i++) {
        acc += row_sum[i];
        t->cdf_rows[i + 1] = total > 0.0 ? (float)(acc / total) : 0.0f;
        float *cdf = t->cdf_cols + (size_t)i * (np + 1);
        double racc = 0.0;
        cdf[0] = 0.0f;
        for (uint32_t j = 0; j < np; j++) {
            racc += weight[(size_t)i * np + j];
            cdf[j + 1] = row_sum[i] > 0.0 ? (float)(racc / row_sum[i]) : (float)((j + 1.0) / np);
        }
        cdf[np] = 1.0f;
    }
    if (total > 0.0) t->cdf_rows[nt] = 1.0f;

    /* The pdf is the exact probability the float CDFs give a cell, over its solid angle. */
    for (uint32_t i = 0; i < nt; i++) {
        double solid = (cos(i * dtheta) - cos((i + 1) * dtheta)) * dphi;
        double p_row = (double)t->cdf_rows[i + 1] - (double)t->cdf_rows[i];
        const float *cdf = t->cdf_cols + (size_t)i * (np + 1);
        for (uint32_t j = 0; j < np; j++) {
            double p = p_row * ((double)cdf[j + 1] - (double)cdf[j]);
            t->pdf[(size_t)i * np + j] = (float)(p / solid);
        }
    }
    rc = 0;

done:
    free(weight);
    free(row_sum);
    if (rc) sky_table_free(t);
    return rc;
}

/* Index k in [0, n) with cdf[k] <= u < cdf[k+1], for cdf[0] <= u < cdf[n]. */
static uint32_t cdf_find(const float *cdf, uint32_t n, float u)
{
    uint32_t lo = 0, hi = n; /* cdf[lo] <= u, and u < cdf[hi] */
    while (hi - lo > 1) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (cdf[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

float sky_table_sample(const sky_table *t, float u1, float u2, float dir[3], float rgb[3])
{
    const float below_one = 0x1.fffffep-1f;
    u1 = u1 > 0.0f ? (u1 < below_one ? u1 : below_one) : 0.0f;
    u2 = u2 > 0.0f ? (u2 < below_one ? u2 : below_one) : 0.0f;
    if (!(t->nt > 0 && t->cdf_rows[t->nt] > 0.0f)) {
        dir[0] = 0.0f;
        dir[1] = 0.0f;
        dir[2] = 1.0f;
        rgb[0] = rgb[1] = rgb[2] = 0.0f;
        return 0.0f;
    }
    uint32_t i = cdf_find(t->cdf_rows, t->nt, u1);
    const float *cdf = t->cdf_cols + (size_t)i * (t->np + 1);
    uint32_t j = cdf_find(cdf, t->np, u2);

    /* Position inside the cell, uniform in (cos theta, phi) between the edge margins. */
    double v1 = ((double)u1 - t->cdf_rows[i]) / ((double)t->cdf_rows[i + 1] - t->cdf_rows[i]);
    double v2 = ((double)u2 - cdf[j]) / ((double)cdf[j + 1] - cdf[j]);
    v1 = clampd(v1, 0.0, 1.0);
    v2 = clampd(v2, 0.0, 1.0);
    double dtheta = M_PI / t->nt, dphi = 2.0 * M_PI / t->np;
    double c0 = cos((i + SKY_TABLE_EDGE) * dtheta), c1 = cos((i + 1 - SKY_TABLE_EDGE) * dtheta);
    double cos_theta = c0 + v1 * (c1 - c0);
    double sin_theta = sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta));
    double phi = (j + SKY_TABLE_EDGE + v2 * (1.0 - 2.0 * SKY_TABLE_EDGE)) * dphi;
    dir[0] = (float)(sin_theta * cos(phi));
    dir[1] = (float)(sin_theta * sin(phi));
    dir[2] = (float)cos_theta;

    size_t idx = (size_t)i * t->np + j;
    for (int k = 0; k < 3; k++) rgb[k] = t->rgb[3 * idx + k] - t->base[3 * i + k];
    return t->pdf[idx];
}

/* The cell of direction dir (any length). */
static void cell_of(const sky_table *t, const float dir[3], uint32_t *i, uint32_t *j)
{
    double x = dir[0], y = dir[1], z = dir[2];
    double theta = atan2(sqrt(x * x + y * y), z);
    double phi = atan2(y, x);
    if (phi < 0.0) phi += 2.0 * M_PI;
    double fi = theta / M_PI * t->nt, fj = phi / (2.0 * M_PI) * t->np;
    *i = fi > 0.0 ? (fi < t->nt - 1 ? (uint32_t)fi : t->nt - 1) : 0;
    *j = fj > 0.0 ? (fj < t->np - 1 ? (uint32_t)fj : t->np - 1) : 0;
}

float sky_table_pdf(const sky_table *t, const float dir[3], float above[3], float base[3])
{
    if (t->nt == 0 || t->np == 0) {
        above[0] = above[1] = above[2] = 0.0f;
        if (base) base[0] = base[1] = base[2] = 0.0f;
        return 0.0f;
    }
    uint32_t i, j;
    cell_of(t, dir, &i, &j);
    size_t idx = (size_t)i * t->np + j;
    for (int k = 0; k < 3; k++) {
        above[k] = t->rgb[3 * idx + k] - t->base[3 * i + k];
        if (base) base[k] = t->base[3 * i + k];
    }
    return t->pdf[idx];
}
