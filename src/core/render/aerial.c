/* aerial.c — the atmosphere's extinction and in-scattering applied to one path segment (see
 * aerial.h and docs/models/atmosphere.md). */
#include "render/aerial.h"

void aerial_segment(const light_summary *l, vec3 a, vec3 b, vec3 *L, vec3 *beta)
{
    if (l->sky_kind != SKY_PHYSICAL) return;
    double d[3] = {(double)b.x - a.x, (double)b.y - a.y, (double)b.z - a.z};
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 0.0)) return;
    for (int k = 0; k < 3; k++) d[k] /= len;
    double t[3], s[3];
    atmosphere_segment(&l->atmosphere, l->origin_altitude + a.z, d, len, t, s);
    *L = v3_add(*L, v3_mul(*beta, v3((float)s[0], (float)s[1], (float)s[2])));
    *beta = v3_mul(*beta, v3((float)t[0], (float)t[1], (float)t[2]));
}
