/* lsys_palette.c — the default palette and colour conversions. */
#include "lsys_palette.h"

#include <math.h>

typedef struct palette_entry {
    const char *name;
    float albedo[3];
} palette_entry;

/* Lparser 2.1 names its colours 1..15 (its manual: 2 red is the starting colour, 8 dark green
 * for leaves, 12 dark red for bark). Index 2 is every file's starting colour, so it is a
 * red-brown bark here rather than a pure red; the rest keep their hue at natural reflectance. */
static const palette_entry palette[LSYS_PALETTE_SIZE] = {
    {"grey-brown bark", {0.20f, 0.18f, 0.15f}},
    {"grey", {0.30f, 0.30f, 0.28f}},
    {"red-brown bark (starting colour)", {0.20f, 0.09f, 0.05f}},
    {"yellow", {0.55f, 0.45f, 0.06f}},
    {"green", {0.10f, 0.28f, 0.05f}},
    {"turquoise", {0.06f, 0.30f, 0.25f}},
    {"blue", {0.06f, 0.10f, 0.45f}},
    {"purple", {0.30f, 0.06f, 0.35f}},
    {"dark green (leaves)", {0.04f, 0.13f, 0.03f}},
    {"dark turquoise", {0.03f, 0.15f, 0.12f}},
    {"dark blue", {0.03f, 0.04f, 0.20f}},
    {"dark purple", {0.15f, 0.03f, 0.17f}},
    {"dark red (bark)", {0.12f, 0.06f, 0.04f}},
    {"dark grey", {0.08f, 0.08f, 0.08f}},
    {"medium grey", {0.22f, 0.22f, 0.22f}},
    {"white (blossom)", {0.75f, 0.75f, 0.72f}},
};

static const palette_entry *entry(int32_t index)
{
    uint32_t i = (uint32_t)(index < 0 ? -(int64_t)index : index) % LSYS_PALETTE_SIZE;
    return &palette[i];
}

void lsys_palette_default(int32_t index, float albedo[3])
{
    const palette_entry *e = entry(index);
    for (int k = 0; k < 3; k++) albedo[k] = e->albedo[k];
}

const char *lsys_palette_name(int32_t index) { return entry(index)->name; }

float lsys_srgb_to_linear(float c)
{
    if (c <= 0.04045f) return c / 12.92f;
    return powf((c + 0.055f) / 1.055f, 2.4f);
}

void lsys_leaf_transmittance(const float albedo[3], float t[3])
{
    for (int k = 0; k < 3; k++) {
        float half = 0.5f * albedo[k], room = 1.0f - albedo[k];
        t[k] = half < room ? half : room;
        if (t[k] < 0) t[k] = 0;
    }
}
