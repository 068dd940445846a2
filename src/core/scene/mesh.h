/* mesh.h — the host's triangle mesh (sylva_mesh of plugin.h): positions, normals, uvs,
 * triangles and a material id per triangle, in growable arrays. Plugins append through the host
 * API; the core reads the arrays directly.
 *
 * Ownership: mesh_new returns a mesh the caller frees with mesh_free. Arrays are owned by the
 * mesh. The position array keeps 4 floats of slack past the end (Embree reads 16 bytes at a
 * time from shared vertex buffers). */
#ifndef SYLVA_MESH_H
#define SYLVA_MESH_H

#include <stdint.h>

#include "sylva/plugin.h"
#include "util/err.h"

#define MESH_MAX_TRIANGLES 50000000u /* per mesh; reported, never hit */
#define MESH_MAX_VERTICES 100000000u

struct sylva_mesh {
    float *pos;      /* 3 * nv (+4 slack) */
    float *nrm;      /* 3 * nv, unit */
    float *uv;       /* 2 * nv */
    uint32_t nv, cap_v;
    uint32_t *tri;   /* 3 * nt, indices into the vertices */
    int32_t *mat;    /* nt material ids (scene material table; -1: the default) */
    uint32_t nt, cap_t;
};

typedef struct sylva_mesh mesh;

mesh *mesh_new(void);
void mesh_free(mesh *m); /* accepts NULL */

/* Appends as sylva_host_api.mesh_append does: triangle indices relative to this call's first
 * vertex; NULL nrm → area-weighted vertex normals of this call's triangles; NULL uv → zeros;
 * NULL mat → default_mat for every triangle. Checks indices and limits. */
int mesh_append(mesh *m, const float *pos, const float *nrm, const float *uv, uint32_t nv,
                const uint32_t *tri, const int32_t *mat, int32_t default_mat, uint32_t nt,
                err_buf *err);

/* Bounding box of the positions; an empty mesh gives lo = hi = 0. */
void mesh_bounds(const mesh *m, float lo[3], float hi[3]);

#endif
