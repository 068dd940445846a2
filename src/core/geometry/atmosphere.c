/* atmosphere.c — single scattering in an exponential atmosphere over a spherical Earth
 * (Nishita et al. 1993; constants of Bruneton and Neyret 2008): the coefficients from the
 * visibility, the tables of the sun's optical path, the sky and the segments. It knows nothing
 * of rays in the scene; the renderer and the POV-Ray export call it.
 * See docs/models/atmosphere.md.
 */
#include "geometry/atmosphere.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "util/task_pool.h"

/* Bruneton and Neyret 2008, section 5 ("Results"): Earth and atmosphere radii, Rayleigh
 * scattering at sea level for 680, 550 and 440 nm and its scale height, the Mie scale height,
 * the Mie single-scattering albedo (scattering / extinction = 0.9) and asymmetry g = 0.76. */
#define R_GROUND 6360e3
#define R_TOP 6420e3
static const double BETA_RAYLEIGH[3] = {5.8e-6, 13.5e-6, 33.1e-6};
#define H_RAYLEIGH 8000.0
#define H_MIE 1200.0
#define MIE_ALBEDO 0.9
#define MIE_G 0.76
/* Koschmieder's constant: ln(1 / 0.02), the contrast threshold of the meteorological range. */
#define KOSCHMIEDER 3.912

/* Quadrature: steps along a sky ray (spaced as (i/N)^2, dense near the observer), along a
 * column toward the sun when tabulating, along a segment of the scene (uniform), and the
 * directions of the sky irradiance integral. */
#define SKY_STEPS 40
#define COLUMN_STEPS 96
/* A segment is cut into equal steps no taller than SEGMENT_RISE and no thicker than one optical
 * depth at 550 nm of the air at its start (at most SEGMENT_STEPS): along a level segment the air
 * is the same everywhere and one step is exact; the second bound keeps the first step, whose air
 * sends the most light, near the segment's start. */
#define SEGMENT_STEPS 16
#define SEGMENT_RISE 50.0
#define IRR_ELEVATIONS 16
#define IRR_AZIMUTHS 32
/* The multiple-scattering table: directions around each point (a Fibonacci sphere) and steps
 * along each of them. */
#define MS_DIRECTIONS 64
#define MS_STEPS 16
/* Where less than this share of the sun's light reaches the observer, the top-of-atmosphere
 * irradiance is taken as if this much did (a sun at or below the horizon). */
#define SUN_TRANSMITTANCE_MIN 1e-3

static double clampd(double v, double lo, double hi) { return v < lo ? lo : (v > hi ? hi : v); }

double atmosphere_clear_visibility_km(double altitude)
{
    return KOSCHMIEDER / (BETA_RAYLEIGH[1] * exp(-altitude / H_RAYLEIGH)) / 1000.0;
}

/* Phase functions: Rayleigh, and Cornette-Shanks for Mie (Bruneton and Neyret 2008, eq. 4). */
static double phase_rayleigh(double nu) { return 3.0 / (16.0 * M_PI) * (1.0 + nu * nu); }
static double phase_mie(double nu, double g)
{
    double g2 = g * g, k = 1.0 + g2 - 2.0 * g * nu;
    return 3.0 / (8.0 * M_PI) * (1.0 - g2) * (1.0 + nu * nu) / ((2.0 + g2) * k * sqrt(k));
}

/* Altitude rows: a = ATMO_ALT_MIN + span u^2. */
static double row_altitude(double u) { return ATMO_ALT_MIN + (R_TOP - R_GROUND - ATMO_ALT_MIN) * u * u; }
static double altitude_u(double alt)
{
    double f = (alt - ATMO_ALT_MIN) / (R_TOP - R_GROUND - ATMO_ALT_MIN);
    return sqrt(clampd(f, 0.0, 1.0));
}

/* Column densities (Rayleigh, Mie) from radius r along cosine mu to the top; -1 when the ray
 * meets the ground first. */
