/* test_aono_model.c — tree_aono_kunii's model against hand computations and the paper's
 * equations: the frame and child tips (16)–(19), the angle laws (13)–(15), the ratios (23)–(24),
 * the deviations (25), age variants, determinism, and the mesh (joints, winding, UVs, leaves). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "aono_angle_law.h"
#include "aono_fixture.h"
#include "aono_frame.h"
#include "aono_mesh.h"
#include "tree_aono_kunii.h"
#include "aono_ratio.h"
#include "harness.h"
#include "tree_look.h"
#include "sylva/tree_stats.h"

#define DEG (3.14159265358979323846 / 180.0)

static double dist3(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

static void check_point(const double got[3], double x, double y, double z, double tol)
{
    CHECK_NEAR(got[0], x, tol);
    CHECK_NEAR(got[1], y, tol);
    CHECK_NEAR(got[2], z, tol);
}

/* ---------------------------------------------------------------------------------------------
 * One branching by hand
 */

/* Mother (0,0,0) -> (3,0,4): z' = (0.6, 0, 0.8), y' = ẑ × z' / S = (0, 1, 0), x' = z' × y' =
 * (−0.8, 0, 0.6). A child of ρ = R ρ_op = 0.8 × 5 = 4 at φ = 30°, δ = 90° lies along
 * sin30 y' + cos30 z'; its sibling at φ = 50°, δ + γ = 90° + 120° = 210°. */
TEST(hand_branching_tilted_mother)
{
    aono_frame f;
    const double pa[3] = {0, 0, 0}, pb[3] = {3, 0, 4};
    CHECK_INT(aono_frame_build(pa, pb, &f), 0);
    check_point(f.z, 0.6, 0.0, 0.8, 1e-12);
    check_point(f.y, 0.0, 1.0, 0.0, 1e-12);
    check_point(f.x, -0.8, 0.0, 0.6, 1e-12);
    double p1[3], p2[3];
    aono_frame_child(&f, pb, 0.8 * 5.0, 30.0, 90.0, p1);
    double s30 = 0.5, c30 = sqrt(3.0) / 2.0;
    check_point(p1, 3.0 + 4.0 * c30 * 0.6, 4.0 * s30, 4.0 + 4.0 * c30 * 0.8, 1e-12);
    aono_frame_child(&f, pb, 0.6 * 5.0, 50.0, 90.0 + 120.0, p2);
    double sp = sin(50 * DEG), cp = cos(50 * DEG), ca = cos(210 * DEG), sa = sin(210 * DEG);
    check_point(p2, 3.0 + 3.0 * (sp * ca * -0.8 + cp * 0.6), 3.0 * sp * sa, 4.0 + 3.0 * (sp * ca * 0.6 + cp * 0.8),
                1e-12);
    /* the lengths are ρ_i */
    CHECK_NEAR(dist3(pb, p1), 4.0, 1e-12);
    CHECK_NEAR(dist3(pb, p2), 3.0, 1e-12);
}

/* The whole growth of two dichotomous levels, fixed δ = 90°, γ = 180°, checked by hand. The
 * trunk (0,0,0)-(0,0,5) is vertical on the axis: x' = +y, y' = +x. */
TEST(hand_branching_two_levels)
{
    aono_fixture fx;
    int rc = aono_fixture_open(&fx,
                               "levels: 2\npattern: dichotomous\nfi: [30, 50]\nri: [0.8, 0.6]\n"
                               "del: 90\ndel_mode: fixed\ngamma: 180\ntrunk_length: 5\n",
                               7);
    CHECK_INT(rc, 0);
    aono_skeleton s = {0};
    CHECK_INT(aono_fixture_grow(&fx, 2, &s), 0);
    CHECK_INT(s.n, 7);
    if (s.n != 7) {
        aono_skeleton_release(&s);
        aono_fixture_close(&fx);
        return;
    }
    double c30 = cos(30 * DEG), s50 = sin(50 * DEG), c50 = cos(50 * DEG);
    /* level 1: child 1 along sin30 y' + cos30 z' = (0.5, 0, cos30), ρ = 4 */
    check_point(s.seg[1].tip, 2.0, 0.0, 5.0 + 4.0 * c30, 1e-12);
    /* child 2 at 270°: sin50 (cos270 x' + sin270 y') + cos50 z' = (−sin50, 0, cos50), ρ = 3 */
    check_point(s.seg[2].tip, -3.0 * s50, 0.0, 5.0 + 3.0 * c50, 1e-12);
    /* level 2 on child 1: z' = (0.5, 0, cos30), y' = (0, 1, 0), x' = (−cos30, 0, 0.5) */
    const double *p1 = s.seg[1].tip;
    double d11[3] = {c30 * 0.5, 0.5, c30 * c30}; /* sin30 y' + cos30 z' */
    check_point(s.seg[3].tip, p1[0] + 3.2 * d11[0], p1[1] + 3.2 * d11[1], p1[2] + 3.2 * d11[2], 1e-12);
    /* child 2 of it: −sin50 y' + cos50 z', ρ = 0.6 × 4 */
    check_point(s.seg[4].tip, p1[0] + 2.4 * c50 * 0.5, p1[1] - 2.4 * s50, p1[2] + 2.4 * c50 * c30, 1e-12);
    CHECK_INT(s.seg[3].parent, 1);
    CHECK_INT(s.seg[5].parent, 2);
    CHECK_NEAR(s.seg[6].length, 0.6 * 3.0, 1e-12);
    aono_skeleton_release(&s);
    aono_fixture_close(&fx);
}

/* The paper's transform (17)–(19) with T23 read as cos β sin α, in its left-handed coordinates,
 * mirrored y -> −y, gives the plugin's child tips for any mother direction. */
