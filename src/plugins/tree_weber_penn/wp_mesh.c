/* wp_mesh.c — stems into triangles as Arbaro 1.9's MeshPartCreator, MeshSection and MeshPart
 * make them (wp_mesh.h). The order matters beyond the faces' order: the trunk's lobed sections
 * draw from the mesh stream, so the stems of level 0 are meshed in Arbaro's traversal order
 * (each trunk, then its clones depth first). */
#include "wp_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>


#define ONE_POINT_RADIUS 0.000001 /* below it a section is a single point */

/* The arrays being filled, with their capacities. */
typedef struct mesh_build {
    wp_growth *g;
    wp_model *m;
    size_t cap_vertices, cap_triangles;
    size_t max_triangles;
    plugin_err *err;
    int failed;
} mesh_build;

/* One cross-section of a stem: where it is and how wide. */
typedef struct section {
    wp_frame trf;
    double rad;
    double dist;   /* from the stem's base, metres */
    int sub_count; /* subsegments of its segment (spreads 0ScaleV over them) */
} section;

/* The next capacity of an array that is full at cap (doubling from `first`). */
static size_t next_capacity(size_t cap, size_t first)
{
    return cap ? 2 * cap : first;
}

static int grow_vertices(mesh_build *b)
{
    wp_model *m = b->m;
    if (m->n_vertices < b->cap_vertices) return 0;
    size_t cap = next_capacity(b->cap_vertices, 4096);
    double(*v)[3] = realloc(m->vertex, cap * sizeof *v); /* owned by m */
    if (!v) return -1;
    m->vertex = v;
    double(*uv)[2] = realloc(m->uv, cap * sizeof *uv); /* owned by m */
    if (!uv) return -1;
    m->uv = uv;
    b->cap_vertices = cap;
    return 0;
}

static int grow_triangles(mesh_build *b)
{
    wp_model *m = b->m;
    if (m->n_triangles < b->cap_triangles) return 0;
    size_t cap = next_capacity(b->cap_triangles, 8192);
    uint32_t(*t)[3] = realloc(m->triangle, cap * sizeof *t); /* owned by m */
    if (!t) return -1;
    m->triangle = t;
    uint8_t *level = realloc(m->level, cap); /* owned by m */
    if (!level) return -1;
    m->level = level;
    b->cap_triangles = cap;
    return 0;
}

static int fail_nomem(mesh_build *b)
{
    if (!b->failed) b->failed = plugin_fail(b->err, SYLVA_ERR_NOMEM, "out of memory while meshing a tree's stems");
    return b->failed;
}

static int add_vertex(mesh_build *b, wp_vec p, double u, double v)
{
    if (grow_vertices(b) < 0) return fail_nomem(b);
    wp_model *m = b->m;
    m->vertex[m->n_vertices][0] = p.x;
    m->vertex[m->n_vertices][1] = p.y;
    m->vertex[m->n_vertices][2] = p.z;
    m->uv[m->n_vertices][0] = u;
    m->uv[m->n_vertices][1] = v;
    m->n_vertices++;
    return 0;
}

static void widen_bbox(wp_model *m, size_t i)
{
    for (int k = 0; k < 3; k++) {
        if (m->vertex[i][k] < m->bbox_min[k]) m->bbox_min[k] = m->vertex[i][k];
        if (m->vertex[i][k] > m->bbox_max[k]) m->bbox_max[k] = m->vertex[i][k];
    }
}

static int add_triangle(mesh_build *b, size_t i, size_t j, size_t k, int level)
{
    if (i == j || j == k || i == k) return 0;
    wp_model *m = b->m;
    if (m->n_triangles >= b->max_triangles) {
        b->failed = plugin_fail(b->err, SYLVA_ERR_LIMIT,
                                "species '%s' has more than %zu stem triangles (the limit max_triangles); lower "
                                "Levels, the nBranches, nCurveRes or Smooth, or raise the limit",
                                b->g->t->p->species, b->max_triangles);
        return b->failed;
    }
    if (grow_triangles(b) < 0) return fail_nomem(b);
    m->triangle[m->n_triangles][0] = (uint32_t)i;
    m->triangle[m->n_triangles][1] = (uint32_t)j;
    m->triangle[m->n_triangles][2] = (uint32_t)k;
    m->level[m->n_triangles] = (uint8_t)level;
    m->n_triangles++;
    return 0;
}

/* One of Arbaro's faces: 3 or 4 corners; counted, its corners in the box, kept as triangles. */
static int add_face(mesh_build *b, const size_t *c, int corners, int level)
{
    b->m->faces[level]++;
    for (int i = 0; i < corners; i++) widen_bbox(b->m, c[i]);
    if (add_triangle(b, c[0], c[1], c[2], level)) return b->failed;
    if (corners == 4 && add_triangle(b, c[0], c[2], c[3], level)) return b->failed;
    return 0;
}

/* The faces between a section of `size` points from vertex inx and the next one of `nsize`
 * points from ninx, as Arbaro's MeshSection enumerates them (quads when the sizes agree). */
