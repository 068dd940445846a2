/* cutout_outline.c — textures' outline polygons and the meshes rebuilt with them (cutout_outline.h). */
#include "geometry/cutout_outline.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/cutout.h"

#define CLIP_MAX (CUTOUT_OUTLINE_CORNERS + 4) /* a convex polygon clipped by a triangle's 3 edges */

/* ------------------------------------------------------------------------------------------ */
/* the outline of a texture                                                                    */

static double cross2(const double o[2], const double a[2], const double b[2])
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

static int point_order(const void *pa, const void *pb)
{
    const double *a = pa, *b = pb;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return a[1] < b[1] ? -1 : a[1] > b[1];
}

/* Andrew's monotone chain: hull (2 per corner, counter-clockwise) of the n points p, sorted in
 * place; returns its corners (at most n). */
static int convex_hull(double (*p)[2], int n, double (*hull)[2])
{
    qsort(p, (size_t)n, sizeof *p, point_order);
    int k = 0;
    for (int i = 0; i < n; i++) {
        while (k >= 2 && cross2(hull[k - 2], hull[k - 1], p[i]) <= 0) k--;
        memcpy(hull[k++], p[i], sizeof *p);
    }
    for (int i = n - 2, lower = k + 1; i >= 0; i--) {
        while (k >= lower && cross2(hull[k - 2], hull[k - 1], p[i]) <= 0) k--;
        memcpy(hull[k++], p[i], sizeof *p);
    }
    return k > 1 ? k - 1 : k;
}

static double polygon_area(double (*q)[2], int n, double centroid[2])
{
    double a = 0, cx = 0, cy = 0;
    for (int i = 0; i < n; i++) {
        const double *p0 = q[i], *p1 = q[(i + 1) % n];
        double c = p0[0] * p1[1] - p1[0] * p0[1];
        a += c;
        cx += (p0[0] + p1[0]) * c;
        cy += (p0[1] + p1[1]) * c;
    }
    a *= 0.5;
    if (centroid && a > 0) centroid[0] = cx / (6 * a), centroid[1] = cy / (6 * a);
    return a;
}

/* Drops corners of the convex polygon q until it has at most CUTOUT_OUTLINE_CORNERS: each time
 * the one whose triangle with its neighbours is smallest. */
static int reduce_corners(double (*q)[2], int n)
{
    while (n > CUTOUT_OUTLINE_CORNERS) {
        int best = 0;
        double least = INFINITY;
        for (int i = 0; i < n; i++) {
            double a = fabs(cross2(q[(i + n - 1) % n], q[i], q[(i + 1) % n]));
            if (a < least) least = a, best = i;
        }
        memmove(q[best], q[best + 1], (size_t)(n - best - 1) * sizeof *q);
        n--;
    }
    return n;
}

void cutout_outline_of_texture(const texture *t, cutout_outline *out)
{
    out->n = 0;
    uint32_t w = t->width, h = t->height;
    /* per row of texels the outer corners of its first and last kept texel: the hull's
     * candidates (every kept texel lies between them) */
    double (*p)[2] = malloc((size_t)h * 4 * sizeof *p);  /* owned here */
    double (*hull)[2] = malloc(((size_t)h * 4 + 1) * sizeof *hull); /* owned here */
    if (!p || !hull) goto done;
    int n = 0;
    uint64_t kept = 0;
    for (uint32_t y = 0; y < h; y++) {
        int first = -1, last = -1;
        for (uint32_t x = 0; x < w; x++)
            if (cutout_texel_kept(t->rgba[((size_t)y * w + x) * 4 + 3])) {
                if (first < 0) first = (int)x;
                last = (int)x;
                kept++;
            }
        if (first < 0) continue;
        double top = 1.0 - (double)y / h, bottom = 1.0 - (double)(y + 1) / h;
        double left = (double)first / w, right = (double)(last + 1) / w;
        double c[4][2] = {{left, top}, {left, bottom}, {right, top}, {right, bottom}};
        memcpy(p[n], c, sizeof c);
        n += 4;
    }
    if (!kept) goto done;
    int k = reduce_corners(hull, convex_hull(p, n, hull));
    double centre[2] = {0.5, 0.5};
    double area = polygon_area(hull, k, centre), want = (double)kept / ((double)w * h);
    double scale = area > 0 ? sqrt(want / area) : 1.0;
    for (int i = 0; i < k; i++) {
        out->uv[i][0] = (float)(centre[0] + scale * (hull[i][0] - centre[0]));
        out->uv[i][1] = (float)(centre[1] + scale * (hull[i][1] - centre[1]));
    }
    out->n = k >= 3 ? k : 0;
done:
    free(p);
    free(hull);
}