TEST(paper_transform_mirrored)
{
    for (int k = 0; k < 200; k++) {
        double pa[3] = {0.3 * k, -0.2 * k, 1.0}, pb[3];
        double th = 0.37 * k, el = -1.2 + 0.0121 * k; /* directions all round, up and down */
        pb[0] = pa[0] + 2.0 * cos(el) * cos(th), pb[1] = pa[1] + 2.0 * cos(el) * sin(th);
        pb[2] = pa[2] + 2.0 * sin(el);
        /* paper coordinates: y mirrored */
        double a[3] = {pa[0], -pa[1], pa[2]}, b[3] = {pb[0], -pb[1], pb[2]};
        double T = dist3(a, b), S = hypot(b[0] - a[0], b[1] - a[1]);
        double sb = (b[2] - a[2]) / T, cb = S / T, ca = (b[0] - a[0]) / S, sa = (b[1] - a[1]) / S; /* (19) */
        double x1[3] = {-sb * ca, -sb * sa, cb}, y1[3] = {sa, -ca, 0}, z1[3] = {cb * ca, cb * sa, sb}; /* (18) */
        double phi = 10.0 + (3 * k) % 150, az = 7.0 * k;
        double cx = sin(phi * DEG) * cos(az * DEG), cy = sin(phi * DEG) * sin(az * DEG), cz = cos(phi * DEG);
        double paper[3];
        for (int i = 0; i < 3; i++) paper[i] = b[i] + 1.5 * (cx * x1[i] + cy * y1[i] + cz * z1[i]); /* (16)-(17) */
        aono_frame f;
        CHECK_INT(aono_frame_build(pa, pb, &f), 0);
        double got[3];
        aono_frame_child(&f, pb, 1.5, phi, az, got);
        check_point(got, paper[0], -paper[1], paper[2], 1e-9);
    }
}

/* The frame is orthonormal, y' horizontal, and the vertical mother takes the special case. */
TEST(frame_orthonormal_and_vertical)
{
    for (int k = 0; k < 100; k++) {
        double pa[3] = {0, 0, 0}, pb[3] = {cos(k * 0.7) * (k % 7) * 0.1, sin(k * 0.3) * (k % 5) * 0.1,
                                           k % 2 ? 1.0 : -1.0};
        aono_frame f;
        CHECK_INT(aono_frame_build(pa, pb, &f), 0);
        double *v[3] = {f.x, f.y, f.z};
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double d = v[i][0] * v[j][0] + v[i][1] * v[j][1] + v[i][2] * v[j][2];
                CHECK_NEAR(d, i == j ? 1.0 : 0.0, 1e-12);
            }
        CHECK_NEAR(f.y[2], 0.0, 1e-15);
    }
    /* on the axis: α = β = 90°, mirrored: x' = +y, y' = +x */
    aono_frame f;
    const double o[3] = {0, 0, 0}, up[3] = {0, 0, 7};
    CHECK_INT(aono_frame_build(o, up, &f), 0);
    check_point(f.x, 0, 1, 0, 0);
    check_point(f.y, 1, 0, 0, 0);
    check_point(f.z, 0, 0, 1, 0);
    /* off the axis at (3, 4): x' points toward the axis, y' along the circle */
    const double a[3] = {3, 4, 1}, b[3] = {3, 4, 6};
    CHECK_INT(aono_frame_build(a, b, &f), 0);
    check_point(f.x, -0.6, -0.8, 0, 1e-15);
    check_point(f.y, -0.8, 0.6, 0, 1e-15);
    /* a branch of no length has no frame */
    CHECK_INT(aono_frame_build(a, a, &f), -1);
}

/* ---------------------------------------------------------------------------------------------
 * Angle laws (13)–(15)
 */

TEST(law_linear_through_two_points)
{
    const double pts[] = {2, 60, 6, 20};
    aono_angle_law law;
    char why[300];
    CHECK_INT(aono_law_fit(AONO_LAW_LINEAR, pts, 2, &law, why, sizeof why), 0);
    CHECK_NEAR(law.a, -10.0, 1e-12); /* (20 − 60)/(6 − 2) */
    CHECK_NEAR(law.b, 80.0, 1e-12);  /* 60 − a 2 */
    CHECK_NEAR(aono_law_eval(&law, 2), 60.0, 1e-12);
    CHECK_NEAR(aono_law_eval(&law, 6), 20.0, 1e-12);
    CHECK_NEAR(aono_law_eval(&law, 4), 40.0, 1e-12);
    const double same[] = {3, 10, 3, 20}, three[] = {1, 1, 2, 2, 3, 3};
    CHECK_INT(aono_law_fit(AONO_LAW_LINEAR, same, 2, &law, why, sizeof why), -1);
    CHECK_STR_CONTAINS(why, "two different levels");
    CHECK_INT(aono_law_fit(AONO_LAW_LINEAR, three, 3, &law, why, sizeof why), -1);
    CHECK_STR_CONTAINS(why, "exactly two points");
}

/* Least squares on n = 1..5, φ = 10, 30, 40, 30, 10: with t = n − 3 the normal equations give
 * φ = −50/7 t² + 268/7, i.e. a = −50/7, b = 300/7, c = −26. An exact parabola comes back. */
