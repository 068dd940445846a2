/* pov_mesh.c — mesh2 declarations, streamed a line at a time. */
#include "pov/pov_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pov/pov_names.h"

#define VECTORS_PER_LINE 4
#define FACES_PER_LINE 6
#define FLAT_COSINE_GAP 1e-9 /* a flat triangle's normal is within 0.003 degrees of its geometric one */

/* Writes one vector list: `name { n, <..>, <..>, ... }` of `dims` floats per entry. */
static void write_vectors(pov_file *pf, const char *name, const float *v, uint32_t n, int dims, int *bad)
{
    char line[VECTORS_PER_LINE * (3 * 34 + 8) + 8];
    pov_printf(pf, "  %s {\n    %u", name, n);
    for (uint32_t i = 0; i < n; i++) {
        char *p = line;
        if (i % VECTORS_PER_LINE == 0) p = pov_append_text(p, ",\n    ");
        else p = pov_append_text(p, ", ");
        *p++ = '<';
        for (int d = 0; d < dims; d++) {
            if (d) *p++ = ',';
            p = pov_append_float(p, v[(size_t)i * dims + d], bad);
        }
        *p++ = '>';
        *p = '\0';
        pov_put(pf, line);
    }
    pov_put(pf, "\n  }\n");
}

/* 1 when triangle t is flat-shaded: its three normals one vector, along its geometric normal
 * (POV-Ray then shades it alike with no normals given). */
static int triangle_flat(const mesh *m, uint32_t t)
{
    const uint32_t *k = m->tri + (size_t)t * 3;
    const float *n0 = m->nrm + (size_t)k[0] * 3, *n1 = m->nrm + (size_t)k[1] * 3, *n2 = m->nrm + (size_t)k[2] * 3;
    if (memcmp(n0, n1, 3 * sizeof(float)) || memcmp(n0, n2, 3 * sizeof(float))) return 0;
    const float *a = m->pos + (size_t)k[0] * 3, *b = m->pos + (size_t)k[1] * 3, *c = m->pos + (size_t)k[2] * 3;
    double e1[3], e2[3], g[3], len = 0, dot = 0, nn = 0;
    for (int d = 0; d < 3; d++) e1[d] = (double)b[d] - a[d], e2[d] = (double)c[d] - a[d];
    g[0] = e1[1] * e2[2] - e1[2] * e2[1];
    g[1] = e1[2] * e2[0] - e1[0] * e2[2];
    g[2] = e1[0] * e2[1] - e1[1] * e2[0];
    for (int d = 0; d < 3; d++) len += g[d] * g[d], dot += g[d] * n0[d], nn += (double)n0[d] * n0[d];
    return len > 0 && nn > 0 && fabs(dot) >= (1.0 - FLAT_COSINE_GAP) * sqrt(len * nn);
}

/* The triangles of one mesh2: those t with want[t] (NULL: all), their vertices renumbered. */
typedef struct mesh_part {
    const mesh *m;
    const uint8_t *want;
    uint8_t value;           /* want[t] == value selects t */
    uint32_t nt;
    uint32_t *vertex;        /* the part's vertices as the mesh's numbers; owned */
    uint32_t nv;
    uint32_t *number;        /* the mesh's vertex -> the part's, UINT32_MAX when unused; owned */
    float *pos, *nrm, *uv;   /* the part's vertices' data; owned */
} mesh_part;

static int part_has(const mesh_part *p, uint32_t t) { return !p->want || p->want[t] == p->value; }

static void part_free(mesh_part *p)
{
    free(p->vertex), free(p->number), free(p->pos), free(p->nrm), free(p->uv);
}

static int part_gather(mesh_part *p)
{
    const mesh *m = p->m;
    p->number = malloc((size_t)m->nv * sizeof(uint32_t));
    p->vertex = malloc((size_t)m->nv * sizeof(uint32_t));
    if (!p->number || !p->vertex) return -1;
    for (uint32_t v = 0; v < m->nv; v++) p->number[v] = UINT32_MAX;
    p->nv = p->nt = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
        if (!part_has(p, t)) continue;
        p->nt++;
        for (int i = 0; i < 3; i++) {
            uint32_t v = m->tri[(size_t)t * 3 + i];
            if (p->number[v] == UINT32_MAX) p->number[v] = p->nv, p->vertex[p->nv++] = v;
        }
    }
    p->pos = malloc(((size_t)p->nv + 1) * 3 * sizeof(float));
    p->nrm = malloc(((size_t)p->nv + 1) * 3 * sizeof(float));
    p->uv = malloc(((size_t)p->nv + 1) * 2 * sizeof(float));
    if (!p->pos || !p->nrm || !p->uv) return -1;
    for (uint32_t i = 0; i < p->nv; i++) {
        memcpy(p->pos + (size_t)i * 3, m->pos + (size_t)p->vertex[i] * 3, 3 * sizeof(float));
        memcpy(p->nrm + (size_t)i * 3, m->nrm + (size_t)p->vertex[i] * 3, 3 * sizeof(float));
        memcpy(p->uv + (size_t)i * 2, m->uv + (size_t)p->vertex[i] * 2, 2 * sizeof(float));
    }
    return 0;
}