static void column(double r, double mu, double out[2])
{
    double b = r * mu, c_ground = r * r - R_GROUND * R_GROUND;
    if (mu < 0.0 && b * b - c_ground >= 0.0 && c_ground >= 0.0) {
        out[0] = out[1] = -1.0;
        return;
    }
    double t_top = -b + sqrt(fmax(0.0, b * b - (r * r - R_TOP * R_TOP)));
    double dr = 0.0, dm = 0.0, prev = 0.0;
    for (int i = 1; i <= COLUMN_STEPS; i++) {
        double s = (double)i / COLUMN_STEPS, t = t_top * s * s, tm = 0.5 * (prev + t);
        double alt = sqrt(r * r + tm * tm + 2.0 * r * mu * tm) - R_GROUND;
        dr += exp(-alt / H_RAYLEIGH) * (t - prev);
        dm += exp(-alt / H_MIE) * (t - prev);
        prev = t;
    }
    out[0] = dr;
    out[1] = dm;
}

/* Sun transmittance from column densities; 0 behind the ground. */
static void transmittance_of(const atmosphere *a, double dr, double dm, double t[3])
{
    for (int k = 0; k < 3; k++) t[k] = dr < 0.0 ? 0.0 : exp(-(a->beta_rayleigh[k] * dr + a->beta_mie_ext * dm));
}

/* Sun transmittance at radius r where the sun's cosine from the local vertical is mu_s, from
 * the depth table (bilinear in the table's coordinates; a corner behind the ground makes the
 * sun blocked). */
static void sun_sphere(const atmosphere *a, double alt, double mu_s, double t[3])
{
    double fu = altitude_u(alt) * (ATMO_DEPTH_ALTITUDES - 1);
    double w = cbrt(clampd(mu_s, -1.0, 1.0));
    double fv = (w + 1.0) * 0.5 * (ATMO_DEPTH_COSINES - 1);
    int i = (int)fu, j = (int)fv;
    if (i > ATMO_DEPTH_ALTITUDES - 2) i = ATMO_DEPTH_ALTITUDES - 2;
    if (j > ATMO_DEPTH_COSINES - 2) j = ATMO_DEPTH_COSINES - 2;
    double x = fu - i, y = fv - j, dr = 0.0, dm = 0.0;
    for (int di = 0; di < 2; di++)
        for (int dj = 0; dj < 2; dj++) {
            const float *c = a->depth[i + di][j + dj];
            if (c[0] < 0.0f) {
                t[0] = t[1] = t[2] = 0.0;
                return;
            }
            double wgt = (di ? x : 1.0 - x) * (dj ? y : 1.0 - y);
            dr += wgt * c[0];
            dm += wgt * c[1];
        }
    transmittance_of(a, dr, dm, t);
}

/* Psi_ms at altitude alt with the sun's cosine mu_s (bilinear in the table). */
static void multiple_sphere(const atmosphere *a, double alt, double mu_s, float ms[3])
{
    double fu = altitude_u(alt) * (ATMO_MS_ALTITUDES - 1);
    double fv = (clampd(mu_s, -1.0, 1.0) + 1.0) * 0.5 * (ATMO_MS_COSINES - 1);
    int i = (int)fu, j = (int)fv;
    if (i > ATMO_MS_ALTITUDES - 2) i = ATMO_MS_ALTITUDES - 2;
    if (j > ATMO_MS_COSINES - 2) j = ATMO_MS_COSINES - 2;
    double x = fu - i, y = fv - j;
    for (int k = 0; k < 3; k++)
        ms[k] = (float)((1.0 - x) * ((1.0 - y) * a->multiple[i][j][k] + y * a->multiple[i][j + 1][k]) +
                        x * ((1.0 - y) * a->multiple[i + 1][j][k] + y * a->multiple[i + 1][j + 1][k]));
}

/* The flat frame's sun transmittance and Psi_ms at altitude alt. */
static void flat_at(const atmosphere *a, double alt, double t[3], float ms[3])
{
    double f = altitude_u(alt) * (ATMO_SUN_ALTITUDES - 1);
    int i = (int)f;
    if (i > ATMO_SUN_ALTITUDES - 2) i = ATMO_SUN_ALTITUDES - 2;
    double x = f - i;
    for (int k = 0; k < 3; k++) {
        t[k] = (1.0 - x) * a->sun_flat[i][k] + x * a->sun_flat[i + 1][k];
        ms[k] = (float)((1.0 - x) * a->multiple_flat[i][k] + x * a->multiple_flat[i + 1][k]);
    }
}

void atmosphere_sun_transmittance(const atmosphere *a, double alt, double t[3])
{
    double f = altitude_u(alt) * (ATMO_SUN_ALTITUDES - 1);
    int i = (int)f;
    if (i > ATMO_SUN_ALTITUDES - 2) i = ATMO_SUN_ALTITUDES - 2;
    double x = f - i;
    for (int k = 0; k < 3; k++) t[k] = (1.0 - x) * a->sun_flat[i][k] + x * a->sun_flat[i + 1][k];
}

