/* stock_mesh.c — a young plant's stems, leaves, guard and stake drawn from its shape and seed
 * (stock_mesh.h). */
#include "scene_build/stock_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "util/rng.h"

#define LEAF_MAX_LENGTH 0.6    /* metres: longer, the model's "leaf" is no leaf (a whole crown's mesh) */
#define LEAF_MAX_VERTICES 512u
#define LEADER_PIECES 8u
#define TWIG_RADIUS 0.0015     /* metres: the thinnest shoot drawn */
#define GUARD_RADIUS 0.045     /* a spiral guard's, metres */
#define STAKE_RADIUS 0.035
#define STAKE_OFFSET 0.08      /* from the stem, metres */

/* --- the species' leaf --- */

void stock_leaf_release(stock_leaf *leaf)
{
    free(leaf->pos), free(leaf->nrm), free(leaf->uv), free(leaf->tri);
    memset(leaf, 0, sizeof *leaf);
}

static int is_leaf_triangle(const scene *s, const mesh *m, uint32_t t)
{
    return s->materials[scene_triangle_material(s, m, t)].bsdf == SYLVA_BSDF_LEAF;
}

/* The index of vertex v in group[0..n), or -1. */
static int group_find(const uint32_t *group, uint32_t n, uint32_t v)
{
    for (uint32_t k = 0; k < n; k++)
        if (group[k] == v) return (int)k;
    return -1;
}

/* The triangles [t0, *t1) of the first leaf and its vertices (group, *n). */
static void first_leaf(const scene *s, const mesh *m, uint32_t t0, uint32_t *t1, uint32_t *group, uint32_t *n)
{
    *n = 0;
    uint32_t t = t0;
    for (; t < m->nt && is_leaf_triangle(s, m, t); t++) {
        const uint32_t *v = &m->tri[3 * t];
        int joined = t == t0 || group_find(group, *n, v[0]) >= 0 || group_find(group, *n, v[1]) >= 0 ||
                     group_find(group, *n, v[2]) >= 0;
        if (!joined || *n + 3 > LEAF_MAX_VERTICES) break;
        for (int c = 0; c < 3; c++)
            if (group_find(group, *n, v[c]) < 0) group[(*n)++] = v[c];
    }
    *t1 = t;
}

static vec3 vertex(const mesh *m, uint32_t v) { return v3(m->pos[3 * v], m->pos[3 * v + 1], m->pos[3 * v + 2]); }

int stock_leaf_of(const scene *s, const mesh *m, stock_leaf *leaf, err_buf *err)
{
    memset(leaf, 0, sizeof *leaf);
    uint32_t t0 = 0;
    while (t0 < m->nt && !is_leaf_triangle(s, m, t0)) t0++;
    if (t0 == m->nt) return 0;
    uint32_t group[LEAF_MAX_VERTICES], n, t1;
    first_leaf(s, m, t0, &t1, group, &n);
    /* its axis: the two vertices farthest apart */
    uint32_t a = 0, b = 0;
    float far = 0;
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t j = i + 1; j < n; j++) {
            float d = v3_len(v3_sub(vertex(m, group[i]), vertex(m, group[j])));
            if (d > far) far = d, a = i, b = j;
        }
    if (!(far > 0) || far > LEAF_MAX_LENGTH) return 0;
    vec3 o = vertex(m, group[a]), x = v3_norm(v3_sub(vertex(m, group[b]), o));
    const uint32_t *f = &m->tri[3 * t0];
    vec3 z = v3_cross(v3_sub(vertex(m, f[1]), vertex(m, f[0])), v3_sub(vertex(m, f[2]), vertex(m, f[0])));
    z = v3_norm(v3_sub(z, v3_scale(x, v3_dot(z, x))));
    if (!(v3_len(z) > 0.5f)) return 0;
    vec3 y = v3_cross(z, x);
    leaf->nv = n, leaf->nt = t1 - t0, leaf->length = far;
    leaf->material = (int32_t)scene_triangle_material(s, m, t0);
    leaf->pos = malloc(3 * n * sizeof(float)), leaf->nrm = malloc(3 * n * sizeof(float)); /* the leaf's */
    leaf->uv = malloc(2 * n * sizeof(float)), leaf->tri = malloc(3 * leaf->nt * sizeof(uint32_t));
    if (!leaf->pos || !leaf->nrm || !leaf->uv || !leaf->tri) {
        stock_leaf_release(leaf);
        return err_nomem(err, "out of memory copying a leaf");
    }
    for (uint32_t k = 0; k < n; k++) {
        vec3 p = v3_sub(vertex(m, group[k]), o), q = v3(m->nrm[3 * group[k]], m->nrm[3 * group[k] + 1], m->nrm[3 * group[k] + 2]);
        leaf->pos[3 * k] = v3_dot(p, x), leaf->pos[3 * k + 1] = v3_dot(p, y), leaf->pos[3 * k + 2] = v3_dot(p, z);
        leaf->nrm[3 * k] = v3_dot(q, x), leaf->nrm[3 * k + 1] = v3_dot(q, y), leaf->nrm[3 * k + 2] = v3_dot(q, z);
        leaf->uv[2 * k] = m->uv[2 * group[k]], leaf->uv[2 * k + 1] = m->uv[2 * group[k] + 1];
    }
    for (uint32_t t = t0; t < t1; t++) {
        const uint32_t *v = &m->tri[3 * t];
        for (int c = 0; c < 3; c++) leaf->tri[3 * (t - t0) + c] = (uint32_t)group_find(group, n, v[c]);
        leaf->area += 0.5 * v3_len(v3_cross(v3_sub(vertex(m, v[1]), vertex(m, v[0])), v3_sub(vertex(m, v[2]), vertex(m, v[0]))));
    }
    return 1;
}

