/* test_lsys_turtle.c — the turtle as Lparser 2.1 moves it (reference-outputs/README.md): the
 * sense of `+`, `&` and `<`, `$` and its handedness, `t`, `|` and `%`, lengths and size
 * modifiers (001 Fig. 3) with Lparser's bare factors, random turns, which commands record
 * polygon vertices, polygons across brackets and rules, colours, limits and unbalanced strings. */
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

/* Unit, square, and U = L x H: the hand the turtle starts with. */
static void check_start_hand(const lsys_frame *f)
{
    double u[3];
    cross3(f->l, f->h, u);
    CHECK_NEAR(dot3(f->h, f->h), 1, 1e-12);
    CHECK_NEAR(dot3(f->l, f->l), 1, 1e-12);
    CHECK_NEAR(dot3(f->h, f->l), 0, 1e-12);
    check_vec(f->u, u[0], u[1], u[2], 1e-12);
}

/* A frame turned away from the axes, so every component takes part. */
static lsys_frame skew_frame(void)
{
    lsys_frame f = {.h = {0, 0, 1}, .l = {0, 1, 0}, .u = {1, 0, 0}};
    lsys_frame_turn(&f, 0.4);
    lsys_frame_pitch(&f, 0.7);
    lsys_frame_roll(&f, -1.1);
    return f;
}

/* The end of the last segment of a one-line L-system (angle 30, F = 1). */
static const double *end_of(const char *str, test_record *rec)
{
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(30, 0, &rng);
    plugin_err e = {0};
    CHECK_INT(test_turtle(str, &cfg, rec, NULL, &e), LSYS_OK);
    CHECK(rec->n_seg > 0);
    return rec->p1[rec->n_seg ? rec->n_seg - 1 : 0];
}

TEST(turn_pitch_and_roll_turn_as_in_lparser)
{
    static test_record rec;
    double c = cos(30 * DEG), s = sin(30 * DEG);
    check_vec(end_of("F+(30)F", &rec), 0, s, 1 + c, 1e-12);       /* + toward +Y */
    check_vec(end_of("F-(30)F", &rec), 0, -s, 1 + c, 1e-12);
    check_vec(end_of("F&(30)F", &rec), s, 0, 1 + c, 1e-12);       /* & toward +X */
    check_vec(end_of("F^(30)F", &rec), -s, 0, 1 + c, 1e-12);
    check_vec(end_of("F>(90)+(30)F", &rec), -s, 0, 1 + c, 1e-12); /* > then +: toward -X */
    check_vec(end_of("F<(90)+(30)F", &rec), s, 0, 1 + c, 1e-12);
    check_vec(end_of("F+F", &rec), 0, s, 1 + c, 1e-12);            /* the file's angle */
    /* The start frame: H = +Z, L = +Y, U = +X, so U = L x H. */
    end_of("F", &rec);
    check_vec(rec.frame[0].h, 0, 0, 1, 0);
    check_vec(rec.frame[0].l, 0, 1, 0, 0);
    check_vec(rec.frame[0].u, 1, 0, 0, 0);
    lsys_frame f = skew_frame();
    check_start_hand(&f);
}

TEST(dollar_lays_L_flat_and_changes_hand)
{
    static test_record rec;
    /* After &(30): H = (sin 30, 0, cos 30). `$`: L = -(H x Z), U = -(H x L), neither made unit:
     * both are sin 30 = 0.5 long, and U = H x L now. */
    end_of("&(30)$F", &rec);
    const lsys_frame *f = &rec.frame[0];
    double s = sin(30 * DEG), c = cos(30 * DEG);
    check_vec(f->h, s, 0, c, 1e-12);
    check_vec(f->l, 0, s, 0, 1e-12);
    check_vec(f->u, -s * c, 0, s * s, 1e-12);
    double hl[3];
    cross3(f->h, f->l, hl);
    check_vec(f->u, hl[0], hl[1], hl[2], 1e-12);
    CHECK(f->u[2] > 0);
    /* A turn about the shortened U is smaller: tan a' = 0.5 tan 30. */
    double h[3] = {f->h[0], f->h[1], f->h[2]};
    const double *p = end_of("&(30)$+(30)F", &rec);
    double turned = acos(dot3(p, h) / sqrt(dot3(p, p)));
    CHECK_NEAR(turned, atan(0.5 * tan(30 * DEG)), 1e-12);
    /* A vertical heading keeps the frame. */
    end_of("$F", &rec);
    check_vec(rec.frame[0].l, 0, 1, 0, 0);
    check_vec(rec.frame[0].u, 1, 0, 0, 0);
    lsys_frame down = {.h = {0, 0, -1}, .l = {0, -1, 0}, .u = {1, 0, 0}};
    lsys_frame_roll_horizontal(&down);
    check_vec(down.l, 0, -1, 0, 0);
    check_vec(down.u, 1, 0, 0, 0);
}

