/* test_lsys_turtle.c — the turtle: 001 Table 2's rotation matrices, `$` (eq. 2), tropism
 * (eq. 3), `|` and `%`, lengths and size modifiers (Fig. 3), random turns, polygons across
 * brackets and rules, colours, limits and unbalanced strings. */
#include "harness.h"

#include <math.h>

#include "lsys_test_util.h"

#define DEG (M_PI / 180.0)

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(const double *a, const double *b, double *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1], o[1] = a[2] * b[0] - a[0] * b[2], o[2] = a[0] * b[1] - a[1] * b[0];
}

static void check_vec(const double *got, double x, double y, double z, double tol)
{
    CHECK_NEAR(got[0], x, tol);
    CHECK_NEAR(got[1], y, tol);
    CHECK_NEAR(got[2], z, tol);
}

static void check_orthonormal(const lsys_frame *f)
{
    double u[3];
    cross3(f->h, f->l, u);
    CHECK_NEAR(dot3(f->h, f->h), 1, 1e-12);
    CHECK_NEAR(dot3(f->l, f->l), 1, 1e-12);
    CHECK_NEAR(dot3(f->h, f->l), 0, 1e-12);
    check_vec(f->u, u[0], u[1], u[2], 1e-12);
}

/* A frame turned away from the axes, so every component takes part. */
static lsys_frame skew_frame(void)
{
    lsys_frame f = {.h = {0, 0, 1}, .l = {0, 1, 0}, .u = {-1, 0, 0}};
    lsys_frame_turn(&f, 0.4);
    lsys_frame_pitch(&f, 0.7);
    lsys_frame_roll(&f, -1.1);
    return f;
}

/* [H L U] R with R given row by row as printed in 001. */
static lsys_frame times(const lsys_frame *f, const double r[3][3])
{
    const double *col[3] = {f->h, f->l, f->u};
    lsys_frame out;
    double *dst[3] = {out.h, out.l, out.u};
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++) dst[j][k] = col[0][k] * r[0][j] + col[1][k] * r[1][j] + col[2][k] * r[2][j];
    return out;
}

static void check_frame(const lsys_frame *got, const lsys_frame *want)
{
    check_vec(got->h, want->h[0], want->h[1], want->h[2], 1e-12);
    check_vec(got->l, want->l[0], want->l[1], want->l[2], 1e-12);
    check_vec(got->u, want->u[0], want->u[1], want->u[2], 1e-12);
}

TEST(rotation_matrices_of_table_2)
{
    double a = 0.3, c = cos(a), s = sin(a);
    const double ru[3][3] = {{c, s, 0}, {-s, c, 0}, {0, 0, 1}};
    const double rl[3][3] = {{c, 0, -s}, {0, 1, 0}, {s, 0, c}};
    const double rh[3][3] = {{1, 0, 0}, {0, c, -s}, {0, s, c}};
    lsys_frame f = skew_frame(), g;
    g = f, lsys_frame_turn(&g, a);
    lsys_frame w = times(&f, ru);
    check_frame(&g, &w);
    check_orthonormal(&g);
    g = f, lsys_frame_pitch(&g, a);
    w = times(&f, rl);
    check_frame(&g, &w);
    check_orthonormal(&g);
    g = f, lsys_frame_roll(&g, a);
    w = times(&f, rh);
    check_frame(&g, &w);
    check_orthonormal(&g);
}

