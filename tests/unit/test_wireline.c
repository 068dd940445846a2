/* test_wireline.c — the development's wireline (render/wireline.h) on a rendered box: every
 * wireline pixel lies within a pixel of one of the box's visible edges as the camera projects
 * them, every visible edge is drawn along its length and painted, and a box that is not the
 * development has none; an open frame is outlined as one silhouette, traced as one closed
 * polyline (render/wireline_trace.h), and hand-made silhouettes trace into the polylines they
 * should. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "render/camera.h"
#include "render/render.h"
#include "render/wireline.h"
#include "render/wireline_trace.h"
#include "scene_fixture.h"
#include "work_dir.h"

static const char *box_scene =
    "image: {width: 160, height: 120, spp: 1, seed: 1}\n"
    "camera: {position: [12, -15, 8], look_at: [0, 0, 3], fov: 40}\n"
    "sun: {azimuth: 200, elevation: 40}\n"
    "terrain: {grid: [[0, 0], [0, 0]], origin: [-50, -50], spacing: [100, 100]}\n"
    "objects:\n"
    "  - {name: hall, shape: box, size: [4, 4, 6], position: [0, 0, 3], development: %s}\n";

/* Pixel position of world point p (the renderer's pinhole). */
static void project(const camera *c, const double p[3], double *x, double *y)
{
    double d[3] = {p[0] - c->origin.x, p[1] - c->origin.y, p[2] - c->origin.z};
    double f = d[0] * c->forward.x + d[1] * c->forward.y + d[2] * c->forward.z;
    double r = d[0] * c->right.x + d[1] * c->right.y + d[2] * c->right.z;
    double u = d[0] * c->up.x + d[1] * c->up.y + d[2] * c->up.z;
    *x = (r / f / c->tan_half_x + 1) * 0.5 * c->width;
    *y = (1 - u / f / c->tan_half_y) * 0.5 * c->height;
}

static double segment_distance(double px, double py, const double a[2], const double b[2])
{
    double dx = b[0] - a[0], dy = b[1] - a[1];
    double t = ((px - a[0]) * dx + (py - a[1]) * dy) / (dx * dx + dy * dy);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(px - (a[0] + t * dx), py - (a[1] + t * dy));
}

static scene *render_box(const char *dev, film **f)
{
    char text[1024];
    snprintf(text, sizeof text, box_scene, dev);
    scene *s = fixture_scene(work_file("box.yaml", text));
    if (!s) return NULL;
    err_buf err = {{0}};
    render_options o = {.threads = 2, .quiet = 1};
    *f = render_scene(s, &o, NULL, &err);
    CHECK(*f != NULL);
    return s;
}

