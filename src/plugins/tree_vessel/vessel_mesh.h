/* vessel_mesh.h — the triangle mesh of a vessel tree (004 §3.3.1, Fig. 3.11): every drawn
 * segment an n-sided truncated cone from its thickness at the base to its main child's at the
 * tip, a terminal segment a cone to a point, leaves as square quads (vessel_leaves.h). Bark
 * vertices carry u around the branch (0 to 1) and v along it (one unit per circumference);
 * leaf vertices u across the blade and v from the stalk (0) to the tip (1).
 *
 * The mesh is counted before it is built: vessel_mesh_count gives the exact sizes, and
 * vessel_mesh_build refuses a tree over VESSEL_MAX_TRIANGLES before allocating anything. */
#ifndef VESSEL_MESH_H
#define VESSEL_MESH_H

#include <stdint.h>

#include "plugin_err.h"
#include "vessel_params.h"
#include "vessel_structure.h"

typedef struct vessel_mesh {
    float *pos;      /* 3 * nv, tree frame, metres; owned */
    float *nrm;      /* 3 * nv, unit; owned */
    float *uv;       /* 2 * nv; owned */
    uint32_t *tri;   /* 3 * nt vertex indices, counter-clockwise seen from outside; owned */
    int32_t *mat;    /* nt material ids: bark_material or leaf_material; owned */
    uint32_t nv, nt;
    uint32_t bark_triangles, leaf_triangles;
    double top;      /* highest z of any vertex, metres */
} vessel_mesh;

typedef struct vessel_mesh_size {
    uint64_t vertices, bark_triangles, leaf_triangles;
} vessel_mesh_size;

/* The exact sizes vessel_mesh_build will produce for t and p. */
vessel_mesh_size vessel_mesh_count(const vessel_tree *t, const vessel_params *p);

/* Builds the mesh of t into *m (any previous content is released first). Returns 0, or -1 with
 * err set when the mesh would pass VESSEL_MAX_TRIANGLES (naming the counts and what to lower)
 * or memory runs out; on failure *m is empty. */
int vessel_mesh_build(const vessel_tree *t, const vessel_params *p, int32_t bark_material,
                      int32_t leaf_material, vessel_mesh *m, plugin_err *err);

/* Frees the arrays and empties *m; accepts an empty mesh. */
void vessel_mesh_release(vessel_mesh *m);

/* A 64-bit FNV-1a hash of positions, normals, uvs, triangles and materials: equal meshes have
 * equal hashes. */
uint64_t vessel_mesh_hash(const vessel_mesh *m);

#endif