double atmosphere_extinction_550(const atmosphere *a, double alt)
{
    return a->beta_rayleigh[1] * exp(-alt / H_RAYLEIGH) + a->beta_mie_ext * exp(-alt / H_MIE);
}

/* One quadrature step of length dt with the densities (rho_r, rho_m), the sun's transmittance
 * sun_t, the multiple-scattering term ms and the phase values there: adds the in-scattered light that reaches the start through
 * *trans, then attenuates *trans. Within the step the medium is taken as homogeneous, for which
 * the step's integral of source times extinction is exact (so a homogeneous path is exact
 * whatever the step count). */
static void scatter_step(const atmosphere *a, double rho_r, double rho_m, const double sun_t[3], const float ms[3],
                         double pr, double pm, double dt, double trans[3], double light[3])
{
    for (int k = 0; k < 3; k++) {
        double sigma = a->beta_rayleigh[k] * rho_r + a->beta_mie_ext * rho_m;
        double scatter = a->beta_rayleigh[k] * rho_r + a->beta_mie_sca * rho_m;
        double source = a->sun_top[k] * a->light_scale *
                        (sun_t[k] * (a->beta_rayleigh[k] * rho_r * pr + a->beta_mie_sca * rho_m * pm) +
                         scatter * ms[k]);
        double tau = sigma * dt, step_t = exp(-tau);
        double integral = tau > 1e-9 ? (1.0 - step_t) / sigma : dt;
        light[k] += trans[k] * source * integral;
        trans[k] *= step_t;
    }
}

/* The sky toward unit d from the observer; with ground_light 0 the ground's own reflection is
 * left out (the irradiance integral, which only looks up, does not need it). */
static void sky_ray(const atmosphere *a, const double d[3], int ground_light, double rgb[3])
{
    double r0 = R_GROUND + a->altitude;
    double b = r0 * d[2], c_ground = r0 * r0 - R_GROUND * R_GROUND;
    int ground = d[2] < 0.0 && b * b - c_ground >= 0.0;
    double t_end = ground ? -b - sqrt(b * b - c_ground) : -b + sqrt(b * b - (r0 * r0 - R_TOP * R_TOP));
    double nu = d[0] * a->sun_dir[0] + d[1] * a->sun_dir[1] + d[2] * a->sun_dir[2];
    double pr = phase_rayleigh(nu), pm = phase_mie(nu, a->mie_g);
    double trans[3] = {1.0, 1.0, 1.0};
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    double prev = 0.0;
    for (int i = 1; i <= SKY_STEPS; i++) {
        double s = (double)i / SKY_STEPS, t = t_end * s * s, tm = 0.5 * (prev + t);
        double p[3] = {d[0] * tm, d[1] * tm, r0 + d[2] * tm};
        double r = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), alt = r - R_GROUND;
        double mu_s = (p[0] * a->sun_dir[0] + p[1] * a->sun_dir[1] + p[2] * a->sun_dir[2]) / r;
        double sun_t[3];
        float ms[3];
        sun_sphere(a, alt, mu_s, sun_t);
        multiple_sphere(a, alt, mu_s, ms);
        scatter_step(a, exp(-alt / H_RAYLEIGH), exp(-alt / H_MIE), sun_t, ms, pr, pm, t - prev, trans, rgb);
        prev = t;
    }
    if (ground && ground_light) {
        /* Lambertian ground lit by the sun through the air and by the observer's sky. */
        double p[3] = {d[0] * t_end, d[1] * t_end, r0 + d[2] * t_end};
        double r = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        double mu_s = (p[0] * a->sun_dir[0] + p[1] * a->sun_dir[1] + p[2] * a->sun_dir[2]) / r;
        double sun_t[3];
        sun_sphere(a, 0.0, mu_s, sun_t);
        for (int k = 0; k < 3; k++)
            rgb[k] += trans[k] * a->ground_albedo / M_PI *
                      (a->sun_top[k] * sun_t[k] * fmax(0.0, mu_s) + a->sky_irradiance[k]);
    }
}

