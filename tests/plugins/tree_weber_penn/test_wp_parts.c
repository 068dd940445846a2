/* test_wp_parts.c — the parts of tree_weber_penn that do not grow a tree, on hand-built inputs:
 * the age rule (levels and Scale by age, the leaves' placement on the last level grown, age 1
 * unchanged), the variants' seeds, the leaf forms (a card shows the leaf's area), a hand-built
 * model's mesh (bark uv, leaves at their frames, top), its figures, the model's caps against a
 * memory budget, and a filled triangle on the silhouette raster. */
#include <math.h>
#include <string.h>

#include "box_count.h"
#include "harness.h"
#include "leaf_affine.h"
#include "wp_age.h"
#include "wp_leaf_form.h"
#include "wp_limits.h"
#include "wp_host_mesh.h"
#include "wp_stats.h"

TEST(levels_and_scale_by_age)
{
    CHECK_INT(wp_age_levels(3, 0.25), 2); /* never the bare trunk: Arbaro grows no leaves on it */
    CHECK_INT(wp_age_levels(3, 1.0 / 3.0), 2);
    CHECK_INT(wp_age_levels(3, 0.34), 2);
    CHECK_INT(wp_age_levels(3, 2.0 / 3.0), 2);
    CHECK_INT(wp_age_levels(3, 0.67), 3);
    CHECK_INT(wp_age_levels(3, 1.0), 3);
    CHECK_INT(wp_age_levels(4, 0.5), 2);
    CHECK_INT(wp_age_levels(4, 0.6), 3);
    CHECK_INT(wp_age_levels(4, 0.1), 2);
    CHECK_INT(wp_age_levels(2, 0.1), 2);
    CHECK_INT(wp_age_levels(1, 0.1), 1);
    CHECK_INT(wp_age_levels(0, 0.5), 0);
    wp_params full, young;
    wp_params_defaults(&full);
    full.scale = 20, full.scale_v = 4, full.levels = 3;
    full.level[3].down_angle = 55, full.level[3].rotate = -77, full.level[3].branch_dist = 0.25;
    wp_params_at_age(&full, 1.0, &young);
    CHECK(!memcmp(&full, &young, sizeof full)); /* age 1: Arbaro's tree */
    wp_params_at_age(&full, 0.5, &young);
    CHECK_NEAR(young.scale, 10, 1e-12);
    CHECK_NEAR(young.scale_v, 2, 1e-12);
    CHECK_INT(young.levels, 2);
    /* the leaves grow on level 1, placed by level 2's parameters: the species' leaf level 3's */
    CHECK_NEAR(young.level[2].down_angle, 55, 0);
    CHECK_NEAR(young.level[2].rotate, -77, 0);
    CHECK_NEAR(young.level[2].branch_dist, 0.25, 0);
    CHECK_NEAR(young.level[1].down_angle, full.level[1].down_angle, 0);
    CHECK_NEAR(young.level[2].length, full.level[2].length, 0);
    full.levels = 4;
    wp_params_at_age(&full, 0.2, &young);
    CHECK_INT(young.levels, 2);
    CHECK_NEAR(young.level[2].down_angle, 55, 0); /* a 4-level species' leaves: level 3's */
    CHECK_NEAR(young.scale, 4, 1e-12);
}

TEST(variant_seeds)
{
    CHECK_INT(wp_variant_seed(13, 3, 4), 13); /* the full-grown variant: Arbaro's own tree */
    CHECK_INT(wp_variant_seed(13, 2, 4), 14);
    CHECK_INT(wp_variant_seed(13, 0, 4), 16);
    CHECK_INT(wp_variant_seed(13, 0, 1), 13);
    CHECK_INT(wp_variant_seed(-5, 0, 2), -4);
}

/* A kite: stalk at z = 0.1, tip at 0.5, 0.2 wide; two triangles facing +y. */
static double kite_v[4][3] = {{0, 0, 0.1}, {0.1, 0, 0.25}, {0, 0, 0.5}, {-0.1, 0, 0.25}};
static double kite_uv[4][2] = {{0.5, 0}, {1, 0.4}, {0.5, 1}, {0, 0.4}};
static uint32_t kite_t[2][3] = {{0, 2, 1}, {0, 3, 2}};

static wp_leaf_shape kite(void)
{
    return (wp_leaf_shape){.vertex = kite_v, .uv = kite_uv, .n_vertices = 4, .triangle = kite_t, .n_triangles = 2,
                           .faces = 1};
}