/* ------------------------------------------------------------------------------------------ */
/* a mesh rebuilt                                                                              */

/* A mesh being built: its arrays owned here until handed to mesh_append. */
typedef struct mesh_build {
    float *pos, *nrm, *uv;
    uint32_t *tri;
    int32_t *mat;
    uint32_t nv, nt, cap_v, cap_t;
} mesh_build;

/* Grows the array whose pointer is at field (owned by the build) to cap entries of size bytes;
 * the pointer is copied as bytes, whatever its type. */
static int grow(void *field, uint32_t cap, size_t size)
{
    void *old, *p;
    memcpy(&old, field, sizeof old);
    p = realloc(old, (size_t)cap * size);
    if (!p) return -1;
    memcpy(field, &p, sizeof p);
    return 0;
}

/* Room for more_v vertices and more_t triangles, doubling the arrays. */
static int build_room(mesh_build *b, uint32_t more_v, uint32_t more_t)
{
    if (b->nv + more_v > b->cap_v) {
        uint32_t cap = b->cap_v ? b->cap_v : 1024;
        while (cap < b->nv + more_v) cap *= 2;
        if (grow(&b->pos, cap, 3 * sizeof(float)) || grow(&b->nrm, cap, 3 * sizeof(float)) ||
            grow(&b->uv, cap, 2 * sizeof(float)))
            return -1;
        b->cap_v = cap;
    }
    if (b->nt + more_t > b->cap_t) {
        uint32_t cap = b->cap_t ? b->cap_t : 1024;
        while (cap < b->nt + more_t) cap *= 2;
        if (grow(&b->tri, cap, 3 * sizeof(uint32_t)) || grow(&b->mat, cap, sizeof(int32_t))) return -1;
        b->cap_t = cap;
    }
    return 0;
}

static void build_free(mesh_build *b)
{
    free(b->pos), free(b->nrm), free(b->uv), free(b->tri), free(b->mat);
}

/* Keeps the part of the convex polygon q (n corners) on the left of the line a -> b. */
static int clip_half(double (*q)[2], int n, const double a[2], const double b[2], double (*out)[2])
{
    int k = 0;
    for (int i = 0; i < n; i++) {
        const double *p0 = q[i], *p1 = q[(i + 1) % n];
        double d0 = cross2(a, b, p0), d1 = cross2(a, b, p1);
        if (d0 >= 0) memcpy(out[k++], p0, sizeof *out);
        if ((d0 >= 0) != (d1 >= 0) && k < CLIP_MAX) {
            double s = d0 / (d0 - d1);
            out[k][0] = p0[0] + s * (p1[0] - p0[0]);
            out[k][1] = p0[1] + s * (p1[1] - p0[1]);
            k++;
        }
    }
    return k;
}

/* The corner of triangle u that triangle t lacks, when t and u share two corners and the four
 * are a parallelogram in position and in uv (a leaf card cut along its diagonal): then the
 * affine map of t's barycentrics covers u too. Returns -1 otherwise. */