static int faces_between(mesh_build *b, size_t inx, int size, size_t ninx, int nsize, int level)
{
    int i = 0, ni = 0;
    while (!((size == 1 && ni >= nsize) || (nsize == 1 && i >= size) || (ni >= nsize && i >= size))) {
        size_t c[4];
        if (size > 1 && nsize == size) {
            c[0] = inx + (size_t)i;
            c[1] = ninx + (size_t)ni;
            ni++;
            c[2] = ninx + (size_t)(ni % nsize);
            i++;
            c[3] = inx + (size_t)(i % size);
            if (add_face(b, c, 4, level)) return b->failed;
        } else if (i <= ni || nsize == 1) {
            c[0] = inx + (size_t)i;
            c[1] = ninx + (size_t)ni;
            i++;
            c[2] = inx + (size_t)(i % size);
            if (add_face(b, c, 3, level)) return b->failed;
        } else {
            c[0] = inx + (size_t)(i % size);
            c[1] = ninx + (size_t)ni;
            ni++;
            c[2] = ninx + (size_t)(ni % nsize);
            if (add_face(b, c, 3, level)) return b->failed;
        }
    }
    return 0;
}

/* The section's points (Arbaro's getSectionPoints); returns how many, or -1. */
static int section_points(mesh_build *b, const wp_stem *st, const section *sec)
{
    wp_prepared *t = b->g->t;
    const wp_params *p = t->p;
    const wp_level_state *lv = wp_level_of(t, st->level);
    if (sec->rad < ONE_POINT_RADIUS) {
        if (add_vertex(b, wp_frame_apply(&sec->trf, wp_v(0, 0, 0)), 0.5, sec->dist)) return -1;
        return 1;
    }
    int n = lv->mesh_points;
    int trunk = lv->level == 0;
    for (int i = 0; i < n; i++) {
        double angle = i * 360.0 / n;
        double u = angle / 360.0;
        if (trunk && p->lobes != 0) angle -= 10.0 / p->lobes;
        wp_vec pt = wp_v(cos(angle * M_PI / 180), sin(angle * M_PI / 180), 0);
        if (trunk && (p->lobes != 0 || p->trunk_scale_v != 0)) {
            double draw = wp_random_uniform(&t->mesh_random, -p->trunk_scale_v, p->trunk_scale_v);
            double rad1 = sec->rad * (1 + draw / sec->sub_count);
            pt = wp_vmul(pt, rad1 * (1.0 + p->lobe_depth * cos(p->lobes * angle * M_PI / 180.0)));
        } else {
            pt = wp_vmul(pt, sec->rad);
        }
        if (add_vertex(b, wp_frame_apply(&sec->trf, pt), u, sec->dist)) return -1;
    }
    return n;
}

/* Adds section sec after the previous one (prev_start, prev_size; prev_size 0 for none). */
static int add_section(mesh_build *b, const wp_stem *st, const section *sec, size_t *prev_start, int *prev_size)
{
    size_t start = b->m->n_vertices;
    int size = section_points(b, st, sec);
    if (size < 0) return b->failed;
    if (*prev_size > 0 && faces_between(b, *prev_start, *prev_size, start, size, st->level)) return b->failed;
    *prev_start = start;
    *prev_size = size;
    return 0;
}

/* The mesh part of one stem (MeshPartCreator.createMeshPart without the unwritten root point). */
static int mesh_stem(mesh_build *b, const wp_stem *st)
{
    const wp_growth *g = b->g;
    if (st->seg_first == WP_NONE) return 0;
    size_t prev_start = 0;
    int prev_size = 0;
    section sec;
    memset(&sec, 0, sizeof sec);
    for (int k = st->seg_first; k != WP_NONE; k = wp_segment_at(g, k)->next) {
        const wp_segment *seg = wp_segment_at(g, k);
        sec.sub_count = seg->sub_count;
        if (k == st->seg_first) {
            sec.trf = seg->transf;
            sec.rad = seg->rad1;
            sec.dist = seg->index * seg->length;
            if (add_section(b, st, &sec, &prev_start, &prev_size)) return b->failed;
        }
        for (int i = 0; i < seg->sub_count; i++) {
            const wp_subsegment *sub = wp_subsegment_at(g, seg->sub_first + i);
            sec.trf = wp_frame_translate(&seg->transf, wp_vsub(sub->pos, seg->transf.t));
            sec.rad = sub->rad;
            sec.dist = seg->index * seg->length + sub->dist;
            if (add_section(b, st, &sec, &prev_start, &prev_size)) return b->failed;
        }
    }
    if (sec.rad > ONE_POINT_RADIUS) {
        size_t start = b->m->n_vertices;
        if (add_vertex(b, wp_frame_apply(&sec.trf, wp_v(0, 0, 0)), 0.5, sec.dist)) return b->failed;
        if (faces_between(b, prev_start, prev_size, start, 1, st->level)) return b->failed;
    }
    return 0;
}

/* Meshes the stems of `level` below stem s, in Arbaro's traversal order (the stem, its leaves,
 * its children, its clones). */
static int mesh_level(mesh_build *b, int s, int level)
{
    const wp_stem *st = wp_stem_at(b->g, s);
    if (st->level > level) return 0;
    if (st->level == level) {
        if (mesh_stem(b, st)) return b->failed;
    } else {
        for (int c = st->child_first; c != WP_NONE; c = wp_stem_at(b->g, c)->next)
            if (mesh_level(b, c, level)) return b->failed;
    }
    for (int c = st->clone_first; c != WP_NONE; c = wp_stem_at(b->g, c)->next)
        if (mesh_level(b, c, level)) return b->failed;
    return 0;
}

int wp_mesh_stems(wp_growth *g, size_t max_triangles, wp_model *m, plugin_err *err)
{
    mesh_build b = { g, m, 0, 0, max_triangles, err, 0 };
    for (int level = 0; level < g->t->levels; level++)
        for (int s = g->trunk_first; s != WP_NONE; s = wp_stem_at(g, s)->next)
            if (mesh_level(&b, s, level)) return b.failed;
    return 0;
}
