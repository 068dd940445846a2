/* ground_shade.c — the ground texture's albedo and bumped normal at a hit (see ground_shade.h). */
#include "render/ground_shade.h"

#include <math.h>

#define TILT_MAX 0.577f      /* tan 30 degrees: the most the micro-relief turns the normal */
#define FACING_MIN 0.05f     /* the tilted normal keeps at least this cosine toward the viewer */

void ground_shade_point(const ground_texture *g, vec3 p, vec3 ng, vec3 wo, double footprint, vec3 *albedo,
                        vec3 *ns)
{
    float w[GROUND_KINDS];
    ground_cover_weights(g->map, p.x, p.y, w);
    *albedo = ground_texture_albedo(g, p.x, p.y, footprint, w);
    float grad[2];
    ground_texture_relief(g, p.x, p.y, footprint, w, grad);
    double gx = grad[0], gy = grad[1];
    vec3 n = *ns;
    vec3 tilt = v3((float)-gx, (float)-gy, 0.0f);
    tilt = v3_sub(tilt, v3_scale(n, v3_dot(tilt, n))); /* in the surface's plane */
    float len = v3_len(tilt);
    if (!(len > 0.0f)) return;
    if (len > TILT_MAX) tilt = v3_scale(tilt, TILT_MAX / len);
    vec3 b = v3_norm(v3_add(n, tilt));
    float facing = v3_dot(b, wo);
    if (v3_dot(n, wo) > FACING_MIN && facing < FACING_MIN) b = v3_norm(v3_madd(b, wo, FACING_MIN - facing));
    if (v3_dot(b, ng) * v3_dot(n, ng) <= 0.0f) return; /* would cross the facet: keep the smooth normal */
    *ns = b;
}