/* --- the plant --- */

/* A straight piece of stem. */
typedef struct shoot {
    vec3 a, b;
    float ra, rb;
} shoot;

typedef struct builder {
    const stock_shape *sh;
    sylva_rng rng;
    mesh *m;
    shoot *leafy;          /* the shoots leaves grow on; owned */
    uint32_t n_leafy, cap_leafy;
    double leafy_length;   /* their lengths summed */
    err_buf *err;
} builder;

static float uniform(builder *b, float lo, float hi) { return lo + (hi - lo) * (float)rng_next_double(&b->rng); }

/* A frustum of `sides` faces from s->a to s->b in material mat, normals outward. */
static int tube(builder *b, const shoot *s, uint32_t sides, int32_t mat)
{
    float pos[2 * 8 * 3], nrm[2 * 8 * 3], uv[2 * 8 * 2];
    uint32_t tri[8 * 6];
    vec3 axis = v3_norm(v3_sub(s->b, s->a)), e1, e2;
    v3_basis(axis, &e1, &e2);
    for (uint32_t k = 0; k < sides; k++) {
        float phi = 2.0f * (float)M_PI * (float)k / (float)sides;
        vec3 n = v3_add(v3_scale(e1, cosf(phi)), v3_scale(e2, sinf(phi)));
        for (int end = 0; end < 2; end++) {
            vec3 p = v3_madd(end ? s->b : s->a, n, end ? s->rb : s->ra);
            uint32_t v = (uint32_t)end * sides + k;
            pos[3 * v] = p.x, pos[3 * v + 1] = p.y, pos[3 * v + 2] = p.z;
            nrm[3 * v] = n.x, nrm[3 * v + 1] = n.y, nrm[3 * v + 2] = n.z;
            uv[2 * v] = (float)k / (float)sides, uv[2 * v + 1] = end ? p.z : s->a.z;
        }
        uint32_t k1 = (k + 1) % sides, *t = &tri[6 * k];
        t[0] = k, t[1] = k1, t[2] = sides + k1, t[3] = k, t[4] = sides + k1, t[5] = sides + k;
    }
    return mesh_append(b->m, pos, nrm, uv, 2 * sides, tri, NULL, mat, 2 * sides, b->err);
}

/* A shoot drawn and kept as a place for leaves. */
static int leafy_shoot(builder *b, const shoot *s)
{
    if (tube(b, s, 4, b->sh->bark)) return -1;
    if (b->n_leafy == b->cap_leafy) {
        uint32_t cap = b->cap_leafy ? 2 * b->cap_leafy : 64;
        shoot *grown = realloc(b->leafy, cap * sizeof *grown);
        if (!grown) return err_nomem(b->err, "out of memory drawing a young plant");
        b->leafy = grown, b->cap_leafy = cap;
    }
    b->leafy[b->n_leafy++] = *s;
    b->leafy_length += v3_len(v3_sub(s->b, s->a));
    return 0;
}

/* The leader's radius at height z. */
static float leader_radius(const stock_shape *sh, double z)
{
    return (float)fmax(TWIG_RADIUS, sh->stem_radius * (1.0 - 0.85 * z / sh->height));
}

/* The leader: LEADER_PIECES pieces leaning a little from piece to piece, its tip at the height.
 * axis[k] is the point at height k h / LEADER_PIECES. Its upper third bears leaves; a whip's
 * (no laterals) its upper four fifths. */
