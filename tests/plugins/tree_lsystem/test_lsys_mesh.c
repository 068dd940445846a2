/* test_lsys_mesh.c — the geometry: tubes closed and joined without gaps (also across chunk
 * boundaries and for flat prisms), normals, material keys, scale, ear clipping of concave
 * polygons, and texture coordinates (bark along and round the tubes, leaves in their own frame). */
#include "harness.h"

#include <math.h>

#include "lsys_leaf_uv.h"
#include "lsys_mesh.h"
#include "lsys_test_util.h"
#include "polygon_fill.h"

#define BARK_TILE 0.5 /* metres of branch per repeat of the bark texture */

typedef struct collected {
    float *pos, *nrm, *uv;
    uint32_t nv, cap_v;
    uint32_t *tri;
    int32_t *key;
    uint32_t nt, cap_t;
    uint32_t flushes;
} collected;

static int collect(void *ctx, const float *pos, const float *nrm, const float *uv, uint32_t nv,
                   const uint32_t *tri, const int32_t *key, uint32_t nt)
{
    collected *c = ctx;
    if (c->nv + nv > c->cap_v) {
        c->cap_v = (c->nv + nv) * 2;
        c->pos = realloc(c->pos, c->cap_v * 3 * sizeof *c->pos);
        c->nrm = realloc(c->nrm, c->cap_v * 3 * sizeof *c->nrm);
        c->uv = realloc(c->uv, c->cap_v * 2 * sizeof *c->uv);
    }
    if (c->nt + nt > c->cap_t) {
        c->cap_t = (c->nt + nt) * 2;
        c->tri = realloc(c->tri, c->cap_t * 3 * sizeof *c->tri);
        c->key = realloc(c->key, c->cap_t * sizeof *c->key);
    }
    if (!c->pos || !c->nrm || !c->uv || !c->tri || !c->key) return -1;
    memcpy(c->pos + 3 * (size_t)c->nv, pos, nv * 3 * sizeof *pos);
    memcpy(c->nrm + 3 * (size_t)c->nv, nrm, nv * 3 * sizeof *nrm);
    memcpy(c->uv + 2 * (size_t)c->nv, uv, nv * 2 * sizeof *uv);
    for (uint32_t i = 0; i < 3 * nt; i++) c->tri[3 * (size_t)c->nt + i] = tri[i] + c->nv;
    memcpy(c->key + c->nt, key, nt * sizeof *key);
    c->nv += nv, c->nt += nt;
    c->flushes++;
    return 0;
}

static void collected_free(collected *c)
{
    free(c->pos), free(c->nrm), free(c->uv), free(c->tri), free(c->key);
    memset(c, 0, sizeof *c);
}

/* Builds the mesh of `str`; returns the status. */
static int build(const char *str, uint32_t sides, int flat, double scale, collected *out)
{
    memset(out, 0, sizeof *out);
    uint64_t rng = 3;
    lsys_turtle_config cfg = test_config(30, 10, &rng);
    cfg.max_segments = 100000000;
    lsys_mesh_config mc = {.sides = sides, .flat = flat, .scale = scale, .bark_tile = BARK_TILE, .max_polygon_vertices = 4096,
                           .flush = collect, .flush_ctx = out};
    plugin_err e = {0};
    lsys_mesh *m = lsys_mesh_new(&mc, &e);
    if (!m) return -1;
    lsys_sink sink = lsys_mesh_sink(m);
    int rc = lsys_interpret((const unsigned char *)str, strlen(str), &cfg, &sink, 1, NULL, &e);
    if (!rc) rc = lsys_mesh_finish(m);
    if (!rc && lsys_mesh_triangles(m) != out->nt) rc = -2;
    lsys_mesh_free(m);
    return rc;
}

/* Edges keyed by their end positions (rounded), so that copies of a ring in another chunk count
 * as the same vertices. */
typedef struct edge {
    int64_t a[3], b[3];
} edge;

static void key_of(const float *p, int64_t k[3])
{
    for (int i = 0; i < 3; i++) k[i] = (int64_t)llround((double)p[i] * 1e5);
}

static int key_cmp(const int64_t *a, const int64_t *b)
{
    for (int i = 0; i < 3; i++)
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    return 0;
}

