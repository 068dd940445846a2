/* The procedural ground's texture (render/ground_shade.h): no period along a transect (the
 * autocorrelation has no secondary peak, while the same texture tiled has one at its tile), the
 * footprint filter keeps the mean and removes the detail, and the bumped shading normal stays
 * within its cone, on the viewer's side and on the facet's side. */
#include "geometry/ground_cover.h"
#include "ground_fixture.h"
#include "harness.h"
#include "render/ground_shade.h"

#define PEAK_LIMIT 0.3 /* a secondary autocorrelation peak above this is a period */

static double gentle(double x, double y) { return 10 + 0.002 * x + 0.001 * y; }

/* Luminance of the ground's albedo at (x, y) seen with footprint fp. */
static double luminance_at(const ground_texture *g, double x, double y, double fp)
{
    float w[GROUND_KINDS];
    ground_cover_weights(g->map, x, y, w);
    vec3 c = ground_texture_albedo(g, x, y, fp, w);
    return v3_luminance(c);
}

/* The highest autocorrelation of the increments of a[0..n) at lags from where it first falls
 * below 0.1 up to max_lag: about 1 for a signal that repeats within max_lag samples, small for
 * one that never does. The increments take out the trend of the coarser octaves, which would
 * otherwise hold the autocorrelation up at every lag. */
static double secondary_peak(const double *a, size_t n, size_t max_lag)
{
    size_t m = n - 1;
    double *d = malloc(m * sizeof *d), mean = 0, var = 0;
    if (!d) return NAN;
    for (size_t i = 0; i < m; i++) d[i] = a[i + 1] - a[i], mean += d[i];
    mean /= m;
    for (size_t i = 0; i < m; i++) d[i] -= mean, var += d[i] * d[i];
    double peak = -1;
    int decorrelated = 0;
    for (size_t lag = 1; lag <= max_lag && lag < m; lag++) {
        double s = 0;
        for (size_t i = 0; i + lag < m; i++) s += d[i] * d[i + lag];
        double r = s / var * (double)m / (double)(m - lag);
        if (!decorrelated) decorrelated = r < 0.1;
        else peak = fmax(peak, r);
    }
    free(d);
    return peak;
}

/* The transect's luminance at n samples `step` apart from x = 1000 along y = 500 (tile > 0: the
 * texture repeated every `tile` metres, as a tiled texture map would be). */
static double *transect(const ground_texture *g, size_t n, double step, double tile)
{
    double *a = malloc(n * sizeof *a);
    for (size_t i = 0; a && i < n; i++) {
        double x = 1000 + step * i;
        if (tile > 0) x = 1000 + fmod(step * i, tile);
        a[i] = luminance_at(g, x, 500, step);
    }
    return a;
}

static ground_texture *shader_of(scene *s)
{
    err_buf err = {{0}};
    ground_texture *g = NULL;
    CHECK_INT(ground_texture_build(s, &g, &err), 0);
    CHECK(g != NULL);
    return g;
}

TEST(no_period_along_a_transect)
{
    scene *s = fixture_scene(241, 21, 0, 0, 50, gentle, 1); /* 12 x 1 km */
    ground_texture *g = shader_of(s);
    if (!g) return;
    /* 10 km at 1 m (lags up to 5 km), and 100 m at 1 cm (lags up to 50 m): every octave from
     * kilometres to centimetres is seen at a footprint that resolves it */
    static const struct {
        size_t n;
        double step, tile;
    } bands[] = {{10000, 1.0, 700.0}, {10000, 0.01, 7.0}};
    for (size_t b = 0; b < 2; b++) {
        double *a = transect(g, bands[b].n, bands[b].step, 0);
        double *tiled = transect(g, bands[b].n, bands[b].step, bands[b].tile);
        CHECK(a && tiled);
        if (!a || !tiled) return;
        double peak = secondary_peak(a, bands[b].n, bands[b].n / 2);
        double tiled_peak = secondary_peak(tiled, bands[b].n, bands[b].n / 2);
        fprintf(stderr, "step %g m: secondary peak %.3f; tiled every %g m: %.3f\n", bands[b].step, peak,
                bands[b].tile, tiled_peak);
        CHECK(peak < PEAK_LIMIT);
        CHECK(tiled_peak > PEAK_LIMIT); /* the check sees a period where there is one */
        free(a), free(tiled);
    }
    ground_texture_free(g);
    scene_free(s);
}

