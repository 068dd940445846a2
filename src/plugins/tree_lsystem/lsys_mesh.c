/* lsys_mesh.c — tubes with joined rings, end caps and triangulated polygons, gathered into
 * fixed-size chunks. A ring's vertices are shared with the next segment when both land in the
 * same chunk; across a chunk boundary the ring is written again from the same numbers, so the
 * surface stays closed. A smooth tube's ring holds sides + 1 vertices: the last repeats the
 * first at u = 1, the bark texture's seam. */
#include "lsys_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lsys_leaf_uv.h"
#include "polygon_fill.h"
#include "vec3.h"

#define CHUNK_VERTICES LSYS_MESH_CHUNK_VERTICES
#define CHUNK_TRIANGLES LSYS_MESH_CHUNK_TRIANGLES

struct lsys_mesh {
    lsys_mesh_config cfg;
    float *pos, *nrm;           /* owned: CHUNK_VERTICES * 3 each */
    float *uv;                  /* owned: CHUNK_VERTICES * 2 */
    uint32_t *tri;              /* owned: CHUNK_TRIANGLES * 3 */
    int32_t *key;               /* owned: CHUNK_TRIANGLES */
    uint32_t nv, nt;
    uint64_t chunk;             /* number of the chunk being filled, from 1 */
    uint64_t total_v, total_t;
    double cos_t[LSYS_MESH_MAX_SIDES], sin_t[LSYS_MESH_MAX_SIDES];
    double *poly_xy;            /* owned: polygon_fill scratch */
    float *poly_uv;             /* owned: a polygon's texture coordinates */
    uint32_t *poly_idx, *poly_tri; /* owned */
    int failed;                 /* the flush callback refused */
};

/* Scales v to unit length; 0 when it has no usable direction (zero, or not finite). A vector
 * whose squared length over- or underflows (a model drawn far out) is scaled by its largest
 * component first. */
static int normalize(double v[3])
{
    double n = vec3_length(v);
    if (n > 1e-300 && isfinite(n)) return vec3_div(v, n), 1;
    return isfinite(v[0] + v[1] + v[2]) && !vec3_normalize_scaled(v);
}

/* The unit normal e x f of a face from its diagonals. A model drawn far out (coordinates of
 * 1e150 before its scale is applied) makes the product overflow; the same direction then comes
 * from the diagonals scaled to unit size. Returns 0 when the face has no direction. */
static int face_normal(const double e[3], const double f[3], double n[3])
{
    vec3_cross(e, f, n);
    if (normalize(n)) return 1;
    double se = vec3_largest(e), sf = vec3_largest(f);
    if (!(se > 0 && sf > 0) || !isfinite(e[0] + e[1] + e[2] + f[0] + f[1] + f[2])) return 0;
    double a[3] = {e[0] / se, e[1] / se, e[2] / se}, b[3] = {f[0] / sf, f[1] / sf, f[2] / sf};
    vec3_cross(a, b, n);
    return normalize(n);
}

static int flush(lsys_mesh *m)
{
    if (m->failed) return -1;
    if (m->nt && m->cfg.flush(m->cfg.flush_ctx, m->pos, m->nrm, m->uv, m->nv, m->tri, m->key, m->nt)) {
        m->failed = 1;
        return -1;
    }
    m->nv = m->nt = 0;
    m->chunk++;
    return 0;
}

/* Makes room for nv vertices and nt triangles in the current chunk. */
static int reserve(lsys_mesh *m, uint32_t nv, uint32_t nt)
{
    if (m->nv + nv <= CHUNK_VERTICES && m->nt + nt <= CHUNK_TRIANGLES) return 0;
    return flush(m);
}

static uint32_t add_vertex(lsys_mesh *m, const double p[3], const double n[3], double u, double v)
{
    uint32_t i = m->nv++;
    float *q = m->pos + 3 * (size_t)i, *r = m->nrm + 3 * (size_t)i, *t = m->uv + 2 * (size_t)i;
    double s = m->cfg.scale;
    q[0] = (float)(p[0] * s), q[1] = (float)(p[1] * s), q[2] = (float)(p[2] * s);
    r[0] = (float)n[0], r[1] = (float)n[1], r[2] = (float)n[2];
    t[0] = (float)u, t[1] = (float)v;
    m->total_v++;
    return i;
}

