/* ztv_sweep.h — the bare-earth visibility of one target from every node of a DTM, by walking
 * rays out from the target over the ground's triangles with the horizon carried along them
 * (a radial sweep of the R2 kind, made exact by bounding its error; docs/ztv.md, "The bare-earth
 * sweep").
 *
 * The ground is the surveyed grid as the tracer draws it: two triangles per cell split along the
 * diagonal from its south-west to its north-east node, heights linear along every edge. A ray
 * from the target T to a node of the sweep's perimeter is walked crossing by crossing (the
 * vertical and horizontal grid lines and the diagonals): between two crossings the ground along
 * it is linear, so its height at the crossings is the ground exactly. Along the ray the horizon is
 * the greatest of (h(t) - zT) / t - c t over the crossings passed (t the horizontal distance from
 * T, c = (1 - k) / 2R: the curved Earth's drop seen from T). Each node P takes the ray that
 * passes nearest it, at the crossing R of P's own grid line, D metres from P, and compares its
 * eye's sightline (sagging as ztv_sight.h's does) with the ray's horizon short of P; the last
 * ZTV_SWEEP_NEAR cells of the sightline, next to P, are walked exactly on the sightline itself.
 *
 * The exact sightline to P and the ray differ by at most G u D in ground height at share u of the
 * way (G the steepest triangle near the ray so far; where that leaves the answer open, the
 * steepness near the ray crossing by crossing), and sylva's Embree sightline differs from the
 * exact one by ZTV_SWEEP_SLACK at most (chords, single precision): a node is declared seen or
 * hidden only when the answer holds with both margins; otherwise it is doubtful, and the Embree
 * sightline decides it. So the sweep never changes an answer; it only spares the sightlines it
 * is sure of (docs/models/ztv_sweep.md). Its cost is a few crossings per node: the rays' (about 2
 * ZTV_SWEEP_RAYS crossings a node they pass) and the walk next to P (about 3 ZTV_SWEEP_NEAR);
 * nothing is allocated here.
 */
#ifndef SYLVA_ZTV_SWEEP_H
#define SYLVA_ZTV_SWEEP_H

#include <stdint.h>

#define ZTV_SWEEP_SLACK 0.25  /* metres: what the Embree sightline may differ from the exact one */
#define ZTV_SWEEP_RAYS 1u     /* rays per perimeter node */
#define ZTV_SWEEP_NEAR 2.0    /* cells of each sightline next to its observer walked exactly */

enum { ZTV_DOUBT = 0, ZTV_SEEN = 1, ZTV_HIDDEN = 2 };

/* The ground the sweep walks: a window of a heightfield's grid with square cells, and the nodes
 * mapped (the window's, row-major from the window's north row). */
typedef struct ztv_sweep_ground {
    const float *z;            /* heightfield nodes, z[j * stride + i], j from the south */
    uint32_t stride;
    uint32_t i0, j0, nx, ny;   /* the window: nodes i0 .. i0 + nx - 1, j0 .. j0 + ny - 1 */
    double x0, y0, cell;       /* position of heightfield node (0, 0); spacing */
    const float *steep;        /* (nx - 1) (ny - 1) window cells, row-major from the south: the
                                * steepest triangle within a cell of each; ztv_sweep_steepness */
    double steepest;           /* the greatest of steep */
    const float *eye;          /* nx ny nodes, row-major from the north: the eye's height, NAN
                                * where no observer stands */
    double observer_height;    /* metres above the ground */
    double c;                  /* (1 - k) / 2R, 1/m; 0 on a flat Earth */
} ztv_sweep_ground;

/* The window's steepness into steep ((nx - 1) (ny - 1) floats): for each cell, the greatest
 * gradient of the triangles of it and of its eight neighbours. */
void ztv_sweep_steepness(const ztv_sweep_ground *g, float *steep);

/* A worker's scratch for one window; owned by the caller. */
typedef struct ztv_sweep_scratch {
    float *nearest;            /* nx ny: the distance D of the nearest ray that tried each node, -1
                                * once it is settled or where no observer stands */
    double *crossing;          /* what the longest ray knows at each of its crossings (ztv_sweep.c) */
    double *run;               /* the same, the greatest over runs of crossings (ztv_sweep.c) */
    uint32_t crossings;        /* room of crossing, in crossings */
} ztv_sweep_scratch;

/* Allocates s for g's window. Returns 0, or -1 when out of memory. */
int ztv_sweep_scratch_alloc(ztv_sweep_scratch *s, const ztv_sweep_ground *g);
void ztv_sweep_scratch_free(ztv_sweep_scratch *s);

/* The status (ZTV_SEEN, ZTV_HIDDEN or ZTV_DOUBT) of every node of the window seen from target
 * t (local metres, inside the window, above its ground) into status (nx ny, as eye). */
void ztv_sweep_target(const ztv_sweep_ground *g, const double t[3], uint8_t *status, ztv_sweep_scratch *s);

#endif