/* Writes the body of one mesh2 (`mesh2 { ... }`) for part p; normals unless flat. */
static int write_part(pov_file *pf, const mesh_part *p, const scene *s, const char *texture_ident, int flat,
                      int *bad)
{
    const mesh *m = p->m;
    /* The materials the part uses, in order of first use: slot[material] is its texture_list
     * index (or -1). */
    int32_t *slot = malloc((size_t)(s->n_materials ? s->n_materials : 1) * sizeof(int32_t));
    uint32_t *used = malloc((size_t)(s->n_materials ? s->n_materials : 1) * sizeof(uint32_t));
    if (!slot || !used) {
        free(slot), free(used);
        return -1;
    }
    for (uint32_t i = 0; i < s->n_materials; i++) slot[i] = -1;
    uint32_t n_used = 0;
    int need_uv = 0;
    for (uint32_t t = 0; t < m->nt && !texture_ident; t++) {
        if (!part_has(p, t)) continue;
        uint32_t mt = scene_triangle_material(s, m, t);
        if (slot[mt] >= 0) continue;
        slot[mt] = (int32_t)n_used;
        used[n_used++] = mt;
        need_uv |= s->materials[mt].texture >= 0;
    }
    pov_put(pf, "mesh2 {\n");
    write_vectors(pf, "vertex_vectors", p->pos, p->nv, 3, bad);
    if (flat) pov_put(pf, "  // flat-shaded: no normals, POV-Ray's own are the triangles' (sylva's)\n");
    else write_vectors(pf, "normal_vectors", p->nrm, p->nv, 3, bad);
    if (need_uv) write_vectors(pf, "uv_vectors", p->uv, p->nv, 2, bad);
    char id[POV_IDENT_MAX];
    if (n_used > 1) {
        pov_printf(pf, "  texture_list {\n    %u", n_used);
        for (uint32_t k = 0; k < n_used; k++) {
            pov_material_identifier(s, used[k], id);
            pov_printf(pf, ",\n    texture { %s }", id);
        }
        pov_put(pf, "\n  }\n");
    }
    pov_printf(pf, "  face_indices {\n    %u", p->nt);
    char line[FACES_PER_LINE * 48 + 8];
    uint32_t written = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
        if (!part_has(p, t)) continue;
        const uint32_t *k = m->tri + (size_t)t * 3;
        char *q = line;
        q = pov_append_text(q, written++ % FACES_PER_LINE == 0 ? ",\n    " : ", ");
        *q++ = '<';
        q = pov_append_uint(q, p->number[k[0]]);
        *q++ = ',';
        q = pov_append_uint(q, p->number[k[1]]);
        *q++ = ',';
        q = pov_append_uint(q, p->number[k[2]]);
        q = pov_append_text(q, ">");
        if (n_used > 1) {
            *q++ = ',';
            q = pov_append_uint(q, (uint64_t)slot[scene_triangle_material(s, m, t)]);
        }
        pov_put(pf, line);
    }
    pov_put(pf, "\n  }\n");
    if (texture_ident) {
        pov_printf(pf, "  texture { %s }\n", texture_ident);
    } else if (n_used == 1) {
        pov_material_identifier(s, used[0], id);
        pov_printf(pf, "  texture { %s }\n", id);
    }
    pov_put(pf, "}\n");
    free(slot), free(used);
    return 0;
}

int pov_write_mesh(pov_file *pf, const char *ident, const mesh *m, const scene *s, const char *texture_ident,
                   err_buf *err)
{
    uint8_t *flat = malloc(m->nt ? m->nt : 1); /* per triangle: 1 flat-shaded; owned here */
    if (!flat) return err_nomem(err, "out of memory writing mesh %s", ident);
    uint32_t n_flat = 0;
    for (uint32_t t = 0; t < m->nt; t++) n_flat += flat[t] = (uint8_t)triangle_flat(m, t);
    /* the smooth triangles with their normals, the flat ones without: text POV-Ray parses
     * faster (a leaf card's normals are a third of its numbers) */
    mesh_part parts[2] = {{.m = m, .want = flat, .value = 0}, {.m = m, .want = flat, .value = 1}};
    int n_parts = 0, first = 0, bad = 0, rc = 0;
    if (n_flat == 0) parts[0].want = NULL, n_parts = 1;
    else if (n_flat == m->nt) parts[1].want = NULL, first = 1, n_parts = 1;
    else n_parts = 2;
    pov_printf(pf, "#declare %s = %s", ident, n_parts > 1 ? "union {\n" : "");
    for (int k = first; k < first + n_parts && !rc; k++) {
        if (part_gather(&parts[k]) || write_part(pf, &parts[k], s, texture_ident, k == 1, &bad))
            rc = err_nomem(err, "out of memory writing mesh %s", ident);
    }
    if (n_parts > 1) pov_put(pf, "}\n");
    for (int k = 0; k < 2; k++) part_free(&parts[k]);
    free(flat);
    if (!rc && bad)
        rc = err_set(err, "mesh %s holds %d non-finite values (positions, normals or uvs); "
                     "POV-Ray needs finite numbers", ident, bad);
    return rc;
}
