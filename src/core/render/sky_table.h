/* sky_table.h — any sky radiance tabulated over the sphere for importance sampling (the path
 * tracer's sky light). Directions are unit vectors in sylva's frame (Z up).
 */
#ifndef SYLVA_SKY_TABLE_H
#define SYLVA_SKY_TABLE_H

#include <stdint.h>

/* A tabulated sky for importance sampling: a lat-long grid (theta from 0 at +Z to pi, phi from
 * 0 at +X counter-clockwise) of radiance and a piecewise-constant 2-D distribution
 * proportional to luminance times sin(theta). */
typedef struct sky_table {
    uint32_t nt, np;       /* rows (theta) and columns (phi) */
    float *rgb;            /* nt*np*3 radiance; owned */
    float *cdf_rows;       /* nt+1 marginal CDF; owned */
    float *cdf_cols;       /* nt*(np+1) conditional CDFs; owned */
    float *pdf;            /* nt*np solid-angle pdf of each cell's directions; owned */
} sky_table;

/* radiance(dir, rgb, user) is evaluated at each cell centre. Returns 0 or -1 (out of memory,
 * nt or np zero, or radiance NULL; *t is then zeroed). *t is overwritten, not freed. */
int sky_table_build(sky_table *t, uint32_t nt, uint32_t np,
                    void (*radiance)(const double dir[3], double rgb[3], const void *user),
                    const void *user);
void sky_table_free(sky_table *t); /* accepts NULL and a zeroed table; zeroes *t */
/* Samples a direction from (u1, u2) in [0,1)^2; returns its solid-angle pdf and cell radiance.
 * A table without radiance anywhere returns pdf 0 (dir +Z, rgb 0). */
float sky_table_sample(const sky_table *t, float u1, float u2, float dir[3], float rgb[3]);
/* Solid-angle pdf of sampling dir (any length), and the tabulated radiance there; 0 and rgb 0
 * for a zeroed table. */
float sky_table_pdf(const sky_table *t, const float dir[3], float rgb[3]);

#endif
