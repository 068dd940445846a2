/* test_vessel_leaves.c — the five leaf distributions of 004 §3.3.2 on one terminal branch
 * standing along +Z from the origin (local x = +X, y = +Z, z = -Y). */
#include "harness.h"
#include "vessel_leaves.h"
#include "vessel_test_util.h"

static vessel_branch upright(double length, uint32_t vessels)
{
    vessel_branch b = {.length = length, .vessels = vessels, .terminal = 1};
    b.frame.c[0] = vv(1, 0, 0), b.frame.c[1] = vv(0, 0, 1), b.frame.c[2] = vv(0, -1, 0);
    return b;
}

static vessel_params with_leaves(vessel_leaf_type type, uint32_t count)
{
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    p.leaf_type = type, p.leaf_density = count, p.leaf_size = 0.1, p.phyllotaxis = 85;
    return p;
}

static double deg_between(vessel_vec a, vessel_vec b) { return acos(vv_dot(a, b)) / VESSEL_DEG; }

TEST(odd_count_puts_one_leaf_on_the_tip)
{
    vessel_branch b = upright(2, 1);
    vessel_leaf l[8];
    for (int type = 0; type < VESSEL_LEAF_TYPES; type++) {
        vessel_params p = with_leaves((vessel_leaf_type)type, 5);
        CHECK_INT(vessel_leaves_place(&b, &p, l), 5);
        CHECK_NEAR(l[0].base.z, 2.0, 1e-12);
        CHECK_NEAR(l[0].out.z, 1.0, 1e-12);
        CHECK_NEAR(l[0].size, M_SQRT2 * 0.1, 1e-12); /* half-diagonal l_l (004 Fig. C.8) */
        for (int k = 0; k < 5; k++) CHECK_NEAR(vv_dot(l[k].out, l[k].across), 0, 1e-12);
    }
    vessel_params none = with_leaves(VESSEL_LEAF_SPIRAL, 0);
    CHECK_INT(vessel_leaves_place(&b, &none, l), 0);
}

TEST(stacked_leaves_come_in_opposite_pairs)
{
    vessel_branch b = upright(3, 1);
    vessel_params p = with_leaves(VESSEL_LEAF_STACKED, 4);
    vessel_leaf l[4];
    CHECK_INT(vessel_leaves_place(&b, &p, l), 4);
    CHECK_NEAR(l[0].base.z, 1.0, 1e-12);
    CHECK_NEAR(l[1].base.z, 1.0, 1e-12);
    CHECK_NEAR(l[2].base.z, 2.0, 1e-12);
    CHECK_NEAR(l[0].out.x, 1.0, 1e-12);
    CHECK_NEAR(l[1].out.x, -1.0, 1e-12);
    /* the next pair is opposite too, turned VESSEL_LEAF_TWIST about the branch: no two pairs
     * share a plane */
    double t = VESSEL_LEAF_TWIST * M_PI / 180.0;
    CHECK_NEAR(l[2].out.x, cos(t), 1e-12);
    CHECK_NEAR(l[3].out.x, -cos(t), 1e-12);
    CHECK_NEAR(l[2].out.y + l[3].out.y, 0.0, 1e-12);
    CHECK(fabs(l[2].out.y) > 0.1);
}

TEST(staggered_leaves_alternate_sides)
{
    vessel_branch b = upright(4, 1);
    vessel_params p = with_leaves(VESSEL_LEAF_STAGGERED, 3);
    vessel_leaf l[3];
    CHECK_INT(vessel_leaves_place(&b, &p, l), 3);
    CHECK_NEAR(l[1].base.z, 4.0 / 3, 1e-12);
    CHECK_NEAR(l[2].base.z, 8.0 / 3, 1e-12);
    CHECK_NEAR(l[1].out.x, 1.0, 1e-12);
    CHECK_NEAR(l[2].out.x, -1.0, 1e-12);
    CHECK_NEAR(l[1].out.z, 0.0, 1e-12); /* perpendicular to the branch */
}

TEST(spiral_leaves_turn_by_the_phyllotaxis_angle)
{
    vessel_branch b = upright(1, 1);
    vessel_params p = with_leaves(VESSEL_LEAF_SPIRAL, 4);
    vessel_leaf l[4];
    CHECK_INT(vessel_leaves_place(&b, &p, l), 4);
    for (int k = 0; k + 1 < 4; k++) {
        CHECK_NEAR(deg_between(l[k].out, l[k + 1].out), 85, 1e-9);
        CHECK(l[k + 1].base.z > l[k].base.z);
        CHECK_NEAR(l[k].out.z, 0, 1e-12);
    }
}

TEST(bunched_leaves_sit_at_the_tip_spread_evenly)
{
    vessel_branch b = upright(1.5, 1);
    vessel_params p = with_leaves(VESSEL_LEAF_BUNCHED, 6);
    vessel_leaf l[6];
    CHECK_INT(vessel_leaves_place(&b, &p, l), 6);
    for (int k = 0; k < 6; k++) {
        CHECK_NEAR(l[k].base.z, 1.5, 1e-12);
        CHECK_NEAR(l[k].out.z, 0, 1e-12);
        CHECK_NEAR(deg_between(l[k].out, l[(k + 1) % 6].out), 60, 1e-9);
    }
}

TEST(coniferous_leaves_lean_toward_the_tip)
{
    vessel_branch b = upright(1, 1);
    vessel_params p = with_leaves(VESSEL_LEAF_CONIFEROUS, 4);
    vessel_leaf l[4];
    CHECK_INT(vessel_leaves_place(&b, &p, l), 4);
    for (int k = 0; k < 4; k++) CHECK_NEAR(deg_between(l[k].out, b.frame.c[1]), VESSEL_CONIFEROUS_ANGLE, 1e-9);
    CHECK(l[0].out.x > 0);
    CHECK(l[1].out.x < 0);
}

/* A branch cut short by the level of detail stands for S0 vessels: leaves sqrt(S0) larger. */
TEST(cut_branches_carry_larger_leaves)
{
    vessel_branch b = upright(1, 9);
    vessel_params p = with_leaves(VESSEL_LEAF_SPIRAL, 2);
    vessel_leaf l[2];
    CHECK_INT(vessel_leaves_place(&b, &p, l), 2);
    CHECK_NEAR(l[0].size, 3 * M_SQRT2 * 0.1, 1e-12);
}

TEST_LIST(TEST_CASE(odd_count_puts_one_leaf_on_the_tip), TEST_CASE(stacked_leaves_come_in_opposite_pairs),
          TEST_CASE(staggered_leaves_alternate_sides), TEST_CASE(spiral_leaves_turn_by_the_phyllotaxis_angle),
          TEST_CASE(bunched_leaves_sit_at_the_tip_spread_evenly),
          TEST_CASE(coniferous_leaves_lean_toward_the_tip), TEST_CASE(cut_branches_carry_larger_leaves))
