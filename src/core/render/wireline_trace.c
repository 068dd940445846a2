/* wireline_trace.c — the wireline's outline and inner edges as polylines (wireline_trace.h). It
 * reads the wireline's pixels only; it draws nothing. */
#include "render/wireline_trace.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* --- the growing arrays ------------------------------------------------------------------------ */

typedef struct builder {
    wireline_paths *p;
    uint32_t cap_points, cap_lines;
    uint32_t open_from;      /* the first point of the polyline being traced */
    int failed;
} builder;

static void add_point(builder *b, double x, double y)
{
    wireline_paths *p = b->p;
    if (b->failed) return;
    if (p->n_points == b->cap_points) {
        uint32_t cap = b->cap_points ? 2 * b->cap_points : 1024;
        double(*grown)[2] = realloc(p->points, (size_t)cap * sizeof *grown);
        if (!grown) {
            b->failed = 1;
            return;
        }
        p->points = grown, b->cap_points = cap;
    }
    p->points[p->n_points][0] = x, p->points[p->n_points][1] = y;
    p->n_points++;
}

static void end_line(builder *b, wireline_kind kind, int closed)
{
    wireline_paths *p = b->p;
    if (b->failed) return;
    if (p->n_lines == b->cap_lines) {
        uint32_t cap = b->cap_lines ? 2 * b->cap_lines : 64;
        wireline_polyline *grown = realloc(p->lines, (size_t)cap * sizeof *grown);
        if (!grown) {
            b->failed = 1;
            return;
        }
        p->lines = grown, b->cap_lines = cap;
    }
    p->lines[p->n_lines++] = (wireline_polyline){b->open_from, p->n_points - b->open_from, (uint8_t)kind,
                                                 (uint8_t)closed};
    b->open_from = p->n_points;
}

/* --- simplification ------------------------------------------------------------------------------ */

static double distance_to_segment(const double *q, const double *a, const double *b)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(q[0] - (a[0] + t * dx), q[1] - (a[1] + t * dy));
}

/* Douglas–Peucker over pts[lo..hi] (both kept): keep[k] set for every point the simplified line
 * keeps. stack holds at least hi - lo + 1 pairs. */
static void keep_between(const double (*pts)[2], uint32_t lo, uint32_t hi, uint8_t *keep, uint32_t (*stack)[2])
{
    uint32_t top = 0;
    keep[lo] = keep[hi] = 1;
    stack[top][0] = lo, stack[top++][1] = hi;
    while (top) {
        uint32_t a = stack[top - 1][0], b = stack[top - 1][1];
        top--;
        double far = -1;
        uint32_t at = a;
        for (uint32_t k = a + 1; k < b; k++) {
            double d = distance_to_segment(pts[k], pts[a], pts[b]);
            if (d > far) far = d, at = k;
        }
        if (far <= WIRELINE_TRACE_TOLERANCE) continue;
        keep[at] = 1;
        stack[top][0] = a, stack[top++][1] = at;
        stack[top][0] = at, stack[top++][1] = b;
    }
}

static int on_frame_point(const wireline_paths *p, const double *q)
{
    return q[0] == 0 || q[1] == 0 || q[0] == p->width || q[1] == p->height;
}

/* Simplifies the last polyline of p in place. Its anchors stay: its ends, and on an outline each
 * point where it comes to or leaves the picture's edge (a closed one then starts at the first of
 * them; with none, it is split at its first point and the point farthest from it). Returns -1
 * when out of memory (the line is then left whole). */