TEST(leaf_forms)
{
    wp_leaf_shape s = kite();
    wp_leaf_form own, card;
    plugin_err err = {0};
    CHECK_NEAR(wp_leaf_shape_face_area(&s), 0.04, 0.04 * 0.01); /* 0.2 x 0.4 / 2, within the grid's 1 % */
    CHECK_INT(wp_leaf_form_own(&s, &own, &err), 0);
    CHECK_INT(own.nv, 4);
    CHECK_INT(own.nt, 2);
    CHECK_NEAR(own.vertex[2][2], 0.5, 0);
    CHECK(own.normal[0][1] > 0 && own.normal[0][0] == 0 && own.normal[0][2] == 0); /* the kite faces +y */
    /* A texture whose leaf fills half its box, as the kite fills half its extent: the card is the
     * extent, and its uv the texture's box. */
    wp_leaf_texture_fit half = {.u0 = 0.25, .u1 = 0.75, .v0 = 0, .v1 = 0.9, .fill = 0.5};
    CHECK_INT(wp_leaf_form_card(&s, &half, &card, &err), 0);
    CHECK_INT(card.nv, 4);
    CHECK_INT(card.nt, 2);
    double lo[3] = {1, 1, 1}, hi[3] = {-1, -1, -1};
    for (uint32_t i = 0; i < card.nv; i++)
        for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], card.vertex[i][k]), hi[k] = fmax(hi[k], card.vertex[i][k]);
    CHECK_NEAR(lo[0], -0.1, 1e-3);
    CHECK_NEAR(hi[0], 0.1, 1e-3);
    CHECK_NEAR(lo[2], 0.1, 0);
    CHECK_NEAR(hi[2], 0.5, 2e-3);
    for (uint32_t t = 0; t < card.nt; t++) { /* each faces +y, the blade's normal */
        const double *a = card.vertex[card.tri[t][0]], *b = card.vertex[card.tri[t][1]], *c = card.vertex[card.tri[t][2]];
        double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, f[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        CHECK(e[2] * f[0] - e[0] * f[2] > 0);
    }
    for (uint32_t i = 0; i < card.nv; i++) { /* stalk at the box's v0, tip at its v1, u across; facing +y */
        CHECK_NEAR(card.uv[i][1], 0.9 * (card.vertex[i][2] - 0.1) / (hi[2] - 0.1), 1e-12);
        CHECK_NEAR(card.uv[i][0], 0.25 + 0.5 * (card.vertex[i][0] - lo[0]) / (hi[0] - lo[0]), 1e-12);
        CHECK(card.normal[i][1] > 0 && card.normal[i][0] == 0 && card.normal[i][2] == 0);
    }
    wp_leaf_form_release(&card);
    /* A texture whose leaf fills an eighth of its box (a needle twig): the card grows twice as
     * long and wide from the blade's base, so it shows the kite's area. */
    wp_leaf_texture_fit twig = {.u0 = 0, .u1 = 1, .v0 = 0, .v1 = 1, .fill = 0.125};
    CHECK_INT(wp_leaf_form_card(&s, &twig, &card, &err), 0);
    for (int k = 0; k < 3; k++) lo[k] = 1, hi[k] = -1;
    for (uint32_t i = 0; i < card.nv; i++)
        for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], card.vertex[i][k]), hi[k] = fmax(hi[k], card.vertex[i][k]);
    CHECK_NEAR(hi[0] - lo[0], 0.4, 2e-3);
    CHECK_NEAR(lo[2], 0.1, 0);
    CHECK_NEAR(hi[2], 0.9, 4e-3);
    CHECK_NEAR(0.125 * (hi[0] - lo[0]) * (hi[2] - lo[2]), 0.04, 0.04 * 0.01);
    wp_leaf_form_release(&own);
    wp_leaf_form_release(&card);
    wp_leaf_texture_fit none = {0};
    CHECK_INT(wp_leaf_form_card(&s, &none, &card, &err), SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "shows no leaf");
    double flat[3][3] = {{0, 0, 0}, {0, 0, 1}, {0, 0.5, 0.5}};
    uint32_t one[1][3] = {{0, 1, 2}};
    wp_leaf_shape needle = {.vertex = flat, .uv = kite_uv, .n_vertices = 3, .triangle = one, .n_triangles = 1};
    CHECK_INT(wp_leaf_form_card(&needle, &half, &card, &err), SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "give leaf: own");
}

