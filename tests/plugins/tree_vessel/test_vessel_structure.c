/* test_vessel_structure.c — Algorithm 2 of 004 on every preset: the vessel invariants (3.1, 3.4,
 * 3.5–3.6), the orders, the lengths (3.24–3.26), the branching angles (3.7–3.8, opposite
 * sides), phyllotaxis, gravimorphism, growth (3.33–3.34), level of detail (3.27–3.29) and the
 * still wind (3.35–3.38). */
#include "harness.h"
#include "vessel_mesh.h"
#include "vessel_test_util.h"

static double angle_between(vessel_vec a, vessel_vec b)
{
    double c = vv_dot(vv_unit(a), vv_unit(b));
    return acos(c > 1 ? 1 : c < -1 ? -1 : c) / VESSEL_DEG;
}

static vessel_vec tip_of(const vessel_branch *b) { return vv_madd(b->base, b->frame.c[1], b->length); }

TEST(invariants_hold_on_every_preset)
{
    for (int k = 0; k < VESSEL_PRESETS; k++) {
        vessel_params p = preset((vessel_preset)k);
        vessel_tree t = {0};
        if (grow(&p, 1.0, 0, &t)) {
            CHECK(0);
            continue;
        }
        uint32_t S = p.vessels, leafy = 0, leafy_single = 0, bad_split = 0, bad_d = 0, bad_g = 0,
                 bad_w = 0, bad_link = 0, bad_frame = 0, bad_base = 0;
        uint64_t vessels_at_tips = 0;
        CHECK_INT(t.vessels, S);
        CHECK_INT(t.n, 2 * S - 1);                                  /* B = 2S - 1 (3.1) */
        for (uint32_t i = 0; i < t.n; i++) {
            const vessel_branch *b = &t.branches[i];
            for (int a = 0; a < 3; a++)
                for (int c = 0; c < 3; c++)
                    if (fabs(vv_dot(b->frame.c[a], b->frame.c[c]) - (a == c)) > 1e-9) bad_frame++;
            if (b->terminal) {
                leafy++;
                leafy_single += b->vessels == 1;
                vessels_at_tips += b->vessels;
                bad_link += b->main_child != -1 || b->lateral_child != -1;
                continue;
            }
            if (b->main_child < 0 || b->lateral_child < 0) {
                bad_link++;
                continue;
            }
            const vessel_branch *m = &t.branches[b->main_child], *l = &t.branches[b->lateral_child];
            bad_link += m->mother != (int32_t)i || l->mother != (int32_t)i || !m->is_main || l->is_main;
            bad_split += m->vessels + l->vessels != b->vessels || l->vessels < 1 || l->vessels > m->vessels;
            double d0 = b->diameter, d1 = m->diameter, d2 = l->diameter;  /* (3.4) */
            bad_d += fabs(d0 * d0 - (d1 * d1 + d2 * d2)) > 1e-12 * d0 * d0;
            bad_d += b->tip_diameter != m->diameter;
            bad_g += m->g != b->g || l->g != b->g + 1;                     /* Gravelius */
            bad_w += m->w != b->w + 1 || l->w != b->w + 1;                 /* Weibull */
            vessel_vec tip = tip_of(b);
            bad_base += vv_len(vv_sub(m->base, tip)) > 1e-12;
            /* the lateral child starts at the bark: (d1 - d2) / 2 from the axis */
            bad_base += fabs(vv_len(vv_sub(l->base, tip)) - 0.5 * (d1 - d2)) > 1e-9;
        }
        CHECK_INT(leafy, S);                     /* leaf-bearing branches = S */
        CHECK_INT(leafy_single, S);
        CHECK_INT(t.n_terminal, S);
        CHECK_INT(vessels_at_tips, S);
        CHECK_INT(bad_split, 0);
        CHECK_INT(bad_d, 0);
        CHECK_INT(bad_g, 0);
        CHECK_INT(bad_w, 0);
        CHECK_INT(bad_link, 0);
        CHECK_INT(bad_frame, 0);
        CHECK_INT(bad_base, 0);
        CHECK_INT(t.branches[0].mother, -1);
        CHECK_NEAR(t.branches[0].length, p.trunk_length, 0);
        if (harness_failures) fprintf(stderr, "  (preset %s)\n", vessel_preset_names[k]);
        vessel_tree_release(&t);
    }
}

