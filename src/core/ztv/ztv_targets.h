/* ztv_targets.h — the points of the development a visibility map looks for, and the
 * developments they belong to. From the scene file's ztv: section (docs/ztv.md), in this order
 * of preference: the targets given by hand; points at target_heights above the base of each
 * object marked development (a layout row, or an object placed alone) as placed: its lowest
 * point, on the ground it was snapped to, so that the targets stand on the object on any slope;
 * points sampled by area on every development object's surface (a development's visible fraction
 * is then the share of its surface in sight). Heights of given targets above ground are taken
 * from the scene's terrain (the water surface where it covers the ground).
 *
 * Ownership: ztv_targets_build allocates the arrays; ztv_targets_free releases them. Names are
 * borrowed from the scene file, which must outlive the targets.
 */
#ifndef SYLVA_ZTV_TARGETS_H
#define SYLVA_ZTV_TARGETS_H

#include <stdint.h>

#include "scene/scene.h"
#include "util/err.h"

struct scene_file; /* scene_file/scene_file.h: the sections of the study read here */

#define ZTV_MAX_TARGETS 65535u /* a cell's count of visible targets is a 16-bit number */

typedef enum ztv_target_source { ZTV_TARGETS_GIVEN, ZTV_TARGETS_HEIGHTS, ZTV_TARGETS_SAMPLED } ztv_target_source;

typedef struct ztv_targets {
    ztv_target_source source;
    uint32_t n;
    double (*p)[3];              /* local positions; owned */
    double (*xy)[2];             /* their horizontal parts (for the map); owned */
    uint32_t *development;       /* index into names; owned */
    uint32_t n_developments;     /* those with at least one target, in the scene file's order */
    const char **names;          /* n_developments, borrowed strings; owned array */
    double (*centre)[2];         /* n_developments: the mean of each one's targets; owned */
} ztv_targets;

/* The targets of sf's ztv: section on the built scene s; seed keys the samples. Returns 0, or -1
 * with err set (no development and no target, a target off the terrain, too many targets). */
int ztv_targets_build(ztv_targets *t, const struct scene_file *sf, const scene *s, uint64_t seed, err_buf *err);
void ztv_targets_free(ztv_targets *t); /* accepts a zeroed one */

/* The height a point at (x, y) stands on: the terrain's drawn surface, or the water surface
 * where it lies above the ground. Returns 0, or -1 when (x, y) is off the terrain. */
int ztv_ground(const scene *s, double x, double y, double *z);

/* 1 when (x, y) lies within radius metres of a target of t (radius INFINITY: always). */
int ztv_within_radius(const ztv_targets *t, double radius, double x, double y);

#endif