TEST(law_quadratic_least_squares)
{
    const double pts[] = {1, 10, 2, 30, 3, 40, 4, 30, 5, 10};
    aono_angle_law law;
    char why[300];
    CHECK_INT(aono_law_fit(AONO_LAW_QUADRATIC, pts, 5, &law, why, sizeof why), 0);
    CHECK_NEAR(law.a, -50.0 / 7.0, 1e-9);
    CHECK_NEAR(law.b, 300.0 / 7.0, 1e-9);
    CHECK_NEAR(law.c, -26.0, 1e-9);
    CHECK_NEAR(aono_law_eval(&law, 3), 268.0 / 7.0, 1e-9);
    const double exact[] = {0, 1, 1, 3, 2, 7, 3, 13, 10, 111}; /* n² + n + 1 */
    CHECK_INT(aono_law_fit(AONO_LAW_QUADRATIC, exact, 5, &law, why, sizeof why), 0);
    CHECK_NEAR(law.a, 1.0, 1e-9);
    CHECK_NEAR(law.b, 1.0, 1e-9);
    CHECK_NEAR(law.c, 1.0, 1e-9);
    const double two_levels[] = {1, 5, 1, 6, 2, 7};
    CHECK_INT(aono_law_fit(AONO_LAW_QUADRATIC, two_levels, 3, &law, why, sizeof why), -1);
    CHECK_STR_CONTAINS(why, "three different levels");
}

/* (15): A = φ(0), B = −ln(φ(n2)/A)/n2; the law returns both points and halves every n2/2 levels
 * when φ(n2) = A/4. */
TEST(law_exponential_at_zero_and_n2)
{
    const double pts[] = {0, 80, 6, 20};
    aono_angle_law law;
    char why[300];
    CHECK_INT(aono_law_fit(AONO_LAW_EXPONENTIAL, pts, 2, &law, why, sizeof why), 0);
    CHECK_NEAR(law.a, 80.0, 1e-12);
    CHECK_NEAR(law.b, -log(20.0 / 80.0) / 6.0, 1e-12);
    CHECK_NEAR(aono_law_eval(&law, 0), 80.0, 1e-12);
    CHECK_NEAR(aono_law_eval(&law, 6), 20.0, 1e-12);
    CHECK_NEAR(aono_law_eval(&law, 3), 40.0, 1e-12);
    const double zero[] = {0, 80, 6, 0};
    CHECK_INT(aono_law_fit(AONO_LAW_EXPONENTIAL, zero, 2, &law, why, sizeof why), -1);
    CHECK_STR_CONTAINS(why, "above 0");
}

/* A law given in the scene reaches the branching angle of its child at each level. */
TEST(law_drives_branching_angle)
{
    aono_fixture fx;
    CHECK_INT(aono_fixture_open(&fx,
                                "pattern: dichotomous\nfi: [20, 40]\n"
                                "fi_laws: [{child: 2, law: linear, points: [[1, 60], [5, 20]]}]\n",
                                1),
              0);
    aono_config cfg;
    CHECK_INT(aono_fixture_config(&fx, &cfg), 0);
    CHECK_NEAR(aono_child_angle(&cfg, 0, 3), 20.0, 1e-12);
    CHECK_NEAR(aono_child_angle(&cfg, 1, 1), 60.0, 1e-12);
    CHECK_NEAR(aono_child_angle(&cfg, 1, 3), 40.0, 1e-12);
    aono_skeleton s = {0};
    CHECK_INT(aono_grow(&cfg, 3, &fx.env, &s, &fx.fail), 0);
    /* angle between each level-3 second child and its mother is 40° */
    for (uint32_t k = 0; k < s.n; k++) {
        const aono_segment *c = &s.seg[k], *m = c->parent == AONO_NONE ? NULL : &s.seg[c->parent];
        if (!m || c->level != 3 || c->child_index != 1) continue;
        double dm[3], dc[3], dot = 0.0;
        for (int i = 0; i < 3; i++) dm[i] = m->tip[i] - m->base[i], dc[i] = c->tip[i] - c->base[i];
        for (int i = 0; i < 3; i++) dot += dm[i] * dc[i];
        CHECK_NEAR(acos(dot / (dist3(m->tip, m->base) * dist3(c->tip, c->base))) / DEG, 40.0, 1e-9);
    }
    aono_skeleton_release(&s);
    aono_config_release(&cfg);
    aono_fixture_close(&fx);
}

/* ---------------------------------------------------------------------------------------------
 * Contraction ratios (23)–(24)
 */

TEST(ratios_from_dimensions)
{
    double r[3];
    char why[400];
    /* H = 20, H0 = 4, L = 12: R1 = 1 − 4/20 = 0.8; h = 16; R2 = (12/16) 0.8 = 0.6 */
    CHECK_INT(aono_ratios_from_dimensions(AONO_MONOPODIAL, 0, 20, 4, 12, 1, r, why, sizeof why), 0);
    CHECK_NEAR(r[0], 0.8, 1e-15);
    CHECK_NEAR(r[1], 0.6, 1e-15);
    /* LVT = 2: the second child continues and takes (23) */
    CHECK_INT(aono_ratios_from_dimensions(AONO_MONOPODIAL, 1, 20, 4, 12, 1, r, why, sizeof why), 0);
    CHECK_NEAR(r[1], 0.8, 1e-15);
    CHECK_NEAR(r[0], 0.6, 1e-15);
    /* dichotomous: R2 = RKO R1 */
    CHECK_INT(aono_ratios_from_dimensions(AONO_DICHOTOMOUS, 0, 25, 5, 12, 0.75, r, why, sizeof why), 0);
    CHECK_NEAR(r[0], 0.8, 1e-15);
    CHECK_NEAR(r[1], 0.6, 1e-15);
    /* ternary: R3 = 1 − H0/H, R1 = R2 = (L/H) R3 */
    CHECK_INT(aono_ratios_from_dimensions(AONO_TERNARY, 0, 20, 5, 10, 1, r, why, sizeof why), 0);
    CHECK_NEAR(r[2], 0.75, 1e-15);
    CHECK_NEAR(r[0], 0.375, 1e-15);
    CHECK_NEAR(r[1], 0.375, 1e-15);
    /* the series (20) with these ratios gives back h/L = R1/R2 */
    double h = 0, L = 0, H0 = 4;
    for (int n = 1; n <= 200; n++) h += H0 * pow(0.8, n), L += H0 * pow(0.8, n - 1) * 0.6;
    CHECK_NEAR(h, 16.0, 1e-9);
    CHECK_NEAR(L, 12.0, 1e-9);
    /* a ratio of 1 or more is refused with the bound that would be valid */
    CHECK_INT(aono_ratios_from_dimensions(AONO_MONOPODIAL, 0, 20, 4, 24, 1, r, why, sizeof why), -1);
    CHECK_STR_CONTAINS(why, "must be below 1");
    CHECK_STR_CONTAINS(why, "smaller than h / R1 = 20 m");
    CHECK_INT(aono_ratios_from_dimensions(AONO_DICHOTOMOUS, 0, 10, 10, 5, 1, r, why, sizeof why), -1);
    CHECK_STR_CONTAINS(why, "below the height");
}

