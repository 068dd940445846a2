/* eco_sun.c — sunniness, 004 Algorithm 5: N_l sun positions along a summer day (4.11–4.13),
 * the cosine of incidence on each patch (4.14–4.15), weighted toward noon (4.16), with terrain
 * shadows found by marching toward the sun; the weighted mean is the patch's sunniness.
 *
 * The sun path for a latitude φ (004 appendix B, generalised): sunrise lies sin(α) north of
 * east and sunset as far north of west, α = (2/π) asin(sin 23.5° / cos φ) the mean over the
 * summer half-year of the sunrise's shift (B.5–B.18; the printed arithmetic gives 0.37 at 46°,
 * the formula 0.38); noon stands in the south at elevation 90° − φ. South of the equator the
 * picture is mirrored: noon in the north, sunrise south of east. */
#include <math.h>

#include "plugin_threads.h"
#include "eco_terrain.h"

void eco_sun_sample(double latitude_deg, uint32_t n_l, uint32_t n, double dir[3], double *weight)
{
    double lat = fabs(latitude_deg) * M_PI / 180.0;
    double north = latitude_deg >= 0 ? 1.0 : -1.0; /* toward the pole on the observer's side */
    double ratio = sin(23.5 * M_PI / 180.0) / cos(lat);
    double alpha = (2.0 / M_PI) * asin(ratio > 1 ? 1 : ratio);
    double shift = sin(alpha);
    double noon_el = M_PI / 2 - lat;
    double p0[3] = {1, shift * north, 0};                                  /* (4.11) */
    double pe[3] = {-1, shift * north, 0};                                 /* (4.12) */
    double pm[3] = {0, -north * cos(noon_el), sin(noon_el)};               /* noon */
    uint32_t half = (n_l - 1) / 2;
    double f, v[3];
    /* (4.13): linear from sunrise to noon, then from noon to sunset (the printed second line
     * starts from p0; it starts from noon). */
    if (n <= half) {
        f = half ? (double)n / half : 1.0;
        for (int c = 0; c < 3; c++) v[c] = p0[c] + f * (pm[c] - p0[c]);
    } else {
        f = (double)(n - half) / half;
        for (int c = 0; c < 3; c++) v[c] = pm[c] + f * (pe[c] - pm[c]);
    }
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int c = 0; c < 3; c++) dir[c] = v[c] / l;
    /* (4.16): 1 at sunrise and sunset, 2 at noon (the printed condition n <= N_l - 1 means
     * n <= (N_l - 1)/2). */
    double s = half ? (double)n / half : 1.0;
    *weight = n <= half ? 1.0 + s : 3.0 - s;
}

int eco_in_shadow(const eco_terrain *t, double z_max, size_t p, const double sun[3])
{
    double hl = hypot(sun[0], sun[1]);
    if (hl <= 0) return 0; /* the sun overhead */
    double ux = sun[0] / hl, uy = sun[1] / hl, tan_el = sun[2] / hl;
    uint32_t i = (uint32_t)(p % t->ni), k = (uint32_t)(p / t->ni);
    double cx = t->x0 + (i + 0.5) * t->kx, cy = t->y0 + (k + 0.5) * t->ky;
    double half_diag = 0.5 * hypot(t->kx, t->ky), rise = z_max - t->cz[p];
    for (uint32_t w = 1;; w++) {
        double reach = w * t->k - half_diag; /* the nearest a patch centre of this step can be */
        if (reach > 0 && rise <= reach * tan_el) return 0;
        int64_t q = eco_patch_of(t, cx + w * t->k * ux, cy + w * t->k * uy);
        if (q < 0) return 0;
        if ((size_t)q == p) continue;
        double qx = t->x0 + (q % t->ni + 0.5) * t->kx, qy = t->y0 + (q / t->ni + 0.5) * t->ky;
        if (t->cz[q] - t->cz[p] > hypot(qx - cx, qy - cy) * tan_el) return 1;
    }
}

typedef struct sun_job {
    eco_terrain *t;
    const eco_factor_params *fp;
    double z_max;
} sun_job;

static void sun_range(void *ctx, size_t begin, size_t end)
{
    sun_job *j = ctx;
    const eco_factor_params *fp = j->fp;
    for (size_t p = begin; p < end; p++) {
        const double *nr = j->t->normal + 3 * p;
        double sum = 0, wsum = 0;
        for (uint32_t n = 0; n < fp->sun_samples; n++) {
            double sun[3], k_l;
            eco_sun_sample(fp->latitude_deg, fp->sun_samples, n, sun, &k_l);
            double c = nr[0] * sun[0] + nr[1] * sun[1] + nr[2] * sun[2]; /* (4.14) */
            double l;
            if (c <= 0) l = fp->ambient;                                  /* (4.15) */
            else l = eco_in_shadow(j->t, j->z_max, p, sun) ? c * fp->ambient : c;
            sum += k_l * l;
            wsum += k_l;
        }
        /* divided by the sum of weights, not by N_l (4.17), so that l stays in [0, 1] */
        j->t->factor[ECO_SUNNINESS][p] = (float)(sum / wsum);
    }
}

void eco_sunniness(eco_terrain *t, const eco_factor_params *fp)
{
    size_t n = (size_t)t->ni * t->nk;
    double z_max = t->cz[0];
    for (size_t p = 1; p < n; p++) z_max = t->cz[p] > z_max ? t->cz[p] : z_max;
    sun_job j = {t, fp, z_max};
    plugin_threads_for(fp->threads, n, sun_range, &j);
}