static int edge_cmp(const void *x, const void *y)
{
    const edge *a = x, *b = y;
    int c = key_cmp(a->a, b->a);
    return c ? c : key_cmp(a->b, b->b);
}

/* 1 when every edge of the surface is shared by exactly two triangles: a closed surface. */
static int closed_surface(const collected *c)
{
    size_t n = 3 * (size_t)c->nt;
    edge *e = malloc(n * sizeof *e);
    if (!e) return 0;
    size_t k = 0;
    for (uint32_t t = 0; t < c->nt; t++)
        for (int i = 0; i < 3; i++) {
            int64_t a[3], b[3];
            key_of(c->pos + 3 * (size_t)c->tri[3 * t + i], a);
            key_of(c->pos + 3 * (size_t)c->tri[3 * t + (i + 1) % 3], b);
            if (!key_cmp(a, b)) continue; /* a degenerate edge of a zero-area cap corner */
            if (key_cmp(a, b) < 0) memcpy(e[k].a, a, sizeof a), memcpy(e[k].b, b, sizeof b);
            else memcpy(e[k].a, b, sizeof b), memcpy(e[k].b, a, sizeof a);
            k++;
        }
    qsort(e, k, sizeof *e, edge_cmp);
    int ok = 1;
    for (size_t i = 0; i < k;) {
        size_t j = i;
        while (j < k && !edge_cmp(&e[i], &e[j])) j++;
        if (j - i != 2) {
            ok = 0;
            fprintf(stderr, "edge (%lld %lld %lld)-(%lld %lld %lld) used %zu times\n", (long long)e[i].a[0],
                    (long long)e[i].a[1], (long long)e[i].a[2], (long long)e[i].b[0], (long long)e[i].b[1],
                    (long long)e[i].b[2], j - i);
            break;
        }
        i = j;
    }
    free(e);
    return ok;
}

TEST(bent_branch_is_one_closed_tube)
{
    collected c;
    CHECK_INT(build("F+F&(50)!F>(20)'F", 8, 0, 1.0, &c), 0);
    /* Four segments joined: 5 rings of 8 corners and the seam (the first written once for the
     * base cap and once as a ring) plus the tip cap; 4 * 16 side triangles plus 2 caps of 6. */
    CHECK_INT(c.nt, 4 * 16 + 2 * 6);
    CHECK_INT(c.nv, 8 + 5 * 9 + 8);
    CHECK(closed_surface(&c));
    collected_free(&c);
}

TEST(flat_prisms_join_without_gaps)
{
    collected c;
    CHECK_INT(build("F+F&(50)!F", 4, 1, 1.0, &c), 0);
    CHECK_INT(c.nt, 3 * 8 + 2 * 2);
    CHECK(closed_surface(&c));
    /* Every side face has one normal square to its face. */
    for (uint32_t t = 0; t < c.nt; t++) {
        const float *a = c.pos + 3 * c.tri[3 * t], *b = c.pos + 3 * c.tri[3 * t + 1], *d = c.pos + 3 * c.tri[3 * t + 2];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        const float *vn = c.nrm + 3 * c.tri[3 * t];
        CHECK_NEAR((n[0] * vn[0] + n[1] * vn[1] + n[2] * vn[2]) / len, 1.0, 1e-4); /* outward, counter-clockwise */
    }
    collected_free(&c);
}

TEST(branches_are_closed_tubes_of_their_own)
{
    collected c;
    CHECK_INT(build("F[&!F][^!!F]F", 6, 0, 1.0, &c), 0);
    /* The trunk (2 joined segments) and two branches: three closed tubes. */
    CHECK_INT(c.nt, 2 * 12 + 2 * 4 + 2 * (12 + 2 * 4));
    CHECK(closed_surface(&c));
    collected_free(&c);
}

TEST(joints_survive_chunk_boundaries)
{
    /* 12000 joined segments of 8 sides write more vertices than one chunk holds. */
    size_t n = 12000;
    char *str = malloc(n * 7 + 1);
    CHECK(str != NULL);
    if (!str) return;
    for (size_t i = 0; i < n; i++) memcpy(str + 7 * i, i % 2 ? "F-(0.9)" : "F+(0.9)", 7);
    str[7 * n] = '\0';
    collected c;
    CHECK_INT(build(str, 8, 0, 0.01, &c), 0);
    CHECK(c.flushes > 1);
    CHECK_INT(c.nt, n * 16 + 2 * 6);
    CHECK(closed_surface(&c));
    free(str);
    collected_free(&c);
}

