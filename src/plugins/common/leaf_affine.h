/* leaf_affine.h — a leaf's outline and venation as the attractor of a few plane affine maps
 * (003 §2: x' = a x + b y + e, y' = c x + d y + f), drawn into an RGBA8 leaf texture.
 *
 * The leaf lives in the unit square with its stalk at y = 0 and its tip towards y = 1; texel
 * (x, row) covers u = (x + 0.5) / size, v = 1 - (row + 0.5) / size, so row 0 is the top, as in
 * every leaf texture the plugins hand the host. The attractor is found by the chaos game with a
 * seeded generator of its own: the same maps, size and seed give the same bytes, and nothing
 * outside the call is read or kept.
 *
 * Venation comes from the maps themselves: a map whose linear part is singular (det = 0)
 * squashes the leaf onto a segment, the midrib; every other map that carries the midrib's line
 * into itself continues it, and each remaining map applied after the midrib raises a point's
 * vein order by one (1: main veins, 2: secondary veins, deeper: blade). */
#ifndef LEAF_AFFINE_H
#define LEAF_AFFINE_H

#include <stddef.h>
#include <stdint.h>

#define LEAF_AFFINE_MAX_MAPS 16u
#define LEAF_AFFINE_MIN_SIZE 16u
#define LEAF_AFFINE_MAX_SIZE 2048u
#define LEAF_AFFINE_NO_VEIN 255u /* order of a texel no vein passes through */

/* One map x' = a x + b y + e, y' = c x + d y + f, chosen with weight p (> 0; the weights of a
 * set need not sum to 1). */
typedef struct leaf_affine_map {
    double a, b, c, d, e, f, p;
} leaf_affine_map;

typedef struct leaf_affine_maps {
    uint32_t n;
    leaf_affine_map map[LEAF_AFFINE_MAX_MAPS];
} leaf_affine_maps;

typedef enum leaf_affine_preset {
    LEAF_AFFINE_BEECH,  /* ovate, pinnate veins, slightly wavy margin */
    LEAF_AFFINE_MAPLE,  /* palmate, five lobes, each lobed again */
    LEAF_AFFINE_SPRUCE, /* a twig with needles on both sides */
    LEAF_AFFINE_SHRUB,  /* small elliptic leaf with few veins */
    LEAF_AFFINE_WILLOW, /* long, narrow (lanceolate) leaf */
    LEAF_AFFINE_PRESET_COUNT
} leaf_affine_preset;

/* The attractor on a size x size raster: hit[i] = 1 where a point of the attractor falls,
 * order[i] = the lowest vein order seen there (LEAF_AFFINE_NO_VEIN for none). Both arrays are
 * owned by the raster; leaf_affine_raster_free releases them (and accepts NULL). */
typedef struct leaf_affine_raster {
    uint32_t size;
    uint8_t *hit;
    uint8_t *order;
} leaf_affine_raster;

/* The preset's name ("beech", "maple", "spruce", "shrub", "willow"); NULL past the end. */
const char *leaf_affine_preset_name(leaf_affine_preset preset);

/* The preset's maps. */
void leaf_affine_preset_maps(leaf_affine_preset preset, leaf_affine_maps *out);

/* Parses user maps: maps separated by ';' or newlines, each 6 numbers "a b c d e f" or 7 with
 * the weight last (all maps with a weight, or none; without, weights follow |det| as in the
 * usual chaos game). Numbers are separated by spaces or commas. Returns 0, or -1 with
 * "column N: what is wrong, what would be valid" in err. The result is also checked as by
 * leaf_affine_check. */
int leaf_affine_parse(const char *text, leaf_affine_maps *out, char *err, size_t err_size);

/* Returns 0 when every map is a strict contraction (largest singular value < 1, so that the
 * attractor exists) with a positive, finite weight, and 1..16 maps; else -1 with a sentence in
 * err naming the map. */
int leaf_affine_check(const leaf_affine_maps *maps, char *err, size_t err_size);

/* (x, y) -> the map's image. */
void leaf_affine_apply(const leaf_affine_map *m, double x, double y, double *ox, double *oy);

/* Runs the chaos game for a size x size raster. The attractor must lie in the unit square
 * (within half a texel); else -1 with a sentence in err. On success the caller owns *out and
 * frees it with leaf_affine_raster_free. */
int leaf_affine_attractor(const leaf_affine_maps *maps, uint32_t size, uint64_t seed,
                          leaf_affine_raster *out, char *err, size_t err_size);

void leaf_affine_raster_free(leaf_affine_raster *raster);

/* Fills a caller-owned mask (size * size bytes) with 1 inside the outline of the raster's
 * attractor (its texels and every region they enclose), 0 outside. Returns 0, or -1 when out of
 * memory (the mask is then undefined). */
int leaf_affine_outline(const leaf_affine_raster *raster, uint8_t *inside);

/* Draws the leaf texture into a caller-owned rgba (size * size * 4 bytes, sRGB-encoded):
 * alpha 255 inside the outline and 0 outside; the colour channels hold a grey brightness that
 * the leaf material's albedo multiplies: blade with a little mottling and a lighter tip,
 * lighter midrib and main veins, secondary veins between. Returns 0, or -1 with err. */
int leaf_affine_render(const leaf_affine_maps *maps, uint32_t size, uint64_t seed, uint8_t *rgba,
                       char *err, size_t err_size);

#endif
