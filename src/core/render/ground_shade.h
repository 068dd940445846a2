/* ground_shade.h — the procedural ground at a terrain hit: the albedo of the ground texture
 * (geometry/ground_texture.h) and the shading normal tilted by its micro-relief, both filtered
 * by the ray's footprint (the distance times the pixel's angle, stretched by the grazing angle).
 * The tilt is kept within 30 degrees of the interpolated normal, turned back toward the viewer
 * where it would face away, and never crosses the facet, so no facet turns black
 * (docs/models/ground.md). Nothing is allocated. */
#ifndef SYLVA_GROUND_SHADE_H
#define SYLVA_GROUND_SHADE_H

#include "geometry/ground_texture.h"
#include "util/vec3.h"

/* Albedo and shading normal at point p: ns, the interpolated normal, is tilted by the
 * micro-relief; ng is the geometric normal and wo the unit direction toward the viewer. */
void ground_shade_point(const ground_texture *g, vec3 p, vec3 ng, vec3 wo, double footprint, vec3 *albedo,
                        vec3 *ns);

#endif
