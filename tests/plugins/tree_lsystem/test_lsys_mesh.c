/* test_lsys_mesh.c — the geometry: tubes closed and joined without gaps (also across chunk
 * boundaries and for flat prisms), normals, material keys, scale, and ear clipping of concave
 * polygons. */
#include "harness.h"

#include <math.h>

#include "lsys_mesh.h"
#include "lsys_test_util.h"
#include "polygon_fill.h"

typedef struct collected {
    float *pos, *nrm;
    uint32_t nv, cap_v;
    uint32_t *tri;
    int32_t *key;
    uint32_t nt, cap_t;
    uint32_t flushes;
} collected;

static int collect(void *ctx, const float *pos, const float *nrm, uint32_t nv, const uint32_t *tri,
                   const int32_t *key, uint32_t nt)
{
    collected *c = ctx;
    if (c->nv + nv > c->cap_v) {
        c->cap_v = (c->nv + nv) * 2;
        c->pos = realloc(c->pos, c->cap_v * 3 * sizeof *c->pos);
        c->nrm = realloc(c->nrm, c->cap_v * 3 * sizeof *c->nrm);
    }
    if (c->nt + nt > c->cap_t) {
        c->cap_t = (c->nt + nt) * 2;
        c->tri = realloc(c->tri, c->cap_t * 3 * sizeof *c->tri);
        c->key = realloc(c->key, c->cap_t * sizeof *c->key);
    }
    if (!c->pos || !c->nrm || !c->tri || !c->key) return -1;
    memcpy(c->pos + 3 * (size_t)c->nv, pos, nv * 3 * sizeof *pos);
    memcpy(c->nrm + 3 * (size_t)c->nv, nrm, nv * 3 * sizeof *nrm);
    for (uint32_t i = 0; i < 3 * nt; i++) c->tri[3 * (size_t)c->nt + i] = tri[i] + c->nv;
    memcpy(c->key + c->nt, key, nt * sizeof *key);
    c->nv += nv, c->nt += nt;
    c->flushes++;
    return 0;
}

static void collected_free(collected *c)
{
    free(c->pos), free(c->nrm), free(c->tri), free(c->key);
    memset(c, 0, sizeof *c);
}

/* Builds the mesh of `str`; returns the status. */
static int build(const char *str, uint32_t sides, int flat, double scale, collected *out)
{
    memset(out, 0, sizeof *out);
    uint64_t rng = 3;
    lsys_turtle_config cfg = test_config(30, 10, &rng);
    cfg.max_segments = 100000000;
    lsys_mesh_config mc = {.sides = sides, .flat = flat, .scale = scale, .max_polygon_vertices = 4096,
                           .flush = collect, .flush_ctx = out};
    lsys_error e = {{0}};
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
    /* Four segments joined: 5 rings of 8 vertices (the first written once for the base cap
     * and once as a ring) plus the tip cap; 4 * 16 side triangles plus 2 caps of 6. */
    CHECK_INT(c.nt, 4 * 16 + 2 * 6);
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

TEST_LIST(TEST_CASE(bent_branch_is_one_closed_tube), TEST_CASE(flat_prisms_join_without_gaps),
          TEST_CASE(branches_are_closed_tubes_of_their_own), TEST_CASE(joints_survive_chunk_boundaries),
          TEST_CASE(normals_scale_and_keys), TEST_CASE(concave_polygons_are_ear_clipped),
          TEST_CASE(flat_faces_far_out_have_unit_normals))
