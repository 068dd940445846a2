/* lsys_mesh.h — the geometry sink: turns the turtle's segments into tubes and its polygons into
 * triangles, and hands them over in chunks.
 *
 * Segments: a tube of `sides` corners around the segment, `radius` from the turtle (Lparser's
 * thickness as a percentage of the segment length, min_thickness below it). A segment that
 * starts where its branch's last segment ended continues that tube from the previous ring, so
 * bends and thickness changes leave no gap; a branch (`[`) starts a tube of its own inside its
 * parent. Tubes are closed at both ends. `flat` gives each side face its own vertices and normal
 * (Lparser's blocks, with sides = 4); otherwise normals are radial (smooth cylinders).
 * Polygons: triangulated by ear clipping (concave outlines too), with their plane's normal.
 *
 * Texture coordinates: a tube's u goes once round it (0 to 1 over the sides; smooth tubes repeat
 * the first corner of each ring at u = 1, the seam) and its v runs along the branch, in metres
 * over `bark_tile` (metres per repeat of the bark texture), carried on from ring to ring and
 * from a parent's last ring into its branches; caps show the bark projected square to the tube
 * at the same scale. A polygon's (u, v) is its own leaf frame (lsys_leaf_uv.h).
 *
 * Every triangle carries a material key: colour index * 2 for wood (segments) and
 * colour index * 2 + 1 for leaves (polygons); the consumer maps keys to materials.
 * Coordinates are multiplied by `scale` (file units to metres) on the way out.
 *
 * Ownership: lsys_mesh_new returns a builder the caller frees with lsys_mesh_free; chunk arrays
 * handed to the flush callback are borrowed for the call.
 */
#ifndef LSYS_MESH_H
#define LSYS_MESH_H

#include <stdint.h>

#include "lsys_status.h"
#include "lsys_turtle.h"

#define LSYS_MESH_MIN_SIDES 3
#define LSYS_MESH_MAX_SIDES 32
#define LSYS_MESH_CHUNK_VERTICES 65536u   /* most vertices handed over at once */
#define LSYS_MESH_CHUNK_TRIANGLES 131072u /* most triangles handed over at once */

/* Receives one chunk: nv vertices (xyz, unit normal and uv, float) and nt triangles whose indices
 * count from this chunk's first vertex, each with its material key. Returns 0, or non-zero to
 * stop (the consumer keeps its own message). */
typedef int (*lsys_flush_fn)(void *ctx, const float *pos, const float *nrm, const float *uv, uint32_t nv,
                             const uint32_t *tri, const int32_t *material_key, uint32_t nt);

typedef struct lsys_mesh_config {
    uint32_t sides;            /* corners of a tube's cross-section, 3..32 */
    int flat;                  /* 1: flat side faces (blocks); 0: smooth */
    double scale;              /* metres per file unit */
    double bark_tile;          /* metres of branch per repeat of the bark texture along it, > 0 */
    uint32_t max_polygon_vertices; /* the largest polygon the turtle may hand over */
    lsys_flush_fn flush;
    void *flush_ctx;
} lsys_mesh_config;

typedef struct lsys_mesh lsys_mesh;

/* NULL when memory runs out or the config is out of range (err set). */
lsys_mesh *lsys_mesh_new(const lsys_mesh_config *cfg, plugin_err *err);
void lsys_mesh_free(lsys_mesh *m); /* accepts NULL */

/* The sink to hand to lsys_interpret. */
lsys_sink lsys_mesh_sink(lsys_mesh *m);

/* Hands over what is left. Returns LSYS_OK or LSYS_ERR_SINK. */
int lsys_mesh_finish(lsys_mesh *m);

uint64_t lsys_mesh_triangles(const lsys_mesh *m); /* triangles handed over or pending */
uint64_t lsys_mesh_vertices(const lsys_mesh *m);

#endif
