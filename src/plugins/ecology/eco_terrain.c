/* eco_terrain.c — the patch grid over the heightfield: patch centres and normals, altitude
 * (4.2), slope (4.3–4.4), water patches (4.5), and the build that runs every factor. The
 * humidity, wind and sun factors live in their own files. */
#include "eco_terrain.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const eco_factor_names[ECO_N_FACTORS] = {"altitude", "slope", "humidity", "windiness",
                                                     "sunniness"};

/* Largest patch grid: 2048 x 2048 patches. */
#define ECO_MAX_PATCHES (2048u * 2048u)

double eco_height_at(const eco_terrain *t, double x, double y)
{
    double gx = (x - t->hx0) / t->hdx, gy = (y - t->hy0) / t->hdy;
    double mx = t->hnx - 1, my = t->hny - 1;
    gx = gx < 0 ? 0 : gx > mx ? mx : gx;
    gy = gy < 0 ? 0 : gy > my ? my : gy;
    uint32_t i = (uint32_t)gx, j = (uint32_t)gy;
    if (i > t->hnx - 2) i = t->hnx - 2;
    if (j > t->hny - 2) j = t->hny - 2;
    double fx = gx - i, fy = gy - j;
    const float *r0 = t->hz + (size_t)j * t->hnx, *r1 = r0 + t->hnx;
    return (1 - fy) * ((1 - fx) * r0[i] + fx * r0[i + 1]) + fy * ((1 - fx) * r1[i] + fx * r1[i + 1]);
}

int64_t eco_patch_of(const eco_terrain *t, double x, double y)
{
    double gi = (x - t->x0) / t->kx, gk = (y - t->y0) / t->ky;
    if (!(gi >= 0 && gk >= 0 && gi <= t->ni && gk <= t->nk)) return -1;
    uint32_t i = (uint32_t)gi, k = (uint32_t)gk;
    if (i >= t->ni) i = t->ni - 1;
    if (k >= t->nk) k = t->nk - 1;
    return (int64_t)i + (int64_t)k * t->ni;
}

int eco_in_water(const eco_terrain *t, double x, double y)
{
    int64_t p = eco_patch_of(t, x, y);
    if (p < 0 || t->water[p]) return 1;
    return t->has_water && eco_height_at(t, x, y) < t->water_level;
}

void eco_normalise(double *v, size_t n)
{
    if (!n) return;
    double lo = v[0], hi = v[0];
    for (size_t i = 1; i < n; i++) lo = v[i] < lo ? v[i] : lo, hi = v[i] > hi ? v[i] : hi;
    double span = hi - lo;
    for (size_t i = 0; i < n; i++) v[i] = span > 0 ? (v[i] - lo) / span : 0.5;
}

void eco_altitude(eco_terrain *t)
{
    size_t n = (size_t)t->ni * t->nk;
    double lo = t->cz[0], hi = t->cz[0];
    for (size_t p = 1; p < n; p++) lo = t->cz[p] < lo ? t->cz[p] : lo, hi = t->cz[p] > hi ? t->cz[p] : hi;
    for (size_t p = 0; p < n; p++)
        t->factor[ECO_ALTITUDE][p] = (float)(hi > lo ? (t->cz[p] - lo) / (hi - lo) : 0.5);
}

void eco_slope(eco_terrain *t)
{
    size_t n = (size_t)t->ni * t->nk;
    for (size_t p = 0; p < n; p++) {
        double s = 1.0 - t->normal[3 * p + 2];
        t->factor[ECO_SLOPE][p] = (float)(s < 0 ? 0 : s > 1 ? 1 : s);
    }
}

/* Grid size: `patches` along the longer side, the other side rounded so patches are nearly
 * square. */