TEST(normals_scale_and_keys)
{
    collected c;
    CHECK_INT(build("c(5)F[c{+f-(90)f-(90)f}]", 8, 0, 2.5, &c), 0);
    float top = -1;
    uint32_t leaves = 0;
    for (uint32_t t = 0; t < c.nt; t++) {
        if (c.key[t] == 13) {
            leaves++;
            continue;
        }
        CHECK_INT(c.key[t], 10); /* colour 5, wood */
        for (int k = 0; k < 3; k++) top = fmaxf(top, c.pos[3 * c.tri[3 * t + k] + 2]);
    }
    CHECK_NEAR(top, 2.5, 1e-6); /* one unit of F, scaled by 2.5 */
    CHECK_INT(leaves, 1);
    /* Side normals of the vertical segment are horizontal unit vectors. */
    for (uint32_t v = 0; v < 16 && v < c.nv; v++) {
        const float *nv = c.nrm + 3 * v;
        CHECK_NEAR(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2], 1.0, 1e-5);
    }
    collected_free(&c);
}

static double area2(const double *p, uint32_t n, const uint32_t *tri, uint32_t nt)
{
    double a = 0;
    for (uint32_t t = 0; t < nt; t++) {
        const double *x = p + 3 * tri[3 * t], *y = p + 3 * tri[3 * t + 1], *z = p + 3 * tri[3 * t + 2];
        a += fabs((y[0] - x[0]) * (z[1] - x[1]) - (y[1] - x[1]) * (z[0] - x[0]));
    }
    (void)n;
    return a / 2;
}

TEST(concave_polygons_are_ear_clipped)
{
    /* An arrow (concave at the notch) in the z = 0 plane. */
    double arrow[6][3] = {{0, 0, 0}, {2, 1, 0}, {4, 0, 0}, {2, 4, 0}, {0, 0, 0}, {0, 0, 0}};
    double xy[12];
    uint32_t idx[6], tri[12];
    double nrm[3];
    uint32_t nt = polygon_fill(&arrow[0][0], 4, tri, nrm, xy, idx);
    CHECK_INT(nt, 2);
    CHECK_NEAR(area2(&arrow[0][0], 4, tri, nt), 6.0, 1e-12); /* shoelace area of the arrow */
    CHECK_NEAR(fabs(nrm[2]), 1, 1e-12);
    /* An L shape of 6 corners, turned into 3-D: 4 triangles covering 3 unit squares. */
    double l[6][3] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    double c = cos(0.7), s = sin(0.7);
    double rot[6][3];
    for (int i = 0; i < 6; i++) {
        rot[i][0] = l[i][0];
        rot[i][1] = c * l[i][1];
        rot[i][2] = s * l[i][1];
    }
    nt = polygon_fill(&l[0][0], 6, tri, nrm, xy, idx);
    CHECK_INT(nt, 4);
    CHECK_NEAR(area2(&l[0][0], 6, tri, nt), 3.0, 1e-12);
    nt = polygon_fill(&rot[0][0], 6, tri, nrm, xy, idx);
    CHECK_INT(nt, 4);
    CHECK_NEAR(nrm[0], 0, 1e-12);
    CHECK_NEAR(nrm[1], -s, 1e-12);
    CHECK_NEAR(nrm[2], c, 1e-12);
    /* Every triangle of the L lies inside it: its centroid is not in the missing square. */
    nt = polygon_fill(&l[0][0], 6, tri, nrm, xy, idx);
    for (uint32_t t = 0; t < nt; t++) {
        double cx = 0, cy = 0;
        for (int k = 0; k < 3; k++) cx += l[tri[3 * t + k]][0] / 3, cy += l[tri[3 * t + k]][1] / 3;
        CHECK(!(cx > 1 && cy > 1));
    }
    /* A bow tie (crossing itself, one lobe larger) still gets n - 2 triangles; collinear points
     * span nothing. */
    double bow[4][3] = {{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 1, 0}};
    CHECK_INT(polygon_fill(&bow[0][0], 4, tri, nrm, xy, idx), 2);
    double line[3][3] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    CHECK_INT(polygon_fill(&line[0][0], 3, tri, nrm, xy, idx), 0);
}