/* (3.5), (3.6), (3.24)–(3.26) at the spruce's first branching, by hand. */
TEST(first_split_of_the_spruce)
{
    vessel_params p = preset(VESSEL_PRESET_SPRUCE);
    vessel_tree t = {0};
    CHECK_INT(grow(&p, 1.0, 0, &t), 0);
    const vessel_branch *b = &t.branches[0];
    const vessel_branch *m = &t.branches[b->main_child], *l = &t.branches[b->lateral_child];
    CHECK_INT(m->vessels, 5730); /* ceil(1 + 0.955 * 5998) = ceil(5729.09) */
    CHECK_INT(l->vessels, 270);
    double r1 = sqrt(5730.0 / 6000.0);            /* inside [0.7109, 0.9953] */
    double r2 = 0.7109;                           /* sqrt(270 / 6000) = 0.21 raised to m */
    CHECK_NEAR(m->rel_length, r1, 1e-12);
    CHECK_NEAR(l->rel_length, r2, 1e-12);
    CHECK_NEAR(m->length, 0.7109 * 1.014 * r1, 1e-12);
    CHECK_NEAR(l->length, 0.7109 * 1.014 * r2, 1e-12);
    CHECK_NEAR(b->diameter, 0.005 * sqrt(6000.0), 1e-12);
    vessel_tree_release(&t);

    p.vessels = 10; /* S1 = ceil(1 + 0.955 * 8) = 9, S2 = 1 */
    CHECK_INT(grow(&p, 1.0, 0, &t), 0);
    CHECK_INT(t.branches[t.branches[0].main_child].vessels, 9);
    vessel_tree_release(&t);
    vessel_params beech = preset(VESSEL_PRESET_BEECH);
    beech.vessels = 10; /* S1 = ceil(1 + 0.75 * 8) = 7, S2 = 3 */
    CHECK_INT(grow(&beech, 1.0, 0, &t), 0);
    CHECK_INT(t.branches[t.branches[0].main_child].vessels, 7);
    CHECK_INT(t.branches[t.branches[0].lateral_child].vessels, 3);
    vessel_tree_release(&t);
}

/* (3.7), (3.8): the children part by alpha on opposite sides of one plane; the main child
 * leaves its mother by k sqrt(S2/S0) alpha with k = 1 - k_c on the trunk and 1 elsewhere; the
 * plane is the mother's, rolled by the phyllotaxis angle. The beech has no gravimorphism. */
TEST(branching_angles_and_phyllotaxis)
{
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    vessel_tree t = {0};
    CHECK_INT(grow(&p, 1.0, 0, &t), 0);
    uint32_t bad_pair = 0, bad_main = 0, bad_roll = 0, splits = 0;
    for (uint32_t i = 0; i < t.n; i++) {
        const vessel_branch *b = &t.branches[i];
        if (b->terminal) continue;
        splits++;
        const vessel_branch *m = &t.branches[b->main_child], *l = &t.branches[b->lateral_child];
        double alpha = vessel_local_at(&p, b->g, b->w).angle;
        double k = b->g == 0 ? 1 - p.gravicentralism : 1;
        double a1 = k * sqrt((double)l->vessels / b->vessels) * alpha;
        bad_pair += fabs(angle_between(m->frame.c[1], l->frame.c[1]) - alpha) > 1e-7;
        bad_main += fabs(angle_between(b->frame.c[1], m->frame.c[1]) - a1) > 1e-7;
        /* the lateral leans toward -x of the mother's frame rolled by alpha_p about y */
        vessel_vec local = frame_to_local(&b->frame, l->frame.c[1]);
        double h = hypot(local.x, local.z), ap = p.phyllotaxis * VESSEL_DEG;
        bad_roll += fabs(local.x / h + cos(ap)) > 1e-7 || fabs(local.z / h - sin(ap)) > 1e-7;
    }
    CHECK_INT(splits, p.vessels - 1);
    CHECK_INT(bad_pair, 0);
    CHECK_INT(bad_main, 0);
    CHECK_INT(bad_roll, 0);
    vessel_tree_release(&t);
}

/* Gravimorphism: alpha_m sin^2(inclination), toward the ground, never past the vertical. One
 * branching: the trunk is vertical, the children lean by alpha1 and alpha2 before the bend. */
TEST(gravimorphism_bends_by_sin_squared_of_the_inclination)
{
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    p.vessels = 2;
    const double angle60[] = {0, 60, 15, 60}, bend40[] = {0, 40, 15, 40};
    set_line(&p.by_g[VESSEL_ANGLE], angle60, 2);
    set_line(&p.by_g[VESSEL_GRAVI], bend40, 2);
    vessel_tree t = {0};
    CHECK_INT(grow(&p, 1.0, 0, &t), 0);
    vessel_vec up = vv(0, 0, 1);
    double a1 = (1 - p.gravicentralism) * sqrt(0.5) * 60, a2 = 60 - a1;
    double s1 = sin(a1 * VESSEL_DEG), s2 = sin(a2 * VESSEL_DEG);
    CHECK_NEAR(angle_between(t.branches[t.branches[0].main_child].frame.c[1], up), a1 + 40 * s1 * s1, 1e-9);
    CHECK_NEAR(angle_between(t.branches[t.branches[0].lateral_child].frame.c[1], up), a2 + 40 * s2 * s2, 1e-9);
    vessel_tree_release(&t);

    /* 180 degrees at an inclination of 60 would pass straight down: it stops there. */
    const double bend180[] = {0, 180, 15, 180}, angle120[] = {0, 120, 15, 120};
    set_line(&p.by_g[VESSEL_GRAVI], bend180, 2);
    set_line(&p.by_g[VESSEL_ANGLE], angle120, 2);
    p.gravicentralism = 0.5; /* alpha1 = 0.5 sqrt(1/2) 120 = 42.4 */
    CHECK_INT(grow(&p, 1.0, 0, &t), 0);
    CHECK_NEAR(angle_between(t.branches[t.branches[0].lateral_child].frame.c[1], up), 180, 1e-6);
    vessel_tree_release(&t);
}

