/* test_ifs_detail.c — the DTM's own roughness and the alpha that continues it (ifs_detail.h):
 * a plane gets no detail, the chosen alpha gives the detail asked for, a steeper copy of a DTM gets
 * detail in proportion and the same alpha, and a rougher DTM gets more detail than a smoother one
 * of the same relief. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "dtm.h"
#include "harness.h"
#include "ifs_detail.h"
#include "ifs_eval.h"
#include "seeded_dtm.h"

/* A seeded midpoint-displacement DTM of n x n nodes 30 m apart with Hurst exponent `hurst`. */
static ifs_dtm *generated(uint32_t n, double relief, double hurst, uint64_t seed)
{
    return seeded_dtm(n, 30, relief, hurst, seed);
}

/* The roughness of two DTMs (NULL after a failed CHECK of either). */
static int measure_both(const ifs_dtm *a, const ifs_dtm *b, ifs_roughness *ra, ifs_roughness *rb)
{
    if (!a || !b) return -1;
    CHECK_INT(ifs_roughness_measure(a, ra), 0);
    CHECK_INT(ifs_roughness_measure(b, rb), 0);
    return 0;
}

/* The RMS and largest detail the maps of d add at alpha. */
static void detail_at(const ifs_dtm *d, double alpha, double *rms, double *max)
{
    ifs_maps_params p = {.mode = IFS_MODE_BILINEAR, .alpha = alpha};
    ifs_maps *m = NULL;
    plugin_err err = {0};
    CHECK(ifs_maps_build(d, &p, &m, &err) == 0);
    *rms = *max = NAN;
    if (m) ifs_detail_measure(m, 0, rms, max);
    ifs_maps_free(m);
}

TEST(a_plane_gets_no_detail)
{
    ifs_dtm *d = NULL;
    plugin_err err = {0};
    CHECK(ifs_dtm_new(9, 7, 30, 30, &d, &err) == 0);
    if (!d) return;
    for (uint32_t j = 0; j < d->ny; j++)
        for (uint32_t i = 0; i < d->nx; i++) d->z[j * d->nx + i] = 100 + 0.3 * i - 0.2 * j;
    ifs_roughness r;
    CHECK_INT(ifs_roughness_measure(d, &r), 0);
    CHECK(r.half2 < 1e-9 && r.target == 0);
    double alpha = 1;
    CHECK_INT(ifs_alpha_for_detail(d, IFS_MODE_BILINEAR, 0, r.target, &alpha, &err), 0);
    CHECK(alpha == 0);
    ifs_dtm_free(d);
}

TEST(too_small_to_measure)
{
    ifs_dtm *d = NULL;
    plugin_err err = {0};
    CHECK(ifs_dtm_new(4, 9, 30, 30, &d, &err) == 0);
    ifs_roughness r;
    if (d) CHECK_INT(ifs_roughness_measure(d, &r), -1);
    if (d) CHECK(r.target == 0);
    ifs_dtm_free(d);
}

/* The alpha found gives the RMS detail asked for, to 1 %. */
TEST(alpha_gives_the_detail_asked_for)
{
    ifs_dtm *d = generated(65, 400, 0.7, 11);
    if (!d) return;
    plugin_err err = {0};
    for (double want = 0.2; want < 20; want *= 4) {
        double alpha = 0, rms, max;
        CHECK_INT(ifs_alpha_for_detail(d, IFS_MODE_BILINEAR, 0, want, &alpha, &err), 0);
        detail_at(d, alpha, &rms, &max);
        printf("detail %.2f m: alpha %.5f, RMS %.3f m, largest %.3f m\n", want, alpha, rms, max);
        CHECK(alpha > 0 && alpha < IFS_ALPHA_AUTO_MAX);
        CHECK_NEAR(rms / want, 1.0, 0.01);
        CHECK(max >= rms);
    }
    ifs_dtm_free(d);
}

/* Ten times the relief: ten times the roughness and the detail, the same alpha; the Hurst
 * exponent of the generator is found to within 0.25 at the finest scales. */
TEST(detail_follows_the_dtm)
{
    ifs_dtm *a = generated(129, 100, 0.7, 5), *b = generated(129, 1000, 0.7, 5);
    ifs_roughness ra, rb;
    if (measure_both(a, b, &ra, &rb)) goto done;
    printf("relief 100 m: d2 %.3f d4 %.3f H %.3f target %.3f m; relief 1000 m: target %.3f m\n", ra.half2,
           ra.half4, ra.hurst, ra.target, rb.target);
    CHECK_NEAR(rb.target / ra.target, 10.0, 1e-6);
    CHECK_NEAR(ra.hurst, 0.7, 0.25);
    plugin_err err = {0};
    double alpha_a = 0, alpha_b = 0;
    CHECK_INT(ifs_alpha_for_detail(a, IFS_MODE_BILINEAR, 0, ra.target, &alpha_a, &err), 0);
    CHECK_INT(ifs_alpha_for_detail(b, IFS_MODE_BILINEAR, 0, rb.target, &alpha_b, &err), 0);
    CHECK_NEAR(alpha_a / alpha_b, 1.0, 1e-3);
done:
    ifs_dtm_free(a), ifs_dtm_free(b);
}

/* Of two DTMs of the same relief, the rough one (H 0.4) gets more detail than the smooth one
 * (H 0.9), and the detail is a small fraction of the relief: texture, not landforms. */
TEST(rough_dtm_more_detail_than_smooth)
{
    ifs_dtm *rough = generated(129, 500, 0.4, 9), *smooth = generated(129, 500, 0.9, 9);
    ifs_roughness rr, rs;
    if (measure_both(rough, smooth, &rr, &rs)) goto done;
    printf("rough: H %.3f target %.3f m; smooth: H %.3f target %.3f m\n", rr.hurst, rr.target, rs.hurst,
           rs.target);
    CHECK(rr.hurst < rs.hurst);
    CHECK(rr.target > 2 * rs.target);
    CHECK(rr.target < 0.05 * 500 && rs.target < 0.01 * 500);
done:
    ifs_dtm_free(rough), ifs_dtm_free(smooth);
}

TEST_LIST(TEST_CASE(a_plane_gets_no_detail), TEST_CASE(too_small_to_measure),
          TEST_CASE(alpha_gives_the_detail_asked_for), TEST_CASE(detail_follows_the_dtm),
          TEST_CASE(rough_dtm_more_detail_than_smooth))