TEST(wireline_lies_on_the_box_edges)
{
    film *f = NULL;
    scene *s = render_box("true", &f);
    if (!s || !f) return;
    err_buf err = {{0}};
    camera c;
    camera_init(&c, &s->camera, f->width, f->height);
    wireline w;
    CHECK_INT(wireline_find(&w, f, s, &c, &err), 0);
    /* the box's corners and its 12 edges; an edge is seen when a face beside it faces the eye */
    double corner[8][3], px[8][2];
    for (int k = 0; k < 8; k++) {
        corner[k][0] = k & 1 ? 2 : -2, corner[k][1] = k & 2 ? 2 : -2, corner[k][2] = k & 4 ? 6 : 0;
        project(&c, corner[k], &px[k][0], &px[k][1]);
    }
    const double eye[3] = {c.origin.x, c.origin.y, c.origin.z};
    /* faces as (axis, side): the face x = +2 faces the eye when eye x > 2, and so on */
    int seen_face[3][2];
    for (int a = 0; a < 3; a++) {
        double lo = a == 2 ? 0 : -2, hi = a == 2 ? 6 : 2;
        seen_face[a][0] = eye[a] < lo, seen_face[a][1] = eye[a] > hi;
    }
    double seg[12][2][2];
    int n_seg = 0;
    for (int k = 0; k < 8; k++)
        for (int a = 0; a < 3; a++) {
            int j = k | (1 << a);
            if (j == k) continue;
            /* the edge from k to j runs along axis a; the faces beside it are the other two axes' */
            int b = (a + 1) % 3, cax = (a + 2) % 3;
            int seen = seen_face[b][(k >> b) & 1] || seen_face[cax][(k >> cax) & 1];
            if (!seen) continue;
            memcpy(seg[n_seg][0], px[k], sizeof px[k]);
            memcpy(seg[n_seg][1], px[j], sizeof px[j]);
            n_seg++;
        }
    CHECK_INT(n_seg, 9); /* three faces in view: six outline edges and three inner ones */
    double worst = 0;
    for (uint32_t y = 0; y < w.height; y++)
        for (uint32_t x = 0; x < w.width; x++) {
            if (!w.edge[(size_t)y * w.width + x]) continue;
            double best = INFINITY;
            for (int e = 0; e < n_seg; e++) best = fmin(best, segment_distance(x + 0.5, y + 0.5, seg[e][0], seg[e][1]));
            worst = fmax(worst, best);
        }
    fprintf(stderr, "wireline: %llu outline and %llu inner pixels, farthest %.2f px from a seen edge\n",
            (unsigned long long)w.outline, (unsigned long long)w.inner, worst);
    CHECK(worst <= 1.0);
    CHECK(w.outline > 100 && w.inner > 50);
    /* every seen edge is drawn along its length: near each point of it, a wireline pixel within
     * a pixel of the edge */
    for (int e = 0; e < n_seg; e++)
        for (int i = 1; i < 20; i++) {
            double q[2] = {seg[e][0][0] + i / 20.0 * (seg[e][1][0] - seg[e][0][0]),
                           seg[e][0][1] + i / 20.0 * (seg[e][1][1] - seg[e][0][1])};
            int found = 0;
            for (int dy = -2; dy <= 2 && !found; dy++)
                for (int dx = -2; dx <= 2 && !found; dx++) {
                    int x = (int)floor(q[0]) + dx, y = (int)floor(q[1]) + dy;
                    if (x < 0 || y < 0 || x >= (int)w.width || y >= (int)w.height) continue;
                    found = w.edge[(size_t)y * w.width + x] &&
                            segment_distance(x + 0.5, y + 0.5, seg[e][0], seg[e][1]) <= 1.0 &&
                            hypot(x + 0.5 - q[0], y + 0.5 - q[1]) <= 1.5;
                }
            if (!found) fprintf(stderr, "edge %d: no wireline near (%.1f, %.1f)\n", e, q[0], q[1]);
            CHECK(found);
        }
    /* painted: every wireline pixel in its colour, nothing else */
    uint8_t *rgb = calloc((size_t)w.width * w.height, 3);
    const uint8_t red[3] = {255, 0, 0}, yellow[3] = {255, 255, 0};
    wireline_draw(&w, rgb, red, yellow);
    uint64_t n_red = 0, n_yellow = 0, other = 0;
    for (size_t k = 0; rgb && k < (size_t)w.width * w.height; k++) {
        const uint8_t *p = &rgb[3 * k];
        if (p[0] == 255 && p[1] == 0) n_red++;
        else if (p[0] == 255 && p[1] == 255) n_yellow++;
        else other += p[0] || p[1] || p[2];
    }
    CHECK(n_red == w.outline && n_yellow == w.inner && other == 0);
    free(rgb);
    wireline_free(&w);
    film_free(f);
    scene_free(s);
}

TEST(a_box_that_is_not_the_development_has_no_wireline)
{
    film *f = NULL;
    scene *s = render_box("false", &f);
    if (!s || !f) return;
    err_buf err = {{0}};
    camera c;
    camera_init(&c, &s->camera, f->width, f->height);
    wireline w;
    CHECK_INT(wireline_find(&w, f, s, &c, &err), 0);
    CHECK(w.outline == 0 && w.inner == 0);
    wireline_free(&w);
    film_free(f);
    scene_free(s);
}

/* An open frame, the development: two posts 6 m apart and five rungs, 30 m from the camera, the
 * gaps between the rungs some 14 pixels high; optionally a small block in front of one gap. */
static const char *frame_scene =
    "image: {width: 160, height: 120, spp: 1, seed: 1}\n"
    "camera: {position: [0, -30, 5], look_at: [0, 0, 5], fov: 40}\n"
    "sun: {azimuth: 200, elevation: 40}\n"
    "terrain: {grid: [[0, 0], [0, 0]], origin: [-100, -100], spacing: [200, 200]}\n"
    "objects:\n"
    "  - {name: post_w, shape: box, size: [0.3, 0.3, 10], position: [-3, 0, 5], development: true}\n"
    "  - {name: post_e, shape: box, size: [0.3, 0.3, 10], position: [3, 0, 5], development: true}\n"
    "  - {name: rung_1, shape: box, size: [6, 0.3, 0.3], position: [0, 0, 1], development: true}\n"
    "  - {name: rung_3, shape: box, size: [6, 0.3, 0.3], position: [0, 0, 3], development: true}\n"
    "  - {name: rung_5, shape: box, size: [6, 0.3, 0.3], position: [0, 0, 5], development: true}\n"
    "  - {name: rung_7, shape: box, size: [6, 0.3, 0.3], position: [0, 0, 7], development: true}\n"
    "  - {name: rung_9, shape: box, size: [6, 0.3, 0.3], position: [0, 0, 9.85], development: true}\n"
    "%s";

