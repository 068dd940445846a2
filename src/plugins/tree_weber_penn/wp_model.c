/* wp_model.c — a Weber–Penn tree grown from a species and a seed (wp_model.h): the species
 * prepared (wp_prepare.h), the trunks and all they bear grown (wp_growth.h), the stems meshed
 * (wp_mesh.h), the leaves' frames gathered in Arbaro's order, and the figures Arbaro's OBJ
 * writer would give: faces per group and the box of every vertex a face uses. */
#include "wp_model.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wp_growth.h"
#include "wp_leaf_shape.h"
#include "wp_mesh.h"

/* The leaf shape's points that its faces use (all of them for Arbaro's shapes), for the box. */
typedef struct leaf_points {
    const wp_leaf_shape *shape;
    int used[WP_LEAF_POINTS_MAX];
    int n;
} leaf_points;

/* Widens m's box by the leaf at frame f. */
static void widen_by_leaf(wp_model *m, const wp_frame *f, const leaf_points *lp)
{
    for (int i = 0; i < lp->n; i++) {
        const double *v = lp->shape->vertex[lp->used[i]];
        wp_vec p = wp_frame_apply(f, wp_v(v[0], v[1], v[2]));
        double q[3] = { p.x, p.y, p.z };
        for (int k = 0; k < 3; k++) {
            if (q[k] < m->bbox_min[k]) m->bbox_min[k] = q[k];
            if (q[k] > m->bbox_max[k]) m->bbox_max[k] = q[k];
        }
    }
}

/* The counts and leaves below stem s in Arbaro's traversal order (leaves, children, clones). */
static void gather(const wp_growth *g, int s, wp_model *m, const leaf_points *lp)
{
    const wp_stem *st = wp_stem_at(g, s);
    if (st->level < WP_LEVELS) m->stems[st->level]++;
    for (int k = st->leaf_first; k != WP_NONE; k = wp_leaf_at(g, k)->next) {
        const wp_frame *f = &wp_leaf_at(g, k)->transf;
        wp_leaf *leaf = &m->leaf[m->n_leaves++];
        leaf->origin[0] = f->t.x, leaf->origin[1] = f->t.y, leaf->origin[2] = f->t.z;
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++) leaf->axis[a][c] = f->rot.m[c][a];
        widen_by_leaf(m, f, lp);
    }
    for (int c = st->child_first; c != WP_NONE; c = wp_stem_at(g, c)->next) gather(g, c, m, lp);
    for (int c = st->clone_first; c != WP_NONE; c = wp_stem_at(g, c)->next) gather(g, c, m, lp);
}

static int add_leaves(const wp_growth *g, const wp_params *p, wp_model *m, plugin_err *err)
{
    wp_leaf_shape shape;
    int rc = wp_leaf_shape_make(p, &shape, err);
    if (rc) return rc;
    if (g->leaves.count > 0) {
        m->leaf = malloc(g->leaves.count * sizeof *m->leaf); /* owned by m */
        if (!m->leaf) {
            wp_leaf_shape_release(&shape);
            return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the %zu leaves of species '%s'",
                               g->leaves.count, p->species);
        }
    }
    static leaf_points none;
    leaf_points lp = none;
    lp.shape = &shape;
    for (size_t i = 0; i < shape.n_vertices && i < WP_LEAF_POINTS_MAX; i++) {
        int used = 0;
        for (size_t t = 0; t < shape.n_triangles && !used; t++)
            used = shape.triangle[t][0] == i || shape.triangle[t][1] == i || shape.triangle[t][2] == i;
        if (used) lp.used[lp.n++] = (int)i;
    }
    for (int s = g->trunk_first; s != WP_NONE; s = wp_stem_at(g, s)->next) gather(g, s, m, &lp);
    m->faces[WP_GROUP_LEAVES] = m->n_leaves * shape.faces;
    wp_leaf_shape_release(&shape);
    return 0;
}

/* Points of the stems and leaves whose position or axes are not finite numbers. */
static size_t count_undefined(const wp_model *m)
{
    size_t n = 0;
    for (size_t i = 0; i < m->n_vertices; i++)
        n += !(isfinite(m->vertex[i][0]) && isfinite(m->vertex[i][1]) && isfinite(m->vertex[i][2]));
    for (size_t i = 0; i < m->n_leaves; i++) {
        const wp_leaf *l = &m->leaf[i];
        int ok = isfinite(l->origin[0]) && isfinite(l->origin[1]) && isfinite(l->origin[2]);
        for (int a = 0; a < 3; a++) ok = ok && isfinite(l->axis[a][0] + l->axis[a][1] + l->axis[a][2]);
        n += !ok;
    }
    return n;
}

static int grow(const wp_params *p, int64_t seed, size_t max_triangles, size_t max_leaves, wp_model *out,
                plugin_err *err)
{
    wp_prepared t;
    int rc = wp_prepare(p, seed, &t, err);
    if (rc) return rc;
    wp_growth g;
    wp_growth_init(&g, &t, max_triangles, max_leaves, err);
    rc = wp_growth_grow(&g);
    if (!rc) rc = wp_mesh_stems(&g, max_triangles, out, err);
    if (!rc) rc = add_leaves(&g, p, out, err);
    wp_growth_free(&g);
    size_t undefined = rc ? 0 : count_undefined(out);
    if (undefined)
        return plugin_fail(err, SYLVA_ERR_PARAM,
                           "species '%s' at seed %lld puts %zu stem points or leaves at no defined place (Arbaro's "
                           "arithmetic gives NaN there, as for a stem of level 2 or more pointing straight up with "
                           "AttractionUp not 0); turn such stems off the vertical (nDownAngle, nCurve) or set "
                           "AttractionUp to 0",
                           p->species, (long long)seed, undefined);
    return rc;
}

int wp_model_grow(const wp_params *p, int64_t seed, size_t max_triangles, size_t max_leaves, wp_model *out,
                  plugin_err *err)
{
    memset(out, 0, sizeof *out);
    for (int i = 0; i < 3; i++) out->bbox_min[i] = INFINITY, out->bbox_max[i] = -INFINITY;
    int rc = grow(p, seed, max_triangles, max_leaves, out, err);
    if (rc) {
        wp_model_release(out);
        return rc;
    }
    if (out->bbox_min[0] > out->bbox_max[0])
        for (int i = 0; i < 3; i++) out->bbox_min[i] = out->bbox_max[i] = 0; /* nothing drawn */
    out->height = out->bbox_max[2];
    return 0;
}

void wp_model_release(wp_model *m)
{
    free(m->vertex);
    free(m->uv);
    free(m->triangle);
    free(m->level);
    free(m->leaf);
    memset(m, 0, sizeof *m);
}