/* A model drawn far out (lengths of 1e155 before its scale of 1e-155): the face normals, whose
 * products overflow a double, are still unit vectors. */
TEST(flat_faces_far_out_have_unit_normals)
{
    collected c;
    CHECK_INT(build("F(1e155)+F(1e155)&(50)F(1e155)", 4, 1, 1e-155, &c), 0);
    CHECK(c.nv > 0);
    int bad = 0;
    for (uint32_t v = 0; v < c.nv; v++) {
        const float *n = c.nrm + 3 * v;
        double len = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
        bad += !(fabs(len - 1.0) < 1e-4);
    }
    CHECK_INT(bad, 0);
    collected_free(&c);
}

/* The side vertices of a vertical tube from the origin: |normal z| tiny. */
static int is_side(const collected *c, uint32_t v) { return fabsf(c->nrm[3 * v + 2]) < 1e-6f; }

static double wrap_angle(double a)
{
    while (a > M_PI) a -= 2 * M_PI;
    while (a < -M_PI) a += 2 * M_PI;
    return a;
}

/* Bark: v is the distance along the branch in metres over the tile length; u goes once round
 * the tube (its angle is 2 pi u from the seam), and the seam's u = 1 vertex repeats the u = 0
 * one. */
TEST(bark_v_runs_along_in_metres_and_u_closes_round)
{
    for (int flat = 0; flat <= 1; flat++) {
        collected c;
        uint32_t sides = flat ? 4 : 8;
        double scale = 1.5;
        CHECK_INT(build("FF", sides, flat, scale, &c), 0);
        uint32_t n_side = 0, seams = 0, bad_v = 0, bad_u = 0;
        double u_max = 0, v_max = 0, phi0 = 0, sign = 0;
        for (uint32_t v = 0; v < c.nv; v++) {
            if (!is_side(&c, v)) continue;
            const float *p = c.pos + 3 * v, *t = c.uv + 2 * v;
            n_side++;
            bad_v += !(fabs(t[1] * BARK_TILE - p[2]) < 1e-5);
            u_max = fmax(u_max, t[0]), v_max = fmax(v_max, t[1]);
            /* The corner's angle about the axis against u: phi = phi0 + sign 2 pi u, one sign for
             * all. Prisms put their corners half a step on. */
            double phi = atan2(p[1], p[0]);
            if (sign == 0) {
                for (uint32_t w = v + 1; w < c.nv && sign == 0; w++) {
                    const float *q = c.pos + 3 * w, *s2 = c.uv + 2 * w;
                    if (!is_side(&c, w) || fabsf(s2[0] - t[0]) < 1e-6f || fabsf(s2[0] - t[0]) > 0.3f) continue;
                    double dphi = wrap_angle(atan2(q[1], q[0]) - phi);
                    sign = dphi * (s2[0] - t[0]) > 0 ? 1 : -1;
                }
                phi0 = phi - sign * 2 * M_PI * t[0];
            }
            bad_u += !(fabs(wrap_angle(phi - sign * 2 * M_PI * t[0] - phi0)) < 1e-4);
            if (t[0] == 1.0f) {
                int twin = 0;
                for (uint32_t w = 0; w < c.nv; w++)
                    twin |= is_side(&c, w) && c.uv[2 * w] == 0.0f && c.uv[2 * w + 1] == t[1] &&
                            !memcmp(c.pos + 3 * w, p, 3 * sizeof *p);
                seams += twin;
                CHECK(twin);
            }
        }
        CHECK(sign != 0);
        CHECK(n_side > 0);
        CHECK_INT(bad_v, 0);
        CHECK_INT(bad_u, 0);
        CHECK(seams > 0);
        CHECK_NEAR(u_max, 1.0, 1e-7);
        CHECK_NEAR(v_max * BARK_TILE, 2 * scale, 1e-5); /* two segments of 1 unit at 1.5 m each */
        collected_free(&c);
    }
}

