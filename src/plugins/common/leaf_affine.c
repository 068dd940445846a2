/* leaf_affine.c — leaves by affine maps (003 §2): the presets, the parser for user maps, the
 * chaos game that finds the attractor with its vein orders, and the leaf texture drawn from
 * it. Owns no state between calls; every allocation is freed before return or handed to the
 * caller's raster. */
#include "leaf_affine.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CHAOS_POINTS_PER_TEXEL 48u
#define CHAOS_SKIP 32u
#define SINGULAR_DET 1e-12 /* |det| at or below this: a midrib map */
#define ON_LINE 1e-9       /* distance and cross product tolerance for "continues the midrib" */

static int fail(char *err, size_t err_size, const char *fmt, ...)
{
    if (err && err_size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, err_size, fmt, ap);
        va_end(ap);
    }
    return -1;
}

/* --- presets ------------------------------------------------------------------------------- */

/* A map that scales the leaf by sx across and sy along, turns it by angle (radians,
 * anticlockwise, so positive leans left) and puts its stalk (0.5, 0) at (bx, by). */
static leaf_affine_map placed(double sx, double sy, double angle, double bx, double by, double p)
{
    double c = cos(angle), s = sin(angle);
    leaf_affine_map m = {c * sx, -s * sy, s * sx, c * sy, 0, 0, p};
    m.e = bx - m.a * 0.5;
    m.f = by - m.c * 0.5;
    return m;
}

/* The midrib: the whole leaf squashed onto x = 0.5, y' = len y (from the stalk up). */
static leaf_affine_map midrib(double len, double p)
{
    leaf_affine_map m = {0, 0, 0, len, 0.5, 0, p};
    return m;
}

/* The leaf scaled by s about its tip (0.5, tip): the next leaf copy up the midrib. */
static leaf_affine_map towards_tip(double s, double tip, double p)
{
    leaf_affine_map m = {s, 0, 0, s, 0.5 * (1 - s), tip * (1 - s), p};
    return m;
}

static const char *const preset_names[LEAF_AFFINE_PRESET_COUNT] = {"beech", "maple", "spruce",
                                                                   "shrub", "willow"};

const char *leaf_affine_preset_name(leaf_affine_preset preset)
{
    return (unsigned)preset < LEAF_AFFINE_PRESET_COUNT ? preset_names[preset] : NULL;
}

/* A preset: the midrib (length, weight), the copy towards the tip (scale, tip, weight) and one
 * or two pairs of side copies, mirrored about the midrib (scale across and along, lean,
 * height of the copy's stalk, weight). */
typedef struct leaf_shape {
    double rib_length, rib_p, tip_scale, tip, tip_p;
    uint32_t pairs;
    struct { double sx, sy, angle, base, p; } side[2];
} leaf_shape;

static const leaf_shape preset_shapes[LEAF_AFFINE_PRESET_COUNT] = {
    [LEAF_AFFINE_BEECH] = {0.95, 0.02, 0.8, 0.97, 0.6, 1, {{0.5, 0.46, 0.72, 0.14, 0.19}}},
    [LEAF_AFFINE_MAPLE] = {0.92, 0.02, 0.62, 0.95, 0.3, 2,
                           {{0.5, 0.5, 0.85, 0.3, 0.22}, {0.3, 0.3, 1.75, 0.27, 0.1}}},
    [LEAF_AFFINE_SPRUCE] = {0.97, 0.05, 0.86, 0.97, 0.55, 1, {{0.05, 0.36, 0.95, 0.04, 0.2}}},
    [LEAF_AFFINE_SHRUB] = {0.93, 0.03, 0.74, 0.95, 0.5, 1, {{0.4, 0.5, 0.5, 0.12, 0.23}}},
    [LEAF_AFFINE_WILLOW] = {0.97, 0.03, 0.84, 0.98, 0.55, 1, {{0.22, 0.3, 0.3, 0.06, 0.2}}},
};

