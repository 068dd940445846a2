/* ztv_sight.h — one line of sight between an observer and a target over the scene, as a
 * visibility map asks it: does anything of the screening (an Embree geometry mask,
 * render/accel.h) lie on it?
 *
 * Over a curved Earth with refraction k (docs/models/curvature.md) the sightline between two
 * points a horizontal distance S apart runs, in the flat scene frame, below the straight
 * segment by c s (S - s) at horizontal distance s from the observer, c = (1 - k) / (2 R): what
 * stands between them rises into it as the Earth bulges. This is the correction gdal_viewshed
 * and GIS viewsheds apply (heights lowered by c s^2 relative to the observer's tangent plane),
 * seen from both ends at once, so the answer does not depend on which end looks. The sagging
 * line is traced as n straight chords through points on it, n the least for which no chord
 * strays more than ZTV_SIGHT_SAG from the curve (a chord of horizontal length L strays c L^2 / 4).
 *
 * Nothing is allocated; a ztv_sight is read-only once set up and shared by all threads.
 */
#ifndef SYLVA_ZTV_SIGHT_H
#define SYLVA_ZTV_SIGHT_H

#include <embree3/rtcore.h>
#include <stdint.h>

#include "scene/scene_settings.h"

#define ZTV_SIGHT_SAG 0.05  /* metres a chord may stray from the curved sightline */
#define ZTV_SIGHT_GAP 0.05  /* metres short of each end a sightline stops (a target or an eye on
                             * the ground must not be hidden by the ground it stands on) */

typedef struct ztv_sight {
    RTCScene scene;
    double c;                /* (1 - k) / (2 R), 1/m; 0 on a flat Earth */
} ztv_sight;

/* earth NULL or its curvature off: straight sightlines. */
void ztv_sight_init(ztv_sight *s, RTCScene scene, const earth_settings *earth);

/* The chords of the sightline from o to t: 1 for a straight one. */
uint32_t ztv_sight_chords(const ztv_sight *s, const double o[3], const double t[3]);

/* 1 when nothing whose mask shares a bit with `mask` lies on the sightline from o to t, else 0.
 * *rays (when not NULL) grows by the occlusion rays traced. */
int ztv_sight_clear(const ztv_sight *s, const double o[3], const double t[3], unsigned mask, uint64_t *rays);

#endif