/* The mesh of `str` (smooth, 8 sides, scale 1) in c and what the turtle drew, as build() draws
 * it; NULL (a failed check) when either fails. The caller frees the record and c. */
static test_record *mesh_and_record(const char *str, collected *c)
{
    CHECK_INT(build(str, 8, 0, 1.0, c), 0);
    uint64_t rng = 3;
    lsys_turtle_config cfg = test_config(30, 10, &rng);
    test_record *rec = malloc(sizeof *rec); /* owned by the caller */
    plugin_err e = {0};
    int ok = rec && !test_turtle(str, &cfg, rec, NULL, &e);
    CHECK(ok);
    if (!ok) {
        free(rec);
        collected_free(c);
        return NULL;
    }
    return rec;
}

/* A branch's v carries on from its parent's ring: the side vertices round the branch's tip are
 * 2 m along from the base (1 m of trunk, 1 m of branch). */
TEST(bark_v_carries_into_branches)
{
    const char *str = "F[&F]";
    collected c;
    test_record *rec = mesh_and_record(str, &c);
    if (!rec) return;
    CHECK_INT(rec->n_seg, 2);
    const double *tip = rec->p1[1], *h = rec->frame[1].h;
    uint32_t n = 0;
    for (uint32_t v = 0; v < c.nv; v++) {
        const float *p = c.pos + 3 * v, *nr = c.nrm + 3 * v;
        double d = sqrt((p[0] - tip[0]) * (p[0] - tip[0]) + (p[1] - tip[1]) * (p[1] - tip[1]) +
                        (p[2] - tip[2]) * (p[2] - tip[2]));
        if (d > rec->radius[1] * 1.001 || fabs(nr[0] * h[0] + nr[1] * h[1] + nr[2] * h[2]) > 1e-4) continue;
        n++;
        CHECK_NEAR(c.uv[2 * v + 1] * BARK_TILE, 2.0, 1e-5);
    }
    CHECK_INT(n, 9); /* the tip ring: 8 corners and the seam */
    free(rec);
    collected_free(&c);
}

