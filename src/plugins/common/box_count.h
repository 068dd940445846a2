/* box_count.h — the box-counting fractal dimension (002 eq. 3) of a binary image, and the
 * image itself: a square raster onto which a tree's branches are projected side-on (x–z),
 * leaves left out, as 002 counts a tree "without its leaves". Every tree plugin measures its
 * models' D_B the same way: a BOX_SILHOUETTE_LEVEL raster over the side view's bounds, fitted
 * over the grids BOX_SILHOUETTE_FIT_MIN..MAX (box_silhouette_init, box_silhouette_dimension).
 *
 * Ownership: box_raster_init allocates the pixels; box_raster_free releases them.
 */
#ifndef BOX_COUNT_H
#define BOX_COUNT_H

#include <stdint.h>

#define BOX_RASTER_MAX_LEVEL 14 /* rasters up to 16384 x 16384 */
#define BOX_SILHOUETTE_LEVEL 10    /* a tree's silhouette raster is 1024 x 1024 */
#define BOX_SILHOUETTE_FIT_MIN 0   /* its D_B fits the grids 1 x 1 ... */
#define BOX_SILHOUETTE_FIT_MAX 7   /* ... 128 x 128 (boxes of 8 pixels and more) */

typedef struct box_raster {
    uint32_t level;            /* the raster is 2^level pixels on a side */
    uint32_t n;                /* 2^level */
    uint8_t *px;               /* owned: n * n, row-major, 1 where covered */
    double x0, y0;             /* world coordinates of the raster's lower-left corner */
    double pixel;              /* world size of a pixel */
} box_raster;

/* A raster of 2^level pixels covering the square [x0, x0 + size] x [y0, y0 + size]. Returns 0
 * or -1 when memory runs out or the arguments are out of range. */
int box_raster_init(box_raster *r, uint32_t level, double x0, double y0, double size);
void box_raster_free(box_raster *r); /* accepts a zeroed raster */

/* Covers the thick line from (ax, ay) to (bx, by) with half-width hw (world units; drawn at
 * least one pixel wide). */
void box_raster_line(box_raster *r, double ax, double ay, double bx, double by, double hw);

/* Covers the triangle (ax, ay), (bx, by), (cx, cy) (world units): every pixel whose centre it
 * holds, and at least the pixels its corners fall in, so a sliver still leaves its trace. */
void box_raster_triangle(box_raster *r, double ax, double ay, double bx, double by, double cx, double cy);

/* Box counts: counts[i] = boxes of side n / 2^i pixels that hold a covered pixel, for the grids
 * of 2^i x 2^i boxes, i = 0..level. */
void box_count(const box_raster *r, uint64_t *counts);

/* The least-squares slope of log N(eps_i) against log(1/eps_i) over m grid classes (002 eq. 3
 * with the sign that makes D positive): D_B. Classes with N = 0 are left out; returns 0 when
 * fewer than two remain. */
double box_dimension_fit(const double *eps, const double *counts, int m);

/* D_B of the raster over the grids of 2^i x 2^i boxes, i = level_min..level_max. */
double box_dimension(const box_raster *r, uint32_t level_min, uint32_t level_max);

/* A tree's silhouette raster: BOX_SILHOUETTE_LEVEL, square, over the side view whose lower-left
 * corner is (x0, z0) and which is w wide and h high (the larger of the two sets the square's
 * side). Returns 0, or -1 when the view is empty or memory runs out (r is then zeroed). */
int box_silhouette_init(box_raster *r, double x0, double z0, double w, double h);

/* D_B of a silhouette raster over the grids BOX_SILHOUETTE_FIT_MIN..MAX. */
double box_silhouette_dimension(const box_raster *r);

#endif