static double mean_tip(const vessel_tree *t, int axis)
{
    double sum = 0;
    uint32_t n = 0;
    for (uint32_t i = 0; i < t->n; i++)
        if (t->branches[i].terminal) {
            vessel_vec tip = tip_of(&t->branches[i]);
            sum += axis == 0 ? tip.x : axis == 1 ? tip.y : tip.z, n++;
        }
    return sum / n;
}

TEST(gravimorphism_lowers_and_negative_gravimorphism_raises)
{
    vessel_params p = preset(VESSEL_PRESET_WEEPING_WILLOW), flat = p, up = p;
    const double none[] = {0, 0, 15, 0}, lift[] = {0, -90, 15, -90};
    set_line(&flat.by_g[VESSEL_GRAVI], none, 2);
    set_line(&up.by_g[VESSEL_GRAVI], lift, 2);
    vessel_tree a = {0}, b = {0}, c = {0};
    CHECK_INT(grow(&p, 1.0, 0, &a) | grow(&flat, 1.0, 0, &b) | grow(&up, 1.0, 0, &c), 0);
    CHECK(mean_tip(&a, 2) < mean_tip(&b, 2) - 1.0);
    CHECK(mean_tip(&c, 2) > mean_tip(&b, 2) + 1.0);
    vessel_tree_release(&a), vessel_tree_release(&b), vessel_tree_release(&c);
}