/* The opaque area of the card's texture, found by looking up the texel under each point of a
 * fine grid over the card (the card's uv is bilinear over its rectangle). */
static double card_leaf_area(const wp_leaf_form *card, const uint8_t *rgba, uint32_t size)
{
    const double *p0 = card->vertex[0], *p2 = card->vertex[2];
    const double *t0 = card->uv[0], *t2 = card->uv[2];
    const int n = 512;
    long opaque = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double u = t0[0] + (t2[0] - t0[0]) * (i + 0.5) / n, v = t0[1] + (t2[1] - t0[1]) * (j + 0.5) / n;
            int col = (int)(u * size), row = (int)((1 - v) * size);
            col = col < 0 ? 0 : col >= (int)size ? (int)size - 1 : col;
            row = row < 0 ? 0 : row >= (int)size ? (int)size - 1 : row;
            opaque += rgba[4 * ((size_t)row * size + col) + 3] >= 128;
        }
    return opaque * fabs(p2[0] - p0[0]) * fabs(p2[2] - p0[2]) / ((double)n * n);
}

/* Every preset texture on a card over Arbaro's plain leaf ("0", as the library's oak and tamarack
 * draw it) and over a two-triangle disc (the willow's): the leaf the card shows has the shape's
 * area within 3 % (the texels at the leaf's edge), where a card over the extent alone showed 10 %
 * (willow) and 11 % (spruce) to 56 % (maple) of the plain leaf's. */
TEST(cards_show_the_leaf_area)
{
    static const char *shapes[] = {"0", "disc2"};
    for (int k = 0; k < 2; k++) {
        wp_params p;
        wp_params_defaults(&p);
        p.leaf_scale = 0.15, p.leaf_scale_x = 0.35;
        snprintf(p.leaf_shape, sizeof p.leaf_shape, "%s", shapes[k]);
        wp_leaf_shape s;
        plugin_err err = {0};
        CHECK_INT(wp_leaf_shape_make(&p, &s, &err), 0);
        double area = wp_leaf_shape_face_area(&s);
        for (int preset = 0; preset < LEAF_AFFINE_PRESET_COUNT; preset++) {
            leaf_affine_maps maps;
            leaf_affine_preset_maps((leaf_affine_preset)preset, &maps);
            uint8_t rgba[128 * 128 * 4];
            char why[256];
            CHECK_INT(leaf_affine_render(&maps, 128, 1, rgba, why, sizeof why), 0);
            wp_leaf_texture_fit fit;
            CHECK_INT(wp_leaf_texture_fit_of(rgba, 128, &fit), 0);
            wp_leaf_form card;
            CHECK_INT(wp_leaf_form_card(&s, &fit, &card, &err), 0);
            double shown = card_leaf_area(&card, rgba, 128);
            printf("%-6s on %-5s: fill %.3f of its box, card %.3f x %.3f m, leaf %.5f m2 for the shape's %.5f\n",
                   leaf_affine_preset_name((leaf_affine_preset)preset), shapes[k], fit.fill,
                   card.vertex[2][0] - card.vertex[0][0], card.vertex[2][2] - card.vertex[0][2], shown, area);
            CHECK_NEAR(shown, area, 0.03 * area);
            wp_leaf_form_release(&card);
        }
        wp_leaf_shape_release(&s);
    }
}

/* A trunk: two rings of 4 vertices round the z axis (radius 1, at z = 0 and 2, v = 0 and 2 m),
 * 8 triangles of level 0; a second stem of level 1 with radius 0.5; two leaves. */
typedef struct hand_tree {
    double vertex[16][3], uv[16][2];
    uint32_t tri[16][3];
    uint8_t level[16];
    wp_leaf leaf[2];
    wp_model m;
} hand_tree;

static void ring_stem(hand_tree *h, uint32_t first_v, uint32_t first_t, double r, double z0, double len, uint8_t level)
{
    for (int ring = 0; ring < 2; ring++)
        for (int s = 0; s < 4; s++) {
            double a = M_PI / 2 * s, *p = h->vertex[first_v + 4 * ring + s];
            p[0] = r * cos(a), p[1] = r * sin(a), p[2] = z0 + len * ring;
            h->uv[first_v + 4 * ring + s][0] = s / 4.0, h->uv[first_v + 4 * ring + s][1] = len * ring;
        }
    for (uint32_t s = 0; s < 4; s++) {
        uint32_t a = first_v + s, b = first_v + (s + 1) % 4, c = a + 4, d = b + 4;
        uint32_t *t0 = h->tri[first_t + 2 * s], *t1 = h->tri[first_t + 2 * s + 1];
        t0[0] = a, t0[1] = b, t0[2] = d, t1[0] = a, t1[1] = d, t1[2] = c;
        h->level[first_t + 2 * s] = h->level[first_t + 2 * s + 1] = level;
    }
}

