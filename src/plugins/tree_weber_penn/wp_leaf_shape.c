/* wp_leaf_shape.c — a leaf's mesh as Arbaro 1.9's LeafMesh draws it for its OBJ writer (quads
 * where it can): "discN" an oval of N triangles (N + 2 points on an outline with a pointed
 * tip, joined by quads from both sides, a last triangle for odd N), "square" one quad,
 * "sphere" an icosahedron of 20 triangles; any other name (Arbaro's "0", "palm", ...) the
 * six-triangle disc. Length LeafScale and width LeafScale * LeafScaleX, both divided by
 * sqrt(LeafQuality); the blade starts LeafStemLen lengths up its z axis (the stalk itself is
 * not drawn, as in Arbaro). */
#include "wp_leaf_shape.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The shape being made: Arbaro's faces (3 or 4 corners) kept as triangles. */
typedef struct shape_build {
    wp_leaf_shape *s;
    double length, width, stem_len;
} shape_build;

static void set_point(shape_build *b, int i, double x, double y, double z)
{
    b->s->vertex[i][0] = x * b->width;
    b->s->vertex[i][1] = y * b->width;
    b->s->vertex[i][2] = (b->stem_len + z) * b->length;
    b->s->uv[i][0] = x + 0.5;
    b->s->uv[i][1] = z;
}

static void add_face(shape_build *b, int i, int j, int k, int m)
{
    wp_leaf_shape *s = b->s;
    s->faces++;
    uint32_t *t = s->triangle[s->n_triangles++];
    t[0] = (uint32_t)i, t[1] = (uint32_t)j, t[2] = (uint32_t)k;
    if (m < 0) return;
    t = s->triangle[s->n_triangles++];
    t[0] = (uint32_t)i, t[1] = (uint32_t)k, t[2] = (uint32_t)m;
}

static double leaf_aux(double x)
{
    return 0.8 * log(x + 1) / log(1.2) - 1.0 * sin(x);
}

/* The outline's departure from a circle that makes the leaf's tip. */
static double leaf_peak(double angle)
{
    return leaf_aux(angle) - angle * leaf_aux(M_PI) / M_PI;
}

static void make_disc(shape_build *b, int triangles)
{
    int cnt = triangles + 2;
    for (int i = 0; i < cnt; i++) {
        double angle = i * 2.0 * M_PI / cnt;
        double x = sin(angle), z = cos(angle);
        if (angle < M_PI)
            x -= leaf_peak(angle);
        else if (angle > M_PI)
            x += leaf_peak(2 * M_PI - angle);
        set_point(b, i, 0.5 * x, 0, 0.5 * z + 0.5);
    }
    int faces = triangles / 2 + triangles % 2;
    int left = 0, right = cnt - 1;
    for (int i = 0; i < faces; i++) {
        if (left + 1 < right - 1) {
            add_face(b, left, left + 1, right - 1, right);
            left++, right--;
        } else {
            add_face(b, left, left + 1, right, -1);
            left++;
        }
    }
}

static void make_square(shape_build *b)
{
    set_point(b, 0, -0.5, 0, 0);
    set_point(b, 1, -0.5, 0, 1);
    set_point(b, 2, 0.5, 0, 1);
    set_point(b, 3, 0.5, 0, 0);
    add_face(b, 0, 3, 2, 1);
}

static void make_sphere(shape_build *b)
{
    double s = (sqrt(5) - 1) / 2 * sqrt(2 / (5 - sqrt(5))) / 2;
    double t = sqrt(2 / (5 - sqrt(5))) / 2;
    set_point(b, 0, 0, s, -t + 0.5), set_point(b, 6, 0, -s, -t + 0.5);
    set_point(b, 1, t, 0, -s + 0.5), set_point(b, 7, t, 0, s + 0.5);
    set_point(b, 2, -s, t, 0 + 0.5), set_point(b, 8, s, t, 0 + 0.5);
    set_point(b, 3, 0, s, t + 0.5), set_point(b, 9, 0, -s, t + 0.5);
    set_point(b, 4, -t, 0, -s + 0.5), set_point(b, 10, -t, 0, s + 0.5);
    set_point(b, 5, -s, -t, 0 + 0.5), set_point(b, 11, s, -t, 0 + 0.5);
    static const int f[20][3] = { { 0, 1, 6 },  { 0, 6, 4 },  { 1, 8, 7 },  { 1, 7, 11 }, { 2, 3, 0 },
                                  { 2, 3, 8 },  { 3, 9, 7 },  { 3, 10, 9 }, { 4, 10, 2 }, { 4, 5, 10 },
                                  { 5, 6, 11 }, { 5, 11, 9 }, { 0, 8, 1 },  { 6, 1, 11 }, { 6, 5, 4 },
                                  { 0, 4, 2 },  { 7, 8, 3 },  { 10, 3, 2 }, { 10, 5, 9 }, { 9, 11, 7 } };
    for (int i = 0; i < 20; i++) add_face(b, f[i][0], f[i][1], f[i][2], -1);
}

