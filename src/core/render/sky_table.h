/* sky_table.h — any sky radiance tabulated over the sphere for importance sampling (the path
 * tracer's sky light). Directions are unit vectors in sylva's frame (Z up).
 */
#ifndef SYLVA_SKY_TABLE_H
#define SYLVA_SKY_TABLE_H

#include <stdint.h>

/* A tabulated sky for importance sampling: a lat-long grid (theta from 0 at +Z to pi, phi from
 * 0 at +X counter-clockwise) of radiance, split into a base (each row's per-channel minimum:
 * light that depends on the elevation alone) and the part above it, and a piecewise-constant
 * 2-D distribution proportional to that part's luminance times sin(theta). The base changes
 * slowly over the sphere, and BSDF sampling integrates it best (for a constant sky it is all of
 * the sky, and the distribution is empty); the part above it (the sky's brightening toward the
 * sun) is what next-event estimation samples. */
typedef struct sky_table {
    uint32_t nt, np;       /* rows (theta) and columns (phi) */
    float irradiance_up;   /* luminance irradiance of the part above the base on a surface facing +Z */
    float irradiance_down; /* ... and on one facing -Z */
    float *rgb;            /* nt*np*3 radiance (base included); owned */
    float *cdf_rows;       /* nt+1 marginal CDF; owned */
    float *cdf_cols;       /* nt*(np+1) conditional CDFs; owned */
    float *pdf;            /* nt*np solid-angle pdf of each cell's directions; owned */
    float *base;           /* nt*3 each row's base radiance; owned */
} sky_table;

/* radiance(dir, rgb, user) is evaluated at each cell centre. Returns 0 or -1 (out of memory,
 * nt or np zero, or radiance NULL; *t is then zeroed). *t is overwritten, not freed. */
int sky_table_build(sky_table *t, uint32_t nt, uint32_t np,
                    void (*radiance)(const double dir[3], double rgb[3], const void *user),
                    const void *user);
void sky_table_free(sky_table *t); /* accepts NULL and a zeroed table; zeroes *t */
/* Samples a direction from (u1, u2) in [0,1)^2; returns its solid-angle pdf and the cell's
 * radiance above the base. A table without variation returns pdf 0 (dir +Z, rgb 0). */
float sky_table_sample(const sky_table *t, float u1, float u2, float dir[3], float rgb[3]);
/* Solid-angle pdf of sampling dir (any length), the tabulated radiance above the base there and
 * (when base is not NULL) the base; 0 and radiances 0 for a zeroed table. */
float sky_table_pdf(const sky_table *t, const float dir[3], float above[3], float base[3]);

#endif
