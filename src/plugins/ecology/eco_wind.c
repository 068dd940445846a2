/* eco_wind.c — windiness, 004 Algorithm 4 as MODELS.md corrects it: the largest upwind shelter
 * angle (4.9) over N_w patches marched against the wind decides the exposure,
 *   w = 1 for φ <= 0,  1 - φ/Θ0 for 0 < φ < Θ0,  0 for φ >= Θ0,
 * so 1 is fully exposed. (The printed algorithm takes a minimum that is never positive and
 * stores the angle itself, which is not in [0, 1].) */
#include <math.h>

#include "plugin_threads.h"
#include "eco_terrain.h"

typedef struct wind_job {
    eco_terrain *t;
    double ux, uy;    /* unit vector pointing upwind (where the wind comes from) */
    uint32_t samples;
    double theta0;    /* radians */
} wind_job;

double eco_shelter_angle(const eco_terrain *t, size_t p, double ux, double uy, uint32_t samples)
{
    uint32_t i = (uint32_t)(p % t->ni), k = (uint32_t)(p / t->ni);
    double cx = t->x0 + (i + 0.5) * t->kx, cy = t->y0 + (k + 0.5) * t->ky;
    double phi = 0.0;
    for (uint32_t w = 1; w <= samples; w++) {
        int64_t q = eco_patch_of(t, cx + w * t->k * ux, cy + w * t->k * uy);
        if (q < 0) break; /* past the terrain's edge */
        if ((size_t)q == p) continue;
        double qx = t->x0 + (q % t->ni + 0.5) * t->kx, qy = t->y0 + (q / t->ni + 0.5) * t->ky;
        double a = atan2(t->cz[q] - t->cz[p], hypot(qx - cx, qy - cy)); /* (4.9) */
        if (a > phi) phi = a;
    }
    return phi;
}

static void wind_range(void *ctx, size_t begin, size_t end)
{
    wind_job *j = ctx;
    for (size_t p = begin; p < end; p++) {
        double phi = eco_shelter_angle(j->t, p, j->ux, j->uy, j->samples);
        double w = phi <= 0 ? 1.0 : phi >= j->theta0 ? 0.0 : 1.0 - phi / j->theta0;
        j->t->factor[ECO_WINDINESS][p] = (float)w;
    }
}

void eco_windiness(eco_terrain *t, const eco_factor_params *fp)
{
    double az = fp->wind_azimuth_deg * M_PI / 180.0;
    wind_job j = {t, sin(az), cos(az), fp->wind_samples, fp->shelter_deg * M_PI / 180.0};
    plugin_threads_for(fp->threads, (size_t)t->ni * t->nk, wind_range, &j);
}