/* The unit direction at view-table node (x, azimuth phi from the sun's). */
static void view_direction(const atmosphere *a, double x, double phi, double d[3])
{
    double e = 0.5 * M_PI * x * fabs(x), c = cos(e);
    double h[2] = {cos(phi), sin(phi)}; /* in the frame (sun_east, its left) */
    d[0] = c * (h[0] * a->sun_east[0] - h[1] * a->sun_east[1]);
    d[1] = c * (h[0] * a->sun_east[1] + h[1] * a->sun_east[0]);
    d[2] = sin(e);
}

void atmosphere_sky(const atmosphere *a, const double dir[3], double rgb[3])
{
    double len = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    double z = clampd(dir[2] / len, -1.0, 1.0), e = asin(z) / (0.5 * M_PI);
    double x = e < 0.0 ? -sqrt(-e) : sqrt(e);
    double hx = dir[0] * a->sun_east[0] + dir[1] * a->sun_east[1];
    double hy = dir[1] * a->sun_east[0] - dir[0] * a->sun_east[1];
    double phi = (hx == 0.0 && hy == 0.0) ? 0.0 : fabs(atan2(hy, hx));
    double fu = (x + 1.0) * 0.5 * (ATMO_VIEW_ELEVATIONS - 1), fv = phi / M_PI * (ATMO_VIEW_AZIMUTHS - 1);
    int i = (int)fu, j = (int)fv;
    if (i > ATMO_VIEW_ELEVATIONS - 2) i = ATMO_VIEW_ELEVATIONS - 2;
    if (j > ATMO_VIEW_AZIMUTHS - 2) j = ATMO_VIEW_AZIMUTHS - 2;
    double u = fu - i, v = fv - j;
    for (int k = 0; k < 3; k++)
        rgb[k] = (1.0 - u) * ((1.0 - v) * a->view[i][j][k] + v * a->view[i][j + 1][k]) +
                 u * ((1.0 - v) * a->view[i + 1][j][k] + v * a->view[i + 1][j + 1][k]);
}

void atmosphere_segment(const atmosphere *a, double alt0, const double dir[3], double length,
                        double transmittance[3], double inscatter[3])
{
    double nu = dir[0] * a->sun_dir[0] + dir[1] * a->sun_dir[1] + dir[2] * a->sun_dir[2];
    double pr = phase_rayleigh(nu), pm = phase_mie(nu, a->mie_g);
    double need = fabs(dir[2]) * length / SEGMENT_RISE + atmosphere_extinction_550(a, alt0) * length;
    int steps = need < SEGMENT_STEPS - 1 ? 1 + (int)need : SEGMENT_STEPS;
    double dt = length / steps;
    transmittance[0] = transmittance[1] = transmittance[2] = 1.0;
    inscatter[0] = inscatter[1] = inscatter[2] = 0.0;
    for (int i = 0; i < steps; i++) {
        double alt = alt0 + dir[2] * (i + 0.5) * dt, sun_t[3];
        float ms[3];
        flat_at(a, alt, sun_t, ms);
        scatter_step(a, exp(-alt / H_RAYLEIGH), exp(-alt / H_MIE), sun_t, ms, pr, pm, dt, transmittance, inscatter);
    }
}

/* Hillaire 2020, eqs. 5-10: at radius r with the sun at cosine mu_s, the light scattered once
 * (isotropically) toward the point from every direction, L_2nd, and the share f_ms of light
 * the surrounding air scatters back to it; Psi_ms = L_2nd / (1 - f_ms), per unit sun irradiance
 * at the top of the atmosphere. The ground below reflects the sun with the ground albedo. */
