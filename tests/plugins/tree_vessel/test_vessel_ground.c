/* test_vessel_ground.c — the soft floor under a weeping tree (vessel_ground.h): the weeping
 * willow's mesh stays above the ground at every age while its curtain still reaches down to the
 * clearance; each main child still starts at its mother's tip; trees clear of the ground (beech,
 * spruce, maple) are left as grown. */
#include <math.h>

#include "harness.h"
#include "vessel_ground.h"
#include "vessel_mesh.h"
#include "vessel_test_util.h"

TEST(willow_mesh_stays_above_the_ground)
{
    vessel_params p = preset(VESSEL_PRESET_WEEPING_WILLOW);
    const double ages[] = {1.0, 0.6, 0.3};
    for (int a = 0; a < 3; a++) {
        vessel_tree t = {0};
        vessel_mesh m = {0};
        plugin_err err = {0};
        CHECK_INT(grow(&p, ages[a], 0, &t), 0);
        CHECK_INT(vessel_mesh_build(&t, &p, 1, 2, &m, &err), 0);
        uint32_t below = 0;
        for (uint32_t v = 0; v < m.nv; v++) below += m.pos[3 * v + 2] < 0.0f;
        CHECK_INT(below, 0);
        double c = vessel_ground_clearance(&t, &p), low = vessel_lowest_hanging_tip(&t);
        if (!(low >= c - 1e-9)) fprintf(stderr, "age %g: lowest hanging tip %.6f m, clearance %.6f m\n", ages[a], low, c);
        CHECK(low >= c - 1e-9);
        if (ages[a] == 1.0) CHECK(low <= c + 0.5); /* the full-grown curtain still reaches the ground */
        vessel_mesh_release(&m);
        vessel_tree_release(&t);
    }
}

TEST(children_start_at_their_mothers_tips)
{
    vessel_params p = preset(VESSEL_PRESET_WEEPING_WILLOW);
    vessel_tree t = {0};
    CHECK_INT(grow(&p, 1.0, 0, &t), 0);
    double worst = 0;
    for (uint32_t i = 0; i < t.n; i++) {
        const vessel_branch *b = &t.branches[i];
        if (b->mother < 0 || !b->is_main) continue;
        const vessel_branch *m = &t.branches[b->mother];
        vessel_vec tip = vv_madd(m->base, m->frame.c[1], m->length);
        worst = fmax(worst, vv_len(vv_sub(tip, b->base)));
        CHECK_NEAR(vv_len(b->frame.c[1]), 1.0, 1e-9);
    }
    CHECK(worst < 1e-9);
    vessel_tree_release(&t);
}

TEST(upright_trees_are_left_as_grown)
{
    const vessel_preset upright[] = {VESSEL_PRESET_BEECH, VESSEL_PRESET_SPRUCE, VESSEL_PRESET_MAPLE};
    for (int k = 0; k < 3; k++) {
        vessel_params p = preset(upright[k]);
        vessel_tree t = {0};
        CHECK_INT(grow(&p, 1.0, 0, &t), 0);
        CHECK(vessel_lowest_hanging_tip(&t) >= vessel_ground_clearance(&t, &p));
        vessel_tree_release(&t);
    }
}

TEST_LIST(TEST_CASE(willow_mesh_stays_above_the_ground), TEST_CASE(children_start_at_their_mothers_tips),
          TEST_CASE(upright_trees_are_left_as_grown))