/* The shape's kind from its name: 'd' a disc of *triangles, 'q' square, 's' sphere. Returns 0,
 * or -1 for a "discN" with N past WP_LEAF_DISC_MAX. */
static int shape_kind(const char *name, char *kind, int *triangles)
{
    *kind = 'd';
    *triangles = 6;
    if (!strcmp(name, "square")) {
        *kind = 'q';
    } else if (!strcmp(name, "sphere")) {
        *kind = 's';
    } else if (!strncmp(name, "disc", 4)) {
        const char *d = name + 4;
        size_t n = strlen(d);
        for (size_t i = 0; i < n; i++)
            if (!isdigit((unsigned char)d[i])) return 0; /* not "disc" + digits: the plain disc */
        if (n == 0) return 0;
        long v = 0;
        for (size_t i = 0; i < n && v <= WP_LEAF_DISC_MAX; i++) v = v * 10 + (d[i] - '0');
        if (v > WP_LEAF_DISC_MAX) return -1;
        *triangles = (int)v;
    }
    return 0;
}

int wp_leaf_shape_make(const wp_params *p, wp_leaf_shape *out, plugin_err *err)
{
    memset(out, 0, sizeof *out);
    char kind;
    int triangles;
    if (shape_kind(p->leaf_shape, &kind, &triangles) < 0)
        return plugin_fail(err, SYLVA_ERR_LIMIT, "species '%s': LeafShape '%s' asks for more than %d triangles per leaf",
                           p->species, p->leaf_shape, WP_LEAF_DISC_MAX);
    size_t n_vertices = kind == 'q' ? 4 : kind == 's' ? 12 : (size_t)triangles + 2;
    size_t max_triangles = kind == 'q' ? 2 : kind == 's' ? 20 : (size_t)triangles + 1;
    out->vertex = calloc(n_vertices, sizeof *out->vertex);      /* owned by out */
    out->uv = calloc(n_vertices, sizeof *out->uv);              /* owned by out */
    out->triangle = calloc(max_triangles, sizeof *out->triangle); /* owned by out */
    if (!out->vertex || !out->uv || !out->triangle) {
        wp_leaf_shape_release(out);
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the leaf shape of species '%s'", p->species);
    }
    out->n_vertices = n_vertices;
    double quality = sqrt(p->leaf_quality);
    shape_build b = { out, p->leaf_scale / quality, p->leaf_scale * p->leaf_scale_x / quality, p->leaf_stem_len };
    if (kind == 'q')
        make_square(&b);
    else if (kind == 's')
        make_sphere(&b);
    else
        make_disc(&b, triangles);
    return 0;
}

/* Whether (x, z) lies in triangle t's shadow on the x-z plane (either winding; a degenerate one
 * covers nothing). */
static int covers(const wp_leaf_shape *s, size_t t, double x, double z)
{
    const double *a = s->vertex[s->triangle[t][0]], *b = s->vertex[s->triangle[t][1]], *c = s->vertex[s->triangle[t][2]];
    double d1 = (b[0] - a[0]) * (z - a[2]) - (b[2] - a[2]) * (x - a[0]);
    double d2 = (c[0] - b[0]) * (z - b[2]) - (c[2] - b[2]) * (x - b[0]);
    double d3 = (a[0] - c[0]) * (z - c[2]) - (a[2] - c[2]) * (x - c[0]);
    return (d1 >= 0 && d2 >= 0 && d3 >= 0 && d1 + d2 + d3 > 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0 && d1 + d2 + d3 < 0);
}

double wp_leaf_shape_face_area(const wp_leaf_shape *s)
{
    double x0 = INFINITY, x1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
    for (size_t i = 0; i < s->n_vertices; i++) {
        x0 = fmin(x0, s->vertex[i][0]), x1 = fmax(x1, s->vertex[i][0]);
        z0 = fmin(z0, s->vertex[i][2]), z1 = fmax(z1, s->vertex[i][2]);
    }
    if (!(x1 > x0) || !(z1 > z0)) return 0;
    const int n = WP_LEAF_FACE_CELLS;
    double dx = (x1 - x0) / n, dz = (z1 - z0) / n;
    long inside = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double x = x0 + (i + 0.5) * dx, z = z0 + (j + 0.5) * dz;
            for (size_t t = 0; t < s->n_triangles; t++)
                if (covers(s, t, x, z)) {
                    inside++;
                    break;
                }
        }
    return inside * dx * dz;
}

void wp_leaf_shape_release(wp_leaf_shape *s)
{
    free(s->vertex);
    free(s->uv);
    free(s->triangle);
    memset(s, 0, sizeof *s);
}