TEST(growth_scales_vessels_and_first_segment)
{
    CHECK_INT(vessel_grown_vessels(1000, 1.0), 1000);
    CHECK_INT(vessel_grown_vessels(1000, 0.5), 250);   /* S' = t^2 S (3.33) */
    CHECK_INT(vessel_grown_vessels(1000, 0.1), 10);
    CHECK_INT(vessel_grown_vessels(6000, 0.3), 540);
    CHECK_INT(vessel_grown_vessels(5, 0.1), 1);        /* at least one vessel */
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    vessel_tree t = {0};
    CHECK_INT(grow(&p, 0.5, 0, &t), 0);
    CHECK_INT(t.vessels, 1000);    /* the preset's 4000 at t = 0.5 */
    CHECK_INT(t.n, 1999);
    CHECK_INT(t.n_terminal, 1000);
    CHECK_NEAR(t.branches[0].length, 0.25 * 5, 1e-12); /* l0' = t^2 l0 (3.34) */
    double young = t.height;
    vessel_tree_release(&t);
    CHECK_INT(grow(&p, 1.0, 0, &t), 0);
    CHECK(t.height > young + 3);
    vessel_tree_release(&t);
    vessel_growth g = {.age = 0};
    plugin_err err = {0};
    CHECK_INT(vessel_tree_grow(&p, &g, &t, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "age 0 is outside (0, 1]");
    g.age = 1.5;
    CHECK_INT(vessel_tree_grow(&p, &g, &t, &err), -1);
    CHECK_INT(t.n, 0);
}

/* (3.27)–(3.29): the structure stops at Weibull order (10 - l)^2 with leaves, and only branches
 * up to 10 - l are drawn; l = 10 keeps the first trunk segment alone. */
TEST(level_of_detail)
{
    vessel_params p = preset(VESSEL_PRESET_SPRUCE);
    vessel_tree full = {0}, t = {0};
    CHECK_INT(grow(&p, 1.0, 0, &full), 0);
    for (uint32_t lod = 1; lod <= 12; lod++) {
        CHECK_INT(grow(&p, 1.0, lod, &t), 0);
        uint32_t l = lod > 10 ? 10 : lod, w_geom = (10 - l) * (10 - l), w_branch = 10 - l;
        CHECK_INT(t.w_geom, w_geom);
        CHECK_INT(t.w_branch, w_branch);
        uint32_t bad = 0, drawn = 0;
        for (uint32_t i = 0; i < t.n; i++) {
            const vessel_branch *b = &t.branches[i];
            bad += b->w > w_geom;
            bad += b->terminal != (b->vessels == 1 || b->w == w_geom);
            bad += b->drawn != (b->w <= w_branch);
            drawn += b->drawn;
        }
        CHECK_INT(bad, 0);
        CHECK(t.n <= full.n);
        CHECK(drawn >= 1);
        if (l == 10) CHECK_INT(t.n, 1);
        vessel_tree_release(&t);
    }
    vessel_tree_release(&full);
}

TEST(smallest_trees)
{
    vessel_params p = preset(VESSEL_PRESET_SPRUCE);
    vessel_tree t = {0};
    p.vessels = 1; /* the first segment alone, bearing the leaves */
    CHECK_INT(grow(&p, 1.0, 0, &t), 0);
    CHECK_INT(t.n, 1);
    CHECK_INT(t.branches[0].terminal, 1);
    CHECK_NEAR(t.height, p.trunk_length, 1e-12);
    p.vessels = 2; /* one branching: S1 = S2 = 1 */
    CHECK_INT(grow(&p, 1.0, 0, &t), 0);
    CHECK_INT(t.n, 3);
    CHECK_INT(t.n_terminal, 2);
    CHECK_INT(t.branches[t.branches[0].main_child].vessels, 1);
    CHECK_INT(t.branches[t.branches[0].lateral_child].vessels, 1);
    vessel_tree_release(&t);
    vessel_tree_release(&t); /* releasing an empty tree is harmless */
}

static uint64_t mesh_hash_of(const vessel_params *p, double age, uint64_t wind_key)
{
    test_stream s = {.key = wind_key};
    vessel_growth g = {.age = age, .uniform = test_uniform, .ctx = &s};
    vessel_tree t = {0};
    vessel_mesh m = {0};
    plugin_err err = {0};
    uint64_t h = 0;
    if (!vessel_tree_grow(p, &g, &t, &err) && !vessel_mesh_build(&t, p, 3, 4, &m, &err))
        h = vessel_mesh_hash(&m);
    else
        fprintf(stderr, "%s\n", err.msg);
    vessel_mesh_release(&m);
    vessel_tree_release(&t);
    return h;
}

TEST(same_parameters_give_the_same_mesh)
{
    for (int k = 0; k < VESSEL_PRESETS; k++) {
        vessel_params p = preset((vessel_preset)k);
        uint64_t a = mesh_hash_of(&p, 1.0, 1), b = mesh_hash_of(&p, 1.0, 2);
        CHECK(a != 0);
        CHECK(a == b); /* no wind: the stream is not used */
        p.vessels++;
        CHECK(mesh_hash_of(&p, 1.0, 1) != a);
    }
    vessel_params w = preset(VESSEL_PRESET_BEECH);
    w.wind_sway = 2;
    uint64_t a = mesh_hash_of(&w, 0.8, 7);
    CHECK(a == mesh_hash_of(&w, 0.8, 7));
    CHECK(a != mesh_hash_of(&w, 0.8, 8)); /* other phases R_x, R_z */
}

/* The directed wind bends the tree downwind (3.36–3.38). */
TEST(directed_wind_bends_downwind)
{
    vessel_params calm = preset(VESSEL_PRESET_BEECH), east = calm, north = calm;
    east.wind_strength = 5;
    north.wind_strength = 5, north.wind_direction[0] = 0, north.wind_direction[1] = 1;
    vessel_tree a = {0}, b = {0}, c = {0};
    CHECK_INT(grow(&calm, 1.0, 0, &a) | grow(&east, 1.0, 0, &b) | grow(&north, 1.0, 0, &c), 0);
    CHECK(mean_tip(&b, 0) > mean_tip(&a, 0) + 1.0);
    CHECK(mean_tip(&c, 1) > mean_tip(&a, 1) + 1.0);
    CHECK_INT(b.n, a.n);
    /* the trunk's first branching bends by w_g (S0 = S) about y x w */
    CHECK_NEAR(b.branches[0].frame.c[1].z, 1.0, 0);
    vessel_tree_release(&a), vessel_tree_release(&b), vessel_tree_release(&c);
}

TEST_LIST(TEST_CASE(invariants_hold_on_every_preset), TEST_CASE(first_split_of_the_spruce),
          TEST_CASE(branching_angles_and_phyllotaxis),
          TEST_CASE(gravimorphism_bends_by_sin_squared_of_the_inclination),
          TEST_CASE(gravimorphism_lowers_and_negative_gravimorphism_raises),
          TEST_CASE(growth_scales_vessels_and_first_segment), TEST_CASE(level_of_detail),
          TEST_CASE(smallest_trees),
          TEST_CASE(same_parameters_give_the_same_mesh), TEST_CASE(directed_wind_bends_downwind))