static void multiple_at(const atmosphere *a, double r, double mu_s, double psi[3])
{
    double sun[3] = {sqrt(fmax(0.0, 1.0 - mu_s * mu_s)), 0.0, mu_s};
    double l2[3] = {0, 0, 0}, f[3] = {0, 0, 0};
    const double golden = M_PI * (3.0 - sqrt(5.0)), pu = 1.0 / (4.0 * M_PI);
    for (int n = 0; n < MS_DIRECTIONS; n++) {
        double z = 1.0 - (2.0 * n + 1.0) / MS_DIRECTIONS, s = sqrt(fmax(0.0, 1.0 - z * z));
        double d[3] = {s * cos(golden * n), s * sin(golden * n), z};
        double b = r * z, c_ground = r * r - R_GROUND * R_GROUND;
        int ground = z < 0.0 && b * b - c_ground >= 0.0;
        double t_end = ground ? -b - sqrt(b * b - c_ground) : -b + sqrt(fmax(0.0, b * b - (r * r - R_TOP * R_TOP)));
        double trans[3] = {1, 1, 1}, prev = 0.0;
        for (int i = 1; i <= MS_STEPS; i++) {
            double u = (double)i / MS_STEPS, t = t_end * u * u, tm = 0.5 * (prev + t), dt = t - prev;
            double p[3] = {d[0] * tm, d[1] * tm, r + d[2] * tm};
            double rp = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), alt = rp - R_GROUND;
            double rho_r = exp(-alt / H_RAYLEIGH), rho_m = exp(-alt / H_MIE), sun_t[3];
            sun_sphere(a, alt, (p[0] * sun[0] + p[2] * sun[2]) / rp, sun_t);
            for (int k = 0; k < 3; k++) {
                double sigma = a->beta_rayleigh[k] * rho_r + a->beta_mie_ext * rho_m;
                double scatter = a->beta_rayleigh[k] * rho_r + a->beta_mie_sca * rho_m;
                double step_t = exp(-sigma * dt), integral = sigma * dt > 1e-9 ? (1.0 - step_t) / sigma : dt;
                l2[k] += trans[k] * scatter * sun_t[k] * pu * integral;
                f[k] += trans[k] * scatter * integral;
                trans[k] *= step_t;
            }
            prev = t;
        }
        if (ground) {
            double p[3] = {d[0] * t_end, d[1] * t_end, r + d[2] * t_end}, sun_t[3];
            double mu_g = (p[0] * sun[0] + p[2] * sun[2]) / R_GROUND;
            sun_sphere(a, 0.0, mu_g, sun_t);
            for (int k = 0; k < 3; k++) l2[k] += trans[k] * a->ground_albedo / M_PI * sun_t[k] * fmax(0.0, mu_g);
        }
    }
    /* each direction carries the isotropic phase pu times its solid angle 4 pi / N */
    for (int k = 0; k < 3; k++) {
        double fms = f[k] / MS_DIRECTIONS;
        psi[k] = l2[k] / MS_DIRECTIONS / (1.0 - fmin(fms, 0.99));
    }
}

/* Row i of the multiple-scattering table, one task each (task_pool.h): its own cells alone. */
static void multiple_row(void *ctx, unsigned worker, uint32_t i)
{
    (void)worker;
    atmosphere *a = ctx;
    double r = R_GROUND + row_altitude((double)i / (ATMO_MS_ALTITUDES - 1));
    for (int j = 0; j < ATMO_MS_COSINES; j++) {
        double psi[3];
        multiple_at(a, r, 2.0 * j / (ATMO_MS_COSINES - 1) - 1.0, psi);
        for (int k = 0; k < 3; k++) a->multiple[i][j][k] = (float)psi[k];
    }
}

/* Row i of the view table, one task each: its own cells alone. */
static void view_row(void *ctx, unsigned worker, uint32_t i)
{
    (void)worker;
    atmosphere *a = ctx;
    for (int j = 0; j < ATMO_VIEW_AZIMUTHS; j++) {
        double d[3], c[3];
        view_direction(a, 2.0 * i / (ATMO_VIEW_ELEVATIONS - 1) - 1.0, M_PI * j / (ATMO_VIEW_AZIMUTHS - 1), d);
        sky_ray(a, d, 1, c);
        for (int k = 0; k < 3; k++) a->view[i][j][k] = (float)c[k];
    }
}

