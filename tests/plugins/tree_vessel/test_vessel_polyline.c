/* test_vessel_polyline.c — reading the per-order control polylines (004 §3.3): linear between
 * points, constant past the ends, steps taking the later point, and the checks of a polyline. */
#include "harness.h"
#include "vessel_polyline.h"

static vessel_polyline make(const double *xy, uint32_t n, double x_max)
{
    vessel_polyline p;
    plugin_err err = {0};
    if (vessel_polyline_set(&p, xy, n, x_max, -1000, 1000, "test", &err))
        fprintf(stderr, "unexpected error: %s\n", err.msg);
    return p;
}

TEST(linear_between_points_and_constant_past_the_ends)
{
    const double xy[] = {2, 1, 10, 3};
    vessel_polyline p = make(xy, 2, 15);
    CHECK_NEAR(vessel_polyline_at(&p, 6), 2.0, 1e-15);
    CHECK_NEAR(vessel_polyline_at(&p, 2), 1.0, 1e-15);
    CHECK_NEAR(vessel_polyline_at(&p, 10), 3.0, 1e-15);
    CHECK_NEAR(vessel_polyline_at(&p, 0), 1.0, 1e-15);
    CHECK_NEAR(vessel_polyline_at(&p, 15), 3.0, 1e-15);
    CHECK_NEAR(vessel_polyline_at(&p, 3), 1.25, 1e-15);
}

TEST(single_point_is_constant)
{
    const double xy[] = {7, 0.4};
    vessel_polyline p = make(xy, 1, 15);
    CHECK_NEAR(vessel_polyline_at(&p, 0), 0.4, 0);
    CHECK_NEAR(vessel_polyline_at(&p, 15), 0.4, 0);
}

/* The spruce's k_s^w (004 §3.4.2) steps from 1.005 to 0.654 at w = 42.89. */
TEST(step_takes_the_later_point)
{
    const double xy[] = {0, 1, 42.89, 1.005, 42.89, 0.654, 50, 0.6256};
    vessel_polyline p = make(xy, 4, 50);
    CHECK_NEAR(vessel_polyline_at(&p, 42), 1 + 0.005 * 42 / 42.89, 1e-12);
    CHECK_NEAR(vessel_polyline_at(&p, 42.89), 0.654, 1e-15);
    CHECK_NEAR(vessel_polyline_at(&p, 43), 0.654 + (0.6256 - 0.654) * (43 - 42.89) / (50 - 42.89), 1e-12);
    CHECK_NEAR(vessel_polyline_at(&p, 50), 0.6256, 1e-15);
}

TEST(step_at_the_first_order)
{
    const double xy[] = {0, 2, 0, 1, 10, 1};
    vessel_polyline p = make(xy, 3, 15);
    CHECK_NEAR(vessel_polyline_at(&p, 0), 1.0, 0);
    CHECK_NEAR(vessel_polyline_at(&p, 5), 1.0, 0);
}

TEST(bad_polylines_are_refused_with_a_reason)
{
    vessel_polyline p;
    plugin_err err = {0};
    const double empty[] = {0, 0};
    CHECK_INT(vessel_polyline_set(&p, empty, 0, 15, 0, 1, "split_g", &err), SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "'split_g' has no points");
    CHECK_STR_CONTAINS(err.param, "split_g");

    const double decreasing[] = {0, 0.8, 5, 0.9, 3, 0.7};
    CHECK_INT(vessel_polyline_set(&p, decreasing, 3, 15, 0.5, 1, "split_g", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "point 2 has order 3 after 5; orders must not decrease");

    const double past_g[] = {0, 0.8, 16, 0.9};
    CHECK_INT(vessel_polyline_set(&p, past_g, 2, 15, 0.5, 1, "split_g", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "order 16; orders run from 0 to 15");

    const double negative[] = {-1, 0.8};
    CHECK_INT(vessel_polyline_set(&p, negative, 1, 50, 0, 2, "split_w", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "orders run from 0 to 50");

    const double angle[] = {0, 45, 15, 200};
    CHECK_INT(vessel_polyline_set(&p, angle, 2, 15, 0, 180, "angle_g", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "'angle_g' point 1 has value 200; values run from 0 to 180");

    const double not_finite[] = {0, NAN};
    CHECK_INT(vessel_polyline_set(&p, not_finite, 1, 15, 0, 1, "split_g", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "values run from 0 to 1");

    double many[2 * (VESSEL_POLYLINE_MAX_POINTS + 1)];
    for (uint32_t i = 0; i <= VESSEL_POLYLINE_MAX_POINTS; i++) many[2 * i] = i * 0.1, many[2 * i + 1] = 1;
    CHECK_INT(vessel_polyline_set(&p, many, VESSEL_POLYLINE_MAX_POINTS + 1, 15, 0, 2, "split_w", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "at most 64 are allowed");
}

TEST_LIST(TEST_CASE(linear_between_points_and_constant_past_the_ends),
          TEST_CASE(single_point_is_constant), TEST_CASE(step_takes_the_later_point),
          TEST_CASE(step_at_the_first_order), TEST_CASE(bad_polylines_are_refused_with_a_reason))