TEST(footprint_keeps_the_mean_and_removes_detail)
{
    scene *s = fixture_scene(41, 41, 0, 0, 50, gentle, 1);
    ground_texture *g = shader_of(s);
    if (!g) return;
    /* a 20 x 20 m patch: its mean seen point by point, and seen with a 2 m footprint */
    double sum = 0, fsum = 0;
    int n = 200;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double x = 700 + 0.1 * i, y = 900 + 0.1 * j;
            sum += luminance_at(g, x, y, 0.0), fsum += luminance_at(g, x, y, 2.0);
        }
    double mean = sum / (n * n), fmean = fsum / (n * n);
    /* the detail: the change from one centimetre to the next, unfiltered and filtered */
    double d2 = 0, fd2 = 0, prev = 0, fprev = 0;
    for (int i = 0; i <= 2000; i++) {
        double l = luminance_at(g, 750 + 0.01 * i, 950, 0.0), f = luminance_at(g, 750 + 0.01 * i, 950, 2.0);
        if (i) d2 += (l - prev) * (l - prev), fd2 += (f - fprev) * (f - fprev);
        prev = l, fprev = f;
    }
    fprintf(stderr, "mean %.5f, filtered %.5f; rms change per cm %.6f, filtered %.6f\n", mean, fmean,
            sqrt(d2 / 2000), sqrt(fd2 / 2000));
    CHECK_NEAR(fmean, mean, 0.03 * mean);
    CHECK(sqrt(fd2) < 0.1 * sqrt(d2));
    ground_texture_free(g);
    scene_free(s);
}

TEST(shading_normal_stays_consistent)
{
    scene *s = fixture_scene(41, 41, 0, 0, 50, gentle, 1);
    ground_texture *g = shader_of(s);
    if (!g) return;
    vec3 ng = v3(0, 0, 1);
    float smallest_facing = 1, largest_tilt = 0;
    int tilted = 0;
    for (int q = 0; q < 20000; q++) {
        double x = 600 + 0.37 * q, y = 800 + 0.011 * q;
        float elev = (float)(0.001 + 1.5 * (q % 100) / 100.0); /* grazing to steep */
        float az = (float)(q * 0.618);
        vec3 wo = v3(cosf(elev) * cosf(az), cosf(elev) * sinf(az), sinf(elev));
        vec3 albedo, ns = ng;
        ground_shade_point(g, v3((float)x, (float)y, 10), ng, wo, 0.001 * (1 + q % 7), &albedo, &ns);
        CHECK_NEAR(v3_len(ns), 1, 1e-4);
        CHECK(v3_dot(ns, ng) > 0);
        if (v3_dot(ng, wo) > 0.05f) smallest_facing = fminf(smallest_facing, v3_dot(ns, wo));
        if (elev > 0.62f) /* steeper than 35 degrees: no turn toward the viewer is needed */
            largest_tilt = fmaxf(largest_tilt, acosf(fminf(1, v3_dot(ns, ng))));
        tilted += v3_dot(ns, ng) < 0.9999f;
        CHECK(albedo.x >= 0 && albedo.y >= 0 && albedo.z >= 0 && albedo.y < 1);
    }
    CHECK(smallest_facing >= 0.0499f);
    CHECK(largest_tilt <= atanf(0.577f) + 1e-3f);
    CHECK(tilted > 10000); /* the relief is there */
    ground_texture_free(g);
    scene_free(s);
}

TEST_LIST(TEST_CASE(no_period_along_a_transect), TEST_CASE(footprint_keeps_the_mean_and_removes_detail),
          TEST_CASE(shading_normal_stays_consistent))