void leaf_affine_preset_maps(leaf_affine_preset preset, leaf_affine_maps *out)
{
    memset(out, 0, sizeof *out);
    const leaf_shape *s = &preset_shapes[(unsigned)preset < LEAF_AFFINE_PRESET_COUNT ? preset : 0];
    out->map[out->n++] = midrib(s->rib_length, s->rib_p);
    out->map[out->n++] = towards_tip(s->tip_scale, s->tip, s->tip_p);
    for (uint32_t k = 0; k < s->pairs; k++)
        for (int side = 1; side >= -1; side -= 2)
            out->map[out->n++] = placed(s->side[k].sx, s->side[k].sy, side * s->side[k].angle,
                                        0.5, s->side[k].base, s->side[k].p);
}

/* --- checking and parsing ------------------------------------------------------------------ */

void leaf_affine_apply(const leaf_affine_map *m, double x, double y, double *ox, double *oy)
{
    *ox = m->a * x + m->b * y + m->e;
    *oy = m->c * x + m->d * y + m->f;
}

/* Largest singular value of [a b; c d]. */
static double largest_stretch(const leaf_affine_map *m)
{
    double s = m->a * m->a + m->b * m->b + m->c * m->c + m->d * m->d;
    double det = m->a * m->d - m->b * m->c;
    double disc = s * s - 4 * det * det;
    return sqrt(0.5 * (s + sqrt(disc > 0 ? disc : 0)));
}

int leaf_affine_check(const leaf_affine_maps *maps, char *err, size_t err_size)
{
    if (maps->n < 1 || maps->n > LEAF_AFFINE_MAX_MAPS)
        return fail(err, err_size, "%u maps given; a leaf needs 1 to %u", maps->n,
                    LEAF_AFFINE_MAX_MAPS);
    for (uint32_t i = 0; i < maps->n; i++) {
        const leaf_affine_map *m = &maps->map[i];
        const double v[7] = {m->a, m->b, m->c, m->d, m->e, m->f, m->p};
        for (int k = 0; k < 7; k++)
            if (!isfinite(v[k]))
                return fail(err, err_size, "map %u: coefficient %d is not a finite number", i + 1,
                            k + 1);
        if (!(m->p > 0))
            return fail(err, err_size, "map %u: weight %g must be greater than 0", i + 1, m->p);
        double s = largest_stretch(m);
        if (!(s < 1))
            return fail(err, err_size,
                        "map %u stretches by %.4g; every map must shrink (largest stretch below "
                        "1) for the leaf to exist",
                        i + 1, s);
    }
    return 0;
}

int leaf_affine_parse(const char *text, leaf_affine_maps *out, char *err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    const char *p = text;
    double num[7];
    int count = 0, weighted = -1;
    size_t map_column = 1;
    for (;;) {
        while (*p == ' ' || *p == '\t' || *p == ',' || *p == '\r') p++;
        if (*p == ';' || *p == '\n' || *p == '\0') {
            if (count > 0) {
                size_t col = map_column;
                if (count != 6 && count != 7)
                    return fail(err, err_size,
                                "column %zu: map %u has %d numbers; give 6 (a b c d e f) or 7 "
                                "(a b c d e f weight)",
                                col, out->n + 1, count);
                if (weighted >= 0 && weighted != (count == 7))
                    return fail(err, err_size,
                                "column %zu: map %u %s a weight but map 1 %s; give weights for "
                                "every map or for none",
                                col, out->n + 1, count == 7 ? "has" : "lacks",
                                weighted ? "has one" : "does not");
                if (out->n == LEAF_AFFINE_MAX_MAPS)
                    return fail(err, err_size, "column %zu: more than %u maps; a leaf takes 1 to %u",
                                col, LEAF_AFFINE_MAX_MAPS, LEAF_AFFINE_MAX_MAPS);
                weighted = count == 7;
                leaf_affine_map *m = &out->map[out->n++];
                *m = (leaf_affine_map){num[0], num[1], num[2], num[3], num[4], num[5], 0};
                m->p = weighted ? num[6] : fmax(fabs(m->a * m->d - m->b * m->c), 0.01);
                count = 0;
            }
            if (*p == '\0') break;
            p++;
            continue;
        }
        size_t col = (size_t)(p - text) + 1;
        if (count == 0) map_column = col;
        char *end;
        double v = strtod(p, &end);
        if (end == p || (*end && !strchr(" \t,;\r\n", *end)))
            return fail(err, err_size, "column %zu: '%.12s' is not a number; maps are numbers "
                        "a b c d e f [weight] separated by ';'", col, p);
        if (count == 7)
            return fail(err, err_size, "column %zu: map %u has more than 7 numbers; give 6 "
                        "(a b c d e f) or 7 (a b c d e f weight)", col, out->n + 1);
        num[count++] = v;
        p = end;
    }
    if (out->n == 0) return fail(err, err_size, "column 1: no maps given; give at least one map "
                                 "a b c d e f");
    return leaf_affine_check(out, err, err_size);
}

