/* pov_mesh.c — mesh2 declarations, streamed a line at a time. */
#include "pov/pov_mesh.h"

#include <stdlib.h>

#include "pov/pov_names.h"

#define VECTORS_PER_LINE 4
#define FACES_PER_LINE 6

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

int pov_write_mesh(pov_file *pf, const char *ident, const mesh *m, const scene *s, const char *texture_ident,
                   err_buf *err)
{
    /* The materials the mesh uses, in order of first use: slot[material] is its texture_list
     * index (or -1). */
    int32_t *slot = malloc((size_t)(s->n_materials ? s->n_materials : 1) * sizeof(int32_t));
    uint32_t *used = malloc((size_t)(s->n_materials ? s->n_materials : 1) * sizeof(uint32_t));
    if (!slot || !used) {
        free(slot), free(used);
        return err_nomem(err, "out of memory writing mesh %s", ident);
    }
    for (uint32_t i = 0; i < s->n_materials; i++) slot[i] = -1;
    uint32_t n_used = 0;
    int need_uv = 0;
    for (uint32_t t = 0; t < m->nt && !texture_ident; t++) {
        uint32_t mt = scene_triangle_material(s, m, t);
        if (slot[mt] >= 0) continue;
        slot[mt] = (int32_t)n_used;
        used[n_used++] = mt;
        need_uv |= s->materials[mt].texture >= 0;
    }

    int bad = 0;
    pov_printf(pf, "#declare %s = mesh2 {\n", ident);
    write_vectors(pf, "vertex_vectors", m->pos, m->nv, 3, &bad);
    write_vectors(pf, "normal_vectors", m->nrm, m->nv, 3, &bad);
    if (need_uv) write_vectors(pf, "uv_vectors", m->uv, m->nv, 2, &bad);
    char id[POV_IDENT_MAX];
    if (n_used > 1) {
        pov_printf(pf, "  texture_list {\n    %u", n_used);
        for (uint32_t k = 0; k < n_used; k++) {
            pov_material_identifier(s, used[k], id);
            pov_printf(pf, ",\n    texture { %s }", id);
        }
        pov_put(pf, "\n  }\n");
    }
    pov_printf(pf, "  face_indices {\n    %u", m->nt);
    char line[FACES_PER_LINE * 48 + 8];
    for (uint32_t t = 0; t < m->nt; t++) {
        const uint32_t *k = m->tri + (size_t)t * 3;
        char *p = line;
        p = pov_append_text(p, t % FACES_PER_LINE == 0 ? ",\n    " : ", ");
        *p++ = '<';
        p = pov_append_uint(p, k[0]);
        *p++ = ',';
        p = pov_append_uint(p, k[1]);
        *p++ = ',';
        p = pov_append_uint(p, k[2]);
        p = pov_append_text(p, ">");
        if (n_used > 1) {
            *p++ = ',';
            p = pov_append_uint(p, (uint64_t)slot[scene_triangle_material(s, m, t)]);
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
    if (bad) return err_set(err, "mesh %s holds %d non-finite values (positions, normals or uvs); "
                            "POV-Ray needs finite numbers", ident, bad);
    return 0;
}
