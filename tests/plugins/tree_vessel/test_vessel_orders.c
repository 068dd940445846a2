/* test_vessel_orders.c — the per-order values of 004 (3.17)–(3.22): products of a Gravelius and
 * a Weibull polyline at whole orders, clamped as the equations say, and the spruce's values
 * checked by hand. */
#include "harness.h"
#include "vessel_params.h"
#include "vessel_test_util.h"

static double lerp(double x0, double y0, double x1, double y1, double x)
{
    return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

TEST(split_ratio_is_clamped_to_half_and_one)
{
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    const double g_one[] = {0, 1, 15, 1}, w_two[] = {0, 2, 50, 2}, w_low[] = {0, 0.1, 50, 0.1};
    set_line(&p.by_g[VESSEL_SPLIT], g_one, 2);
    set_line(&p.by_w[VESSEL_SPLIT], w_two, 2);
    CHECK_NEAR(vessel_local_at(&p, 3, 7).split, 1.0, 0);      /* 2 -> 1 (3.17) */
    set_line(&p.by_w[VESSEL_SPLIT], w_low, 2);
    CHECK_NEAR(vessel_local_at(&p, 3, 7).split, 0.5, 0);      /* 0.1 -> 1/2 */
}

TEST(angles_are_clamped)
{
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    const double a150[] = {0, 150, 15, 150}, w_two[] = {0, 2, 50, 2}, am150[] = {0, -150, 15, -150};
    set_line(&p.by_g[VESSEL_ANGLE], a150, 2);
    set_line(&p.by_w[VESSEL_ANGLE], w_two, 2);
    CHECK_NEAR(vessel_local_at(&p, 0, 0).angle, 180.0, 0);    /* min(300, 180) (3.18) */
    set_line(&p.by_g[VESSEL_GRAVI], a150, 2);
    set_line(&p.by_w[VESSEL_GRAVI], w_two, 2);
    CHECK_NEAR(vessel_local_at(&p, 0, 0).gravi, 180.0, 0);    /* (3.19) */
    set_line(&p.by_g[VESSEL_GRAVI], am150, 2);
    CHECK_NEAR(vessel_local_at(&p, 0, 0).gravi, -180.0, 0);
    const double w_half[] = {0, 0.5, 50, 0.5};
    set_line(&p.by_w[VESSEL_GRAVI], w_half, 2);
    CHECK_NEAR(vessel_local_at(&p, 0, 0).gravi, -75.0, 1e-12); /* inside: the plain product */
}

TEST(lengths_are_plain_products)
{
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    const double g8[] = {0, 8, 15, 8}, w2[] = {0, 2, 50, 2}, g3[] = {0, 3, 15, 3}, w15[] = {0, 1.5, 50, 1.5};
    set_line(&p.by_g[VESSEL_LEN_MAX], g8, 2);
    set_line(&p.by_w[VESSEL_LEN_MAX], w2, 2);
    set_line(&p.by_g[VESSEL_LEN_MIN], g3, 2);
    set_line(&p.by_w[VESSEL_LEN_MIN], w15, 2);
    set_line(&p.by_g[VESSEL_LEN_SCALE], g3, 2);
    set_line(&p.by_w[VESSEL_LEN_SCALE], w2, 2);
    vessel_local_values v = vessel_local_at(&p, 4, 9);
    CHECK_NEAR(v.len_max, 16.0, 0);   /* (3.20) */
    CHECK_NEAR(v.len_min, 4.5, 0);    /* (3.21) */
    CHECK_NEAR(v.len_scale, 6.0, 0);  /* (3.22) */
}

/* The spruce of 004 §3.4.2 at a few whole orders, computed from the printed points. */
TEST(spruce_values_at_whole_orders)
{
    vessel_params p = preset(VESSEL_PRESET_SPRUCE);
    vessel_local_values v = vessel_local_at(&p, 1, 0);
    CHECK_NEAR(v.split, lerp(0.7749, 0.9615, 1.827, 0.8288, 1), 1e-12);
    CHECK_NEAR(v.angle, lerp(0, 128.8, 1.164, 17.91, 1), 1e-12);
    CHECK_NEAR(v.gravi, lerp(0.3875, 34.62, 1.034, -4.265, 1), 1e-12);
    CHECK_NEAR(v.len_min, lerp(0, 0.7109, 1.293, 0.8531, 1), 1e-12);
    CHECK_NEAR(v.len_scale, lerp(0.7749, 0.5385, 2.522, 1.327, 1) * 1.014, 1e-12);
    v = vessel_local_at(&p, 0, 42);
    CHECK_NEAR(v.split, 0.955 * lerp(0, 1, 42.89, 1.005, 42), 1e-12);
    v = vessel_local_at(&p, 0, 43); /* past the step at 42.89 */
    CHECK_NEAR(v.split, 0.955 * lerp(42.89, 0.654, 50, 0.6256, 43), 1e-12);
    v = vessel_local_at(&p, 2, 46);
    CHECK_NEAR(v.split, fmax(0.5, lerp(1.827, 0.8288, 4.207, 0.8269, 2) * lerp(42.89, 0.654, 50, 0.6256, 46)), 1e-12);
    CHECK_NEAR(v.len_scale, lerp(0.7749, 0.5385, 2.522, 1.327, 2) * lerp(45.26, 0.5877, 50, 0.01896, 46), 1e-12);
}

TEST(orders_past_the_polylines_read_the_last_values)
{
    vessel_params p = preset(VESSEL_PRESET_SPRUCE);
    vessel_local_values a = vessel_local_at(&p, 20, 80), b = vessel_local_at(&p, 15, 50);
    CHECK_NEAR(a.split, b.split, 0);
    CHECK_NEAR(a.len_scale, b.len_scale, 0);
    vessel_order_table *t = malloc(sizeof *t);
    vessel_order_table_fill(&p, t);
    CHECK_NEAR(vessel_order_lookup(t, 40, 400)->len_scale, b.len_scale, 0);
    CHECK_NEAR(vessel_order_lookup(t, 1, 43)->split, vessel_local_at(&p, 1, 43).split, 0);
    free(t);
}

TEST(every_preset_passes_its_checks)
{
    for (int k = 0; k < VESSEL_PRESETS; k++) {
        vessel_params p = preset((vessel_preset)k);
        plugin_err err = {0};
        CHECK_INT(vessel_params_check(&p, &err), 0);
        if (err.msg[0]) fprintf(stderr, "%s: %s\n", vessel_preset_names[k], err.msg);
    }
}

TEST(parameter_checks_name_the_key)
{
    plugin_err err = {0};
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    p.vessels = 0;
    CHECK_INT(vessel_params_check(&p, &err), -1);
    CHECK_STR_CONTAINS(err.param, "vessels");
    CHECK_STR_CONTAINS(err.msg, "1 to 100000 vessels");
    p.vessels = VESSEL_MAX_VESSELS + 1;
    CHECK_INT(vessel_params_check(&p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "'vessels' (S) is 100001");
    p = preset(VESSEL_PRESET_BEECH);
    p.trunk_length = -2;
    CHECK_INT(vessel_params_check(&p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "'trunk_length' is -2 m; valid values are above 0 to 100 m");
    p = preset(VESSEL_PRESET_BEECH);
    p.leaf_size = -0.1;
    CHECK_INT(vessel_params_check(&p, &err), -1);
    CHECK_STR_CONTAINS(err.param, "leaf_size");
    p = preset(VESSEL_PRESET_BEECH);
    p.phyllotaxis = 400;
    CHECK_INT(vessel_params_check(&p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "'phyllotaxis' is 400 deg");
    p = preset(VESSEL_PRESET_BEECH);
    p.by_g[VESSEL_ANGLE].y[1] = 181;
    CHECK_INT(vessel_params_check(&p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "'angle_g' point 1 has value 181; values run from 0 to 180");
    p = preset(VESSEL_PRESET_BEECH);
    p.by_w[VESSEL_GRAVI].n = 0;
    CHECK_INT(vessel_params_check(&p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "'gravimorphism_w' has no points");
    p = preset(VESSEL_PRESET_BEECH);
    p.by_g[VESSEL_LEN_MIN].x[2] = 3; /* after 7.5 */
    CHECK_INT(vessel_params_check(&p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "orders must not decrease");
    p = preset(VESSEL_PRESET_BEECH);
    p.sides = 3;
    CHECK_INT(vessel_params_check(&p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "4 to 15 sides");
    p = preset(VESSEL_PRESET_BEECH);
    p.wind_direction[0] = 0;
    CHECK_INT(vessel_params_check(&p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "zero vector");
    p = preset(VESSEL_PRESET_BEECH);
    p.leaf_transmittance[1] = 0.9f;
    CHECK_INT(vessel_params_check(&p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "cannot scatter more than it receives");
}

TEST_LIST(TEST_CASE(split_ratio_is_clamped_to_half_and_one), TEST_CASE(angles_are_clamped),
          TEST_CASE(lengths_are_plain_products), TEST_CASE(spruce_values_at_whole_orders),
          TEST_CASE(orders_past_the_polylines_read_the_last_values),
          TEST_CASE(every_preset_passes_its_checks), TEST_CASE(parameter_checks_name_the_key))
