/* test_vessel_mesh.c — the mesh of a vessel tree: exact counts (2n triangles per truncated
 * cone, n per terminal cone, 2 per leaf), valid indices, unit normals, outward winding, bark
 * texture coordinates that continue from mother to main child, the triangle limit, the
 * textures' alpha. */
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "vessel_mesh.h"
#include "vessel_test_util.h"
#include "vessel_texture.h"

static int build(const vessel_params *p, uint32_t lod, vessel_tree *t, vessel_mesh *m, plugin_err *err)
{
    vessel_growth g = {.age = 1.0, .lod = lod};
    int rc = vessel_tree_grow(p, &g, t, err);
    return rc ? rc : vessel_mesh_build(t, p, 7, 9, m, err);
}

TEST(counts_indices_and_normals_on_every_preset)
{
    for (int k = 0; k < VESSEL_PRESETS; k++) {
        vessel_params p = preset((vessel_preset)k);
        vessel_tree t = {0};
        vessel_mesh m = {0};
        plugin_err err = {0};
        if (build(&p, 0, &t, &m, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            CHECK(0);
            continue;
        }
        uint32_t S = p.vessels, n = p.sides;
        CHECK_INT(m.bark_triangles, (S - 1) * 2 * n + S * n);
        CHECK_INT(m.leaf_triangles, S * 2 * p.leaf_density);
        CHECK_INT(m.nt, m.bark_triangles + m.leaf_triangles);
        vessel_mesh_size c = vessel_mesh_count(&t, &p);
        CHECK_INT(c.vertices, m.nv);
        uint32_t bad_index = 0, bad_normal = 0, bark = 0, leaf = 0, bad_mat = 0;
        for (uint32_t i = 0; i < 3 * m.nt; i++) bad_index += m.tri[i] >= m.nv;
        for (uint32_t i = 0; i < m.nt; i++) {
            bark += m.mat[i] == 7, leaf += m.mat[i] == 9;
            bad_mat += m.mat[i] != 7 && m.mat[i] != 9;
        }
        for (uint32_t v = 0; v < m.nv; v++) {
            const float *nr = m.nrm + 3 * v;
            bad_normal += fabs(nr[0] * nr[0] + nr[1] * nr[1] + nr[2] * nr[2] - 1) > 1e-5;
        }
        CHECK_INT(bad_index, 0);
        CHECK_INT(bad_normal, 0);
        CHECK_INT(bad_mat, 0);
        CHECK_INT(bark, m.bark_triangles);
        CHECK_INT(leaf, m.leaf_triangles);
        CHECK(m.top > 5);
        vessel_mesh_release(&m);
        vessel_tree_release(&t);
    }
}

/* Bark triangles face outward: the face normal agrees with the vertex normals. */
TEST(bark_faces_outward)
{
    vessel_params p = preset(VESSEL_PRESET_MAPLE);
    p.leaf_density = 0;
    vessel_tree t = {0};
    vessel_mesh m = {0};
    plugin_err err = {0};
    CHECK_INT(build(&p, 0, &t, &m, &err), 0);
    uint32_t inward = 0;
    for (uint32_t i = 0; i < m.nt; i++) {
        const uint32_t *tr = m.tri + 3 * i;
        const float *a = m.pos + 3 * tr[0], *b = m.pos + 3 * tr[1], *c = m.pos + 3 * tr[2];
        vessel_vec e1 = vv(b[0] - a[0], b[1] - a[1], b[2] - a[2]), e2 = vv(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
        vessel_vec fn = vv_cross(e1, e2);
        if (vv_len(fn) < 1e-12) continue;
        const float *na = m.nrm + 3 * tr[0];
        inward += vv_dot(fn, vv(na[0], na[1], na[2])) < 0;
    }
    CHECK_INT(inward, 0);
    vessel_mesh_release(&m);
    vessel_tree_release(&t);
}

TEST(bark_v_continues_into_the_main_child)
{
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    vessel_tree t = {0};
    CHECK_INT(grow(&p, 1.0, 0, &t), 0);
    uint32_t bad = 0;
    for (uint32_t i = 0; i < t.n; i++) {
        const vessel_branch *b = &t.branches[i];
        if (b->terminal) continue;
        bad += t.branches[b->main_child].bark_v != vessel_bark_v_tip(b);
        bad += t.branches[b->lateral_child].bark_v != vessel_bark_v_tip(b);
        bad += !(vessel_bark_v_tip(b) > b->bark_v);
    }
    CHECK_INT(bad, 0);
    vessel_tree_release(&t);
}

TEST(level_of_detail_draws_fewer_triangles)
{
    vessel_params p = preset(VESSEL_PRESET_SPRUCE);
    uint32_t previous = UINT32_MAX;
    for (uint32_t lod = 0; lod <= 10; lod += 2) {
        vessel_tree t = {0};
        vessel_mesh m = {0};
        plugin_err err = {0};
        CHECK_INT(build(&p, lod, &t, &m, &err), 0);
        CHECK(m.nt < previous);
        previous = m.nt;
        if (lod == 10) CHECK_INT(m.nt, p.sides + 2 * p.leaf_density); /* one cone and its leaves */
        vessel_mesh_release(&m);
        vessel_tree_release(&t);
    }
}

TEST(triangle_limit_is_checked_before_building)
{
    vessel_params p = preset(VESSEL_PRESET_SPRUCE);
    p.vessels = VESSEL_MAX_VESSELS, p.leaf_density = 200; /* 40 million leaf triangles */
    vessel_tree t = {0};
    vessel_mesh m = {0};
    plugin_err err = {0};
    CHECK_INT(build(&p, 0, &t, &m, &err), SYLVA_ERR_LIMIT); /* refused by the parameters */
    CHECK_STR_CONTAINS(err.msg, "would need 41799988 triangles (1799988 bark, 40000000 leaves)");
    CHECK_STR_CONTAINS(err.msg, "at most 20000000");
    CHECK_STR_CONTAINS(err.param, "leaf_density");
    CHECK(t.n == 0 && m.pos == NULL && m.nt == 0);

    /* the mesh builder counts again before it allocates */
    p = preset(VESSEL_PRESET_SPRUCE);
    CHECK_INT(grow(&p, 1.0, 0, &t), 0);
    p.leaf_density = 2000;
    memset(&err, 0, sizeof err);
    CHECK_INT(vessel_mesh_build(&t, &p, 0, 1, &m, &err), SYLVA_ERR_LIMIT);
    CHECK_STR_CONTAINS(err.msg, "would need 24107988 triangles");
    CHECK(m.pos == NULL && m.nt == 0);
    vessel_tree_release(&t);
}

TEST(textures_are_opaque_bark_and_outlined_leaves)
{
    uint8_t *px = malloc(VESSEL_LEAF_TEXTURE_SIZE * VESSEL_LEAF_TEXTURE_SIZE * 4);
    for (int s = 0; s < VESSEL_PRESETS; s++) {
        vessel_params p = preset((vessel_preset)s);
        CHECK_INT(vessel_texture_leaf(&p, px), 0);
        uint32_t inside = 0, n = VESSEL_LEAF_TEXTURE_SIZE * VESSEL_LEAF_TEXTURE_SIZE;
        for (uint32_t i = 0; i < n; i++) inside += px[4 * i + 3] == 255;
        CHECK(inside > n / 20);  /* an outline, neither empty ... */
        CHECK(inside < n * 3 / 4); /* ... nor the whole square */
        /* the stalk reaches the bottom edge in the middle (row n-1 is v = 0) */
        CHECK_INT(px[4 * ((VESSEL_LEAF_TEXTURE_SIZE - 1) * VESSEL_LEAF_TEXTURE_SIZE + VESSEL_LEAF_TEXTURE_SIZE / 2) + 3], 255);
    }
    free(px);
    px = malloc(VESSEL_BARK_TEXTURE_SIZE * VESSEL_BARK_TEXTURE_SIZE * 4);
    for (int k = 0; k < VESSEL_PRESETS; k++) {
        vessel_params p = preset((vessel_preset)k);
        vessel_texture_bark(&p, px);
        uint32_t opaque = 0, lo = 255, hi = 0;
        for (uint32_t i = 0; i < VESSEL_BARK_TEXTURE_SIZE * VESSEL_BARK_TEXTURE_SIZE; i++) {
            opaque += px[4 * i + 3] == 255;
            if (px[4 * i] < lo) lo = px[4 * i];
            if (px[4 * i] > hi) hi = px[4 * i];
        }
        CHECK_INT(opaque, VESSEL_BARK_TEXTURE_SIZE * VESSEL_BARK_TEXTURE_SIZE);
        CHECK(hi - lo > 40); /* a pattern, not a flat grey */
    }
    free(px);
}

static uint32_t alpha_area(const uint8_t *px)
{
    uint32_t inside = 0;
    for (uint32_t i = 0; i < VESSEL_LEAF_TEXTURE_SIZE * VESSEL_LEAF_TEXTURE_SIZE; i++) inside += px[4 * i + 3] > 127;
    return inside;
}

/* leaf_spray 1 is the affine leaf itself; a spray fans smaller copies of it from the stalk, so
 * that a quad of the beech's ovate leaf carries about the leaf area the quad had before the
 * leaves were drawn by maps (0.39 of the quad), and more than the one leaf (0.30). */
TEST(leaf_spray_fans_the_affine_leaf)
{
    const uint32_t n = VESSEL_LEAF_TEXTURE_SIZE;
    uint8_t *one = malloc(n * n * 4), *want = malloc(n * n * 4), *spray = malloc(n * n * 4);
    vessel_params p = preset(VESSEL_PRESET_BEECH);
    CHECK_INT(p.leaf_spray, 5);
    CHECK_INT(vessel_texture_leaf(&p, spray), 0);
    p.leaf_spray = 1;
    CHECK_INT(vessel_texture_leaf(&p, one), 0);
    CHECK_INT(leaf_affine_render(&p.leaf, n, VESSEL_LEAF_TEXTURE_SEED, want, NULL, 0), 0);
    CHECK(!memcmp(one, want, (size_t)n * n * 4));
    double a1 = alpha_area(one) / (double)(n * n), a5 = alpha_area(spray) / (double)(n * n);
    CHECK(a1 > 0.28 && a1 < 0.32);
    CHECK(a5 > 0.37 && a5 < 0.43);
    /* the middle leaf lies on top: up the midline the spray shows the one leaf shrunk by the scale */
    for (uint32_t row = 0; row < n; row++) {
        double v = 1.0 - (row + 0.5) / n;
        uint32_t src = n - 1 - (uint32_t)(v / VESSEL_SPRAY_SCALE * n);
        if (v / VESSEL_SPRAY_SCALE >= 1) continue;
        const uint8_t *s = one + 4 * ((size_t)src * n + n / 2), *t = spray + 4 * ((size_t)row * n + n / 2);
        if (s[3] > 127) CHECK(!memcmp(s, t, 4));
    }
    free(one), free(want), free(spray);
}

TEST_LIST(TEST_CASE(leaf_spray_fans_the_affine_leaf), TEST_CASE(counts_indices_and_normals_on_every_preset), TEST_CASE(bark_faces_outward),
          TEST_CASE(bark_v_continues_into_the_main_child), TEST_CASE(level_of_detail_draws_fewer_triangles),
          TEST_CASE(triangle_limit_is_checked_before_building),
          TEST_CASE(textures_are_opaque_bark_and_outlined_leaves))
