/* aono_mesh_buffer.c — growing vertex and triangle arrays (doubling), bounded by the host's
 * per-mesh limits so that a too-large tree is reported, never attempted. */
#include "aono_mesh_buffer.h"

#include <stdlib.h>
#include <string.h>

static int grow(void **p, uint32_t *cap, uint64_t need, size_t elem, uint32_t limit)
{
    if (need <= *cap) return 0;
    if (need > limit) return -2;
    uint64_t c = *cap ? *cap : 1024;
    while (c < need) c *= 2;
    if (c > limit) c = limit;
    void *q = realloc(*p, (size_t)c * elem);
    if (!q) return -1;
    *p = q;
    *cap = (uint32_t)c;
    return 0;
}

int aono_mesh_reserve(aono_mesh_buffer *b, uint32_t vertices, uint32_t triangles)
{
    uint64_t nv = (uint64_t)b->nv + vertices, nt = (uint64_t)b->nt + triangles;
    if (nv > b->cap_v) {
        if (nv > AONO_MESH_MAX_VERTICES) return -2;
        uint32_t cap = b->cap_v;
        int rc = grow((void **)&b->pos, &cap, nv, 3 * sizeof(float), AONO_MESH_MAX_VERTICES);
        cap = b->cap_v;
        if (!rc) rc = grow((void **)&b->nrm, &cap, nv, 3 * sizeof(float), AONO_MESH_MAX_VERTICES);
        cap = b->cap_v;
        if (!rc) rc = grow((void **)&b->uv, &cap, nv, 2 * sizeof(float), AONO_MESH_MAX_VERTICES);
        if (rc) return rc;
        b->cap_v = cap;
    }
    if (nt > b->cap_t) {
        if (nt > AONO_MESH_MAX_TRIANGLES) return -2;
        uint32_t cap = b->cap_t;
        int rc = grow((void **)&b->tri, &cap, nt, 3 * sizeof(uint32_t), AONO_MESH_MAX_TRIANGLES);
        cap = b->cap_t;
        if (!rc) rc = grow((void **)&b->mat, &cap, nt, sizeof(int32_t), AONO_MESH_MAX_TRIANGLES);
        if (rc) return rc;
        b->cap_t = cap;
    }
    return 0;
}

uint32_t aono_mesh_vertex(aono_mesh_buffer *b, const double p[3], const double n[3], double u, double v)
{
    uint32_t i = b->nv++;
    for (int k = 0; k < 3; k++) b->pos[3 * i + k] = (float)p[k], b->nrm[3 * i + k] = (float)n[k];
    b->uv[2 * i] = (float)u, b->uv[2 * i + 1] = (float)v;
    return i;
}

void aono_mesh_triangle(aono_mesh_buffer *b, uint32_t i, uint32_t j, uint32_t k, int32_t material)
{
    uint32_t t = b->nt++;
    b->tri[3 * t] = i, b->tri[3 * t + 1] = j, b->tri[3 * t + 2] = k;
    b->mat[t] = material;
}

void aono_mesh_buffer_release(aono_mesh_buffer *b)
{
    if (!b) return;
    free(b->pos), free(b->nrm), free(b->uv), free(b->tri), free(b->mat);
    memset(b, 0, sizeof *b);
}