TEST(tropism_pitches_by_e_times_horizontal_heading)
{
    static test_record rec;
    /* Horizontal H: t(0.5) pitches by 0.5 rad, as & does: down. */
    check_vec(end_of("&(90)t(0.5)F", &rec), cos(0.5), 0, -sin(0.5), 1e-12);
    /* At 30 degrees from vertical: by 0.5 sin 30. */
    const double *p = end_of("&(30)t(0.5)F", &rec);
    CHECK_NEAR(acos(p[2]), 30 * DEG + 0.5 * sin(30 * DEG), 1e-12);
    /* About the turtle's own L: after a roll, the bend follows L, not the world's -Z. */
    p = end_of("&(90)>(90)t(0.5)F", &rec);
    check_vec(p, cos(0.5), sin(0.5), 0, 1e-12);
    /* t without an argument: e = 0.2. */
    check_vec(end_of("&(90)tF", &rec), cos(0.2), 0, -sin(0.2), 1e-12);
    /* A negative e bends up. */
    CHECK(end_of("&(90)t(-0.1)F", &rec)[2] > 0);
}

TEST(tropism_argument_is_read_at_a_vertical_heading)
{
    /* Lparser leaves t's argument unread when H is vertical, so the `-` of t(-.5) turns the
     * turtle; sylva reads the argument and, H being vertical, does nothing. */
    static test_record rec;
    check_vec(end_of("Ft(-.5)F", &rec), 0, 0, 2, 0);
    check_vec(end_of("Ft(.5)F", &rec), 0, 0, 2, 0);
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
    static test_record rec;
    end_of("F|F%&F", &rec);
    check_vec(rec.p1[1], 0, 0, 0, 1e-12);      /* | comes back down */
    check_vec(rec.frame[1].l, 0, -1, 0, 1e-12);
    /* % after | turns U from +X to -X, so & then pitches the downward heading toward -X. */
    check_vec(rec.frame[2].h, -sin(30 * DEG), 0, -cos(30 * DEG), 1e-12);
}