/* --- the chaos game ------------------------------------------------------------------------ */

static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static int singular(const leaf_affine_map *m)
{
    return fabs(m->a * m->d - m->b * m->c) <= SINGULAR_DET;
}

/* Whether m carries the line through (px, py) along (dx, dy) into itself. */
static int keeps_line(const leaf_affine_map *m, double px, double py, double dx, double dy)
{
    double qx, qy;
    leaf_affine_apply(m, px, py, &qx, &qy);
    double len = hypot(dx, dy);
    double off = fabs((qx - px) * dy - (qy - py) * dx) / len;
    double tx = m->a * dx + m->b * dy, ty = m->c * dx + m->d * dy;
    double cross = fabs(tx * dy - ty * dx) / (len * len);
    return off < ON_LINE && cross < ON_LINE;
}

/* kind[i]: 0 raises the vein order, 1 continues the midrib, 2 is a midrib. */
static void vein_kinds(const leaf_affine_maps *maps, uint8_t *kind)
{
    const leaf_affine_map *rib = NULL;
    for (uint32_t i = 0; i < maps->n; i++) {
        kind[i] = 0;
        if (singular(&maps->map[i])) {
            kind[i] = 2;
            if (!rib && largest_stretch(&maps->map[i]) > 0) rib = &maps->map[i];
        }
    }
    if (!rib) return;
    double dx = rib->a, dy = rib->c;
    if (hypot(rib->b, rib->d) > hypot(dx, dy)) dx = rib->b, dy = rib->d;
    for (uint32_t i = 0; i < maps->n; i++)
        if (kind[i] == 0 && keeps_line(&maps->map[i], rib->e, rib->f, dx, dy)) kind[i] = 1;
}

void leaf_affine_raster_free(leaf_affine_raster *raster)
{
    if (!raster) return;
    free(raster->hit);
    free(raster->order);
    raster->hit = raster->order = NULL;
}

/* The chaos game reaches the ends of a midrib only through points already near them, so a
 * stalk below the blade, and its copies at the base of every vein, stay sparse. The attractor
 * holds its own images under every map (the Hutchinson operator's fixed point), so the raster is
 * completed from those images: first every texel found is mapped through the midrib maps, then
 * every texel so added through every map, and so on until nothing new appears (vein orders
 * carried along). A midrib map takes the texel's four corners, as its slow contraction along the
 * midrib would otherwise round back into the same texel; its images lie on the midrib's line, so
 * this spreads them only along it. The other maps take the texel's centre. Texels the game found
 * are not mapped through those again: near a map's fixed point rounding would hold their images
 * a texel away from it and blunt the tip. fresh (size^2 bytes) is scratch. */
static void complete_from_images(const leaf_affine_maps *maps, const uint8_t *kind,
                                 leaf_affine_raster *r, uint8_t *fresh)
{
    uint32_t n = r->size;
    size_t texels = (size_t)n * n;
    memcpy(fresh, r->hit, texels); /* pass 0: the game's texels, through the midrib maps only */
    for (uint32_t pass = 0, changed = 1; changed && pass < 4 * n; pass++) {
        changed = 0;
        for (size_t t = 0; t < texels; t++) {
            if (fresh[t] != 1) continue;
            fresh[t] = 0;
            for (uint32_t k = 0; k < 4 * maps->n; k++) {
                uint32_t i = k / 4;
                if (kind[i] != 2 && ((k & 3) || pass == 0)) continue;
                double du = kind[i] != 2 ? 0 : (k & 1) ? 0.49 : -0.49;
                double dv = kind[i] != 2 ? 0 : (k & 2) ? 0.49 : -0.49;
                double u = (t % n + 0.5 + du) / n, v = 1 - (t / n + 0.5 + dv) / n;
                double x, y;
                leaf_affine_apply(&maps->map[i], u, v, &x, &y);
                int32_t col = (int32_t)floor(x * n), row = (int32_t)floor((1 - y) * n);
                col = col < 0 ? 0 : col >= (int32_t)n ? (int32_t)n - 1 : col;
                row = row < 0 ? 0 : row >= (int32_t)n ? (int32_t)n - 1 : row;
                size_t image = (size_t)row * n + (size_t)col;
                unsigned order = kind[i] == 2 ? 0 : kind[i] == 1 ? r->order[t]
                                 : r->order[t] < LEAF_AFFINE_NO_VEIN ? r->order[t] + 1u
                                                                      : LEAF_AFFINE_NO_VEIN;
                if (r->hit[image] && r->order[image] <= order) continue;
                r->hit[image] = 1;
                r->order[image] = (uint8_t)order;
                fresh[image] = 2; /* mapped in the next pass */
                changed = 1;
            }
        }
        for (size_t t = 0; t < texels; t++) fresh[t] = fresh[t] == 2;
    }
}