TEST(turtle_starts_up_and_turns_as_table_2)
{
    /* H = +Z, L = +Y, U = H x L = -X. `+(90)` gives H = -L, `&(90)` H = U, and a roll
     * `<(90)` turns L into U before `&(90)` pitches. */
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(90, 10, &rng);
    static test_record rec;
    lsys_error e = {{0}};
    CHECK_INT(test_turtle("F[+F][-F][&F][^F][<&F]", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 6);
    check_vec(rec.p1[0], 0, 0, 1, 1e-12);
    check_vec(rec.p1[1], 0, -1, 1, 1e-12);
    check_vec(rec.p1[2], 0, 1, 1, 1e-12);
    check_vec(rec.p1[3], -1, 0, 1, 1e-12);
    check_vec(rec.p1[4], 1, 0, 1, 1e-12);
    check_vec(rec.p1[5], 0, -1, 1, 1e-12);
    check_vec(rec.frame[0].u, -1, 0, 0, 0);
}

TEST(dollar_keeps_L_horizontal)
{
    lsys_frame f = skew_frame();
    double h[3] = {f.h[0], f.h[1], f.h[2]};
    lsys_frame_roll_horizontal(&f);
    CHECK_NEAR(f.l[2], 0, 1e-15);
    check_vec(f.h, h[0], h[1], h[2], 0);
    check_orthonormal(&f);
    /* L = V x H / |V x H| with V = (0, 0, -1) (001 eq. 2). */
    double v[3] = {0, 0, -1}, l[3];
    cross3(v, h, l);
    double n = sqrt(dot3(l, l));
    check_vec(f.l, l[0] / n, l[1] / n, l[2] / n, 1e-12);
    /* Through the turtle: after any turns, $ leaves L horizontal, also after later segments. */
    uint64_t rng = 7;
    lsys_turtle_config cfg = test_config(33, 10, &rng);
    static test_record rec;
    lsys_error e = {{0}};
    CHECK_INT(test_turtle("&>(40)+$F~(30)$F^(70)<(15)$F", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 3);
    for (uint32_t i = 0; i < rec.n_seg; i++) {
        CHECK_NEAR(rec.frame[i].l[2], 0, 1e-12);
        check_orthonormal(&rec.frame[i]);
    }
    /* Vertical heading: nothing to roll to, the frame is kept. */
    lsys_frame up = {.h = {0, 0, 1}, .l = {0, 1, 0}, .u = {-1, 0, 0}};
    lsys_frame_roll_horizontal(&up);
    check_vec(up.l, 0, 1, 0, 0);
}

TEST(tropism_bends_toward_minus_z)
{
    /* H horizontal: |H x T| = 1, so t(0.2) turns H by 0.2 rad straight down. */
    lsys_frame f = {.h = {1, 0, 0}, .l = {0, 1, 0}, .u = {0, 0, 1}};
    lsys_frame_tropism(&f, 0.2);
    check_vec(f.h, cos(0.2), 0, -sin(0.2), 1e-12);
    check_orthonormal(&f);
    /* H at 60 degrees from T: turned by e sin 60 (eq. 3), within the plane of H and T. */
    double th = 60 * DEG;
    lsys_frame g = {.h = {sin(th), 0, -cos(th)}, .l = {0, 1, 0}, .u = {0, 0, 0}};
    cross3(g.h, g.l, g.u);
    lsys_frame_tropism(&g, 0.5);
    double t[3] = {0, 0, -1}, d = acos(dot3(g.h, t));
    CHECK_NEAR(d, th - 0.5 * sin(th), 1e-12);
    CHECK_NEAR(g.h[1], 0, 1e-15);
    /* A negative e bends up; a vertical heading is left alone. */
    lsys_frame k = {.h = {1, 0, 0}, .l = {0, 1, 0}, .u = {0, 0, 1}};
    lsys_frame_tropism(&k, -0.1);
    CHECK(k.h[2] > 0);
    lsys_frame v = {.h = {0, 0, 1}, .l = {0, 1, 0}, .u = {-1, 0, 0}};
    lsys_frame_tropism(&v, 0.3);
    check_vec(v.h, 0, 0, 1, 0);
    /* Repeated t along a horizontal branch: each segment lower than the one before (Fig. 6). */
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(10, 10, &rng);
    static test_record rec;
    lsys_error e = {{0}};
    CHECK_INT(test_turtle("&(90)tFtFtFtF", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 4);
    double prev = 0;
    for (uint32_t i = 0; i < 4; i++) {
        double dz = rec.p1[i][2] - rec.p0[i][2];
        CHECK(dz < prev);
        prev = dz;
    }
    CHECK_NEAR(rec.p1[0][2], -sin(0.2), 1e-12); /* t without argument: e = 0.2 */
}

TEST(turn_around_and_roll_around)
{
    lsys_frame f = skew_frame(), g = f;
    lsys_frame_turn(&g, M_PI); /* | */
    check_vec(g.h, -f.h[0], -f.h[1], -f.h[2], 1e-12);
    check_vec(g.l, -f.l[0], -f.l[1], -f.l[2], 1e-12);
    check_vec(g.u, f.u[0], f.u[1], f.u[2], 1e-12);
    g = f;
    lsys_frame_roll(&g, M_PI); /* % */
    check_vec(g.h, f.h[0], f.h[1], f.h[2], 1e-12);
    check_vec(g.l, -f.l[0], -f.l[1], -f.l[2], 1e-12);
    check_vec(g.u, -f.u[0], -f.u[1], -f.u[2], 1e-12);
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(30, 10, &rng);
    static test_record rec;
    lsys_error e = {{0}};
    CHECK_INT(test_turtle("F|F%&F", &cfg, &rec, NULL, &e), LSYS_OK);
    check_vec(rec.p1[1], 0, 0, 0, 1e-12);      /* | comes back down */
    check_vec(rec.frame[1].l, 0, -1, 0, 1e-12);
    /* % after | turns U from -X to +X, so & then pitches the downward heading toward +X. */
    check_vec(rec.frame[2].h, sin(30 * DEG), 0, -cos(30 * DEG), 1e-12);
}

TEST(fig3_segments_halve)
{
    /* 001 Fig. 3: A=FA, F='(2)F'(0.5); at recursion 4 the prisms are 8, 4, 2, 1 long. */
    lsys_system *s = test_read("4\n30\n10\nA\nA=FA\nF='(2)F'(0.5)\n@\n");
    char *str = s ? test_derive(s, 4) : NULL;
    CHECK(str != NULL);
    if (!str) return;
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(30, 10, &rng);
    static test_record rec;
    lsys_error e = {{0}};
    CHECK_INT(test_turtle(str, &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 4);
    double want = 8, z = 0;
    for (uint32_t i = 0; i < rec.n_seg && i < 4; i++) {
        CHECK_NEAR(rec.p1[i][2] - rec.p0[i][2], want, 1e-12);
        CHECK_NEAR(rec.p0[i][2], z, 1e-12);
        CHECK_NEAR(rec.radius[i], want * 0.10 / 2, 1e-12); /* width 10 % of the length */
        z += want, want /= 2;
    }
    free(str);
    lsys_system_free(s);
}

TEST(moves_and_modifiers)
{
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(30, 10, &rng);
    cfg.base_length = 2;
    static test_record rec;
    lsys_turtle_stats st;
    lsys_error e = {{0}};
    /* F(x) and Z(x) move x; Z is half of F; f, z, g move without drawing; ' and " scale the
     * length, ! and ? the thickness; ; and : the angle. */
    CHECK_INT(test_turtle("FZF(.5)Z(3)fzg'F\"\"F!F?(2)F;+F:(0.5)-F", &cfg, &rec, &st, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 10);
    double l2 = 1.8 * 1.1 * 1.1;
    double lengths[10] = {2, 1, 0.5, 3, 1.8, l2, l2, l2, l2, l2};
    for (uint32_t i = 0; i < 4; i++) CHECK_NEAR(rec.p1[i][2] - rec.p0[i][2], lengths[i], 1e-12);
    CHECK_NEAR(rec.p0[4][2], 6.5 + 2 + 1 + 2, 1e-12); /* after f, z, g */
    for (uint32_t i = 4; i < 10; i++) {
        double dx = rec.p1[i][0] - rec.p0[i][0], dy = rec.p1[i][1] - rec.p0[i][1], dz = rec.p1[i][2] - rec.p0[i][2];
        CHECK_NEAR(sqrt(dx * dx + dy * dy + dz * dz), lengths[i], 1e-9);
    }
    CHECK_NEAR(rec.radius[5], l2 * 0.10 / 2, 1e-12);
    CHECK_NEAR(rec.radius[6], l2 * 0.07 / 2, 1e-12);
    CHECK_NEAR(rec.radius[7], l2 * 0.14 / 2, 1e-12);
    /* ; makes the angle 33 degrees: the segment after `+` leans 33 degrees; : (0.5) halves it
     * and `-` turns back by 16.5. */
    CHECK_NEAR(acos((rec.p1[8][2] - rec.p0[8][2]) / l2), 33 * DEG, 1e-9);
    CHECK_NEAR(acos((rec.p1[9][2] - rec.p0[9][2]) / l2), 16.5 * DEG, 1e-9);
    CHECK_INT(st.segments, 10);
    CHECK_INT(st.symbols, 22);
    /* min_thickness holds the width up. */
    cfg.min_thickness = 50;
    CHECK_INT(test_turtle("!!!F", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_NEAR(rec.radius[0], 2 * 0.5 / 2, 1e-12);
}

TEST(random_turns_are_bounded_and_repeatable)
{
    static test_record rec, again;
    lsys_error e = {{0}};
    double max_dev = 0;
    for (uint64_t seed = 1; seed <= 200; seed++) {
        uint64_t rng = seed;
        lsys_turtle_config cfg = test_config(20, 10, &rng);
        CHECK_INT(test_turtle("~(5)F~F", &cfg, &rec, NULL, &e), LSYS_OK);
        double dev = acos(rec.p1[0][2] - rec.p0[0][2]);
        if (dev > max_dev) max_dev = dev;
        /* Three turns of at most 5 degrees each. */
        CHECK(dev <= 15 * DEG);
        /* ~ without an argument: at most the standard angle (20) per axis. */
        double dz = rec.p1[1][2] - rec.p0[1][2];
        CHECK(acos(dz) <= 15 * DEG + 3 * 20 * DEG);
        rng = seed;
        CHECK_INT(test_turtle("~(5)F~F", &cfg, &again, NULL, &e), LSYS_OK);
        CHECK(!memcmp(rec.p1, again.p1, 2 * sizeof rec.p1[0]));
    }
    CHECK(max_dev > 2 * DEG);
}

TEST(polygons_span_brackets_and_rules)
{
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(90, 10, &rng);
    static test_record rec;
    lsys_error e = {{0}};
    /* `]` inside an open polygon restores the turtle, not the polygon. */
    CHECK_INT(test_turtle("{.[+f.]f.}", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_poly, 1);
    CHECK_INT(rec.poly_n[0], 3);
    check_vec(rec.poly_v[0][0], 0, 0, 0, 0);
    check_vec(rec.poly_v[0][1], 0, -1, 0, 1e-12);
    check_vec(rec.poly_v[0][2], 0, 0, 1, 1e-12);
    /* A polygon opened in one rule and closed in another (abop-nested-polygon-leaves.ls). */
    lsys_system *s = test_read("1\n90\n10\nAB\nA={.f\nB=+f.}\n@\n");
    char *str = s ? test_derive(s, 1) : NULL;
    CHECK(str && !strcmp(str, "{.f+f.}"));
    if (str) CHECK_INT(test_turtle(str, &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_poly, 1);
    CHECK_INT(rec.poly_n[0], 3);
    free(str);
    lsys_system_free(s);
    /* Nested polygons: the inner one closes first, the outer keeps its vertices. The closing
     * f of a leaf that returns to its start adds no vertex. */
    CHECK_INT(test_turtle("{.f{.+f+f}&f.}c{+(30)f(2)-(120)f(2)-(120)f(2)}", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_poly, 3);
    CHECK_INT(rec.poly_n[0], 3);
    CHECK_INT(rec.poly_n[1], 3);
    CHECK_INT(rec.poly_n[2], 3);
    CHECK_INT(rec.poly_colour[2], 3);
    /* F inside a polygon draws and records. */
    CHECK_INT(test_turtle("{F+F+F}", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 3);
    CHECK_INT(rec.n_poly, 1);
}

TEST(colours)
{
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(90, 10, &rng);
    static test_record rec;
    lsys_error e = {{0}};
    CHECK_INT(test_turtle("FcF[c(7)F]Fc(0)Fc(-3)F", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 6);
    int want[6] = {2, 3, 7, 3, 0, 0};
    for (int i = 0; i < 6; i++) CHECK_INT(rec.seg_colour[i], want[i]);
    /* 0e400 is zero (not 0 times infinity, a NaN cast to an index); a number past the range of
     * doubles is no argument, so c counts on by one. */
    CHECK_INT(test_turtle("c(0e400)Fc(1e400)F", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 2);
    CHECK_INT(rec.seg_colour[0], 0);
    CHECK_INT(rec.seg_colour[1], 1);
}

TEST(limits_are_named)
{
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(90, 10, &rng);
    static test_record rec;
    lsys_error e = {{0}};
    cfg.max_segments = 3;
    CHECK_INT(test_turtle("FFFF", &cfg, &rec, NULL, &e), LSYS_ERR_LIMIT);
    CHECK_STR_CONTAINS(e.msg, "max_segments = 3");
    cfg.max_segments = 100;
    cfg.max_depth = 3;
    CHECK_INT(test_turtle("[[[[F]]]]", &cfg, &rec, NULL, &e), LSYS_ERR_LIMIT);
    CHECK_STR_CONTAINS(e.msg, "deeper than 3 levels");
    cfg.max_depth = 100;
    cfg.max_polygons = 1;
    CHECK_INT(test_turtle("{f+f+f}{f+f+f}", &cfg, &rec, NULL, &e), LSYS_ERR_LIMIT);
    CHECK_STR_CONTAINS(e.msg, "max_polygons = 1");
    cfg.max_polygons = 100;
    cfg.max_polygon_vertices = 4;
    CHECK_INT(test_turtle("{ff+ff+ff}", &cfg, &rec, NULL, &e), LSYS_ERR_LIMIT);
    CHECK_STR_CONTAINS(e.msg, "max_polygon_vertices = 4");
    cfg.max_polygon_vertices = 100;
    CHECK_INT(test_turtle("\"(1e300)\"(1e300)F", &cfg, &rec, NULL, &e), LSYS_ERR_LIMIT);
    CHECK_STR_CONTAINS(e.msg, "beyond finite coordinates");
}

TEST(unbalanced_strings_are_survived)
{
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(90, 10, &rng);
    static test_record rec;
    lsys_turtle_stats st;
    lsys_error e = {{0}};
    CHECK_INT(test_turtle("]]F}[F{f", &cfg, &rec, &st, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 2);
    CHECK_INT(st.stray_pops, 2);
    CHECK_INT(st.stray_polygon_ends, 1);
    CHECK_INT(st.open_at_end, 2);
    CHECK(st.has_bounds);
    /* Vertical tubes of radius 0.05: their rings reach sideways, not up or down. */
    CHECK_NEAR(st.hi[2], 2, 1e-12);
    CHECK_NEAR(st.lo[2], 0, 1e-12);
    CHECK_NEAR(st.lo[0], -0.05, 1e-12);
    CHECK_NEAR(st.hi[1], 0.05, 1e-12);
    /* Polygons without enough vertices: the first `{` closes before any vertex was ever stored
     * (no vertex buffer yet), the others hold one and two. */
    CHECK_INT(test_turtle("{}F{.}{.f.}", &cfg, &rec, &st, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 1);
    CHECK_INT(rec.n_poly, 0);
    CHECK_INT(st.polygons, 0);
    CHECK_INT(st.stray_polygon_ends, 0);
    CHECK_INT(st.open_at_end, 0);
}

TEST_LIST(TEST_CASE(rotation_matrices_of_table_2), TEST_CASE(turtle_starts_up_and_turns_as_table_2),
          TEST_CASE(dollar_keeps_L_horizontal), TEST_CASE(tropism_bends_toward_minus_z),
          TEST_CASE(turn_around_and_roll_around), TEST_CASE(fig3_segments_halve), TEST_CASE(moves_and_modifiers),
          TEST_CASE(random_turns_are_bounded_and_repeatable), TEST_CASE(polygons_span_brackets_and_rules),
          TEST_CASE(colours), TEST_CASE(limits_are_named), TEST_CASE(unbalanced_strings_are_survived))