static int grid_layout(eco_terrain *t, const sylva_heightfield *hf, uint32_t patches, char *msg, size_t n)
{
    double lx = (hf->nx - 1) * hf->dx, ly = (hf->ny - 1) * hf->dy;
    if (!(lx > 0 && ly > 0 && isfinite(lx) && isfinite(ly))) {
        snprintf(msg, n, "the terrain spans %g x %g m; the ecology needs a terrain of positive size", lx, ly);
        return -1;
    }
    if (lx >= ly) {
        t->ni = patches;
        double k = lx / patches;
        double c = floor(ly / k + 0.5);
        t->nk = c < 1 ? 1 : (uint32_t)fmin(c, 1e9);
    } else {
        t->nk = patches;
        double k = ly / patches;
        double c = floor(lx / k + 0.5);
        t->ni = c < 1 ? 1 : (uint32_t)fmin(c, 1e9);
    }
    if ((uint64_t)t->ni * t->nk > ECO_MAX_PATCHES) {
        snprintf(msg, n, "the terrain's %g x %g m at %u patches along its longer side makes %u x %u patches; at "
                 "most %u patches in all are supported: use fewer patches", lx, ly, patches, t->ni, t->nk,
                 ECO_MAX_PATCHES);
        return -1;
    }
    t->x0 = hf->x0, t->y0 = hf->y0;
    t->kx = lx / t->ni, t->ky = ly / t->nk;
    t->k = t->kx < t->ky ? t->kx : t->ky;
    return 0;
}

int eco_terrain_build(eco_terrain *t, const sylva_heightfield *hf, const eco_factor_params *fp, char *msg, size_t n)
{
    memset(t, 0, sizeof *t);
    if (grid_layout(t, hf, fp->patches, msg, n)) return -1;
    size_t np = (size_t)t->ni * t->nk, nh = (size_t)hf->nx * hf->ny;
    t->hnx = hf->nx, t->hny = hf->ny, t->hx0 = hf->x0, t->hy0 = hf->y0, t->hdx = hf->dx, t->hdy = hf->dy;
    t->has_water = hf->has_water, t->water_level = hf->water_level;
    t->hz = malloc(nh * sizeof *t->hz);
    t->cz = malloc(np * sizeof *t->cz);
    t->normal = malloc(np * 3 * sizeof *t->normal);
    t->water = calloc(np, 1);
    t->water_map = malloc(np * sizeof *t->water_map);
    int ok = t->hz && t->cz && t->normal && t->water && t->water_map;
    for (int f = 0; f < ECO_N_FACTORS; f++) ok = ok && (t->factor[f] = malloc(np * sizeof(float)));
    if (!ok) {
        snprintf(msg, n, "out of memory for the factor maps of %u x %u patches", t->ni, t->nk);
        eco_terrain_free(t);
        return -1;
    }
    memcpy(t->hz, hf->z, nh * sizeof *t->hz);
    for (uint32_t k = 0; k < t->nk; k++)
        for (uint32_t i = 0; i < t->ni; i++) {
            size_t p = i + (size_t)k * t->ni;
            double xa = t->x0 + i * t->kx, xb = xa + t->kx, ya = t->y0 + k * t->ky, yb = ya + t->ky;
            t->cz[p] = eco_height_at(t, 0.5 * (xa + xb), 0.5 * (ya + yb));
            /* (4.4) takes the edges from corner (i, k); both pairs of opposite edges are
             * averaged here, so the normal belongs to the patch's centre. */
            double z00 = eco_height_at(t, xa, ya), z10 = eco_height_at(t, xb, ya);
            double z01 = eco_height_at(t, xa, yb), z11 = eco_height_at(t, xb, yb);
            double gx = ((z10 - z00) + (z11 - z01)) / (2 * t->kx), gy = ((z01 - z00) + (z11 - z10)) / (2 * t->ky);
            double l = sqrt(gx * gx + gy * gy + 1);
            t->normal[3 * p] = -gx / l, t->normal[3 * p + 1] = -gy / l, t->normal[3 * p + 2] = 1 / l;
        }
    eco_altitude(t);
    for (size_t p = 0; p < np; p++) {
        t->water[p] = (fp->water_altitude > 0 && t->factor[ECO_ALTITUDE][p] < fp->water_altitude) ||
                      (t->has_water && t->cz[p] < t->water_level);
        t->water_map[p] = t->water[p];
    }
    eco_slope(t);
    if (eco_humidity(t, fp)) {
        snprintf(msg, n, "out of memory computing humidity on %u x %u patches", t->ni, t->nk);
        eco_terrain_free(t);
        return -1;
    }
    eco_windiness(t, fp);
    eco_sunniness(t, fp);
    return 0;
}

void eco_terrain_free(eco_terrain *t)
{
    if (!t) return;
    free(t->hz), free(t->cz), free(t->normal), free(t->water), free(t->water_map);
    for (int f = 0; f < ECO_N_FACTORS; f++) free(t->factor[f]);
    memset(t, 0, sizeof *t);
}