int leaf_affine_attractor(const leaf_affine_maps *maps, uint32_t size, uint64_t seed,
                          leaf_affine_raster *out, char *err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    if (leaf_affine_check(maps, err, err_size)) return -1;
    if (size < LEAF_AFFINE_MIN_SIZE || size > LEAF_AFFINE_MAX_SIZE)
        return fail(err, err_size, "texture size %u is outside %u..%u", size,
                    LEAF_AFFINE_MIN_SIZE, LEAF_AFFINE_MAX_SIZE);
    size_t texels = (size_t)size * size;
    out->size = size;
    out->hit = calloc(texels, 1);      /* owned by out */
    out->order = malloc(texels);       /* owned by out */
    if (!out->hit || !out->order) {
        leaf_affine_raster_free(out);
        return fail(err, err_size, "out of memory for a %ux%u leaf texture", size, size);
    }
    memset(out->order, LEAF_AFFINE_NO_VEIN, texels);

    uint8_t kind[LEAF_AFFINE_MAX_MAPS];
    vein_kinds(maps, kind);
    double cumulative[LEAF_AFFINE_MAX_MAPS], total = 0;
    for (uint32_t i = 0; i < maps->n; i++) cumulative[i] = total += maps->map[i].p;

    /* Start on the attractor: the fixed point of the first map that has one. */
    const leaf_affine_map *m0 = &maps->map[0];
    double det = (1 - m0->a) * (1 - m0->d) - m0->b * m0->c; /* non-zero: m0 shrinks */
    double x = (m0->e * (1 - m0->d) + m0->b * m0->f) / det;
    double y = (m0->f * (1 - m0->a) + m0->c * m0->e) / det;
    unsigned order = kind[0] == 2 ? 0 : LEAF_AFFINE_NO_VEIN;

    uint64_t state = seed;
    const double slack = 0.5 / size;
    size_t points = texels * CHAOS_POINTS_PER_TEXEL;
    for (size_t k = 0; k < points + CHAOS_SKIP; k++) {
        double r = (double)(splitmix64(&state) >> 11) * (1.0 / 9007199254740992.0) * total;
        uint32_t i = 0;
        while (i + 1 < maps->n && r >= cumulative[i]) i++;
        leaf_affine_apply(&maps->map[i], x, y, &x, &y);
        if (kind[i] == 2) order = 0;
        else if (kind[i] == 0 && order < LEAF_AFFINE_NO_VEIN) order++;
        if (k < CHAOS_SKIP) continue;
        if (x < -slack || x > 1 + slack || y < -slack || y > 1 + slack) {
            leaf_affine_raster_free(out);
            return fail(err, err_size,
                        "the leaf reaches (%.4g, %.4g), outside the unit square its texture "
                        "covers; scale or move the maps so that it stays within 0..1",
                        x, y);
        }
        int32_t col = (int32_t)(x * size), row = (int32_t)((1 - y) * size);
        col = col < 0 ? 0 : col >= (int32_t)size ? (int32_t)size - 1 : col;
        row = row < 0 ? 0 : row >= (int32_t)size ? (int32_t)size - 1 : row;
        size_t t = (size_t)row * size + (size_t)col;
        out->hit[t] = 1;
        if (order < out->order[t]) out->order[t] = (uint8_t)order;
    }
    uint8_t *fresh = malloc(texels); /* owned here */
    if (!fresh) {
        leaf_affine_raster_free(out);
        return fail(err, err_size, "out of memory for a %ux%u leaf texture", size, size);
    }
    complete_from_images(maps, kind, out, fresh);
    free(fresh);
    return 0;
}