static void add_triangle(lsys_mesh *m, uint32_t a, uint32_t b, uint32_t c, int32_t key)
{
    uint32_t *t = m->tri + 3 * (size_t)m->nt;
    t[0] = a, t[1] = b, t[2] = c;
    m->key[m->nt++] = key;
    m->total_t++;
}

/* Corner k of a ring and its outward direction. Blocks put their corners on the diagonals so
 * that the faces are square to e1 and e2 and the width is twice the radius. */
static void ring_corner(const lsys_mesh *m, const lsys_joint *j, uint32_t k, double p[3], double dir[3])
{
    k %= m->cfg.sides;
    double c = m->cos_t[k], s = m->sin_t[k];
    double r = m->cfg.flat ? j->radius * sqrt(2.0) : j->radius;
    for (int i = 0; i < 3; i++) {
        dir[i] = c * j->e1[i] + s * j->e2[i];
        p[i] = j->center[i] + r * dir[i];
    }
}

/* Writes a ring's sides + 1 vertices (smooth tubes; the last at the first's place with u = 1)
 * into the current chunk and records where. */
static void emit_ring(lsys_mesh *m, lsys_joint *j)
{
    double p[3], d[3];
    j->first = m->nv;
    j->chunk = m->chunk;
    for (uint32_t k = 0; k <= m->cfg.sides; k++) {
        ring_corner(m, j, k, p, d);
        add_vertex(m, p, d, (double)k / m->cfg.sides, j->bark_v);
    }
}

/* Closes a ring with a flat fan facing `side` (+1: along e1 x e2, -1: against it). The bark
 * is projected onto the cap square to the tube: the corner's offsets along e1 and e2 in metres
 * over the tile length, added to the ring's (0, v), so the end face shows the bark at the scale
 * it has along the branch. */
static int cap_ring(lsys_mesh *m, const lsys_joint *j, double side, int32_t key)
{
    uint32_t n = m->cfg.sides;
    if (reserve(m, n, n - 2)) return -1;
    double axis[3], p[3], d[3];
    vec3_cross(j->e1, j->e2, axis);
    for (int i = 0; i < 3; i++) axis[i] *= side;
    uint32_t first = m->nv;
    double to_v = m->cfg.scale / m->cfg.bark_tile;
    for (uint32_t k = 0; k < n; k++) {
        ring_corner(m, j, k, p, d);
        double du = 0, dv = 0;
        for (int i = 0; i < 3; i++) du += (p[i] - j->center[i]) * j->e1[i], dv += (p[i] - j->center[i]) * j->e2[i];
        add_vertex(m, p, axis, du * to_v, j->bark_v + dv * to_v);
    }
    for (uint32_t k = 1; k + 1 < n; k++) {
        if (side > 0) add_triangle(m, first, first + k, first + k + 1, key);
        else add_triangle(m, first, first + k + 1, first + k, key);
    }
    return 0;
}

static int32_t wood_key(int32_t colour) { return colour * 2; }

static int side_faces_smooth(lsys_mesh *m, lsys_joint *bottom, lsys_joint *top, int32_t key)
{
    uint32_t n = m->cfg.sides;
    int bottom_here = bottom->chunk == m->chunk;
    if (reserve(m, (bottom_here ? 0 : n + 1) + n + 1, 2 * n)) return -1;
    if (bottom->chunk != m->chunk) emit_ring(m, bottom);
    uint32_t b = bottom->first;
    emit_ring(m, top);
    uint32_t t = top->first;
    for (uint32_t k = 0; k < n; k++) {
        add_triangle(m, b + k, b + k + 1, t + k + 1, key);
        add_triangle(m, b + k, t + k + 1, t + k, key);
    }
    return 0;
}