static int64_t card_fourth_corner(const mesh *m, uint32_t t, uint32_t u)
{
    const uint32_t *a = m->tri + (size_t)t * 3, *b = m->tri + (size_t)u * 3;
    int shared = 0, lone_t = -1, lone_u = -1;
    for (int i = 0; i < 3; i++) {
        int in_u = a[i] == b[0] || a[i] == b[1] || a[i] == b[2];
        int in_t = b[i] == a[0] || b[i] == a[1] || b[i] == a[2];
        shared += in_u;
        if (!in_u) lone_t = i;
        if (!in_t) lone_u = i;
    }
    if (shared != 2 || lone_t < 0 || lone_u < 0) return -1;
    uint32_t p = a[(lone_t + 1) % 3], q = a[(lone_t + 2) % 3], x = a[lone_t], y = b[lone_u];
    float scale = 0.0f;
    for (int d = 0; d < 3; d++) scale = fmaxf(scale, fabsf(m->pos[p * 3 + d]) + fabsf(m->pos[q * 3 + d]));
    for (int d = 0; d < 3; d++) /* x + y = p + q */
        if (fabsf(m->pos[x * 3 + d] + m->pos[y * 3 + d] - m->pos[p * 3 + d] - m->pos[q * 3 + d]) > 1e-5f * (1.0f + scale))
            return -1;
    for (int d = 0; d < 2; d++)
        if (fabsf(m->uv[x * 2 + d] + m->uv[y * 2 + d] - m->uv[p * 2 + d] - m->uv[q * 2 + d]) > 1e-5f) return -1;
    for (int d = 0; d < 3; d++)
        if (m->nrm[x * 3 + d] != m->nrm[y * 3 + d] || m->nrm[p * 3 + d] != m->nrm[x * 3 + d] ||
            m->nrm[q * 3 + d] != m->nrm[x * 3 + d])
            return -1; /* a flat card: one normal */
    return y;
}

/* Appends the part of outline o inside cut-out triangle t of m (its uvs) as a fan; with
 * fourth >= 0, inside the card of t and the triangle whose lone corner is vertex fourth. */
static int add_outline_part(mesh_build *b, const mesh *m, uint32_t t, int64_t fourth, const cutout_outline *o,
                            int32_t mat)
{
    const uint32_t *k = m->tri + (size_t)t * 3;
    double c[3][2];
    for (int i = 0; i < 3; i++) c[i][0] = m->uv[k[i] * 2], c[i][1] = m->uv[k[i] * 2 + 1];
    double area = cross2(c[0], c[1], c[2]);
    if (!(fabs(area) > 1e-12)) return 0; /* no extent in uv: nothing of the texture to show */
    /* the region to clip by, counter-clockwise in uv: the triangle, or the card */
    double region[4][2];
    int nr = 3;
    for (int i = 0; i < 3; i++) memcpy(region[i], c[area < 0 ? 2 - i : i], sizeof region[i]);
    if (fourth >= 0) {
        /* the fourth corner sits opposite the corner of t that the other triangle lacks */
        double f[2] = {m->uv[fourth * 2], m->uv[fourth * 2 + 1]};
        int opposite = 0;
        for (int i = 0; i < 3; i++)
            if (fabs(c[(i + 1) % 3][0] + c[(i + 2) % 3][0] - c[i][0] - f[0]) < 1e-5 &&
                fabs(c[(i + 1) % 3][1] + c[(i + 2) % 3][1] - c[i][1] - f[1]) < 1e-5)
                opposite = i;
        /* counter-clockwise: c[opposite], c[opposite+1], f, c[opposite+2] when t is */
        int r0 = opposite, r1 = (opposite + 1) % 3, r2 = (opposite + 2) % 3;
        const double *ring[4] = {c[r0], c[r1], f, c[r2]};
        for (int i = 0; i < 4; i++) memcpy(region[i], ring[area < 0 ? (4 - i) % 4 : i], sizeof region[i]);
        nr = 4;
    }
    double q[CLIP_MAX][2], r[CLIP_MAX][2];
    int n = o->n;
    for (int i = 0; i < n; i++) q[i][0] = o->uv[i][0], q[i][1] = o->uv[i][1];
    for (int e = 0; e < nr && n > 0; e++) {
        n = clip_half(q, n, region[e], region[(e + 1) % nr], r);
        memcpy(q, r, (size_t)n * sizeof *q);
    }
    if (n < 3) return 0;
    if (build_room(b, (uint32_t)n, (uint32_t)n - 2)) return -1;
    uint32_t v0 = b->nv;
    for (int i = 0; i < n; i++) {
        /* barycentrics of the corner in the triangle's uvs (outside it, on a card, the same
         * affine map) */
        double bu = cross2(c[0], q[i], c[2]) / cross2(c[0], c[1], c[2]);
        double bv = cross2(c[0], c[1], q[i]) / cross2(c[0], c[1], c[2]);
        double bw = 1.0 - bu - bv, len = 0;
        float *p = b->pos + (size_t)b->nv * 3, *nn = b->nrm + (size_t)b->nv * 3, *uv = b->uv + (size_t)b->nv * 2;
        for (int d = 0; d < 3; d++) {
            p[d] = (float)(bw * m->pos[k[0] * 3 + d] + bu * m->pos[k[1] * 3 + d] + bv * m->pos[k[2] * 3 + d]);
            double nd = bw * m->nrm[k[0] * 3 + d] + bu * m->nrm[k[1] * 3 + d] + bv * m->nrm[k[2] * 3 + d];
            nn[d] = (float)nd;
            len += nd * nd;
        }
        len = sqrt(len);
        for (int d = 0; d < 3; d++) nn[d] = len > 0 ? (float)(nn[d] / len) : (d == 2);
        uv[0] = (float)q[i][0];
        uv[1] = (float)q[i][1];
        b->nv++;
    }
    /* the fan, wound as the triangle it replaces */
    int flip = area < 0;
    for (int i = 1; i + 1 < n; i++) {
        uint32_t *f = b->tri + (size_t)b->nt * 3;
        f[0] = v0;
        f[1] = v0 + (uint32_t)(flip ? i + 1 : i);
        f[2] = v0 + (uint32_t)(flip ? i : i + 1);
        b->mat[b->nt++] = mat;
    }
    return 0;
}

