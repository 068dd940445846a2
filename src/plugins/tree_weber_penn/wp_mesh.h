/* wp_mesh.h — the stems of a grown tree meshed as Arbaro 1.9's mesh generator meshes them for
 * its OBJ writer: level by level, each stem a tube of cross-sections (the first segment's base,
 * then every subsegment; a section of radius below 1e-6 is a single point), the trunk's
 * sections with their lobes and 0ScaleV drawn from the tree's mesh stream, a point closing the
 * top, and between sections Arbaro's faces (quads between rings, triangles to a point). */
#ifndef WP_MESH_H
#define WP_MESH_H

#include "plugin_err.h"
#include "wp_growth.h"
#include "wp_model.h"

/* Appends the stems of g to m (vertex, uv, triangle, level; empty on entry), sets m->faces for
 * the stem levels to Arbaro's face counts and widens m's bounding box by every vertex a face
 * uses (m->bbox_min/max must be set to +inf/-inf first). Quads become two triangles; faces whose
 * corners repeat a vertex (Arbaro makes some where a point meets a ring) are counted but not
 * kept as triangles. Stops with SYLVA_ERR_LIMIT past max_triangles triangles. Returns 0 or a
 * negative sylva_status with err set (m keeps what it has; the caller releases it). */
int wp_mesh_stems(wp_growth *g, size_t max_triangles, wp_model *m, plugin_err *err);

#endif