/* The dimensions method reaches the tree: each child's length is R_i times its mother's. */
TEST(ratios_reach_the_tree)
{
    aono_fixture fx;
    CHECK_INT(aono_fixture_open(&fx, "ri_method: dimensions\nheight: 20\ntrunk_length: 4\ncrown_diameter: 12\n", 3), 0);
    aono_skeleton s = {0};
    CHECK_INT(aono_fixture_grow(&fx, 4, &s), 0);
    for (uint32_t k = 1; k < s.n; k++) {
        const aono_segment *c = &s.seg[k];
        double want = (c->child_index == 0 ? 0.8 : 0.6) * s.seg[c->parent].length;
        CHECK_NEAR(c->length, want, 1e-12);
        CHECK_NEAR(dist3(c->base, c->tip), want, 1e-9);
    }
    aono_skeleton_release(&s);
    aono_fixture_close(&fx);
    /* random ratios stay in their interval */
    CHECK_INT(aono_fixture_open(&fx, "pattern: stochastic\nfi: [30, 40, 5]\nri_method: random\nri_range: [0.55, 0.7]\n", 3),
              0);
    CHECK_INT(aono_fixture_grow(&fx, 5, &s), 0);
    double lo = 1, hi = 0;
    for (uint32_t k = 1; k < s.n; k++) {
        double r = s.seg[k].length / s.seg[s.seg[k].parent].length;
        lo = fmin(lo, r), hi = fmax(hi, r);
    }
    CHECK(lo >= 0.55 && hi <= 0.7 && hi - lo > 0.1);
    aono_skeleton_release(&s);
    aono_fixture_close(&fx);
}

/* ---------------------------------------------------------------------------------------------
 * Deviations (25)
 */

static int grow_tips(const char *yaml, uint32_t levels, aono_skeleton *s)
{
    aono_fixture fx;
    int rc = aono_fixture_open(&fx, yaml, 11);
    if (!rc) rc = aono_fixture_grow(&fx, levels, s);
    if (rc) fprintf(stderr, "%s%s\n", fx.err.msg, fx.fail.msg);
    aono_fixture_close(&fx);
    return rc;
}

/* Fig. 23 and 24: Q = (30, 0, 0), FAC = ±1. Every tip's distance to Q shrinks with the attractor
 * and grows with the inhibitor, and the crown's centre moves toward / away from Q along x. */
TEST(attractor_and_inhibitor)
{
    const char *base = "levels: 6\npattern: monopodial\nfi: [0, 45]\nri: [0.9, 0.8]\n";
    char attract[256], inhibit[256];
    snprintf(attract, sizeof attract, "%scontrollers: [{position: [30, 0, 0], fac: 1}]\n", base);
    snprintf(inhibit, sizeof inhibit, "%scontrollers: [{position: [30, 0, 0], fac: -1}]\n", base);
    aono_skeleton plain = {0}, a = {0}, i = {0};
    CHECK_INT(grow_tips(base, 6, &plain), 0);
    CHECK_INT(grow_tips(attract, 6, &a), 0);
    CHECK_INT(grow_tips(inhibit, 6, &i), 0);
    CHECK_INT(a.n, plain.n);
    CHECK_INT(i.n, plain.n);
    const double q[3] = {30, 0, 0};
    int closer = 0, farther = 0, tips = 0;
    double xp = 0, xa = 0, xi = 0;
    for (uint32_t k = 1; k < plain.n && k < a.n && k < i.n; k++) {
        double dp = dist3(plain.seg[k].tip, q), da = dist3(a.seg[k].tip, q), di = dist3(i.seg[k].tip, q);
        closer += da < dp, farther += di > dp, tips++;
        xp += plain.seg[k].tip[0], xa += a.seg[k].tip[0], xi += i.seg[k].tip[0];
    }
    CHECK_INT(closer, tips);
    CHECK_INT(farther, tips);
    CHECK(xa / tips > xp / tips + 2.0);
    CHECK(xi / tips < xp / tips - 2.0);
    aono_skeleton_release(&plain), aono_skeleton_release(&a), aono_skeleton_release(&i);
}

