/* test_vessel_stats.c — a vessel tree's figures for `sylva tree-stats`: S vessels give 2S − 1
 * segments (S − 1 forks), S axes (the trunk and one lateral child per fork) and S ρ_l leaves;
 * the triangles and bounds are the mesh's; D_B of a lone trunk is a line's (1) and of a
 * full-grown preset a branching tree's (between 1 and 2). */
#include <math.h>

#include "harness.h"
#include "vessel_mesh.h"
#include "vessel_stats.h"
#include "vessel_test_util.h"
#include "sylva/tree_stats.h"

static int measure(const vessel_params *p, double age, sylva_tree_stats *st, vessel_mesh *m)
{
    vessel_tree t = {0};
    vessel_growth g = {.age = age};
    plugin_err err = {0};
    int rc = vessel_tree_grow(p, &g, &t, &err);
    if (!rc) rc = vessel_mesh_build(&t, p, 1, 2, m, &err);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    if (!rc) rc = vessel_stats_measure(&t, m, st);
    vessel_tree_release(&t);
    return rc;
}

TEST(counts_follow_the_vessels_on_every_preset)
{
    for (int k = 0; k < VESSEL_PRESETS; k++) {
        vessel_params p = preset((vessel_preset)k);
        sylva_tree_stats st = {.size = sizeof st};
        vessel_mesh m = {0};
        CHECK_INT(measure(&p, 1.0, &st, &m), 0);
        uint32_t S = p.vessels;
        CHECK_INT(st.segments, 2 * S - 1);
        CHECK_INT(st.branches, S);
        CHECK_INT(st.leaves, (uint64_t)S * p.leaf_density);
        CHECK_INT(st.triangles, m.nt);
        CHECK(st.recursion >= 1 && st.recursion <= S);
        CHECK_NEAR(st.height, m.top, 1e-9);
        for (uint32_t v = 0; v < m.nv; v++)
            for (int a = 0; a < 3; a++)
                CHECK(m.pos[3 * v + a] >= st.bbox_min[a] && m.pos[3 * v + a] <= st.bbox_max[a]);
        CHECK(st.box_dimension > 1.2 && st.box_dimension < 1.9);
        vessel_mesh_release(&m);
    }
}

TEST(a_lone_trunk_is_a_line)
{
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    p.vessels = 1;
    sylva_tree_stats st = {.size = sizeof st};
    vessel_mesh m = {0};
    CHECK_INT(measure(&p, 1.0, &st, &m), 0);
    CHECK_INT(st.segments, 1);
    CHECK_INT(st.branches, 1);
    CHECK_INT(st.recursion, 1);
    CHECK_NEAR(st.box_dimension, 1.0, 0.05);
    vessel_mesh_release(&m);
}

TEST(a_younger_tree_has_fewer_segments)
{
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    sylva_tree_stats old = {.size = sizeof old}, young = {.size = sizeof young};
    vessel_mesh a = {0}, b = {0};
    CHECK_INT(measure(&p, 1.0, &old, &a), 0);
    CHECK_INT(measure(&p, 0.4, &young, &b), 0);
    CHECK(young.segments < old.segments && young.height < old.height);
    vessel_mesh_release(&a);
    vessel_mesh_release(&b);
}

TEST_LIST(TEST_CASE(counts_follow_the_vessels_on_every_preset), TEST_CASE(a_lone_trunk_is_a_line),
          TEST_CASE(a_younger_tree_has_fewer_segments))