int atmosphere_init(atmosphere *a, const double sun_dir[3], const double sun_irradiance[3], double altitude,
                    double visibility_km, double density, double light_scale, double ground_albedo, unsigned threads)
{
    double len = sqrt(sun_dir[0] * sun_dir[0] + sun_dir[1] * sun_dir[1] + sun_dir[2] * sun_dir[2]);
    if (!(len > 0.0 && len <= DBL_MAX)) return -1;
    if (!(visibility_km > 0.0 && density >= 0.0 && density <= DBL_MAX && light_scale >= 0.0 &&
          light_scale <= DBL_MAX && ground_albedo >= 0.0 && ground_albedo <= 1.0 && isfinite(altitude)))
        return -1;
    for (int k = 0; k < 3; k++)
        if (!(sun_irradiance[k] >= 0.0 && sun_irradiance[k] <= DBL_MAX)) return -1;
    memset(a, 0, sizeof *a);
    /* The observer stays between a metre above sea level and a kilometre under the top, where the
     * sphere's geometry is well defined for the sky. */
    a->altitude = clampd(altitude, 1.0, R_TOP - R_GROUND - 1000.0);
    for (int k = 0; k < 3; k++) a->sun_dir[k] = sun_dir[k] / len;
    double horizontal = sqrt(a->sun_dir[0] * a->sun_dir[0] + a->sun_dir[1] * a->sun_dir[1]);
    a->sun_east[0] = horizontal > 1e-9 ? a->sun_dir[0] / horizontal : 1.0;
    a->sun_east[1] = horizontal > 1e-9 ? a->sun_dir[1] / horizontal : 0.0;

    /* Koschmieder: beta(550 nm) at the observer = 3.912 / V; Mie makes up what Rayleigh does not. */
    double beta_550 = KOSCHMIEDER / (visibility_km * 1000.0);
    double rayleigh_here = BETA_RAYLEIGH[1] * exp(-altitude / H_RAYLEIGH);
    if (beta_550 < rayleigh_here) return -1;
    double mie_here = beta_550 - rayleigh_here;
    for (int k = 0; k < 3; k++) a->beta_rayleigh[k] = density * BETA_RAYLEIGH[k];
    a->beta_mie_ext = density * mie_here * exp(altitude / H_MIE);
    a->beta_mie_sca = MIE_ALBEDO * a->beta_mie_ext;
    a->scale_rayleigh = H_RAYLEIGH;
    a->scale_mie = H_MIE;
    a->mie_g = MIE_G;
    a->r_ground = R_GROUND;
    a->r_top = R_TOP;
    a->light_scale = light_scale;
    a->ground_albedo = ground_albedo;

    for (int i = 0; i < ATMO_DEPTH_ALTITUDES; i++) {
        double r = R_GROUND + row_altitude((double)i / (ATMO_DEPTH_ALTITUDES - 1));
        for (int j = 0; j < ATMO_DEPTH_COSINES; j++) {
            double w = 2.0 * j / (ATMO_DEPTH_COSINES - 1) - 1.0, c[2];
            column(r, w * w * w, c);
            a->depth[i][j][0] = (float)c[0];
            a->depth[i][j][1] = (float)c[1];
        }
    }
    task_pool_run(threads, ATMO_MS_ALTITUDES, multiple_row, a);
    /* The sun seen from each altitude of the flat frame: the sun's direction is the same there,
     * so its cosine from the vertical is sun_dir.z; the column itself runs over the sphere. */
    for (int i = 0; i < ATMO_SUN_ALTITUDES; i++) {
        double c[2], t[3], alt = row_altitude((double)i / (ATMO_SUN_ALTITUDES - 1));
        float ms[3];
        column(R_GROUND + alt, a->sun_dir[2], c);
        transmittance_of(a, c[0], c[1], t);
        multiple_sphere(a, alt, a->sun_dir[2], ms);
        for (int k = 0; k < 3; k++) {
            a->sun_flat[i][k] = (float)t[k];
            a->multiple_flat[i][k] = ms[k];
        }
    }
    double here[3];
    atmosphere_sun_transmittance(a, a->altitude, here);
    for (int k = 0; k < 3; k++) {
        a->sun_ground[k] = sun_irradiance[k];
        a->sun_top[k] = sun_irradiance[k] / fmax(here[k], SUN_TRANSMITTANCE_MIN);
    }

    /* The sky's irradiance on level ground at the observer (midpoint rule in elevation and
     * azimuth over the upper hemisphere), for the ground below the horizon. */
    double dth = 0.5 * M_PI / IRR_ELEVATIONS, dph = 2.0 * M_PI / IRR_AZIMUTHS;
    for (int i = 0; i < IRR_ELEVATIONS; i++) {
        double th = (i + 0.5) * dth;
        for (int j = 0; j < IRR_AZIMUTHS; j++) {
            double ph = (j + 0.5) * dph, d[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)}, c[3];
            sky_ray(a, d, 0, c);
            for (int k = 0; k < 3; k++) a->sky_irradiance[k] += c[k] * cos(th) * sin(th) * dth * dph;
        }
    }
    task_pool_run(threads, ATMO_VIEW_ELEVATIONS, view_row, a);
    return 0;
}
