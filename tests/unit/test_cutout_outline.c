/* test_cutout_outline.c — cut-outs as outline polygons (geometry/cutout_outline.h): a texture's outline
 * is convex, has at most CUTOUT_OUTLINE_CORNERS corners and the kept texels' area; a leaf card (two
 * cut-out triangles) becomes opaque triangles inside the card with the card's uvs and normals,
 * while opaque triangles of the same mesh stay as they were. */
#include <math.h>

#include "geometry/cutout.h"
#include "geometry/cutout_outline.h"
#include "harness.h"

#define SIZE 64

/* A texture whose kept texels are a disc of radius r (texels) about (cx, cy). */
static int32_t disc_texture(scene *s, double cx, double cy, double r, uint32_t *kept)
{
    static uint8_t rgba[SIZE * SIZE * 4];
    *kept = 0;
    for (int y = 0; y < SIZE; y++)
        for (int x = 0; x < SIZE; x++) {
            uint8_t *p = rgba + (y * SIZE + x) * 4;
            int in = hypot(x + 0.5 - cx, y + 0.5 - cy) <= r;
            p[0] = p[1] = p[2] = 200;
            p[3] = in ? 255 : 0;
            *kept += (uint32_t)in;
        }
    err_buf err = {{0}};
    int32_t t = scene_add_texture(s, "disc", SIZE, SIZE, rgba, &err);
    CHECK(t >= 0);
    return t;
}

static double outline_area(const cutout_outline *o)
{
    double a = 0;
    for (int i = 0; i < o->n; i++) {
        const float *p = o->uv[i], *q = o->uv[(i + 1) % o->n];
        a += (double)p[0] * q[1] - (double)q[0] * p[1];
    }
    return 0.5 * a;
}

TEST(outline_is_convex_and_keeps_the_area)
{
    scene *s = scene_new();
    uint32_t kept;
    int32_t t = disc_texture(s, 40, 20, 12, &kept);
    cutout_outline o;
    cutout_outline_of_texture(&s->textures[t], &o);
    CHECK(o.n >= 3 && o.n <= CUTOUT_OUTLINE_CORNERS);
    CHECK_NEAR(outline_area(&o), (double)kept / (SIZE * SIZE), 1e-5);
    double cu = 0, cv = 0;
    for (int i = 0; i < o.n; i++) {
        const float *a = o.uv[i], *b = o.uv[(i + 1) % o.n], *c = o.uv[(i + 2) % o.n];
        CHECK((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) > 0); /* counter-clockwise */
        cu += a[0] / o.n, cv += a[1] / o.n;
    }
    /* row 0 is v = 1: the disc's centre at texel (40, 20) is uv (0.625, 0.6875) */
    CHECK_NEAR(cu, 40.0 / SIZE, 0.02);
    CHECK_NEAR(cv, 1.0 - 20.0 / SIZE, 0.02);
    scene_free(s);
}

TEST(cards_become_opaque_outlines)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    uint32_t kept;
    int32_t tex = disc_texture(s, 32, 32, 20, &kept);
    sylva_material_desc leaf = {.size = sizeof leaf, .name = "leaf", .bsdf = SYLVA_BSDF_LAMBERT,
                                .albedo = {1, 1, 1}, .texture = tex, .alpha_mask = 1};
    sylva_material_desc bark = {.size = sizeof bark, .name = "bark", .bsdf = SYLVA_BSDF_LAMBERT,
                                .albedo = {1, 1, 1}, .texture = -1};
    int32_t ml = scene_add_material(s, &leaf, &err), mb = scene_add_material(s, &bark, &err);
    /* a card 2 m x 2 m in the plane y = 1 (two cut-out triangles) and one bark triangle */
    float pos[] = {0, 1, 0, 2, 1, 0, 2, 1, 2, 0, 1, 2, 5, 0, 0, 6, 0, 0, 5, 0, 1};
    float uv[] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 0, 0, 0, 0};
    uint32_t tri[] = {0, 1, 2, 0, 2, 3, 4, 5, 6};
    int32_t mat[] = {ml, ml, mb};
    mesh *m = mesh_new();
    CHECK(!mesh_append(m, pos, NULL, uv, 7, tri, mat, -1, 3, &err));
    int32_t sp = scene_add_species(s, "tree", &err);
    CHECK(scene_add_prototype(s, (uint32_t)sp, 0, 1, 2, m, &err) >= 0);
    CHECK_INT(cutout_outline_triangles_in(s), 2);

    cutout_outline_stats st;
    CHECK_INT(cutout_outline_apply(s, LEAF_MODE_AUTO, &st, &err), 0); /* a small scene keeps its masks */
    CHECK_INT(cutout_outline_apply(s, LEAF_MODE_OUTLINE, &st, &err), 1);
    CHECK_INT(st.cutout_triangles, 2);
    CHECK_INT(st.materials, 1);
    CHECK(!cutout_material(s, &s->materials[ml]));
    const mesh *o = s->prototypes[0].mesh;
    CHECK_INT(o->nt, 1 + st.outline_triangles);
    CHECK_INT(st.outline_triangles, CUTOUT_OUTLINE_CORNERS - 2); /* the card in one piece */
    double area = 0;
    uint32_t bark_left = 0;
    for (uint32_t t = 0; t < o->nt; t++) {
        const uint32_t *k = o->tri + 3 * t;
        if (o->mat[t] == mb) {
            bark_left++;
            CHECK_NEAR(o->pos[k[0] * 3], 5, 0);
            continue;
        }
        CHECK_INT(o->mat[t], ml);
        for (int i = 0; i < 3; i++) {
            const float *p = o->pos + k[i] * 3, *q = o->uv + k[i] * 2;
            CHECK_NEAR(p[1], 1, 1e-6);           /* in the card's plane */
            CHECK_NEAR(p[0], 2 * q[0], 1e-5);    /* at its uv */
            CHECK_NEAR(p[2], 2 * q[1], 1e-5);
            CHECK_NEAR(fabs(o->nrm[k[i] * 3 + 1]), 1, 1e-6); /* the card's normal */
        }
        const float *a = o->pos + k[0] * 3, *b = o->pos + k[1] * 3, *c = o->pos + k[2] * 3;
        double cy = (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]);
        CHECK(cy < 0); /* wound as the card: its normal along -y, as (0,1,2) */
        area += 0.5 * fabs(cy);
    }
    CHECK_INT(bark_left, 1);
    CHECK_NEAR(area, 4.0 * kept / (SIZE * SIZE), 1e-3);
    scene_free(s);
}

TEST_LIST(TEST_CASE(outline_is_convex_and_keeps_the_area), TEST_CASE(cards_become_opaque_outlines))
