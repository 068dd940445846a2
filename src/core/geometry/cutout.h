/* cutout.h — alpha cut-outs (leaves drawn on a quad, say): where a material's texture has alpha
 * below one half, its surface is not there. Decides which materials and triangles are cut-outs
 * and where a cut-out triangle is kept, by the nearest texel (texture_lookup.h), and splits a
 * mesh's triangles into an opaque part and a cut-out part so a back end tests alpha on the
 * cut-out part alone. The path tracer filters its hits by this; the POV-Ray export cuts its
 * images' alpha at the same threshold.
 *
 * The test at a hit runs millions of times per frame, on meshes of a million triangles and more,
 * so a cut-out part carries what it needs in its own triangle order: per triangle one small
 * record (its corners' uvs as numbers into the part's table of distinct uvs, and its mask: one
 * byte on leaf cards, whose corners hold 4 distinct uvs), and per texture a coverage mask, one
 * bit per texel (cutout_texel_kept, decided once). Its decision (cutout_part_point_kept) is the
 * one cutout_point_kept takes from the mesh, bit for bit: the same uvs, interpolated by the same
 * arithmetic (cutout_uv), at the same texel.
 *
 * Ownership: a cutout_part owns all its arrays (cutout_part_free); it borrows nothing.
 */
#ifndef SYLVA_CUTOUT_H
#define SYLVA_CUTOUT_H

#include <stdint.h>

#include "geometry/texture_lookup.h"
#include "scene/scene.h"
#include "util/err.h"

/* 1 when material m is a cut-out: it asks for the mask and its texture has some alpha. */
static inline int cutout_material(const scene *s, const material *m)
{
    return m->alpha_mask && m->texture >= 0 && s->textures[m->texture].has_alpha;
}

/* 1 when triangle t of mesh m is a cut-out (its material is one). */
int cutout_triangle(const scene *s, const mesh *m, uint32_t t);

/* 1 when a texel of stored alpha `alpha` (0..255) keeps a cut-out's surface: alpha / 255 is at
 * least one half. */
static inline int cutout_texel_kept(uint8_t alpha) { return alpha >= 128; }

/* The uv at barycentrics (bu, bv) of a triangle whose corners have uvs a, b and c (2 floats
 * each): the one interpolation of a cut-out test. */
static inline void cutout_uv(const float *a, const float *b, const float *c, float bu, float bv, float uv[2])
{
    float w = 1.0f - bu - bv;
    uv[0] = w * a[0] + bu * b[0] + bv * c[0];
    uv[1] = w * a[1] + bu * b[1] + bv * c[1];
}

/* 1 when the point at barycentrics (bu, bv) of cut-out triangle t of m is kept (the texel nearest
 * to its interpolated uv), read from the mesh, its material and its texture. */
int cutout_point_kept(const scene *s, const mesh *m, uint32_t t, float bu, float bv);

/* A texture's alpha test decided for every texel: bit k of the mask (word k / 64, bit k % 64)
 * is cutout_texel_kept of texel k (texture_texel_index). */
typedef struct cutout_mask {
    uint32_t width, height;
    uint64_t *bits;     /* (width * height + 63) / 64 words; owned */
} cutout_mask;

/* One side of a mesh's split: its triangles' vertex indices and where each came from; a cut-out
 * part also carries its test (the arrays after to_mesh; NULL in an opaque part). */
typedef struct cutout_part {
    uint32_t *tri;      /* 3 per triangle, indices into the mesh's vertices; owned */
    uint32_t *to_mesh;  /* per triangle: its number in the mesh; owned */
    uint32_t n;         /* triangles */
    /* per triangle a record of 4 numbers, each number_bits wide (2, 4, 8, 16 or 32: as few as
     * hold the largest), little-endian, number 0 in the lowest bits: its 3 corners' uvs, as
     * numbers into uv, and its texture's mask, a number into masks. 8 bytes of slack at the end
     * let a record be read in whole 64-bit words. Owned. */
    uint8_t *corners;
    uint32_t number_bits;
    float *uv;          /* 2 per distinct uv of the triangles' corners, bit for bit the mesh's; owned */
    uint32_t n_uv;
    cutout_mask *masks; /* one per texture the triangles use, with its bits; owned */
    uint32_t n_masks;
} cutout_part;

/* The 4 numbers of triangle i's record in part p. */
static inline void cutout_part_record(const cutout_part *p, uint32_t i, uint32_t number[4])
{
    uint32_t bits = p->number_bits;
    const uint8_t *r = p->corners + (size_t)i * bits / 2; /* 4 numbers: bits / 2 bytes */
    uint64_t lo = 0, hi = 0;
    for (int b = 0; b < 8; b++) lo |= (uint64_t)r[b] << (8 * b);
    if (bits == 32)
        for (int b = 0; b < 8; b++) hi |= (uint64_t)r[8 + b] << (8 * b);
    uint64_t mask = bits == 32 ? 0xffffffffu : (1u << bits) - 1;
    number[0] = (uint32_t)(lo & mask);
    number[1] = (uint32_t)(lo >> bits & mask);
    number[2] = bits == 32 ? (uint32_t)(hi & mask) : (uint32_t)(lo >> 2 * bits & mask);
    number[3] = bits == 32 ? (uint32_t)(hi >> 32) : (uint32_t)(lo >> 3 * bits & mask);
}

/* 1 when the point at barycentrics (bu, bv) of triangle i of cut-out part p is kept: the decision
 * of cutout_point_kept for the mesh's triangle p->to_mesh[i], from the part alone. */
static inline int cutout_part_point_kept(const cutout_part *p, uint32_t i, float bu, float bv)
{
    uint32_t c[4];
    cutout_part_record(p, i, c);
    const cutout_mask *k = &p->masks[c[3]];
    float uv[2];
    cutout_uv(p->uv + 2 * (size_t)c[0], p->uv + 2 * (size_t)c[1], p->uv + 2 * (size_t)c[2], bu, bv, uv);
    size_t x = texture_texel_index(k->width, k->height, uv[0], uv[1]);
    return (int)(k->bits[x >> 6] >> (x & 63) & 1u);
}

/* The triangles of m that are cut-outs (cutouts 1, with their test) or opaque (cutouts 0), in
 * mesh order, into *p (arrays NULL when there are none). Returns 0, or -1 with err set and *p
 * empty. */
int cutout_part_build(const scene *s, const mesh *m, int cutouts, cutout_part *p, err_buf *err);
void cutout_part_free(cutout_part *p); /* accepts an empty part; leaves it empty */

#endif
