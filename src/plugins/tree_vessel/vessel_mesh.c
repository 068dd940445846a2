/* vessel_mesh.c — cones, truncated cones and leaf quads of a vessel tree into flat arrays,
 * sized exactly before they are filled. */
#include "vessel_mesh.h"

#include <stdlib.h>
#include <string.h>

#include "vessel_leaves.h"

vessel_mesh_size vessel_mesh_count(const vessel_tree *t, const vessel_params *p)
{
    vessel_mesh_size c = {0};
    uint64_t n = p->sides;
    for (uint32_t i = 0; i < t->n; i++) {
        const vessel_branch *b = &t->branches[i];
        if (b->drawn) {
            if (b->tip_diameter > 0) c.vertices += 2 * (n + 1), c.bark_triangles += 2 * n;
            else c.vertices += 2 * n + 1, c.bark_triangles += n;
        }
        if (b->terminal) c.vertices += 4ull * p->leaf_density, c.leaf_triangles += 2ull * p->leaf_density;
    }
    return c;
}

void vessel_mesh_release(vessel_mesh *m)
{
    if (!m) return;
    free(m->pos), free(m->nrm), free(m->uv), free(m->tri), free(m->mat);
    memset(m, 0, sizeof *m);
}

static void put_vertex(vessel_mesh *m, vessel_vec p, vessel_vec n, double u, double v)
{
    float *P = m->pos + 3 * (size_t)m->nv, *N = m->nrm + 3 * (size_t)m->nv, *T = m->uv + 2 * (size_t)m->nv;
    P[0] = (float)p.x, P[1] = (float)p.y, P[2] = (float)p.z;
    N[0] = (float)n.x, N[1] = (float)n.y, N[2] = (float)n.z;
    T[0] = (float)u, T[1] = (float)v;
    if (p.z > m->top) m->top = p.z;
    m->nv++;
}

static void put_triangle(vessel_mesh *m, uint32_t a, uint32_t b, uint32_t c, int32_t mat)
{
    uint32_t *t = m->tri + 3 * (size_t)m->nt;
    t[0] = a, t[1] = b, t[2] = c;
    m->mat[m->nt++] = mat;
}

/* cos and sin of the ring's corners (n + 1, the last repeating the first for the texture
 * seam) and of the cone's apex corners (n, half a step on). */
typedef struct ring_table {
    double c[VESSEL_MAX_SIDES + 1], s[VESSEL_MAX_SIDES + 1];
    double apex_c[VESSEL_MAX_SIDES], apex_s[VESSEL_MAX_SIDES];
} ring_table;

static void ring_table_fill(ring_table *r, uint32_t n)
{
    for (uint32_t k = 0; k <= n; k++) r->c[k] = cos(2 * M_PI * k / n), r->s[k] = sin(2 * M_PI * k / n);
    for (uint32_t k = 0; k < n; k++)
        r->apex_c[k] = cos(2 * M_PI * (k + 0.5) / n), r->apex_s[k] = sin(2 * M_PI * (k + 0.5) / n);
}

static void put_ring(vessel_mesh *m, const vessel_branch *b, vessel_vec centre, double r,
                     double slope, double v, const ring_table *t, uint32_t n)
{
    vessel_vec y = b->frame.c[1];
    for (uint32_t k = 0; k <= n; k++) {
        vessel_vec dir = vv_add(vv_scale(b->frame.c[0], t->c[k]), vv_scale(b->frame.c[2], t->s[k]));
        put_vertex(m, vv_madd(centre, dir, r), vv_unit(vv_madd(dir, y, slope)), (double)k / n, v);
    }
}

/* A truncated cone (tip_diameter > 0) or a cone (tip_diameter 0) along the segment's axis. */
static void put_branch(vessel_mesh *m, const vessel_branch *b, const ring_table *t, uint32_t n,
                       int32_t mat)
{
    double r0 = 0.5 * b->diameter, r1 = 0.5 * b->tip_diameter;
    double slope = b->length > 0 ? (r0 - r1) / b->length : 0.0;
    vessel_vec y = b->frame.c[1], tip = vv_madd(b->base, y, b->length);
    uint32_t first = m->nv;
    put_ring(m, b, b->base, r0, slope, b->bark_v, t, n);
    if (r1 > 0) {
        put_ring(m, b, tip, r1, slope, vessel_bark_v_tip(b), t, n);
        uint32_t top = first + n + 1;
        for (uint32_t k = 0; k < n; k++) {
            put_triangle(m, first + k, top + k + 1, first + k + 1, mat);
            put_triangle(m, first + k, top + k, top + k + 1, mat);
        }
    } else {
        uint32_t apex = m->nv;
        double v1 = vessel_bark_v_tip(b);
        for (uint32_t k = 0; k < n; k++) {
            vessel_vec dir = vv_add(vv_scale(b->frame.c[0], t->apex_c[k]), vv_scale(b->frame.c[2], t->apex_s[k]));
            put_vertex(m, tip, vv_unit(vv_madd(dir, y, slope)), (k + 0.5) / n, v1);
        }
        for (uint32_t k = 0; k < n; k++) put_triangle(m, first + k, apex + k, first + k + 1, mat);
    }
}

