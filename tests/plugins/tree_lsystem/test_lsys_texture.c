/* test_lsys_texture.c — the species' textures: the same bytes every time, one look per preset,
 * the leaf opaque everywhere (the grammar's polygon is the outline) with its veins kept, and
 * the key choices in the presets' order. */
#include "harness.h"

#include <stdlib.h>

#include "bark_fractal.h"
#include "leaf_affine.h"
#include "lsys_texture.h"

#define BARK_BYTES ((size_t)LSYS_BARK_TEXTURE_SIZE * LSYS_BARK_TEXTURE_SIZE * 4)
#define LEAF_BYTES ((size_t)LSYS_LEAF_TEXTURE_SIZE * LSYS_LEAF_TEXTURE_SIZE * 4)

TEST(choices_name_the_shared_presets)
{
    for (int k = 0; k < LSYS_LEAF_TEXTURE_OFF; k++)
        CHECK(!strcmp(lsys_leaf_texture_names[k], leaf_affine_preset_name((leaf_affine_preset)k)));
    CHECK(!strcmp(lsys_leaf_texture_names[LSYS_LEAF_TEXTURE_OFF], "off"));
    CHECK(lsys_leaf_texture_names[LSYS_LEAF_TEXTURE_OFF + 1] == NULL);
    CHECK(!strcmp(lsys_bark_texture_names[0], "smooth"));
    CHECK(!strcmp(lsys_bark_texture_names[3], "fissured"));
    CHECK(!strcmp(lsys_bark_texture_names[LSYS_BARK_TEXTURE_OFF], "off"));
    CHECK(lsys_bark_texture_names[LSYS_BARK_TEXTURE_OFF + 1] == NULL);
    CHECK_INT(LSYS_BARK_TEXTURE_OFF, BARK_FRACTAL_PRESETS);
    CHECK_INT(LSYS_LEAF_TEXTURE_OFF, LEAF_AFFINE_PRESET_COUNT);
}

TEST(bark_is_deterministic_and_differs_by_preset)
{
    float *height = malloc((size_t)LSYS_BARK_TEXTURE_SIZE * LSYS_BARK_TEXTURE_SIZE * sizeof *height);
    uint8_t *a = malloc(BARK_BYTES), *b = malloc(BARK_BYTES), *c = malloc(BARK_BYTES);
    CHECK(height && a && b && c);
    if (height && a && b && c) {
        lsys_texture_bark(2, height, a);
        lsys_texture_bark(2, height, b);
        lsys_texture_bark(0, height, c);
        CHECK(!memcmp(a, b, BARK_BYTES));
        CHECK(memcmp(a, c, BARK_BYTES) != 0);
        /* Grey, opaque, and not flat: furrows and plates. */
        uint8_t lo = 255, hi = 0;
        int grey = 1, opaque = 1;
        for (size_t t = 0; t < BARK_BYTES / 4; t++) {
            grey &= a[4 * t] == a[4 * t + 1] && a[4 * t] == a[4 * t + 2];
            opaque &= a[4 * t + 3] == 255;
            lo = a[4 * t] < lo ? a[4 * t] : lo, hi = a[4 * t] > hi ? a[4 * t] : hi;
        }
        CHECK(grey && opaque);
        CHECK(hi - lo > 40);
    }
    free(height), free(a), free(b), free(c);
}

TEST(leaf_is_opaque_keeps_its_veins_and_is_deterministic)
{
    uint8_t *a = malloc(LEAF_BYTES), *b = malloc(LEAF_BYTES), *ref = malloc(LEAF_BYTES);
    CHECK(a && b && ref);
    if (a && b && ref) {
        CHECK_INT(lsys_texture_leaf(0, a), 0);
        CHECK_INT(lsys_texture_leaf(0, b), 0);
        CHECK(!memcmp(a, b, LEAF_BYTES));
        CHECK_INT(lsys_texture_leaf(1, b), 0);
        CHECK(memcmp(a, b, LEAF_BYTES) != 0);
        /* The affine leaf's colour unchanged, its alpha outline dropped. */
        leaf_affine_maps maps;
        leaf_affine_preset_maps(LEAF_AFFINE_BEECH, &maps);
        CHECK_INT(leaf_affine_render(&maps, LSYS_LEAF_TEXTURE_SIZE, LSYS_LEAF_TEXTURE_SEED, ref, NULL, 0), 0);
        size_t outside = 0, same_colour = 0, vein = 0;
        for (size_t t = 0; t < LEAF_BYTES / 4; t++) {
            outside += ref[4 * t + 3] == 0;
            same_colour += !memcmp(a + 4 * t, ref + 4 * t, 3);
            vein += a[4 * t] >= 240; /* midrib and main veins (linear 0.9 and more) */
            CHECK_INT(a[4 * t + 3], 255);
        }
        CHECK(outside > 0);
        CHECK_INT(same_colour, LEAF_BYTES / 4);
        CHECK(vein > 0);
    }
    free(a), free(b), free(ref);
}

TEST_LIST(TEST_CASE(choices_name_the_shared_presets), TEST_CASE(bark_is_deterministic_and_differs_by_preset),
          TEST_CASE(leaf_is_opaque_keeps_its_veins_and_is_deterministic))