TEST(bare_size_modifiers_divide)
{
    static test_record rec;
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(30, 10, &rng);
    plugin_err e = {0};
    CHECK_INT(test_turtle("F\"F?F;+F", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 4);
    CHECK_NEAR(rec.p1[1][2] - rec.p0[1][2], 1 / 0.9, 1e-12);       /* " : length / 0.9 */
    CHECK_NEAR(rec.radius[2], 1 / 0.9 * 0.10 / 0.7 / 2, 1e-12);    /* ? : thickness / 0.7 */
    double dy = rec.p1[3][1] - rec.p0[3][1];
    CHECK_NEAR(asin(dy / (1 / 0.9)), 30 * DEG / 0.9, 1e-12);         /* ; : angle / 0.9 */
}

TEST(only_f_z_and_dot_record_polygon_vertices)
{
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(90, 10, &rng);
    static test_record rec;
    lsys_turtle_stats st;
    plugin_err e = {0};
    CHECK_INT(test_turtle("{F+F+F}", &cfg, &rec, &st, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 3);
    CHECK_INT(st.polygons, 0);
    CHECK_INT(test_turtle("{f+f+f}", &cfg, &rec, &st, &e), LSYS_OK);
    CHECK_INT(st.polygons, 1);
    CHECK_INT(test_turtle("{.z+z}", &cfg, &rec, &st, &e), LSYS_OK);
    CHECK_INT(st.polygons, 1);
    CHECK_INT(test_turtle("{g.+g.+g}", &cfg, &rec, &st, &e), LSYS_OK);
    CHECK_INT(st.polygons, 0);
    /* Three recorded vertices make a polygon even when they coincide; the sinks do not get it. */
    CHECK_INT(test_turtle("{...}", &cfg, &rec, &st, &e), LSYS_OK);
    CHECK_INT(st.polygons, 1);
    CHECK_INT(rec.n_poly, 0);
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
    plugin_err e = {0};
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
    plugin_err e = {0};
    /* F(x) and Z(x) move x; Z is half of F; f, z, g move without drawing; ' and " scale the
     * length, ! and ? the thickness; ; and : the angle. */
    CHECK_INT(test_turtle("FZF(.5)Z(3)fzg'F\"\"F!F?(2)F;+F:(0.5)-F", &cfg, &rec, &st, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 10);
    double l2 = 1.8 / 0.9 / 0.9;
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
    /* ; makes the angle 30 / 0.9 degrees: the segment after `+` leans that much; : (0.5) halves
     * it and `-` turns back by half of it. */
    double a = 30 / 0.9;
    CHECK_NEAR(acos((rec.p1[8][2] - rec.p0[8][2]) / l2), a * DEG, 1e-9);
    CHECK_NEAR(acos((rec.p1[9][2] - rec.p0[9][2]) / l2), a / 2 * DEG, 1e-9);
    CHECK_INT(st.segments, 10);
    CHECK_INT(st.symbols, 22);
    /* min_thickness holds the width up to min_thickness / 100 file units, whatever the length
     * (Lparser): 0.5 here, against 2 x 0.1 x 0.7^3 and 0.1 x 0.1. */
    cfg.min_thickness = 50;
    CHECK_INT(test_turtle("!!!FF(0.1)?(100)F", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_NEAR(rec.radius[0], 0.5 / 2, 1e-12);
    CHECK_NEAR(rec.radius[1], 0.5 / 2, 1e-12);
    CHECK_NEAR(rec.radius[2], 2 * 0.1 * 0.343 * 100 / 2, 1e-12);
}

TEST(random_turns_are_bounded_and_repeatable)
{
    static test_record rec, again;
    plugin_err e = {0};
    double max_dev = 0;
    int wide = 0;
    for (uint64_t seed = 1; seed <= 200; seed++) {
        uint64_t rng = seed;
        lsys_turtle_config cfg = test_config(20, 10, &rng);
        CHECK_INT(test_turtle("~(5)F~F", &cfg, &rec, NULL, &e), LSYS_OK);
        double dev = acos(rec.p1[0][2] - rec.p0[0][2]);
        if (dev > max_dev) max_dev = dev;
        /* Three turns of at most 5 degrees each. */
        CHECK(dev <= 15 * DEG);
        /* ~ without an argument: up to 6 radians per axis, whatever the standard angle. */
        double dz = rec.p1[1][2] - rec.p0[1][2];
        if (acos(dz) > 3 * 20 * DEG + 15 * DEG) wide++;
        rng = seed;
        CHECK_INT(test_turtle("~(5)F~F", &cfg, &again, NULL, &e), LSYS_OK);
        CHECK(!memcmp(rec.p1, again.p1, 2 * sizeof rec.p1[0]));
    }
    CHECK(max_dev > 2 * DEG);
    CHECK(wide > 20);
}

TEST(polygons_span_brackets_and_rules)
{
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(90, 10, &rng);
    static test_record rec;
    plugin_err e = {0};
    /* `]` inside an open polygon restores the turtle, not the polygon. */
    CHECK_INT(test_turtle("{.[+f.]f.}", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_poly, 1);
    CHECK_INT(rec.poly_n[0], 3);
    check_vec(rec.poly_v[0][0], 0, 0, 0, 0);
    check_vec(rec.poly_v[0][1], 0, 1, 0, 1e-12);
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
}

TEST(colours)
{
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(90, 10, &rng);
    static test_record rec;
    plugin_err e = {0};
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
    plugin_err e = {0};
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

/* A segment near the largest double keeps a finite width (thickness percent of its length);
 * a width beyond finite numbers is refused with a sentence, not handed to the mesh. */
TEST(huge_segments_have_finite_width_or_are_refused)
{
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(90, 8, &rng);
    static test_record rec;
    plugin_err e = {0};
    CHECK_INT(test_turtle("F(1e308)", &cfg, &rec, NULL, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 1);
    CHECK_NEAR(rec.radius[0] / 4e306, 1, 1e-12);
    cfg.thickness = 500;
    CHECK_INT(test_turtle("F(1e308)", &cfg, &rec, NULL, &e), LSYS_ERR_LIMIT);
    CHECK_STR_CONTAINS(e.msg, "wider than finite numbers");
}

TEST(unbalanced_strings_are_survived)
{
    uint64_t rng = 1;
    lsys_turtle_config cfg = test_config(90, 10, &rng);
    static test_record rec;
    lsys_turtle_stats st;
    plugin_err e = {0};
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
     * (no vertex buffer yet), the others record one and two. */
    CHECK_INT(test_turtle("{}F{.}{.f}", &cfg, &rec, &st, &e), LSYS_OK);
    CHECK_INT(rec.n_seg, 1);
    CHECK_INT(rec.n_poly, 0);
    CHECK_INT(st.polygons, 0);
    CHECK_INT(st.stray_polygon_ends, 0);
    CHECK_INT(st.open_at_end, 0);
}

TEST_LIST(TEST_CASE(turn_pitch_and_roll_turn_as_in_lparser), TEST_CASE(dollar_lays_L_flat_and_changes_hand),
          TEST_CASE(tropism_pitches_by_e_times_horizontal_heading),
          TEST_CASE(tropism_argument_is_read_at_a_vertical_heading), TEST_CASE(turn_around_and_roll_around),
          TEST_CASE(bare_size_modifiers_divide), TEST_CASE(only_f_z_and_dot_record_polygon_vertices),
          TEST_CASE(fig3_segments_halve), TEST_CASE(moves_and_modifiers),
          TEST_CASE(random_turns_are_bounded_and_repeatable), TEST_CASE(polygons_span_brackets_and_rules),
          TEST_CASE(colours), TEST_CASE(limits_are_named),
          TEST_CASE(huge_segments_have_finite_width_or_are_refused), TEST_CASE(unbalanced_strings_are_survived))
