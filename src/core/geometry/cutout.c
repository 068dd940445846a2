/* cutout.c — cut-out triangles, the alpha test at a point, and a mesh's split with the cut-out
 * part's own test (see cutout.h). */
#include "geometry/cutout.h"

#include <stdlib.h>
#include <string.h>

int cutout_triangle(const scene *s, const mesh *m, uint32_t t)
{
    return cutout_material(s, &s->materials[scene_triangle_material(s, m, t)]);
}

int cutout_point_kept(const scene *s, const mesh *m, uint32_t t, float bu, float bv)
{
    const material *mt = &s->materials[scene_triangle_material(s, m, t)];
    const uint32_t *k = m->tri + (size_t)t * 3;
    float uv[2];
    cutout_uv(m->uv + (size_t)k[0] * 2, m->uv + (size_t)k[1] * 2, m->uv + (size_t)k[2] * 2, bu, bv, uv);
    return cutout_texel_kept(texture_texel(&s->textures[mt->texture], uv[0], uv[1])[3]);
}

/* --- the cut-out part's test ---------------------------------------------------------------- */

/* The part's table of distinct uvs while it is built: an open-addressing hash of the uvs' bits
 * (slot: 1 + the uv's number, 0 empty), so corners with the same uv, bit for bit, share a number. */
typedef struct uv_table {
    float *uv;          /* 2 per uv; becomes the part's */
    uint32_t n, cap;
    uint32_t *slot;     /* a power of two of them, at most half full */
    uint32_t n_slots;
} uv_table;

static uint32_t uv_slot_of(const uv_table *t, const float *uv)
{
    uint64_t key;
    memcpy(&key, uv, sizeof key);
    uint32_t i = (uint32_t)((key * 0x9E3779B97F4A7C15ull) >> 32) & (t->n_slots - 1);
    while (t->slot[i] && memcmp(t->uv + 2 * (size_t)(t->slot[i] - 1), uv, 2 * sizeof(float)))
        i = (i + 1) & (t->n_slots - 1);
    return i;
}

/* The number of uv (2 floats) in t, added when new. Returns 0, or -1 out of memory. */
static int uv_number(uv_table *t, const float *uv, uint32_t *number)
{
    uint32_t i = uv_slot_of(t, uv);
    if (t->slot[i]) {
        *number = t->slot[i] - 1;
        return 0;
    }
    if (t->n == t->cap) {
        uint32_t cap = t->cap * 2;
        float *more = realloc(t->uv, (size_t)cap * 2 * sizeof(float));
        if (!more) return -1;
        t->uv = more, t->cap = cap;
    }
    memcpy(t->uv + 2 * (size_t)t->n, uv, 2 * sizeof(float));
    t->slot[i] = ++t->n;
    *number = t->n - 1;
    if (2 * t->n <= t->n_slots) return 0;
    uint32_t *old = t->slot, n_old = t->n_slots; /* rehash into twice the slots */
    t->n_slots *= 2;
    t->slot = calloc(t->n_slots, sizeof *t->slot);
    if (!t->slot) {
        free(old);
        return -1;
    }
    for (uint32_t k = 0; k < n_old; k++)
        if (old[k]) t->slot[uv_slot_of(t, t->uv + 2 * (size_t)(old[k] - 1))] = old[k];
    free(old);
    return 0;
}

/* The coverage mask of texture tx into *k. Returns 0, or -1 out of memory. */
static int mask_build(const texture *tx, cutout_mask *k)
{
    size_t texels = (size_t)tx->width * tx->height;
    k->width = tx->width, k->height = tx->height;
    k->bits = calloc((texels + 63) / 64, sizeof *k->bits);
    if (!k->bits) return -1;
    for (size_t x = 0; x < texels; x++)
        k->bits[x >> 6] |= (uint64_t)cutout_texel_kept(tx->rgba[x * 4 + 3]) << (x & 63);
    return 0;
}

/* Bits enough for numbers up to largest: 2, 4, 8, 16 or 32. */
static uint32_t number_bits(uint32_t largest)
{
    uint32_t bits = 2;
    while (bits < 32 && largest >> bits) bits *= 2;
    return bits;
}