static int simplify_last(wireline_paths *p)
{
    wireline_polyline *l = &p->lines[p->n_lines - 1];
    double(*pts)[2] = p->points + l->first;
    uint32_t n = l->n, len = l->closed ? n + 1 : n;
    if (n < 3) return 0;
    uint8_t *keep = calloc(len, 1);                                 /* owned here */
    uint32_t(*stack)[2] = malloc((size_t)len * sizeof *stack);      /* owned here */
    uint32_t *anchor = malloc((size_t)len * sizeof *anchor);        /* owned here */
    double(*ring)[2] = malloc((size_t)len * sizeof *ring);          /* owned here */
    if (!keep || !stack || !anchor || !ring) {
        free(keep), free(stack), free(anchor), free(ring);
        return -1;
    }
    int outline = l->kind == WIRELINE_OUTLINE;
    uint32_t start = 0;
    for (uint32_t k = 0; l->closed && outline && k < n && !start; k++)
        if (on_frame_point(p, pts[k]) != on_frame_point(p, pts[(k + n - 1) % n])) start = k;
    for (uint32_t k = 0; k < len; k++) ring[k][0] = pts[(start + k) % n][0], ring[k][1] = pts[(start + k) % n][1];
    uint32_t m = 0;
    anchor[m++] = 0;
    for (uint32_t k = 1; outline && k + 1 < len; k++) {
        int here = on_frame_point(p, ring[k]);
        if (here != on_frame_point(p, ring[k - 1]) || here != on_frame_point(p, ring[k + 1])) anchor[m++] = k;
    }
    if (m == 1 && l->closed) { /* no anchor within: the point farthest from the first */
        uint32_t far_at = 1;
        double far = -1;
        for (uint32_t k = 1; k < n; k++) {
            double d = hypot(ring[k][0] - ring[0][0], ring[k][1] - ring[0][1]);
            if (d > far) far = d, far_at = k;
        }
        anchor[m++] = far_at;
    }
    anchor[m++] = len - 1;
    for (uint32_t a = 0; a + 1 < m; a++) keep_between((const double(*)[2])ring, anchor[a], anchor[a + 1], keep, stack);
    uint32_t kept = 0;
    for (uint32_t k = 0; k < n; k++)
        if (keep[k]) pts[kept][0] = ring[k][0], pts[kept][1] = ring[k][1], kept++;
    l->n = kept;
    p->n_points = l->first + kept;
    free(keep), free(stack), free(anchor), free(ring);
    return 0;
}

/* Ends the polyline being traced and simplifies it; the next one starts after what is kept. */
static void finish_line(builder *b, wireline_kind kind, int closed)
{
    end_line(b, kind, closed);
    if (!b->failed && simplify_last(b->p)) b->failed = 1;
    b->open_from = b->p->n_points;
}

/* --- the outline: marching squares --------------------------------------------------------------- */

/* The silhouette on the grid of pixel centres padded by one sample of outside all round: sample
 * (i, j) is pixel (i - 1, j - 1). */
static int sample(const wireline *w, int64_t i, int64_t j)
{
    return i >= 1 && j >= 1 && i <= (int64_t)w->width && j <= (int64_t)w->height &&
           w->inside[(size_t)(j - 1) * w->width + (size_t)(i - 1)];
}

/* A crossing of the contour is the middle of a grid edge: the edge from sample (i, j) to its right
 * (even id) or down (odd id) neighbour. */
typedef struct crossing_step {
    uint64_t from, to;       /* the contour runs from crossing `from` to crossing `to`, inside on its right */
} crossing_step;

static uint64_t edge_id(const wireline *w, int64_t i, int64_t j, int down)
{
    return 2 * ((uint64_t)j * (w->width + 2) + (uint64_t)i) + (uint64_t)down;
}

static void crossing_point(const wireline *w, uint64_t id, double *x, double *y)
{
    uint64_t k = id / 2, i = k % (w->width + 2), j = k / (w->width + 2);
    if (id & 1) *x = (double)i - 0.5, *y = (double)j; /* between (i, j) and (i, j + 1) */
    else *x = (double)i, *y = (double)j - 0.5;        /* between (i, j) and (i + 1, j) */
}

static int by_from(const void *a, const void *b)
{
    uint64_t x = ((const crossing_step *)a)->from, y = ((const crossing_step *)b)->from;
    return x < y ? -1 : x > y;
}

/* The steps of cell (i, j) (its corners samples (i, j) to (i + 1, j + 1)) appended to steps.
 * Diagonal corners alone inside are joined through the cell (the silhouette is one piece there). */
