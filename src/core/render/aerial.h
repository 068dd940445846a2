/* aerial.h — aerial perspective on the path tracer's segments: what the air between two path
 * vertices takes from and adds to the light that travels along them, from the physical sky's
 * model (geometry/atmosphere.h). Other skies have no air: the segment is left as it is.
 *
 * Deterministic: numerical quadrature, no random numbers. Shadow rays are not attenuated (the
 * sun's and the sky's light at a surface is already the light at the ground, and there are no
 * volumetric shadows). The verification mode uses the simpler constant fog of
 * light_summary_fog instead, as POV-Ray does.
 */
#ifndef SYLVA_AERIAL_H
#define SYLVA_AERIAL_H

#include "geometry/light_summary.h"
#include "util/vec3.h"

/* The segment from a to b (scene coordinates; b is the surface the path met): adds the light the
 * air scatters into it toward a, weighted by *beta, to *L, then multiplies *beta by the segment's
 * transmittance. Does nothing unless the sky is physical. */
void aerial_segment(const light_summary *l, vec3 a, vec3 b, vec3 *L, vec3 *beta);

#endif