static int side_faces_flat(lsys_mesh *m, const lsys_joint *bottom, const lsys_joint *top, int32_t key)
{
    uint32_t n = m->cfg.sides;
    if (reserve(m, 4 * n, 2 * n)) return -1;
    for (uint32_t k = 0; k < n; k++) {
        uint32_t k1 = (k + 1) % n;
        double b0[3], b1[3], t0[3], t1[3], d[3], e[3], f[3], nrm[3];
        ring_corner(m, bottom, k, b0, d);
        ring_corner(m, bottom, k1, b1, d);
        ring_corner(m, top, k, t0, d);
        ring_corner(m, top, k1, t1, d);
        /* The face's diagonals: their cross product points out of the tube. */
        for (int i = 0; i < 3; i++) e[i] = b1[i] - t0[i], f[i] = t1[i] - b0[i];
        if (!face_normal(e, f, nrm)) {
            /* A face of no area (zero radius): its normal does not matter. */
            nrm[0] = d[0], nrm[1] = d[1], nrm[2] = d[2];
        }
        uint32_t v = m->nv;
        double u0 = (double)k / n, u1 = (double)(k + 1) / n;
        add_vertex(m, b0, nrm, u0, bottom->bark_v), add_vertex(m, b1, nrm, u1, bottom->bark_v);
        add_vertex(m, t1, nrm, u1, top->bark_v), add_vertex(m, t0, nrm, u0, top->bark_v);
        add_triangle(m, v, v + 1, v + 2, key);
        add_triangle(m, v, v + 2, v + 3, key);
    }
    return 0;
}

static int on_joint_end(void *ctx, lsys_joint *j)
{
    lsys_mesh *m = ctx;
    return cap_ring(m, j, 1.0, wood_key(j->colour));
}

static int on_segment(void *ctx, const lsys_segment *s)
{
    lsys_mesh *m = ctx;
    double axis[3] = {s->p1[0] - s->p0[0], s->p1[1] - s->p0[1], s->p1[2] - s->p0[2]};
    if (!normalize(axis)) return 0;
    lsys_joint *j = s->joint;
    int32_t key = wood_key(s->colour);
    int connected = 0;
    if (j->open) {
        double d = fabs(j->center[0] - s->p0[0]) + fabs(j->center[1] - s->p0[1]) + fabs(j->center[2] - s->p0[2]);
        double size = fabs(s->p0[0]) + fabs(s->p0[1]) + fabs(s->p0[2]) + s->radius;
        connected = d <= 1e-9 * size;
        if (!connected && cap_ring(m, j, 1.0, wood_key(j->colour))) return -1;
    }
    lsys_joint bottom, top;
    double e1[3];
    if (connected) {
        bottom = *j;
        memcpy(e1, j->e1, sizeof e1);
    } else {
        memcpy(e1, s->frame->u, sizeof e1);
    }
    /* The new ring's e1: the previous e1 (or the turtle's U) made square to the new axis, so
     * that the tube does not twist at the joint. */
    double d = vec3_dot(e1, axis);
    for (int i = 0; i < 3; i++) e1[i] -= d * axis[i];
    if (!normalize(e1)) {
        memcpy(e1, s->frame->l, sizeof e1);
        d = vec3_dot(e1, axis);
        for (int i = 0; i < 3; i++) e1[i] -= d * axis[i];
        if (!normalize(e1)) return 0;
    }
    /* v runs on from the joint: along the branch from its parent's ring, in metres over the
     * tile length. */
    double step[3] = {s->p1[0] - s->p0[0], s->p1[1] - s->p0[1], s->p1[2] - s->p0[2]};
    double length = vec3_dot(step, axis); /* axis is step's direction */
    double v0 = j->bark_v, v1 = v0 + length * m->cfg.scale / m->cfg.bark_tile;
    top = (lsys_joint){.center = {s->p1[0], s->p1[1], s->p1[2]}, .radius = s->radius, .bark_v = v1,
                       .colour = s->colour, .open = 1};
    memcpy(top.e1, e1, sizeof e1);
    vec3_cross(axis, e1, top.e2);
    if (!connected) {
        bottom = top;
        memcpy(bottom.center, s->p0, sizeof bottom.center);
        bottom.bark_v = v0;
        bottom.chunk = 0; /* not written yet */
        if (cap_ring(m, &bottom, -1.0, key)) return -1;
    }
    int rc = m->cfg.flat ? side_faces_flat(m, &bottom, &top, key) : side_faces_smooth(m, &bottom, &top, key);
    if (rc) return -1;
    *j = top;
    j->open = 1;
    return 0;
}