static uint32_t cell_steps(const wireline *w, int64_t i, int64_t j, crossing_step *out)
{
    /* corners a (top left), b (top right), c (bottom right), d (bottom left), at unit positions */
    static const double corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    static const double mid[4][2] = {{0.5, 0}, {1, 0.5}, {0.5, 1}, {0, 0.5}}; /* top, right, bottom, left */
    int in[4] = {sample(w, i, j), sample(w, i + 1, j), sample(w, i + 1, j + 1), sample(w, i, j + 1)};
    int count = in[0] + in[1] + in[2] + in[3];
    if (count == 0 || count == 4) return 0;
    uint64_t ids[4] = {edge_id(w, i, j, 0), edge_id(w, i + 1, j, 1), edge_id(w, i, j + 1, 0), edge_id(w, i, j, 1)};
    int pairs[2][2], n_pairs = 0;
    double inner[2][2];
    if (count == 2 && in[0] == in[2]) { /* a saddle: cut off each outside corner */
        int out0 = in[0] ? 1 : 0;      /* b and d outside, or a and c */
        for (int k = 0; k < 2; k++) {
            int c = out0 + 2 * k;      /* the outside corner; its edges are c - 1 and c (mod 4) */
            pairs[n_pairs][0] = (c + 3) % 4, pairs[n_pairs][1] = c;
            inner[n_pairs][0] = inner[n_pairs][1] = 0.5;
            n_pairs++;
        }
    } else {
        int k0 = -1, k1 = -1;
        for (int k = 0; k < 4; k++)
            if (in[k] != in[(k + 1) % 4]) { /* edge k joins corners k and k + 1 */
                if (k0 < 0) k0 = k;
                else k1 = k;
            }
        pairs[0][0] = k0, pairs[0][1] = k1;
        inner[0][0] = inner[0][1] = 0;
        for (int k = 0; k < 4; k++)
            if (in[k]) inner[0][0] += corner[k][0] / count, inner[0][1] += corner[k][1] / count;
        n_pairs = 1;
    }
    for (int s = 0; s < n_pairs; s++) {
        const double *p = mid[pairs[s][0]], *q = mid[pairs[s][1]], *m = inner[s];
        double cross = (q[0] - p[0]) * (m[1] - p[1]) - (q[1] - p[1]) * (m[0] - p[0]);
        int forward = cross > 0; /* y runs down: the inside on the right of p -> q */
        out[s] = (crossing_step){ids[pairs[s][forward ? 0 : 1]], ids[pairs[s][forward ? 1 : 0]]};
    }
    return (uint32_t)n_pairs;
}

/* Every closed contour of the silhouette, in the order of its first crossing. */
static int trace_outline(builder *b, const wireline *w)
{
    size_t cap = 1024, n = 0;
    crossing_step *steps = malloc(cap * sizeof *steps); /* owned here */
    if (!steps) return -1;
    for (int64_t j = 0; j <= (int64_t)w->height; j++)
        for (int64_t i = 0; i <= (int64_t)w->width; i++) {
            if (n + 2 > cap) {
                crossing_step *grown = realloc(steps, 2 * cap * sizeof *grown);
                if (!grown) {
                    free(steps);
                    return -1;
                }
                steps = grown, cap *= 2;
            }
            n += cell_steps(w, i, j, steps + n);
        }
    qsort(steps, n, sizeof *steps, by_from);
    uint8_t *used = calloc(n ? n : 1, 1); /* owned here */
    if (!used) {
        free(steps);
        return -1;
    }
    for (size_t start = 0; start < n && !b->failed; start++) {
        if (used[start]) continue;
        size_t at = start;
        while (!used[at]) {
            used[at] = 1;
            double x, y;
            crossing_point(w, steps[at].from, &x, &y);
            add_point(b, x, y);
            crossing_step key = {steps[at].to, 0};
            crossing_step *next = bsearch(&key, steps, n, sizeof *steps, by_from);
            if (!next) break;
            at = (size_t)(next - steps);
        }
        finish_line(b, WIRELINE_OUTLINE, 1);
        b->p->n_outlines += !b->failed;
    }
    free(used), free(steps);
    return b->failed ? -1 : 0;
}

/* --- the inner edges: chains of pixel centres ---------------------------------------------------- */

static const int step_x[8] = {1, 1, 0, -1, -1, -1, 0, 1}, step_y[8] = {0, 1, 1, 1, 0, -1, -1, -1};

