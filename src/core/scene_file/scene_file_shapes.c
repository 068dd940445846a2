/* scene_file_shapes.c — the built-in shapes a species or an object can be (mesh, box, sphere,
 * quad, disk): their validated keys into a shape_spec, with a mesh's indices and row lengths
 * checked where the file gives them. */
#include "scene_file/scene_file_loader.h"

#include <math.h>
#include <string.h>

/* Fills a shape_spec from validated shape keys; mesh indices and column counts are checked
 * against the nodes in `map` so messages point at the offending number. */
int sf_read_shape(loader *L, const char *file, shape_kind kind, const sylva_params *p,
                  const ynode *map, shape_spec *s)
{
    memset(s, 0, sizeof *s);
    s->kind = kind;
    switch (kind) {
    case SHAPE_BOX:
        sf_copy3(s->size, sylva_param(p, "size"));
        return 0;
    case SHAPE_SPHERE:
        s->radius = sylva_param_real(p, "radius");
        s->subdivisions = (uint32_t)sylva_param_int(p, "subdivisions");
        return 0;
    case SHAPE_QUAD: {
        const sylva_value *size = sylva_param(p, "size");
        s->size[0] = size->list[0], s->size[1] = size->list[1];
        return 0;
    }
    case SHAPE_DISK:
        s->radius = sylva_param_real(p, "radius");
        s->subdivisions = (uint32_t)sylva_param_int(p, "segments");
        return 0;
    case SHAPE_MESH:
        break;
    }
    const sylva_value *vtx = sylva_param(p, "vertices"), *tri = sylva_param(p, "triangles"),
                      *uv = sylva_param(p, "uvs");
    if (vtx->cols != 3)
        return sf_located(L->err, file, vtx->line, vtx->column,
                          "'vertices' must be rows of 3 numbers [x, y, z], got rows of %u", vtx->cols);
    if (tri->cols != 3)
        return sf_located(L->err, file, tri->line, tri->column,
                          "'triangles' must be rows of 3 vertex indices [i, j, k], got rows of %u",
                          tri->cols);
    const ynode *tri_node = ynode_get(map, "triangles");
    for (uint32_t r = 0; r < tri->rows; r++)
        for (uint32_t c = 0; c < 3; c++) {
            double x = tri->list[(size_t)r * 3 + c];
            if (floor(x) != x || x >= vtx->rows) {
                const ynode *at = tri_node->items[r]->items[c];
                return sf_located(L->err, file, at->line, at->column,
                                  "'triangles'[%u][%u] must be a vertex index, an integer in [0, %u], "
                                  "got %s",
                                  r, c, vtx->rows - 1, at->text);
            }
        }
    if (uv->is_set && (uv->cols != 2 || uv->rows != vtx->rows))
        return sf_located(
            L->err, file, uv->line, uv->column,
            "'uvs' must be %u rows of 2 numbers [u, v] (one per vertex), got %u rows of %u",
            vtx->rows, uv->rows, uv->cols);
    s->vertices = vtx->list, s->n_vertices = vtx->rows;
    s->triangles = tri->list, s->n_triangles = tri->rows;
    if (uv->is_set) s->uvs = uv->list, s->n_uvs = uv->rows;
    return 0;
}