static void put_leaf(vessel_mesh *m, const vessel_leaf *l, int32_t mat)
{
    double h = 0.5 * l->size;
    vessel_vec nrm = vv_unit(vv_cross(l->out, l->across));
    vessel_vec tip = vv_madd(l->base, l->out, l->size);
    uint32_t v = m->nv;
    put_vertex(m, vv_madd(l->base, l->across, -h), nrm, 0, 0);
    put_vertex(m, vv_madd(l->base, l->across, h), nrm, 1, 0);
    put_vertex(m, vv_madd(tip, l->across, h), nrm, 1, 1);
    put_vertex(m, vv_madd(tip, l->across, -h), nrm, 0, 1);
    put_triangle(m, v, v + 2, v + 1, mat);
    put_triangle(m, v, v + 3, v + 2, mat);
}

int vessel_mesh_build(const vessel_tree *t, const vessel_params *p, int32_t bark_material,
                      int32_t leaf_material, vessel_mesh *m, plugin_err *err)
{
    vessel_mesh_release(m);
    vessel_mesh_size c = vessel_mesh_count(t, p);
    uint64_t nt = c.bark_triangles + c.leaf_triangles;
    if (nt > VESSEL_MAX_TRIANGLES || c.vertices > UINT32_MAX)
        return plugin_fail_key(err, SYLVA_ERR_LIMIT, NULL, c.leaf_triangles > c.bark_triangles ? "leaf_density" : "vessels",
                           "this tree would need %llu triangles (%llu bark, %llu leaves); one "
                           "model may have at most %u: lower vessels (S), leaf_density or sides",
                           (unsigned long long)nt, (unsigned long long)c.bark_triangles,
                           (unsigned long long)c.leaf_triangles, VESSEL_MAX_TRIANGLES);
    /* All owned by m until vessel_mesh_release. */
    m->pos = malloc((size_t)c.vertices * 3 * sizeof(float) + 1);
    m->nrm = malloc((size_t)c.vertices * 3 * sizeof(float) + 1);
    m->uv = malloc((size_t)c.vertices * 2 * sizeof(float) + 1);
    m->tri = malloc((size_t)nt * 3 * sizeof(uint32_t) + 1);
    m->mat = malloc((size_t)nt * sizeof(int32_t) + 1);
    if (!m->pos || !m->nrm || !m->uv || !m->tri || !m->mat) {
        vessel_mesh_release(m);
        return plugin_fail_key(err, SYLVA_ERR_NOMEM, NULL, NULL, "out of memory for a mesh of %llu vertices and %llu triangles",
                           (unsigned long long)c.vertices, (unsigned long long)nt);
    }
    m->top = 0;
    vessel_leaf_slot *slots = malloc((p->leaf_density + 1) * sizeof *slots); /* owned here */
    if (!slots) {
        vessel_mesh_release(m);
        return plugin_fail_key(err, SYLVA_ERR_NOMEM, NULL, NULL, "out of memory for %u leaves", p->leaf_density);
    }
    uint32_t n_slots = vessel_leaf_layout(p, slots);
    ring_table ring;
    ring_table_fill(&ring, p->sides);
    for (uint32_t i = 0; i < t->n; i++) {
        const vessel_branch *b = &t->branches[i];
        if (b->drawn) put_branch(m, b, &ring, p->sides, bark_material);
        if (b->terminal) {
            double side = vessel_leaf_side(b, p);
            for (uint32_t k = 0; k < n_slots; k++) {
                vessel_leaf leaf = vessel_leaf_on(b, &slots[k], side);
                put_leaf(m, &leaf, leaf_material);
            }
        }
    }
    free(slots);
    m->bark_triangles = (uint32_t)c.bark_triangles;
    m->leaf_triangles = (uint32_t)c.leaf_triangles;
    return 0;
}

static uint64_t fnv1a(uint64_t h, const void *data, size_t n)
{
    const unsigned char *b = data;
    for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 0x100000001b3ull;
    return h;
}

uint64_t vessel_mesh_hash(const vessel_mesh *m)
{
    uint64_t h = 0xcbf29ce484222325ull;
    h = fnv1a(h, &m->nv, sizeof m->nv);
    h = fnv1a(h, &m->nt, sizeof m->nt);
    if (m->nv) {
        h = fnv1a(h, m->pos, (size_t)m->nv * 3 * sizeof(float));
        h = fnv1a(h, m->nrm, (size_t)m->nv * 3 * sizeof(float));
        h = fnv1a(h, m->uv, (size_t)m->nv * 2 * sizeof(float));
    }
    if (m->nt) {
        h = fnv1a(h, m->tri, (size_t)m->nt * 3 * sizeof(uint32_t));
        h = fnv1a(h, m->mat, (size_t)m->nt * sizeof(int32_t));
    }
    return h;
}