/* Rebuilds *mp with its cut-out triangles replaced; outlines[material] for each cut-out
 * material (n 0 elsewhere). */
static int outline_mesh(const scene *s, mesh **mp, const cutout_outline *outlines, const uint8_t *is_cutout,
                        cutout_outline_stats *st, err_buf *err)
{
    mesh *m = *mp;
    if (!m || !m->nt) return 0;
    uint32_t cut = 0;
    for (uint32_t t = 0; t < m->nt; t++) cut += is_cutout[scene_triangle_material(s, m, t)];
    if (!cut) return 0;
    mesh_build b = {0};
    uint32_t *remap = malloc((size_t)m->nv * sizeof(uint32_t)); /* owned here */
    int rc = -1;
    if (!remap) goto nomem;
    for (uint32_t v = 0; v < m->nv; v++) remap[v] = UINT32_MAX;
    for (uint32_t t = 0; t < m->nt; t++) {
        uint32_t mt = scene_triangle_material(s, m, t);
        if (is_cutout[mt]) {
            /* a card's two triangles in one piece, so the outline is not cut along its diagonal */
            int64_t fourth = t + 1 < m->nt && m->mat[t + 1] == m->mat[t] ? card_fourth_corner(m, t, t + 1) : -1;
            if (add_outline_part(&b, m, t, fourth, &outlines[mt], m->mat[t])) goto nomem;
            t += fourth >= 0;
            continue;
        }
        if (build_room(&b, 3, 1)) goto nomem;
        for (int i = 0; i < 3; i++) {
            uint32_t v = m->tri[(size_t)t * 3 + i];
            if (remap[v] == UINT32_MAX) {
                memcpy(b.pos + (size_t)b.nv * 3, m->pos + (size_t)v * 3, 3 * sizeof(float));
                memcpy(b.nrm + (size_t)b.nv * 3, m->nrm + (size_t)v * 3, 3 * sizeof(float));
                memcpy(b.uv + (size_t)b.nv * 2, m->uv + (size_t)v * 2, 2 * sizeof(float));
                remap[v] = b.nv++;
            }
            b.tri[(size_t)b.nt * 3 + i] = remap[v];
        }
        b.mat[b.nt++] = m->mat[t];
    }
    mesh *out = mesh_new(); /* owned by the scene in place of m */
    if (!out) goto nomem;
    if (mesh_append(out, b.pos, b.nrm, b.uv, b.nv, b.tri, b.mat, -1, b.nt, err)) {
        mesh_free(out);
        goto done;
    }
    st->cutout_triangles += cut;
    st->outline_triangles += out->nt - (m->nt - cut);
    mesh_free(m);
    *mp = out;
    rc = 0;
    goto done;
nomem:
    err_nomem(err, "out of memory drawing a mesh's %u cut-out triangles as outlines", cut);
done:
    free(remap);
    build_free(&b);
    return rc;
}

