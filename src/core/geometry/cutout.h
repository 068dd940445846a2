/* cutout.h — alpha cut-outs (leaves drawn on a quad, say): where a material's texture has alpha
 * below one half, its surface is not there. Decides which materials and triangles are cut-outs
 * and where a cut-out triangle is kept, by the nearest texel (texture_lookup.h), and splits a
 * mesh's triangles into an opaque part and a cut-out part so a back end tests alpha on the
 * cut-out part alone. The path tracer filters its hits by this; the POV-Ray export cuts its
 * images' alpha at the same threshold.
 *
 * Ownership: a cutout_part owns its two arrays (cutout_part_free); it borrows nothing.
 */
#ifndef SYLVA_CUTOUT_H
#define SYLVA_CUTOUT_H

#include <stdint.h>

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

/* 1 when the point at barycentrics (bu, bv) of cut-out triangle t of m is kept (the texel nearest
 * to its interpolated uv). */
int cutout_point_kept(const scene *s, const mesh *m, uint32_t t, float bu, float bv);

/* One side of a mesh's split: its triangles' vertex indices and where each came from. */
typedef struct cutout_part {
    uint32_t *tri;      /* 3 per triangle, indices into the mesh's vertices; owned */
    uint32_t *to_mesh;  /* per triangle: its number in the mesh; owned */
    uint32_t n;         /* triangles */
} cutout_part;

/* The triangles of m that are cut-outs (cutouts 1) or opaque (cutouts 0), in mesh order, into
 * *p (arrays NULL when there are none). Returns 0, or -1 with err set and *p empty. */
int cutout_part_build(const scene *s, const mesh *m, int cutouts, cutout_part *p, err_buf *err);
void cutout_part_free(cutout_part *p); /* accepts an empty part; leaves it empty */

#endif