/* --- outline and texture ------------------------------------------------------------------- */

int leaf_affine_outline(const leaf_affine_raster *raster, uint8_t *inside)
{
    /* Everything is inside until a flood from the border through empty texels reaches it. */
    uint32_t n = raster->size;
    size_t texels = (size_t)n * n;
    memset(inside, 1, texels);
    uint32_t *stack = malloc(texels * sizeof *stack); /* owned here */
    if (!stack) return -1;
    size_t top = 0;
    for (uint32_t i = 0; i < n; i++) {
        const uint32_t edge[4] = {i, (n - 1) * n + i, i * n, i * n + n - 1};
        for (int k = 0; k < 4; k++)
            if (!raster->hit[edge[k]] && inside[edge[k]]) inside[edge[k]] = 0, stack[top++] = edge[k];
    }
    while (top > 0) {
        uint32_t t = stack[--top], x = t % n, row = t / n;
        uint32_t next[4];
        int count = 0;
        if (x > 0) next[count++] = t - 1;
        if (x + 1 < n) next[count++] = t + 1;
        if (row > 0) next[count++] = t - n;
        if (row + 1 < n) next[count++] = t + n;
        for (int k = 0; k < count; k++)
            if (!raster->hit[next[k]] && inside[next[k]]) inside[next[k]] = 0, stack[top++] = next[k];
    }
    free(stack);
    return 0;
}

/* Smooth lattice noise in [0, 1) over an 8 x 8 grid of the unit square. */
static double mottle(double u, double v, uint64_t seed)
{
    double gx = u * 8, gy = v * 8;
    int32_t ix = (int32_t)floor(gx), iy = (int32_t)floor(gy);
    double fx = gx - ix, fy = gy - iy, corner[4];
    for (int k = 0; k < 4; k++) {
        uint64_t s = seed ^ ((uint64_t)(uint32_t)(ix + (k & 1)) << 32 | (uint32_t)(iy + (k >> 1)));
        corner[k] = (double)(splitmix64(&s) >> 11) * (1.0 / 9007199254740992.0);
    }
    fx = fx * fx * (3 - 2 * fx), fy = fy * fy * (3 - 2 * fy);
    double lo = corner[0] + (corner[1] - corner[0]) * fx, hi = corner[2] + (corner[3] - corner[2]) * fx;
    return lo + (hi - lo) * fy;
}

static uint8_t srgb_encode(double linear)
{
    linear = linear < 0 ? 0 : linear > 1 ? 1 : linear;
    double s = linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1 / 2.4) - 0.055;
    return (uint8_t)(s * 255.0 + 0.5);
}

int leaf_affine_render(const leaf_affine_maps *maps, uint32_t size, uint64_t seed, uint8_t *rgba,
                       char *err, size_t err_size)
{
    leaf_affine_raster raster;
    if (leaf_affine_attractor(maps, size, seed, &raster, err, err_size)) return -1;
    size_t texels = (size_t)size * size;
    uint8_t *inside = malloc(texels); /* owned here */
    if (!inside || leaf_affine_outline(&raster, inside)) {
        free(inside);
        leaf_affine_raster_free(&raster);
        return fail(err, err_size, "out of memory for a %ux%u leaf texture", size, size);
    }
    for (uint32_t row = 0; row < size; row++)
        for (uint32_t x = 0; x < size; x++) {
            size_t t = (size_t)row * size + x;
            double u = (x + 0.5) / size, v = 1 - (row + 0.5) / size;
            double grey = 0.72 + 0.1 * v + 0.08 * (mottle(u, v, seed) - 0.5);
            switch (raster.order[t]) {
            case 0: grey = 0.96; break;
            case 1: grey = 0.9; break;
            case 2: grey += 0.06; break;
            default: break;
            }
            uint8_t *p = rgba + t * 4;
            p[0] = p[1] = p[2] = srgb_encode(grey);
            p[3] = inside[t] ? 255 : 0;
        }
    free(inside);
    leaf_affine_raster_free(&raster);
    return 0;
}
