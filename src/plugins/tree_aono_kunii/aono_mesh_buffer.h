/* aono_mesh_buffer.h — the plugin's own growing vertex and triangle arrays, filled by the branch
 * and leaf builders and handed to the host in one api->mesh_append call.
 *
 * Ownership: the buffer owns its arrays; aono_mesh_buffer_release() frees them and accepts a
 * zeroed buffer.
 */
#ifndef AONO_MESH_BUFFER_H
#define AONO_MESH_BUFFER_H

#include <stdint.h>

#define AONO_MESH_MAX_VERTICES 100000000u /* the host's per-mesh limits */
#define AONO_MESH_MAX_TRIANGLES 50000000u

typedef struct aono_mesh_buffer {
    float *pos, *nrm, *uv;   /* owned: 3, 3 and 2 floats per vertex */
    uint32_t nv, cap_v;
    uint32_t *tri;           /* owned: 3 indices per triangle */
    int32_t *mat;            /* owned: material id per triangle */
    uint32_t nt, cap_t;
} aono_mesh_buffer;

/* Makes room for `vertices` and `triangles` more. Returns 0, -1 out of memory, -2 past the
 * host's per-mesh limits. */
int aono_mesh_reserve(aono_mesh_buffer *b, uint32_t vertices, uint32_t triangles);

/* Appends a vertex (room reserved) and returns its index. n is a unit normal. */
uint32_t aono_mesh_vertex(aono_mesh_buffer *b, const double p[3], const double n[3], double u, double v);

/* Appends a triangle (room reserved), counter-clockwise seen from its front. */
void aono_mesh_triangle(aono_mesh_buffer *b, uint32_t i, uint32_t j, uint32_t k, int32_t material);

void aono_mesh_buffer_release(aono_mesh_buffer *b);

#endif