/* ------------------------------------------------------------------------------------------ */
/* the scene                                                                                   */

static uint32_t mesh_cutouts(const scene *s, const mesh *m)
{
    uint32_t n = 0;
    for (uint32_t t = 0; m && t < m->nt; t++) n += cutout_material(s, &s->materials[scene_triangle_material(s, m, t)]);
    return n;
}

uint64_t cutout_outline_triangles_in(const scene *s)
{
    uint64_t n = 0;
    for (uint32_t p = 0; p < s->n_prototypes; p++) n += mesh_cutouts(s, s->prototypes[p].mesh);
    for (uint32_t m = 0; m < s->n_models; m++) n += mesh_cutouts(s, s->models[m].mesh);
    for (uint32_t o = 0; o < s->n_objects; o++) n += mesh_cutouts(s, s->objects[o].mesh);
    return n;
}

int cutout_outline_scene(scene *s, cutout_outline_stats *st, err_buf *err)
{
    memset(st, 0, sizeof *st);
    uint32_t nm = s->n_materials ? s->n_materials : 1;
    cutout_outline *outlines = calloc(nm, sizeof *outlines); /* owned here */
    uint8_t *is_cutout = calloc(nm, 1);                      /* owned here */
    int rc = -1;
    if (!outlines || !is_cutout) {
        err_nomem(err, "out of memory for the leaves' outlines");
        goto done;
    }
    for (uint32_t i = 0; i < s->n_materials; i++) {
        if (!cutout_material(s, &s->materials[i])) continue;
        is_cutout[i] = 1;
        cutout_outline_of_texture(&s->textures[s->materials[i].texture], &outlines[i]);
        st->materials++;
    }
    if (st->materials) {
        for (uint32_t p = 0; p < s->n_prototypes; p++)
            if (outline_mesh(s, &s->prototypes[p].mesh, outlines, is_cutout, st, err)) goto done;
        for (uint32_t m = 0; m < s->n_models; m++)
            if (outline_mesh(s, &s->models[m].mesh, outlines, is_cutout, st, err)) goto done;
        for (uint32_t o = 0; o < s->n_objects; o++)
            if (outline_mesh(s, &s->objects[o].mesh, outlines, is_cutout, st, err)) goto done;
        for (uint32_t i = 0; i < s->n_materials; i++)
            if (is_cutout[i]) s->materials[i].alpha_mask = 0;
    }
    rc = 0;
done:
    free(outlines);
    free(is_cutout);
    return rc;
}

int cutout_outline_apply(scene *s, leaf_mode mode, cutout_outline_stats *st, err_buf *err)
{
    memset(st, 0, sizeof *st);
    if (mode == LEAF_MODE_MASK) return 0;
    if (mode == LEAF_MODE_AUTO && cutout_outline_triangles_in(s) <= CUTOUT_OUTLINE_AUTO_TRIANGLES) return 0;
    if (cutout_outline_scene(s, st, err)) return -1;
    return st->cutout_triangles > 0;
}
