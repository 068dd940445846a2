/* wp_mesh.h — the stems of a grown tree meshed as Arbaro 1.9's mesh generator meshes them for
 * its OBJ writer: level by level, each stem a tube of cross-sections (the first segment's base,
 * then every subsegment; a section of radius below 1e-6 is a single point), the trunk's
 * sections with their lobes and 0ScaleV drawn from the tree's mesh stream, a point closing the
 * top, and between sections Arbaro's faces (quads between rings, triangles to a point). */
#ifndef WP_MESH_H
#define WP_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "plugin_err.h"
#include "wp_growth.h"

/* The stems' mesh (wp_model.h takes its arrays over). */
typedef struct wp_stem_mesh {
    double (*vertex)[3];     /* owned; n_vertices */
    double (*uv)[2];         /* owned; per vertex: u around the stem, v along it in metres */
    size_t n_vertices;
    uint32_t (*triangle)[3]; /* owned; n_triangles */
    uint8_t *level;          /* owned; per triangle, its stem's level */
    size_t n_triangles;
    size_t faces[WP_LEVELS]; /* Arbaro's OBJ faces per stem level */
    double bbox_min[3], bbox_max[3]; /* every vertex a face uses; +inf / -inf when none */
} wp_stem_mesh;

/* The stems of g meshed into *m (emptied first) with Arbaro's face counts per level and the box.
 * Quads become two triangles; faces whose corners repeat a vertex (Arbaro makes some where a
 * point meets a ring) are counted but not kept as triangles. Stops with SYLVA_ERR_LIMIT past
 * max_triangles triangles. Returns 0, or a negative sylva_status with err set and *m empty. */
int wp_mesh_stems(wp_growth *g, size_t max_triangles, wp_stem_mesh *m, plugin_err *err);

/* Frees what *m owns and empties it. */
void wp_stem_mesh_release(wp_stem_mesh *m);

#endif