/* The 8-connected pieces of the wireline's pixels of kind k. */
static int pieces(const wireline *w, wireline_kind k)
{
    size_t n = (size_t)w->width * w->height;
    uint8_t *seen = calloc(n, 1);
    uint32_t *stack = malloc(n * sizeof *stack);
    int count = 0;
    for (size_t start = 0; seen && stack && start < n; start++) {
        if (w->edge[start] != k || seen[start]) continue;
        count++;
        size_t top = 0;
        stack[top++] = (uint32_t)start, seen[start] = 1;
        while (top) {
            size_t at = stack[--top];
            int x = (int)(at % w->width), y = (int)(at / w->width);
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= (int)w->width || ny >= (int)w->height) continue;
                    size_t m = (size_t)ny * w->width + (size_t)nx;
                    if (w->edge[m] == k && !seen[m]) seen[m] = 1, stack[top++] = (uint32_t)m;
                }
        }
    }
    free(seen), free(stack);
    return count;
}

static int traced_outlines = -1; /* the closed outlines wireline_trace found in the last frame */

static void frame_contours(const char *extra, int *outline, uint64_t *outline_px, uint64_t *inner_px)
{
    char text[2048];
    snprintf(text, sizeof text, frame_scene, extra);
    scene *s = fixture_scene(work_file("frame.yaml", text));
    *outline = -1, *outline_px = *inner_px = 0;
    if (!s) return;
    err_buf err = {{0}};
    render_options o = {.threads = 2, .quiet = 1};
    film *f = render_scene(s, &o, NULL, &err);
    CHECK(f != NULL);
    camera c;
    wireline w = {0};
    if (f) camera_init(&c, &s->camera, f->width, f->height);
    if (f && !wireline_find(&w, f, s, &c, &err))
        *outline = pieces(&w, WIRELINE_OUTLINE), *outline_px = w.outline, *inner_px = w.inner;
    wireline_paths p;
    traced_outlines = w.edge && !wireline_trace(&p, &w, 1, &err) ? (int)p.n_outlines : -1;
    if (w.edge) wireline_paths_free(&p);
    wireline_free(&w);
    film_free(f);
    scene_free(s);
}

/* The silhouette: the frame's outline is one closed contour round it, some 2 x (46 + 73)
 * pixels, the gaps between its rungs filled (with each rung's edges as outline it would be
 * some 440 pixels more); the rungs' edges are inner edges. A block in front of a gap is no hole
 * of the frame: the outline goes round that gap too (some 2 x (44 + 12) pixels more). */
TEST(an_open_frame_is_outlined_as_one_silhouette)
{
    int outline;
    uint64_t outline_px, inner_px, blocked_px, blocked_inner;
    frame_contours("", &outline, &outline_px, &inner_px);
    printf("frame: outline %d contour(s), %llu pixels; inner edges %llu pixels\n", outline,
           (unsigned long long)outline_px, (unsigned long long)inner_px);
    CHECK_INT(outline, 1);
    CHECK_INT(traced_outlines, 1);
    CHECK(outline_px > 200 && outline_px < 320);
    CHECK(inner_px > 250);
    frame_contours("  - {name: block, shape: box, size: [0.5, 0.5, 0.5], position: [0, -10, 4.33]}\n", &outline,
                   &blocked_px, &blocked_inner);
    printf("frame behind a block: outline %d contour(s), %llu pixels; inner edges %llu pixels\n", outline,
           (unsigned long long)blocked_px, (unsigned long long)blocked_inner);
    CHECK(blocked_px > outline_px + 60);
}

/* A hand-made wireline of w x h pixels: the silhouette the rectangles [x0, x1] x [y0, y1] of
 * pixels (inclusive), an inner edge along row `row` from column c0 to c1 (none when c1 < c0). */
static void hand_made(wireline *w, uint32_t wd, uint32_t ht, const int (*rect)[4], int n_rect, int row, int c0, int c1)
{
    memset(w, 0, sizeof *w);
    w->width = wd, w->height = ht;
    w->edge = calloc((size_t)wd * ht, 1), w->inside = calloc((size_t)wd * ht, 1);
    for (int r = 0; r < n_rect; r++)
        for (int y = rect[r][2]; y <= rect[r][3]; y++)
            for (int x = rect[r][0]; x <= rect[r][1]; x++) w->inside[(size_t)y * wd + x] = 1;
    w->outline = 1;
    for (int x = c0; x <= c1; x++) w->edge[(size_t)row * wd + x] = WIRELINE_EDGE, w->inner++;
}