/* Fig. 22: Dz < 0 lowers every tip below where it stands without gravity. */
TEST(gravity_lowers_every_tip)
{
    const char *plain_yaml = "levels: 8\npattern: dichotomous\nfi: [20, 50]\nri: [0.9, 0.6]\n";
    char heavy_yaml[256];
    snprintf(heavy_yaml, sizeof heavy_yaml, "%sdeviation: [0, 0, -0.6]\n", plain_yaml);
    aono_skeleton plain = {0}, heavy = {0};
    CHECK_INT(grow_tips(plain_yaml, 8, &plain), 0);
    CHECK_INT(grow_tips(heavy_yaml, 8, &heavy), 0);
    CHECK_INT(heavy.n, plain.n);
    int lower = 0;
    for (uint32_t k = 1; k < plain.n && k < heavy.n; k++) lower += heavy.seg[k].tip[2] < plain.seg[k].tip[2];
    CHECK_INT(lower, (int)plain.n - 1);
    /* the trunk does not deviate */
    CHECK_NEAR(heavy.seg[0].tip[2], 4.0, 0);
    aono_skeleton_release(&plain), aono_skeleton_release(&heavy);
}

/* (25) on one tip by hand, with and without renormalisation to ρ. */
TEST(deviation_by_hand)
{
    aono_controller ctl[2] = {{.q = {10, 0, 5}, .fac = 2.0}, {.q = {0, 0, 20}, .fac = -1.0}};
    aono_config cfg = {.deviation = {0, 0, -0.5}, .controllers = ctl, .n_controllers = 2, .preserve_length = 0};
    const double pb[3] = {0, 0, 5};
    double p[3] = {0, 0, 7};
    uint32_t which = 99;
    CHECK_INT(aono_deviate(&cfg, pb, 2.0, p, &which), 0);
    /* (0,0,7) + (0,0,−0.5) + 2 (10,0,−2)/√104 − (0,0,13)/13 */
    double d1 = sqrt(104.0);
    check_point(p, 20.0 / d1, 0.0, 7.0 - 0.5 - 4.0 / d1 - 1.0, 1e-12);
    cfg.preserve_length = 1;
    double q[3] = {0, 0, 7};
    CHECK_INT(aono_deviate(&cfg, pb, 2.0, q, &which), 0);
    CHECK_NEAR(dist3(q, pb), 2.0, 1e-12);
    double dir = (p[0] - pb[0]) / dist3(p, pb);
    CHECK_NEAR((q[0] - pb[0]) / 2.0, dir, 1e-12);
    /* a tip on a controller has no direction toward it */
    double on[3] = {10, 0, 5};
    CHECK_INT(aono_deviate(&cfg, pb, 2.0, on, &which), -1);
    CHECK_INT(which, 0);
}

/* ---------------------------------------------------------------------------------------------
 * Variants and determinism
 */

TEST(age_variants_by_levels)
{
    CHECK_INT(aono_variant_levels(8, 1.0), 8);
    CHECK_INT(aono_variant_levels(8, 0.5), 4);
    CHECK_INT(aono_variant_levels(7, 0.3), 3);
    CHECK_INT(aono_variant_levels(7, 0.01), 1);
    CHECK_INT(aono_variant_levels(6, 1.0 / 3.0), 2);
    aono_fixture fx;
    CHECK_INT(aono_fixture_open(&fx, "levels: 6\npattern: dichotomous\nfi: [25, 35]\n", 5), 0);
    mesh *young = NULL, *old = NULL;
    double hy = 0, ho = 0;
    CHECK_INT(aono_fixture_generate(&fx, 0.5, &young, &hy), 0);
    CHECK_INT(aono_fixture_generate(&fx, 1.0, &old, &ho), 0);
    CHECK(hy > 4.0 && hy < ho);
    CHECK(young->nt < old->nt / 4);
    aono_skeleton s = {0};
    CHECK_INT(aono_fixture_grow(&fx, 3, &s), 0);
    CHECK_INT(s.n, 15); /* 1 + 2 + 4 + 8 */
    aono_skeleton_release(&s);
    mesh_free(young), mesh_free(old);
    aono_fixture_close(&fx);
}

static mesh *generate_with_seed(const char *yaml, uint64_t seed)
{
    aono_fixture fx;
    mesh *m = NULL;
    if (aono_fixture_open(&fx, yaml, seed) || aono_fixture_generate(&fx, 1.0, &m, NULL)) {
        fprintf(stderr, "%s\n", fx.err.msg);
        mesh_free(m);
        m = NULL;
    }
    aono_fixture_close(&fx);
    return m;
}

static int same_mesh(const mesh *a, const mesh *b)
{
    return a->nv == b->nv && a->nt == b->nt && !memcmp(a->pos, b->pos, 3 * sizeof(float) * a->nv) &&
           !memcmp(a->nrm, b->nrm, 3 * sizeof(float) * a->nv) && !memcmp(a->uv, b->uv, 2 * sizeof(float) * a->nv) &&
           !memcmp(a->tri, b->tri, 3 * sizeof(uint32_t) * a->nt) && !memcmp(a->mat, b->mat, sizeof(int32_t) * a->nt);
}

TEST(same_seed_same_mesh)
{
    const char *yaml = "levels: 7\npattern: stochastic\nfi: [35, 40, 10]\nsf: 8\nri_method: random\n"
                       "leaf_count: 4\n";
    mesh *a = generate_with_seed(yaml, 42), *b = generate_with_seed(yaml, 42), *c = generate_with_seed(yaml, 43);
    CHECK(a && b && c);
    if (a && b && c) {
        CHECK(a->nt > 1000);
        CHECK(same_mesh(a, b));
        CHECK(!same_mesh(a, c));
    }
    mesh_free(a), mesh_free(b), mesh_free(c);
}

/* ---------------------------------------------------------------------------------------------
 * Geometry
 */

typedef struct edge {
    uint32_t a, b;
} edge;

static int edge_cmp(const void *x, const void *y)
{
    const edge *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    return p->b < q->b ? -1 : p->b > q->b;
}