static void hand_tree_make(hand_tree *h)
{
    memset(h, 0, sizeof *h);
    ring_stem(h, 0, 0, 1.0, 0.0, 2.0, 0);
    ring_stem(h, 8, 8, 0.5, 2.0, 1.0, 1);
    for (int i = 0; i < 2; i++) {
        wp_leaf *f = &h->leaf[i];
        f->origin[0] = 3.0 * i, f->origin[2] = 3.0;
        /* x across = +x, normal = -y... as a right-handed frame: x, y = z cross x, z = up */
        f->axis[0][0] = 1, f->axis[1][1] = 1, f->axis[2][2] = 1;
    }
    h->m = (wp_model){.vertex = h->vertex, .uv = h->uv, .n_vertices = 16, .triangle = h->tri, .level = h->level,
                      .n_triangles = 16, .leaf = h->leaf, .n_leaves = 2};
    h->m.stems[0] = 1, h->m.stems[1] = 1, h->m.faces[0] = 4, h->m.faces[1] = 4, h->m.faces[WP_LEVELS] = 2;
}

TEST(mesh_of_a_hand_built_tree)
{
    hand_tree h;
    hand_tree_make(&h);
    double round[WP_LEVELS];
    wp_host_mesh_bark_rounds(&h.m, round);
    CHECK_NEAR(round[0], sqrt(2.0) / 0.25, 1e-9); /* chord of a quarter turn over the turn */
    CHECK_NEAR(round[1], 0.5 * sqrt(2.0) / 0.25, 1e-9);
    CHECK_NEAR(round[2], 0, 0);
    wp_leaf_shape s = kite();
    wp_leaf_form form;
    plugin_err err = {0};
    CHECK_INT(wp_leaf_form_own(&s, &form, &err), 0);
    wp_host_mesh w;
    CHECK_INT(wp_host_mesh_build(&h.m, &form, 7, 9, &w, &err), 0);
    CHECK_INT(w.nv, 16 + 4 + 2 * 4); /* the stems, a seam copy of each ring's u = 0 vertex, the leaves */
    CHECK_INT(w.nt, 16 + 2 * 2);
    CHECK_INT(w.stem_triangles, 16);
    CHECK_INT(w.mat[0], 7);
    CHECK_INT(w.mat[15], 7);
    CHECK_INT(w.mat[16], 9);
    CHECK_INT(w.tri[3 * 16], 20);
    CHECK_NEAR(w.uv[2 * 4 + 1], 2.0 / round[0], 1e-6);  /* the trunk's top ring: 2 m in bark tiles */
    CHECK_NEAR(w.uv[2 * 12 + 1], 1.0 / round[1], 1e-6); /* the branch's: 1 m in its own tiles */
    CHECK_NEAR(w.uv[2 * 16], 1.0, 0);                   /* vertex 0's seam copy at u = 1 */
    CHECK_NEAR(w.pos[3 * 16], w.pos[0], 0);
    for (uint32_t t = 0; t < w.stem_triangles; t++) { /* no triangle runs back across the texture */
        float lo = 2, hi = -1;
        for (int k = 0; k < 3; k++) lo = fminf(lo, w.uv[2 * w.tri[3 * t + k]]), hi = fmaxf(hi, w.uv[2 * w.tri[3 * t + k]]);
        CHECK(hi - lo <= 0.5f);
    }
    for (uint32_t i = 0; i < 16; i++) { /* the stems' normals point out of them, the seam's as its vertex's */
        const float *p = w.pos + 3 * i, *n = w.nrm + 3 * i;
        CHECK(p[0] * n[0] + p[1] * n[1] > 0 && fabsf(n[2]) < 1e-6f);
    }
    CHECK(w.nrm[3 * 16] == w.nrm[0] && w.nrm[3 * 16 + 1] == w.nrm[1]);
    CHECK(w.nrm[3 * 20 + 1] > 0 && fabsf(w.nrm[3 * 20]) < 1e-6f); /* the kite faces +y, the frame's y */
    /* leaf 1's tip: origin (3, 0, 3) + 0.5 along its z axis */
    CHECK_NEAR(w.pos[3 * (20 + 4 + 2) + 0], 3.0, 1e-6);
    CHECK_NEAR(w.pos[3 * (20 + 4 + 2) + 2], 3.5, 1e-6);
    CHECK_NEAR(w.top, 3.5, 1e-12);
    sylva_tree_stats st = {.size = sizeof st, .age = 1};
    CHECK_INT(wp_stats_measure(&h.m, 2, &w, &st), 0);
    CHECK_INT(st.recursion, 2);
    CHECK_INT(st.segments, 8);
    CHECK_INT(st.branches, 2);
    CHECK_INT(st.leaves, 2);
    CHECK_INT(st.triangles, 20);
    CHECK_NEAR(st.height, 3.5, 1e-12);
    CHECK_NEAR(st.bbox_max[0], 3.1, 1e-6);
    CHECK_NEAR(st.bbox_min[2], 0, 0);
    CHECK(st.box_dimension > 1.0 && st.box_dimension < 2.01);
    wp_host_mesh_release(&w);
    /* no leaf form: the stems alone */
    CHECK_INT(wp_host_mesh_build(&h.m, NULL, 7, -1, &w, &err), 0);
    CHECK_INT(w.nt, 16);
    CHECK_INT(w.nv, 16 + 4);
    CHECK_NEAR(w.top, 3.0, 1e-12);
    wp_host_mesh_release(&w);
    wp_leaf_form_release(&form);
}