static double ring_area(const wireline_paths *p, const wireline_polyline *l)
{
    double a = 0;
    for (uint32_t k = 0; k < l->n; k++) {
        const double *u = p->points[l->first + k], *v = p->points[l->first + (k + 1) % l->n];
        a += u[0] * v[1] - v[0] * u[1];
    }
    return fabs(a) / 2;
}

/* Two parts, the second running out of the picture's right edge: two closed outlines round them,
 * each within the tolerance of the pixels' boundary (the marching squares cut each corner by
 * half a pixel), the stretch along the edge said to be on the frame; an inner edge along a row is
 * one straight polyline through its pixels' centres; the same wireline traces the same. */
TEST(hand_made_silhouettes_trace_into_their_outlines)
{
    static const int rect[2][4] = {{2, 7, 2, 8}, {12, 19, 3, 5}};
    wireline w;
    hand_made(&w, 20, 12, rect, 2, 5, 3, 6);
    err_buf err = {{0}};
    wireline_paths p, again;
    CHECK_INT(wireline_trace(&p, &w, 1, &err), 0);
    CHECK_INT(p.n_outlines, 2);
    CHECK_INT(p.n_lines, 3);
    for (uint32_t k = 0; k < p.n_lines && k < 3; k++) {
        const wireline_polyline *l = &p.lines[k];
        if (k < 2) {
            CHECK(l->closed && l->kind == WIRELINE_OUTLINE);
            double x0 = rect[k][0], x1 = rect[k][1] + 1, y0 = rect[k][2], y1 = rect[k][3] + 1;
            CHECK_NEAR(ring_area(&p, l), (x1 - x0) * (y1 - y0) - 4 * 0.125, 0.3);
            for (uint32_t i = 0; i < l->n; i++) {
                const double *q = p.points[l->first + i];
                double d = fmin(fmin(fabs(q[0] - x0), fabs(q[0] - x1)), fmin(fabs(q[1] - y0), fabs(q[1] - y1)));
                CHECK(d <= 0.5 + 1e-9);
            }
        } else {
            CHECK(!l->closed && l->kind == WIRELINE_EDGE);
            CHECK_INT(l->n, 2);
            if (l->n == 2) {
                CHECK_NEAR(p.points[l->first][0], 3.5, 1e-9);
                CHECK_NEAR(p.points[l->first + 1][0], 6.5, 1e-9);
                CHECK_NEAR(p.points[l->first][1], 5.5, 1e-9);
            }
        }
    }
    int on_frame = 0;
    if (p.n_lines >= 2)
        for (uint32_t i = 0; i < p.lines[1].n; i++)
            on_frame += wireline_on_frame(&p, p.points[p.lines[1].first + i],
                                          p.points[p.lines[1].first + (i + 1) % p.lines[1].n]);
    CHECK_INT(on_frame, 1);
    CHECK_INT(wireline_trace(&again, &w, 1, &err), 0);
    CHECK(again.n_points == p.n_points && !memcmp(again.points, p.points, p.n_points * sizeof *p.points));
    wireline_paths_free(&again);
    CHECK_INT(wireline_trace(&again, &w, 0, &err), 0); /* the outline alone */
    CHECK_INT(again.n_lines, 2);
    wireline_paths_free(&again);
    wireline_paths_free(&p);
    wireline_free(&w);
}

/* Two parts touching at a corner only are one piece of the silhouette (its holes are filled
 * through side-by-side pixels, so its pieces join at corners): one outline round both. */
TEST(parts_touching_at_a_corner_are_one_outline)
{
    static const int rect[2][4] = {{2, 4, 2, 4}, {5, 7, 5, 7}};
    wireline w;
    hand_made(&w, 10, 10, rect, 2, 0, 1, 0);
    err_buf err = {{0}};
    wireline_paths p;
    CHECK_INT(wireline_trace(&p, &w, 1, &err), 0);
    CHECK_INT(p.n_outlines, 1);
    CHECK_NEAR(p.n_lines ? ring_area(&p, &p.lines[0]) : 0, 17.5, 0.5); /* 2 x 9, 6 corners cut, the saddle's cell */
    wireline_paths_free(&p);
    wireline_free(&w);
}

TEST_LIST(TEST_CASE(hand_made_silhouettes_trace_into_their_outlines), TEST_CASE(parts_touching_at_a_corner_are_one_outline),
          TEST_CASE(wireline_lies_on_the_box_edges), TEST_CASE(a_box_that_is_not_the_development_has_no_wireline),
          TEST_CASE(an_open_frame_is_outlined_as_one_silhouette))