typedef struct welded {
    float p[3];
    uint32_t index;
} welded;

static int welded_cmp(const void *x, const void *y)
{
    const welded *p = x, *q = y;
    int c = memcmp(p->p, q->p, sizeof p->p);
    return c ? c : (p->index < q->index ? -1 : p->index > q->index);
}

/* Vertex ids with vertices at the same position merged (the u seam repeats a vertex). */
static uint32_t *weld(const mesh *m)
{
    welded *w = malloc(m->nv * sizeof *w);
    uint32_t *id = malloc(m->nv * sizeof *id);
    for (uint32_t i = 0; i < m->nv; i++) memcpy(w[i].p, &m->pos[3 * i], sizeof w[i].p), w[i].index = i;
    qsort(w, m->nv, sizeof *w, welded_cmp);
    for (uint32_t i = 0; i < m->nv; i++)
        id[w[i].index] = i && !memcmp(w[i].p, w[i - 1].p, sizeof w[i].p) ? id[w[i - 1].index] : w[i].index;
    free(w);
    return id;
}

/* Is p inside the mother's tube or her continuation's at the joint J (mitre plane normal n)? */
static int inside_joint(const aono_skeleton *s, const aono_segment *m, const double p[3])
{
    double dm[3], J[3];
    for (int i = 0; i < 3; i++) dm[i] = m->tip[i] - m->base[i], J[i] = m->tip[i];
    double lm = sqrt(dm[0] * dm[0] + dm[1] * dm[1] + dm[2] * dm[2]);
    for (int i = 0; i < 3; i++) dm[i] /= lm;
    const aono_segment *c = &s->seg[m->continuation];
    double dc[3], n[3], lc;
    for (int i = 0; i < 3; i++) dc[i] = c->tip[i] - c->base[i];
    lc = sqrt(dc[0] * dc[0] + dc[1] * dc[1] + dc[2] * dc[2]);
    for (int i = 0; i < 3; i++) dc[i] /= lc, n[i] = dm[i] + dc[i];
    double side = 0, v[3];
    for (int i = 0; i < 3; i++) v[i] = p[i] - J[i], side += v[i] * n[i];
    const double *axis = side < 0 ? dm : dc;
    double along = v[0] * axis[0] + v[1] * axis[1] + v[2] * axis[2];
    double off = sqrt(fmax(0.0, v[0] * v[0] + v[1] * v[1] + v[2] * v[2] - along * along));
    return off <= m->radius_tip * (1.0 + 1e-4);
}

/* The bark is closed: every edge is shared by two triangles except the open bases of side
 * branches, and each of those lies inside the mother and her continuation at the joint. Every
 * triangle winds counter-clockwise round its outward normal; UVs are finite and u in [0, 1]. */
static void check_bark(const char *yaml, uint32_t levels, int expect_open)
{
    aono_fixture fx;
    CHECK_INT(aono_fixture_open(&fx, yaml, 9), 0);
    mesh *m = NULL;
    CHECK_INT(aono_fixture_generate(&fx, 1.0, &m, NULL), 0);
    aono_skeleton s = {0};
    CHECK_INT(aono_fixture_grow(&fx, levels, &s), 0);
    if (!m || !s.n) {
        mesh_free(m);
        aono_skeleton_release(&s);
        aono_fixture_close(&fx);
        return;
    }
    uint32_t *id = weld(m);
    edge *e = malloc(3 * m->nt * sizeof *e);
    for (uint32_t t = 0; t < m->nt; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = id[m->tri[3 * t + k]], b = id[m->tri[3 * t + (k + 1) % 3]];
            e[3 * t + k] = (edge){a < b ? a : b, a < b ? b : a};
        }
    qsort(e, 3 * m->nt, sizeof *e, edge_cmp);
    uint32_t open = 0, over = 0, outside = 0;
    for (uint32_t i = 0; i < 3 * m->nt;) {
        uint32_t j = i;
        while (j < 3 * m->nt && !edge_cmp(&e[i], &e[j])) j++;
        if (j - i == 1) {
            open++;
            /* which side branch's base ring holds it? */
            const float *pv = &m->pos[3 * e[i].a];
            double p[3] = {pv[0], pv[1], pv[2]};
            int found = 0;
            for (uint32_t k = 1; k < s.n && !found; k++) {
                const aono_segment *c = &s.seg[k];
                if (c->continues || fabs(dist3(p, c->base) - c->radius_base) > 1e-5) continue;
                found = 1;
                if (!inside_joint(&s, &s.seg[c->parent], p)) outside++;
            }
            if (!found) outside++;
        } else if (j - i > 2) {
            over++;
        }
        i = j;
    }
    uint32_t lateral_sides = 0;
    for (uint32_t k = 1; k < s.n; k++)
        if (!s.seg[k].continues && s.seg[s.seg[k].parent].continuation != AONO_NONE) lateral_sides += aono_ring_sides(&(aono_config){.sides = 8, .min_sides = 3,
                                                                                   .trunk_radius = 0.25},
                                                                   s.seg[k].radius_base);
    CHECK_INT(open, lateral_sides);
    CHECK(expect_open ? open > 0 : open == 0);
    /* capped bases of side branches may touch at a shared rim point, which welds their caps'
     * spokes together; with continuations every edge is shared by exactly two triangles */
    if (expect_open) CHECK_INT(over, 0);
    CHECK_INT(outside, 0);
    uint32_t inward = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
        const float *a = &m->pos[3 * m->tri[3 * t]], *b = &m->pos[3 * m->tri[3 * t + 1]],
                    *c = &m->pos[3 * m->tri[3 * t + 2]];
        double u[3], v[3], fn[3], vn[3] = {0, 0, 0};
        for (int i = 0; i < 3; i++) u[i] = b[i] - a[i], v[i] = c[i] - a[i];
        fn[0] = u[1] * v[2] - u[2] * v[1], fn[1] = u[2] * v[0] - u[0] * v[2], fn[2] = u[0] * v[1] - u[1] * v[0];
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 3; i++) vn[i] += m->nrm[3 * m->tri[3 * t + k] + i];
        inward += fn[0] * vn[0] + fn[1] * vn[1] + fn[2] * vn[2] <= 0.0;
    }
    CHECK_INT(inward, 0);
    uint32_t bad_uv = 0;
    for (uint32_t i = 0; i < m->nv; i++)
        bad_uv += !(m->uv[2 * i] >= 0.0f && m->uv[2 * i] <= 1.0f && isfinite(m->uv[2 * i + 1]) && m->uv[2 * i + 1] >= 0.0f);
    CHECK_INT(bad_uv, 0);
    free(e), free(id);
    aono_skeleton_release(&s);
    mesh_free(m);
    aono_fixture_close(&fx);
}