/* A square of two filled triangles is two-dimensional; one triangle covers half the raster. */
TEST(filled_triangles_on_the_silhouette)
{
    box_raster r;
    CHECK_INT(box_silhouette_init(&r, 0, 0, 1, 1), 0);
    box_raster_triangle(&r, 0, 0, 1, 0, 0, 1);
    uint64_t covered = 0;
    for (size_t i = 0; i < (size_t)r.n * r.n; i++) covered += r.px[i];
    CHECK_NEAR((double)covered / ((double)r.n * r.n), 0.5, 0.01);
    box_raster_triangle(&r, 1, 0, 1, 1, 0, 1);
    CHECK_NEAR(box_silhouette_dimension(&r), 2.0, 1e-9);
    box_raster_free(&r);
    CHECK_INT(box_silhouette_init(&r, 0, 0, 1, 1), 0);
    box_raster_triangle(&r, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5); /* a point still leaves its pixel */
    covered = 0;
    for (size_t i = 0; i < (size_t)r.n * r.n; i++) covered += r.px[i];
    CHECK_INT(covered, 1);
    box_raster_triangle(&r, NAN, 0, 1, 1, 2, 2); /* nothing breaks */
    box_raster_free(&r);
}

static int fits_one_gib(void *ctx, uint64_t bytes)
{
    (void)ctx;
    return bytes <= (1ull << 30);
}

static int fits_nothing(void *ctx, uint64_t bytes)
{
    (void)ctx, (void)bytes;
    return 0;
}

TEST(caps_from_the_budget)
{
    wp_caps c;
    wp_caps_fit(8, NULL, NULL, &c);
    CHECK_INT(c.triangles, WP_HOST_MESH_MAX_TRIANGLES);
    CHECK_INT(c.leaves, WP_HOST_MESH_MAX_TRIANGLES / 8);
    CHECK_INT(c.by_memory, 0);
    wp_caps_fit(2, fits_one_gib, NULL, &c);
    CHECK_INT(c.by_memory, 1);
    CHECK(c.triangles * WP_BYTES_PER_TRIANGLE + c.leaves * WP_BYTES_PER_LEAF <= (1ull << 30));
    CHECK(2 * c.triangles * WP_BYTES_PER_TRIANGLE > (1ull << 30)); /* the largest halving that fits */
    CHECK_INT(c.leaves, c.triangles / 2);
    wp_caps_fit(0, fits_nothing, NULL, &c);
    CHECK_INT(c.triangles, WP_MIN_TRIANGLES);
}

TEST_LIST(TEST_CASE(levels_and_scale_by_age), TEST_CASE(variant_seeds), TEST_CASE(leaf_forms), TEST_CASE(cards_show_the_leaf_area),
          TEST_CASE(mesh_of_a_hand_built_tree), TEST_CASE(filled_triangles_on_the_silhouette),
          TEST_CASE(caps_from_the_budget))