static int leader(builder *b, vec3 axis[LEADER_PIECES + 1])
{
    const stock_shape *sh = b->sh;
    float lean = (float)(0.006 * sh->height);
    axis[0] = v3(0, 0, 0);
    for (uint32_t k = 1; k <= LEADER_PIECES; k++)
        axis[k] = v3(axis[k - 1].x + uniform(b, -lean, lean), axis[k - 1].y + uniform(b, -lean, lean),
                     (float)(sh->height * k / LEADER_PIECES));
    double leafy_from = sh->lateral_share > 0 ? 0.66 : 0.2;
    for (uint32_t k = 0; k < LEADER_PIECES; k++) {
        shoot s = {axis[k], axis[k + 1], leader_radius(sh, axis[k].z), leader_radius(sh, axis[k + 1].z)};
        int rc = (double)(k + 1) / LEADER_PIECES > leafy_from ? leafy_shoot(b, &s) : tube(b, &s, 6, sh->bark);
        if (rc) return -1;
    }
    return 0;
}

/* The leader's axis at height z. */
static vec3 leader_at(const vec3 axis[LEADER_PIECES + 1], const stock_shape *sh, double z)
{
    double f = fmin(fmax(z / sh->height, 0), 1) * LEADER_PIECES;
    uint32_t k = f >= LEADER_PIECES ? LEADER_PIECES - 1 : (uint32_t)f;
    float w = (float)(f - k);
    return v3_add(v3_scale(axis[k], 1 - w), v3_scale(axis[k + 1], w));
}

/* A direction at angle theta (radians) from the vertical toward azimuth phi. */
static vec3 direction(float theta, float phi) { return v3(sinf(theta) * cosf(phi), sinf(theta) * sinf(phi), cosf(theta)); }

/* Twigs on a lateral from p along d, of length len: one every 15 cm past its first quarter,
 * turned to either side, each a third as long as the lateral is beyond it. */
static int twigs(builder *b, vec3 p, float theta, float phi, float len, float radius)
{
    uint32_t n = (uint32_t)(len / 0.15f);
    for (uint32_t j = 0; j < n; j++) {
        float f = 0.25f + 0.65f * ((float)j + 0.5f) / (float)n, tl = 0.35f * len * (1.1f - f);
        vec3 base = v3_madd(p, direction(theta, phi), f * len);
        float side = (j % 2 ? 1.0f : -1.0f) * uniform(b, 0.6f, 0.9f);
        vec3 tip = v3_madd(base, direction(theta - 0.15f, phi + side), tl);
        if (tip.z > 0.97f * (float)b->sh->height) continue;
        shoot s = {base, tip, fmaxf(TWIG_RADIUS, 0.5f * radius), TWIG_RADIUS};
        if (leafy_shoot(b, &s)) return -1;
    }
    return 0;
}

/* The laterals: one station every lateral_spacing from crown_base to near the top, each bearing a
 * lateral with probability lateral_share, turned by the golden angle from the one below. */
static int laterals(builder *b, const vec3 axis[LEADER_PIECES + 1])
{
    const stock_shape *sh = b->sh;
    double lo = sh->crown_base, hi = 0.94 * sh->height;
    uint32_t n = hi > lo && sh->lateral_spacing > 0 ? (uint32_t)((hi - lo) / sh->lateral_spacing) : 0;
    float phi0 = uniform(b, 0, 2 * (float)M_PI);
    for (uint32_t i = 0; i < n; i++) {
        float keep = uniform(b, 0, 1), jitter = uniform(b, -0.3f, 0.3f), turn = uniform(b, -0.25f, 0.25f);
        float spread = uniform(b, 0.8f, 1.2f), tilt = uniform(b, -8, 8);
        if (keep >= sh->lateral_share) continue;
        double z = lo + ((double)i + 0.5 + jitter) * sh->lateral_spacing, t = (z - lo) / (hi - lo);
        double profile = sh->rounded ? 0.35 + 0.65 * sin(M_PI * t) : 1.0 - 0.75 * t;
        float theta = (float)((sh->lateral_angle + tilt) * M_PI / 180), phi = phi0 + (float)i * 2.39996f + turn;
        float reach = (float)(sh->crown_radius * profile) * spread, len = reach / sinf(theta);
        float room = (float)(0.97 * sh->height - z) / cosf(theta);
        if (len > room) len = room;
        if (!(len > 0.02f)) continue;
        vec3 p = leader_at(axis, sh, z), mid = v3_madd(p, direction(theta, phi), 0.5f * len);
        float r0 = fminf(0.55f * leader_radius(sh, z), 0.003f + 0.012f * len);
        /* the outer half bends a little toward the horizontal under its leaves */
        shoot inner = {p, mid, r0, 0.5f * (r0 + TWIG_RADIUS)};
        shoot outer = {mid, v3_madd(mid, direction(fminf(theta + 0.17f, 1.5f), phi), 0.5f * len), inner.rb, TWIG_RADIUS};
        if (outer.b.z > 0.97f * (float)sh->height) outer.b.z = 0.97f * (float)sh->height;
        if (leafy_shoot(b, &inner) || leafy_shoot(b, &outer)) return -1;
        if (len > 0.3f && twigs(b, p, theta, phi, len, r0)) return -1;
    }
    return 0;
}