TEST(bark_joints_closed_and_outward)
{
    /* joints with continuations: open side-branch bases, all buried */
    check_bark("levels: 6\npattern: dichotomous\nfi: [20, 50]\nri: [0.9, 0.7]\ndeviation: [0, 0, -0.3]\nsides: 8\n", 6,
               1);
    /* every child turns more than 90 degrees: capped ends and capped bases, no opening at all */
    check_bark("levels: 4\npattern: dichotomous\nfi: [100, 120]\nri: [0.9, 0.7]\nsides: 8\n", 4, 0);
}

/* Leaves: leaf_count quads on an outermost branch of the full-grown tree and as many per metre
 * on the other leaf-bearing branches, with the leaf material. Ratios 0.8 make every level-k
 * branch 4 x 0.8^k long: level 4 carries 5 leaves, level 3 6.25 (6 or 7); the age-0.5 variant
 * (2 levels) carries 5 x 3.2/1.6384 = 9.77 on level 1 and 7.81 on level 2. */
static uint32_t leaf_quads(aono_fixture *fx, double age)
{
    mesh *m = NULL;
    CHECK_INT(aono_fixture_generate(fx, age, &m, NULL), 0);
    int32_t leaf_mat = scene_find_material(fx->scene, "tree_aono_kunii.leaf");
    CHECK(leaf_mat >= 0);
    uint32_t tris = 0;
    for (uint32_t t = 0; m && t < m->nt; t++) tris += m->mat[t] == leaf_mat;
    mesh_free(m);
    CHECK_INT(tris % 2, 0);
    return tris / 2;
}

TEST(leaves_and_materials)
{
    aono_fixture fx;
    CHECK_INT(aono_fixture_open(&fx,
                                "levels: 4\npattern: dichotomous\nfi: [30, 30]\nri: [0.8, 0.8]\nleaf_count: 5\n"
                                "leaf_levels: 2\n",
                                2),
              0);
    uint32_t old = leaf_quads(&fx, 1.0), young = leaf_quads(&fx, 0.5);
    CHECK(old >= 16 * 5 + 8 * 6 && old <= 16 * 5 + 8 * 7);
    CHECK(young >= 2 * 9 + 4 * 7 && young <= 2 * 10 + 4 * 8);
    CHECK_INT(fx.scene->n_textures, 2);
    int32_t leaf_mat = scene_find_material(fx.scene, "tree_aono_kunii.leaf");
    CHECK(leaf_mat >= 0 && fx.scene->materials[leaf_mat].alpha_mask == 1);
    aono_fixture_close(&fx);
}

/* The texture of material `name` of a tree made from `yaml` (owned by the fixture). */
static const texture *material_texture(aono_fixture *fx, const char *yaml, const char *name)
{
    CHECK_INT(aono_fixture_open(fx, yaml, 2), 0);
    int32_t mat = scene_find_material(fx->scene, name);
    CHECK(mat >= 0);
    int32_t tex = mat >= 0 ? fx->scene->materials[mat].texture : -1;
    CHECK(tex >= 0 && (uint32_t)tex < fx->scene->n_textures);
    return tex >= 0 ? &fx->scene->textures[tex] : NULL;
}

/* The leaf texture is the affine-map leaf of the `leaf:` key (the beech preset by default, user
 * maps as given): the same texels, so the same alpha area and outline, as leaf_affine_render. */
TEST(leaf_texture_is_the_affine_leaf)
{
    static const struct { const char *key, *maps; int preset; } cases[] = {
        {"", NULL, LEAF_AFFINE_BEECH},
        {"leaf: maple\n", NULL, LEAF_AFFINE_MAPLE},
        {"leaf: willow\n", NULL, LEAF_AFFINE_WILLOW},
        {"leaf: \"0.5 0 0 0.5 0.15 0; 0.5 0 0 0.5 0.35 0; 0.5 0 0 0.5 0.15 0.5; 0.5 0 0 0.5 0.35 0.5\"\n",
         "0.5 0 0 0.5 0.15 0; 0.5 0 0 0.5 0.35 0; 0.5 0 0 0.5 0.15 0.5; 0.5 0 0 0.5 0.35 0.5", -1},
    };
    /* the user maps fill the rectangle [0.3, 0.7] x [0, 1] */
    const uint32_t n = AONO_LEAF_TEXTURE_SIZE;
    static uint8_t want[AONO_LEAF_TEXTURE_SIZE * AONO_LEAF_TEXTURE_SIZE * 4];
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        char yaml[256];
        snprintf(yaml, sizeof yaml, "levels: 3\nleaf_count: 4\n%s", cases[c].key);
        leaf_affine_maps maps;
        if (cases[c].maps) CHECK_INT(leaf_affine_parse(cases[c].maps, &maps, NULL, 0), 0);
        else leaf_affine_preset_maps((leaf_affine_preset)cases[c].preset, &maps);
        CHECK_INT(leaf_affine_render(&maps, n, AONO_LEAF_TEXTURE_SEED, want, NULL, 0), 0);
        aono_fixture fx;
        const texture *t = material_texture(&fx, yaml, "tree_aono_kunii.leaf");
        CHECK(t && t->width == n && t->height == n && t->has_alpha);
        uint64_t area = 0, want_area = 0;
        for (uint32_t i = 0; t && i < n * n; i++) area += t->rgba[4 * i + 3] > 127, want_area += want[4 * i + 3] > 127;
        CHECK(want_area > n * n / 40);
        CHECK(area == want_area);
        CHECK(t && !memcmp(t->rgba, want, sizeof want));
        aono_fixture_close(&fx);
    }
}