static int on_polygon(void *ctx, const double *xyz, uint32_t n, int32_t colour)
{
    lsys_mesh *m = ctx;
    if (n > m->cfg.max_polygon_vertices || n < 3) return 0;
    double normal[3];
    uint32_t nt = polygon_fill(xyz, n, m->poly_tri, normal, m->poly_xy, m->poly_idx);
    if (!nt) return 0;
    if (reserve(m, n, nt)) return -1;
    uint32_t first = m->nv;
    lsys_leaf_uv(xyz, n, normal, m->poly_uv);
    for (uint32_t i = 0; i < n; i++) add_vertex(m, xyz + 3 * i, normal, m->poly_uv[2 * i], m->poly_uv[2 * i + 1]);
    for (uint32_t t = 0; t < nt; t++)
        add_triangle(m, first + m->poly_tri[3 * t], first + m->poly_tri[3 * t + 1], first + m->poly_tri[3 * t + 2],
                     colour * 2 + 1);
    return 0;
}

lsys_mesh *lsys_mesh_new(const lsys_mesh_config *cfg, plugin_err *err)
{
    if (cfg->sides < LSYS_MESH_MIN_SIDES || cfg->sides > LSYS_MESH_MAX_SIDES || !cfg->flush ||
        !(cfg->scale > 0) || !(cfg->bark_tile > 0) || cfg->max_polygon_vertices < 3 ||
        cfg->max_polygon_vertices > CHUNK_VERTICES) {
        plugin_fail(err, LSYS_ERR_SYNTAX,
                  "mesh builder: sides must be %d to %d, scale and bark tile positive, a flush callback given "
                  "and the polygon limit 3 to %u",
                  LSYS_MESH_MIN_SIDES, LSYS_MESH_MAX_SIDES, CHUNK_VERTICES);
        return NULL;
    }
    lsys_mesh *m = calloc(1, sizeof *m); /* owned by the caller */
    if (!m) {
        plugin_fail(err, LSYS_ERR_NOMEM, "out of memory for the mesh builder");
        return NULL;
    }
    m->cfg = *cfg;
    m->chunk = 1;
    uint32_t pv = cfg->max_polygon_vertices;
    m->pos = malloc(CHUNK_VERTICES * 3 * sizeof *m->pos);
    m->nrm = malloc(CHUNK_VERTICES * 3 * sizeof *m->nrm);
    m->uv = malloc(CHUNK_VERTICES * 2 * sizeof *m->uv);
    m->tri = malloc(CHUNK_TRIANGLES * 3 * sizeof *m->tri);
    m->key = malloc(CHUNK_TRIANGLES * sizeof *m->key);
    m->poly_xy = malloc(POLYGON_FILL_SCRATCH_DOUBLES(pv) * sizeof *m->poly_xy);
    m->poly_idx = malloc(POLYGON_FILL_SCRATCH_INDICES(pv) * sizeof *m->poly_idx);
    m->poly_tri = malloc(3 * (size_t)pv * sizeof *m->poly_tri);
    m->poly_uv = malloc(2 * (size_t)pv * sizeof *m->poly_uv);
    if (!m->pos || !m->nrm || !m->uv || !m->poly_uv || !m->tri || !m->key || !m->poly_xy || !m->poly_idx || !m->poly_tri) {
        lsys_mesh_free(m);
        plugin_fail(err, LSYS_ERR_NOMEM, "out of memory for the mesh builder's buffers");
        return NULL;
    }
    double phase = cfg->flat ? M_PI / cfg->sides : 0.0;
    for (uint32_t k = 0; k < cfg->sides; k++) {
        double a = phase + 2.0 * M_PI * k / cfg->sides;
        m->cos_t[k] = cos(a), m->sin_t[k] = sin(a);
    }
    return m;
}

void lsys_mesh_free(lsys_mesh *m)
{
    if (!m) return;
    free(m->pos), free(m->nrm), free(m->uv), free(m->tri), free(m->key);
    free(m->poly_xy), free(m->poly_idx), free(m->poly_tri), free(m->poly_uv);
    free(m);
}

lsys_sink lsys_mesh_sink(lsys_mesh *m)
{
    return (lsys_sink){.ctx = m, .segment = on_segment, .polygon = on_polygon, .joint_end = on_joint_end};
}

int lsys_mesh_finish(lsys_mesh *m) { return flush(m) ? LSYS_ERR_SINK : LSYS_OK; }

uint64_t lsys_mesh_triangles(const lsys_mesh *m) { return m->total_t; }
uint64_t lsys_mesh_vertices(const lsys_mesh *m) { return m->total_v; }
