/* test_bark_bump.c — bark relief (render/bark_bump.h): a flat texture leaves the normal alone; a
 * luminance ramp along u tilts it away from the brighter (higher) side by the stated slope,
 * whatever the triangle's size; a texture of extreme contrast never turns the normal past the
 * geometric surface; leaves, untextured and non-plant surfaces are left alone. */
#include "harness.h"

#include <math.h>

#include "geometry/texture_lookup.h"
#include "render/bark_bump.h"
#include "scene/mesh.h"

enum { TW = 16, TH = 16 };

/* A textured bark material over one triangle in the XY plane, u along x over `size` metres,
 * v along y, normals +z; the texels are the test's to fill. */
typedef struct bark_fixture {
    uint8_t texels[TW * TH * 4];
    texture tx;
    material bark;
    scene s;
    float pos[9], nrm[9], uv[6];
    uint32_t tri[3];
    int32_t mat[1];
    mesh m;
} bark_fixture;

static void fixture_init(bark_fixture *f, float size)
{
    const float p[9] = {0, 0, 0, size, 0, 0, 0, size, 0}, t[6] = {0, 0, 1, 0, 0, 1};
    for (int i = 0; i < 9; i++) f->pos[i] = p[i], f->nrm[i] = (i % 3 == 2);
    for (int i = 0; i < 6; i++) f->uv[i] = t[i];
    f->tri[0] = 0, f->tri[1] = 1, f->tri[2] = 2, f->mat[0] = 0;
    f->m = (mesh){.pos = f->pos, .nrm = f->nrm, .uv = f->uv, .nv = 3, .tri = f->tri, .mat = f->mat, .nt = 1};
    f->tx = (texture){.width = TW, .height = TH, .rgba = f->texels};
    f->bark = (material){.bsdf = SYLVA_BSDF_LAMBERT, .albedo = {1, 1, 1}, .texture = 0};
    f->s = (scene){.textures = &f->tx, .n_textures = 1};
}

static vec3 bumped(const scene *s, const mesh *m, const material *mat, geom_kind kind, vec3 ns)
{
    hit_info h = {.ng = v3(0, 0, 1), .ns = v3_norm(ns), .u = 0.5f, .v = 0.25f, .mat = mat, .kind = kind};
    bark_bump(s, m, 0, NULL, &h);
    return h.ns;
}

TEST(ramp_tilts_by_the_stated_slope)
{
    static bark_fixture f;
    fixture_init(&f, 1.0f);
    for (int y = 0; y < TH; y++)
        for (int x = 0; x < TW; x++) {
            uint8_t *t = f.texels + (y * TW + x) * 4;
            t[0] = t[1] = t[2] = (uint8_t)(100 + 4 * x), t[3] = 255;
        }
    /* the luminance step per texel at u = 0.5 (texel 8), over two texels either side */
    float step = (texture_srgb_to_linear(100 + 4 * 10) - texture_srgb_to_linear(100 + 4 * 6)) / 4.0f;
    for (int k = 0; k < 3; k++) {
        float size = k == 0 ? 0.01f : k == 1 ? 1.0f : 30.0f;
        fixture_init(&f, size);
        vec3 n = bumped(&f.s, &f.m, &f.bark, GEOM_PROTOTYPE, v3(0, 0, 1));
        CHECK(n.x < 0.0f);                           /* away from the higher, brighter side */
        CHECK_NEAR(-n.x / n.z, BARK_BUMP_SLOPE * step, 1e-4);
        CHECK_NEAR(n.y, 0.0, 1e-6);
    }
    /* flat texture: unchanged */
    for (int i = 0; i < TW * TH; i++) f.texels[i * 4] = f.texels[i * 4 + 1] = f.texels[i * 4 + 2] = 90;
    vec3 n = bumped(&f.s, &f.m, &f.bark, GEOM_PROTOTYPE, v3(0.1f, 0, 1));
    vec3 want = v3_norm(v3(0.1f, 0, 1));
    CHECK_NEAR(n.x, want.x, 1e-6);
    CHECK_NEAR(n.z, want.z, 1e-6);
}

TEST(never_past_the_surface_and_only_on_bark)
{
    static bark_fixture f;
    fixture_init(&f, 1.0f);
    for (int i = 0; i < TW * TH; i++) {
        int x = i % TW, y = i / TW;
        f.texels[i * 4] = f.texels[i * 4 + 1] = f.texels[i * 4 + 2] = ((x / 3 + y / 3) & 1) ? 255 : 0;
        f.texels[i * 4 + 3] = 255;
    }
    int tilted = 0;
    for (int a = 0; a < 64; a++) {
        /* interpolated normals leaning up to 80 degrees off the face, every which way */
        float th = 1.4f * (a % 8) / 7.0f, ph = 0.785f * (float)(a / 8);
        vec3 ns = v3(sinf(th) * cosf(ph), sinf(th) * sinf(ph), cosf(th));
        for (int j = 0; j < 16; j++) {
            hit_info h = {.ng = v3(0, 0, -1), .ns = ns, .u = (j + 0.3f) / 16, .v = (j * 7 % 16 + 0.6f) / 16,
                          .mat = &f.bark, .kind = GEOM_PROTOTYPE};
            bark_bump(&f.s, &f.m, 0, NULL, &h);
            CHECK(h.ns.z >= BARK_BUMP_MIN_COSINE * 0.99f);
            CHECK_NEAR(v3_len(h.ns), 1.0, 1e-5);
            tilted += fabsf(h.ns.x - ns.x) > 0.05f;
        }
    }
    CHECK(tilted > 100);
    material leaf = {.bsdf = SYLVA_BSDF_LEAF, .texture = 0}, plain = {.bsdf = SYLVA_BSDF_LAMBERT, .texture = -1};
    material masked = {.bsdf = SYLVA_BSDF_LAMBERT, .texture = 0, .alpha_mask = 1};
    vec3 up = v3(0, 0, 1);
    CHECK_NEAR(bumped(&f.s, &f.m, &leaf, GEOM_PROTOTYPE, up).z, 1.0, 0.0);
    CHECK_NEAR(bumped(&f.s, &f.m, &plain, GEOM_PROTOTYPE, up).z, 1.0, 0.0);
    CHECK_NEAR(bumped(&f.s, &f.m, &masked, GEOM_PROTOTYPE, up).z, 1.0, 0.0);
    CHECK_NEAR(bumped(&f.s, &f.m, &f.bark, GEOM_OBJECT, up).z, 1.0, 0.0);
    CHECK(bumped(&f.s, &f.m, &f.bark, GEOM_PROTOTYPE, up).z < 1.0f);
}

TEST_LIST(TEST_CASE(ramp_tilts_by_the_stated_slope), TEST_CASE(never_past_the_surface_and_only_on_bark))
