/* crown_hull.h — the envelope of a plant's crown as one closed mesh: a star-shaped surface
 * around the crown's centre whose radius in each direction is the farthest leaf vertex there,
 * rounded off by averaging with the neighbouring directions (so a few leaves may stick out).
 * It stands for the crown when the crown spans only a few pixels (render/crown_proxy.h). The
 * crown is the triangles whose material is a leaf or an alpha cut-out; a mesh without any has
 * no crown and no hull.
 *
 * Ownership: crown_hull_build returns a new mesh the caller frees (mesh_free); it borrows the
 * scene and the mesh. */
#ifndef SYLVA_CROWN_HULL_H
#define SYLVA_CROWN_HULL_H

#include "scene/scene.h"
#include "util/err.h"

/* Directions of the hull: CROWN_HULL_AZIMUTHS around the vertical, CROWN_HULL_RINGS from the
 * bottom to the top, each the centre of its cell. */
enum { CROWN_HULL_AZIMUTHS = 24, CROWN_HULL_RINGS = 12 };

/* The typical size of a leaf of m's crown: the square root of twice its triangles' mean area (a
 * leaf is a quad of two triangles, or a polygon of a few); 0 when m has no crown. */
double crown_leaf_size(const scene *s, const mesh *m);

/* The hull of m's crown in m's frame into *out (NULL when m has no crown). Its triangles carry
 * material -1 and face outward. Returns 0, or -1 with err set (out of memory). */
int crown_hull_build(const scene *s, const mesh *m, mesh **out, err_buf *err);

#endif