/* A leaf's vertices in the frame of lsys_leaf_uv. */
TEST(leaf_uv_frame)
{
    const double up[3] = {0, -1, 0}; /* the normal of polygons in the x-z plane drawn counter-clockwise */
    /* A diamond: stalk at the origin, tip at z = 2, sides at x = +-0.5. */
    double diamond[4][3] = {{0, 0, 0}, {0.5, 0, 1}, {0, 0, 2}, {-0.5, 0, 1}};
    float uv[8];
    lsys_leaf_uv(&diamond[0][0], 4, up, uv);
    CHECK_NEAR(uv[0], 0.5, 1e-7);
    CHECK_NEAR(uv[1], 0.0, 1e-7); /* stalk */
    CHECK_NEAR(uv[4], 0.5, 1e-7);
    CHECK_NEAR(uv[5], 1.0, 1e-7); /* tip */
    CHECK_NEAR(uv[3], 0.5, 1e-7);
    CHECK_NEAR(uv[7], 0.5, 1e-7);
    CHECK_NEAR(fmin(uv[2], uv[6]), 0.0, 1e-7);
    CHECK_NEAR(fmax(uv[2], uv[6]), 1.0, 1e-7);
    /* Seen from the front (against the normal) u grows to the right: x = (long axis) x normal. */
    CHECK_NEAR(uv[2], 1.0, 1e-7);
    /* A lopsided triangle: v spans [0, 1] along the stalk-tip line, u stays in [0, 1] with the
     * stalk on the centre line and the widest side at an edge. */
    double tri[3][3] = {{0, 0, 0}, {0, 0, 3}, {1, 0, 1}};
    lsys_leaf_uv(&tri[0][0], 3, up, uv);
    CHECK_NEAR(uv[0], 0.5, 1e-7);
    CHECK_NEAR(uv[1], 0, 1e-7);
    CHECK_NEAR(uv[2], 0.5, 1e-7);
    CHECK_NEAR(uv[3], 1, 1e-7);
    CHECK_NEAR(uv[4], 1.0, 1e-7);
    CHECK_NEAR(uv[5], 1.0 / 3, 1e-7);
    /* A vertex behind the stalk moves the stalk up from v = 0, keeping [0, 1]. */
    double back[4][3] = {{0, 0, 0}, {0.5, 0, 3}, {0, 0, 4}, {-0.5, 0, -1}};
    lsys_leaf_uv(&back[0][0], 4, up, uv);
    float vmin = 1, vmax = 0, umin = 1, umax = 0;
    for (int i = 0; i < 4; i++)
        umin = fminf(umin, uv[2 * i]), umax = fmaxf(umax, uv[2 * i]), vmin = fminf(vmin, uv[2 * i + 1]),
        vmax = fmaxf(vmax, uv[2 * i + 1]);
    CHECK_NEAR(vmin, 0, 1e-7);
    CHECK_NEAR(vmax, 1, 1e-7);
    CHECK(umin >= 0 && umax <= 1);
    CHECK_NEAR(uv[1], 0.2, 1e-6);
    /* The same diamond far out and huge: the same coordinates. */
    double big[4][3];
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++) big[i][k] = 1e300 + diamond[i][k] * 1e290;
    float uv_big[8];
    lsys_leaf_uv(&big[0][0], 4, up, uv_big);
    lsys_leaf_uv(&diamond[0][0], 4, up, uv);
    for (int i = 0; i < 8; i++) CHECK_NEAR(uv_big[i], uv[i], 1e-6);
    /* No long axis: the centre everywhere. */
    double spot[3][3] = {{1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
    lsys_leaf_uv(&spot[0][0], 3, up, uv);
    for (int i = 0; i < 6; i++) CHECK_NEAR(uv[i], 0.5, 0);
}

/* Fig. 9's leaf through the mesh: its vertices are the polygon the turtle drew (the geometry
 * does not change) and their coordinates span [0, 1] with the stalk at the first vertex. */
TEST(leaf_polygon_keeps_its_outline_and_spans_the_texture)
{
    const char *str = "F[-c(3){+(30)f(2)-120f(2)-120f(2)}]";
    collected c;
    test_record *rec = mesh_and_record(str, &c);
    if (!rec) return;
    CHECK_INT(rec->n_poly, 1);
    uint32_t first = UINT32_MAX, n = 0;
    float umin = 1, umax = 0, vmin = 1, vmax = 0;
    for (uint32_t t = 0; t < c.nt; t++) {
        if (c.key[t] != 7) continue; /* colour 3, leaf */
        for (int k = 0; k < 3; k++) {
            uint32_t v = c.tri[3 * t + k];
            if (v < first) first = v;
        }
    }
    CHECK(first != UINT32_MAX);
    if (first == UINT32_MAX) {
        free(rec);
        collected_free(&c);
        return;
    }
    for (uint32_t v = first; v < c.nv && v - first < rec->poly_n[0]; v++, n++) {
        for (int k = 0; k < 3; k++) CHECK_NEAR(c.pos[3 * v + k], rec->poly_v[0][v - first][k], 1e-6);
        const float *t = c.uv + 2 * v;
        umin = fminf(umin, t[0]), umax = fmaxf(umax, t[0]), vmin = fminf(vmin, t[1]), vmax = fmaxf(vmax, t[1]);
    }
    CHECK_INT(n, rec->poly_n[0]);
    CHECK_NEAR(c.uv[2 * first], 0.5, 1e-7);
    CHECK_NEAR(vmin, 0, 1e-7);
    CHECK_NEAR(vmax, 1, 1e-7);
    CHECK(umin >= 0 && umax <= 1 && (umin == 0 || umax == 1));
    free(rec);
    collected_free(&c);
}

TEST_LIST(TEST_CASE(bent_branch_is_one_closed_tube), TEST_CASE(flat_prisms_join_without_gaps),
          TEST_CASE(branches_are_closed_tubes_of_their_own), TEST_CASE(joints_survive_chunk_boundaries),
          TEST_CASE(normals_scale_and_keys), TEST_CASE(concave_polygons_are_ear_clipped),
          TEST_CASE(flat_faces_far_out_have_unit_normals), TEST_CASE(bark_v_runs_along_in_metres_and_u_closes_round),
          TEST_CASE(bark_v_carries_into_branches), TEST_CASE(leaf_uv_frame),
          TEST_CASE(leaf_polygon_keeps_its_outline_and_spans_the_texture))