/* `sylva tree-stats` figures: 5 levels of two children make 2^6 − 1 segments (the trunk is
 * level 0) and 32 axes (the trunk and, at each of the 31 forks, the child that does not continue
 * its mother); 3 levels of three children 40 segments and 1 + 13 · 2 = 27 axes. D_B of a
 * branching tree's wood lies between a line's and a plane's. */
static sylva_tree_stats stats_of(const char *yaml)
{
    sylva_tree_stats st = {.size = sizeof st};
    aono_fixture fx;
    mesh *m = NULL;
    if (aono_fixture_open(&fx, yaml, 3) || aono_fixture_generate(&fx, 1.0, &m, NULL)) {
        fprintf(stderr, "%s\n", fx.err.msg);
        CHECK(0);
        aono_fixture_close(&fx);
        return st;
    }
    const sylva_tree_stats_v1 *ext = aono_plugin()->extension(SYLVA_TREE_STATS_V1);
    CHECK(ext != NULL);
    if (ext) CHECK_INT(ext->last_stats(fx.state, &st), SYLVA_OK);
    if (m) CHECK_INT(st.triangles, m->nt);
    mesh_free(m);
    aono_fixture_close(&fx);
    return st;
}

TEST(tree_stats_count_segments_and_axes)
{
    sylva_tree_stats mono = stats_of("levels: 5\npattern: monopodial\nfi: [0, 35]\n");
    CHECK_INT(mono.recursion, 5);
    CHECK_INT(mono.segments, 63);
    CHECK_INT(mono.branches, 32);
    CHECK(mono.box_dimension > 1.0 && mono.box_dimension < 2.0);
    CHECK(mono.height > 0 && mono.bbox_max[2] == mono.height);
    sylva_tree_stats three = stats_of("levels: 3\npattern: ternary\nfi: [25, 35, 45]\nri: [0.8, 0.7, 0.7]\n");
    CHECK_INT(three.segments, 40);
    CHECK_INT(three.branches, 27);
}

/* The bark texture is the fractal bark of `bark:` and `bark_angle:` (smooth by default). */
TEST(bark_texture_is_the_fractal_bark)
{
    static const struct { const char *yaml; int preset; double angle; } cases[] = {
        {"levels: 3\n", BARK_FRACTAL_SMOOTH, NAN},
        {"levels: 3\nbark: furrowed\n", BARK_FRACTAL_FURROWED, NAN},
        {"levels: 3\nbark: scaly\nbark_angle: 40\n", BARK_FRACTAL_SCALY, 40},
    };
    const uint32_t n = AONO_BARK_TEXTURE_SIZE;
    static uint8_t want[AONO_BARK_TEXTURE_SIZE * AONO_BARK_TEXTURE_SIZE * 4];
    uint64_t sums[3] = {0};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        bark_fractal_params p = bark_fractal_preset_params((bark_fractal_preset)cases[c].preset);
        if (!isnan(cases[c].angle)) p.theta = cases[c].angle * M_PI / 180.0;
        tree_look_bark_texture(&p, n, want);
        aono_fixture fx;
        const texture *t = material_texture(&fx, cases[c].yaml, "tree_aono_kunii.bark");
        CHECK(t && t->width == n && t->height == n && !t->has_alpha);
        CHECK(t && !memcmp(t->rgba, want, sizeof want));
        for (uint32_t i = 0; t && i < n * n; i++) sums[c] += t->rgba[4 * i];
        aono_fixture_close(&fx);
    }
    CHECK(sums[0] != sums[1] && sums[1] != sums[2] && sums[0] != sums[2]); /* three different barks */
}

TEST_LIST(TEST_CASE(tree_stats_count_segments_and_axes), TEST_CASE(hand_branching_tilted_mother), TEST_CASE(hand_branching_two_levels),
          TEST_CASE(paper_transform_mirrored), TEST_CASE(frame_orthonormal_and_vertical),
          TEST_CASE(law_linear_through_two_points), TEST_CASE(law_quadratic_least_squares),
          TEST_CASE(law_exponential_at_zero_and_n2), TEST_CASE(law_drives_branching_angle),
          TEST_CASE(ratios_from_dimensions), TEST_CASE(ratios_reach_the_tree), TEST_CASE(attractor_and_inhibitor),
          TEST_CASE(gravity_lowers_every_tip), TEST_CASE(deviation_by_hand), TEST_CASE(age_variants_by_levels),
          TEST_CASE(same_seed_same_mesh), TEST_CASE(bark_joints_closed_and_outward), TEST_CASE(leaves_and_materials),
          TEST_CASE(leaf_texture_is_the_affine_leaf), TEST_CASE(bark_texture_is_the_fractal_bark))