/* The records of p from wide (4 numbers per triangle), each number number_bits wide. */
static int corners_pack(cutout_part *p, const uint32_t *wide)
{
    uint32_t bits = p->number_bits = number_bits(p->n_uv > p->n_masks ? p->n_uv - 1 : p->n_masks - 1);
    p->corners = calloc((size_t)p->n * bits / 2 + 8, 1);
    if (!p->corners) return -1;
    for (size_t k = 0; k < (size_t)p->n * 4; k++) /* number k at bit k * bits, little-endian */
        for (uint32_t b = 0; b < bits; b += 8) {
            size_t at = k * bits + b;
            p->corners[at / 8] |= (uint8_t)((wide[k] >> b) << (at % 8));
        }
    return 0;
}

/* The test of cut-out part p (its tri and to_mesh filled): records, uv table and masks. Returns
 * 0, or -1 out of memory. */
static int part_test_build(const scene *s, const mesh *m, cutout_part *p)
{
    int rc = -1;
    uv_table t = {.cap = 64, .n_slots = 128};
    int32_t *mask_of = malloc((s->n_textures ? s->n_textures : 1) * sizeof *mask_of); /* texture → mask; owned */
    uint32_t *wide = malloc((size_t)p->n * 4 * sizeof *wide); /* the records at 4 bytes a number; owned */
    t.uv = malloc((size_t)t.cap * 2 * sizeof(float));
    t.slot = calloc(t.n_slots, sizeof *t.slot);
    p->masks = calloc(s->n_textures ? s->n_textures : 1, sizeof *p->masks);
    if (!mask_of || !wide || !t.uv || !t.slot || !p->masks) goto done;
    for (uint32_t x = 0; x < s->n_textures; x++) mask_of[x] = -1;
    for (uint32_t i = 0; i < p->n; i++) {
        uint32_t *c = wide + (size_t)i * 4;
        for (int k = 0; k < 3; k++)
            if (uv_number(&t, m->uv + (size_t)p->tri[3 * (size_t)i + k] * 2, &c[k])) goto done;
        int32_t tex = s->materials[scene_triangle_material(s, m, p->to_mesh[i])].texture;
        if (mask_of[tex] < 0) {
            if (mask_build(&s->textures[tex], &p->masks[p->n_masks])) goto done;
            mask_of[tex] = (int32_t)p->n_masks++;
        }
        c[3] = (uint32_t)mask_of[tex];
    }
    p->uv = t.uv, p->n_uv = t.n, t.uv = NULL;
    rc = corners_pack(p, wide);
done:
    free(t.uv);
    free(t.slot);
    free(mask_of);
    free(wide);
    return rc;
}

/* --- the split ------------------------------------------------------------------------------ */

int cutout_part_build(const scene *s, const mesh *m, int cutouts, cutout_part *p, err_buf *err)
{
    memset(p, 0, sizeof *p);
    uint32_t n = 0;
    for (uint32_t t = 0; t < m->nt; t++) n += cutout_triangle(s, m, t) == cutouts;
    if (!n) return 0;
    p->tri = malloc((size_t)n * 3 * sizeof *p->tri);
    p->to_mesh = malloc((size_t)n * sizeof *p->to_mesh);
    if (!p->tri || !p->to_mesh) goto nomem;
    for (uint32_t t = 0; t < m->nt; t++)
        if (cutout_triangle(s, m, t) == cutouts) {
            memcpy(p->tri + (size_t)p->n * 3, m->tri + (size_t)t * 3, 3 * sizeof *p->tri);
            p->to_mesh[p->n++] = t;
        }
    if (cutouts && part_test_build(s, m, p)) goto nomem;
    return 0;
nomem:
    cutout_part_free(p);
    return err_nomem(err, "out of memory splitting a mesh of %u triangles into opaque and cut-out parts", m->nt);
}

void cutout_part_free(cutout_part *p)
{
    free(p->tri);
    free(p->to_mesh);
    free(p->corners);
    free(p->uv);
    for (uint32_t k = 0; p->masks && k < p->n_masks; k++) free(p->masks[k].bits);
    free(p->masks);
    memset(p, 0, sizeof *p);
}