static int is_edge(const wireline *w, int64_t x, int64_t y)
{
    return x >= 0 && y >= 0 && x < (int64_t)w->width && y < (int64_t)w->height &&
           w->edge[(size_t)y * w->width + (size_t)x] == WIRELINE_EDGE;
}

/* The links of edge pixel (x, y): bit d for its neighbour in direction d, a diagonal one only
 * when neither pixel beside both is an edge pixel. */
static uint8_t links_of(const wireline *w, int64_t x, int64_t y)
{
    uint8_t m = 0;
    for (int d = 0; d < 8; d++) {
        if (!is_edge(w, x + step_x[d], y + step_y[d])) continue;
        if ((d & 1) && (is_edge(w, x + step_x[d], y) || is_edge(w, x, y + step_y[d]))) continue;
        m |= (uint8_t)(1u << d);
    }
    return m;
}

static int link_count(uint8_t m) { return __builtin_popcount(m); }

/* Follows the links from pixel k in direction d until a pixel with other than two links, or back
 * to k; one polyline. */
static void follow(builder *b, const wireline *w, const uint8_t *links, uint8_t *used, size_t k, int d)
{
    size_t start = k;
    int closed = 0;
    add_point(b, (double)(k % w->width) + 0.5, (double)(k / w->width) + 0.5);
    for (;;) {
        size_t next = (size_t)((int64_t)k + step_x[d] + (int64_t)step_y[d] * w->width);
        used[k] |= (uint8_t)(1u << d), used[next] |= (uint8_t)(1u << ((d + 4) & 7));
        if (next == start) {
            closed = 1;
            break;
        }
        add_point(b, (double)(next % w->width) + 0.5, (double)(next / w->width) + 0.5);
        uint8_t left = links[next] & (uint8_t)~used[next];
        if (link_count(links[next]) != 2 || !left) break;
        k = next, d = __builtin_ctz(left);
    }
    finish_line(b, WIRELINE_EDGE, closed);
}

static int trace_inner(builder *b, const wireline *w)
{
    size_t n = (size_t)w->width * w->height;
    uint8_t *links = calloc(n ? n : 1, 1), *used = calloc(n ? n : 1, 1); /* both owned here */
    if (!links || !used) {
        free(links), free(used);
        return -1;
    }
    for (size_t k = 0; k < n; k++)
        if (w->edge[k] == WIRELINE_EDGE) links[k] = links_of(w, (int64_t)(k % w->width), (int64_t)(k / w->width));
    /* from the ends and the branchings first, then round the loops that are left */
    for (int pass = 0; pass < 2 && !b->failed; pass++)
        for (size_t k = 0; k < n && !b->failed; k++) {
            if (w->edge[k] != WIRELINE_EDGE || (link_count(links[k]) == 2) != pass) continue;
            if (!links[k]) { /* a pixel alone: a dot */
                add_point(b, (double)(k % w->width) + 0.5, (double)(k / w->width) + 0.5);
                end_line(b, WIRELINE_EDGE, 0);
                continue;
            }
            for (int d = 0; d < 8 && !b->failed; d++)
                if (links[k] & ~used[k] & (1u << d)) follow(b, w, links, used, k, d);
        }
    free(links), free(used);
    return b->failed ? -1 : 0;
}

int wireline_trace(wireline_paths *p, const wireline *w, int inner_edges, err_buf *err)
{
    memset(p, 0, sizeof *p);
    p->width = w->width, p->height = w->height;
    builder b = {.p = p};
    int rc = w->inside && w->outline ? trace_outline(&b, w) : 0;
    if (!rc && inner_edges && w->inner) rc = trace_inner(&b, w);
    if (rc) {
        wireline_paths_free(p);
        return err_nomem(err, "out of memory tracing a %ux%u wireline", w->width, w->height);
    }
    return 0;
}

void wireline_paths_free(wireline_paths *p)
{
    free(p->points);
    free(p->lines);
    memset(p, 0, sizeof *p);
}

int wireline_on_frame(const wireline_paths *p, const double a[2], const double b[2])
{
    double w = p->width, h = p->height;
    return (a[0] == 0 && b[0] == 0) || (a[1] == 0 && b[1] == 0) || (a[0] == w && b[0] == w) ||
           (a[1] == h && b[1] == h);
}
