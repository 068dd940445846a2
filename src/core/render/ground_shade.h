/* ground_shade.h — the procedural ground at a terrain hit: the albedo and the shading normal of
 * the ground cover (geometry/ground_cover.h) with texture at several scales and micro-relief,
 * all evaluated in world space and filtered by the ray's footprint (docs/models/ground.md).
 *
 * Each kind has a mean albedo (the terrain's class albedos for meadow, dry grass, scree, rock and
 * snow; measured values for leaf litter, bare soil and wet ground) varied by octaves of gradient
 * noise from kilometres to centimetres (util/gradient_noise.h), and a micro-relief of its own
 * whose gradient tilts the shading normal. Octaves finer than the footprint (the distance times
 * the pixel's angle, stretched by the grazing angle) fade to their mean, so far ground neither
 * aliases into noise nor changes its mean colour; the tilt is kept within a cone around the
 * interpolated normal and on the viewer's side, so no facet turns black.
 *
 * Ownership: a ground_shader owns its cover map and borrows the scene (which must outlive it).
 */
#ifndef SYLVA_GROUND_SHADE_H
#define SYLVA_GROUND_SHADE_H

#include "geometry/ground_cover.h"
#include "util/vec3.h"

typedef struct ground_shader {
    ground_cover_map *map;       /* owned */
    vec3 albedo[GROUND_KINDS];   /* mean linear RGB albedo of each kind */
    vec3 dry_grass;              /* the meadow's albedo where it is dry */
} ground_shader;

/* The shader of scene s's ground into *out: NULL when the terrain keeps its materials
 * (ground_cover_map_new), else a shader the caller frees with ground_shader_free. Returns 0, or
 * -1 with err set when memory runs out. */
int ground_shader_build(const scene *s, ground_shader **out, err_buf *err);
void ground_shader_free(ground_shader *g); /* accepts NULL */

/* Albedo at map point (x, y) seen with footprint (metres), given the weights there. */
vec3 ground_shade_albedo(const ground_shader *g, double x, double y, double footprint,
                         const float w[GROUND_KINDS]);

/* Albedo and shading normal at point p: ns, the interpolated normal, is tilted by the
 * micro-relief; ng is the geometric normal and wo the unit direction toward the viewer. */
void ground_shade_point(const ground_shader *g, vec3 p, vec3 ng, vec3 wo, double footprint, vec3 *albedo,
                        vec3 *ns);

#endif