/* One leaf of the species at p on a shoot heading toward azimuth phi, its far end no higher than
 * the leader's tip. */
static int leaf_at(builder *b, vec3 p, float phi)
{
    const stock_leaf *lf = b->sh->leaf;
    float side = uniform(b, 0.5f, 1.4f) * (uniform(b, 0, 1) < 0.5f ? -1.0f : 1.0f);
    vec3 x = direction((float)M_PI / 2 - uniform(b, -0.2f, 0.6f), phi + side);
    vec3 up = v3_norm(v3_add(v3(0, 0, 1), v3(uniform(b, -0.4f, 0.4f), uniform(b, -0.4f, 0.4f), 0)));
    vec3 z = v3_norm(v3_sub(up, v3_scale(x, v3_dot(up, x)))), y = v3_cross(z, x);
    float pos[3 * LEAF_MAX_VERTICES], nrm[3 * LEAF_MAX_VERTICES], top = -INFINITY;
    for (uint32_t k = 0; k < lf->nv; k++) {
        const float *q = &lf->pos[3 * k], *n = &lf->nrm[3 * k];
        vec3 w = v3_add(v3_add(v3_scale(x, q[0]), v3_scale(y, q[1])), v3_scale(z, q[2]));
        vec3 wn = v3_add(v3_add(v3_scale(x, n[0]), v3_scale(y, n[1])), v3_scale(z, n[2]));
        pos[3 * k] = p.x + w.x, pos[3 * k + 1] = p.y + w.y, pos[3 * k + 2] = p.z + w.z;
        nrm[3 * k] = wn.x, nrm[3 * k + 1] = wn.y, nrm[3 * k + 2] = wn.z;
        top = fmaxf(top, pos[3 * k + 2]);
    }
    float over = top - 0.995f * (float)b->sh->height;
    for (uint32_t k = 0; over > 0 && k < lf->nv; k++) pos[3 * k + 2] -= over;
    return mesh_append(b->m, pos, nrm, lf->uv, lf->nv, lf->tri, NULL, lf->material, lf->nt, b->err);
}

/* The leaves spread over the leafy shoots by their lengths, each on the outer three quarters of
 * its shoot. */
static int leaves(builder *b)
{
    const stock_shape *sh = b->sh;
    if (!sh->leaf || !sh->leaves || !b->n_leafy) return 0;
    for (uint32_t k = 0; k < sh->leaves; k++) {
        double at = uniform(b, 0, 1) * b->leafy_length;
        uint32_t i = 0;
        for (double acc = 0; i + 1 < b->n_leafy; i++)
            if ((acc += v3_len(v3_sub(b->leafy[i].b, b->leafy[i].a))) > at) break;
        const shoot *s = &b->leafy[i];
        vec3 d = v3_sub(s->b, s->a);
        vec3 p = v3_madd(s->a, d, uniform(b, 0.25f, 1.0f));
        float phi = fabsf(d.x) + fabsf(d.y) > 1e-4f * v3_len(d) ? atan2f(d.y, d.x) : uniform(b, 0, 2 * (float)M_PI);
        if (leaf_at(b, p, phi)) return -1;
    }
    return 0;
}

/* The guard round the stem's foot and the stake beside it. */
static int protection(builder *b)
{
    const stock_shape *sh = b->sh;
    shoot guard = {v3(0, 0, 0), v3(0, 0, (float)sh->guard_height), GUARD_RADIUS, GUARD_RADIUS};
    shoot stake = {v3(STAKE_OFFSET, 0, 0), v3(STAKE_OFFSET, 0, (float)sh->stake_height), STAKE_RADIUS, STAKE_RADIUS};
    if (sh->guard_height > 0 && tube(b, &guard, 8, sh->guard)) return -1;
    if (sh->stake_height > 0 && tube(b, &stake, 6, sh->stake)) return -1;
    return 0;
}

mesh *stock_mesh_new(const stock_shape *sh, uint64_t seed, err_buf *err)
{
    builder b = {.sh = sh, .m = mesh_new(), .err = err}; /* b.m returned; b.leafy owned here */
    if (!b.m) {
        err_nomem(err, "out of memory drawing a young plant");
        return NULL;
    }
    rng_stream(&b.rng, seed, "young planted stock", 0);
    vec3 axis[LEADER_PIECES + 1];
    int rc = leader(&b, axis) || laterals(&b, axis) || leaves(&b) || protection(&b);
    free(b.leafy);
    if (rc) {
        mesh_free(b.m);
        return NULL;
    }
    return b.m;
}
