/* wireline.c — the development's outline and visible edges from a rendered frame's layers. */
#include "render/wireline.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The part of the development a pixel shows: its object (index + 1), its new plant (beyond the
 * objects: n_objects + instance index + 1), or 0. */
static uint32_t development_at(const film *f, const scene *s, size_t k)
{
    uint32_t id = f->object_id[k], in = f->instance_id[k];
    if (id) return id <= s->n_objects && s->objects[id - 1].development ? id : 0;
    return in && in <= s->n_instances && s->instances[in - 1].development ? s->n_objects + in : 0;
}

/* The point pixel (x, y) shows, relative to the camera, from the depth layer; its distance. */
static double pixel_point(const film *f, const camera *c, uint32_t x, uint32_t y, double p[3])
{
    vec3 d = camera_direction(c, x + 0.5f, y + 0.5f);
    double along = c->cylindrical ? sqrt(fmax(0.0, 1.0 - (double)v3_dot(d, c->up) * v3_dot(d, c->up)))
                                  : (double)v3_dot(d, c->forward);
    double t = f->depth[(size_t)y * f->width + x] / fmax(along, 1e-9);
    p[0] = t * d.x, p[1] = t * d.y, p[2] = t * d.z;
    return t;
}

/* What pixel (x, y) (a development pixel) is with respect to its neighbour (nx, ny). */
static wireline_kind edge_between(const film *f, const scene *s, const camera *c, uint32_t x, uint32_t y,
                                  uint32_t nx, uint32_t ny, double cos_crease)
{
    size_t k = (size_t)y * f->width + x, n = (size_t)ny * f->width + nx;
    uint32_t a = development_at(f, s, k), b = development_at(f, s, n);
    if (!b) return WIRELINE_EDGE; /* a gap of the structure, inside its silhouette */
    if (a != b) return WIRELINE_EDGE;
    const float *na = &f->normal[3 * k], *nb = &f->normal[3 * n];
    double dot = (double)na[0] * nb[0] + (double)na[1] * nb[1] + (double)na[2] * nb[2];
    if (dot < cos_crease) return WIRELINE_EDGE;
    double pk[3], pn[3];
    double t = pixel_point(f, c, x, y, pk);
    pixel_point(f, c, nx, ny, pn);
    double off = fabs(na[0] * (pn[0] - pk[0]) + na[1] * (pn[1] - pk[1]) + na[2] * (pn[2] - pk[2]));
    return off > WIRELINE_DEPTH_STEP * t ? WIRELINE_EDGE : WIRELINE_NONE;
}

/* The development's silhouette: its pixels, gaps of up to 2 * WIRELINE_CLOSING pixels closed
 * (a dilation then an erosion by a square of that radius), and every hole filled (what the
 * background cannot reach through 4-neighbours from the picture's edge or from something nearer
 * the camera than all of the development). out holds 1 inside. */
static int silhouette(const film *f, const scene *s, uint8_t *out, err_buf *err)
{
    uint32_t w = f->width, h = f->height;
    size_t n = (size_t)w * h;
    uint8_t *grown = calloc(n ? n : 1, 1); /* owned here */
    uint32_t *queue = malloc((n ? n : 1) * sizeof *queue); /* owned here */
    if (!grown || !queue) {
        free(grown), free(queue);
        return err_nomem(err, "out of memory for a %ux%u silhouette", w, h);
    }
    const int r = WIRELINE_CLOSING;
    for (size_t k = 0; k < n; k++) out[k] = development_at(f, s, k) != 0;
    for (uint32_t y = 0; y < h; y++) /* dilation */
        for (uint32_t x = 0; x < w; x++) {
            if (!out[(size_t)y * w + x]) continue;
            for (int dy = -r; dy <= r; dy++)
                for (int dx = -r; dx <= r; dx++) {
                    int64_t xx = (int64_t)x + dx, yy = (int64_t)y + dy;
                    if (xx >= 0 && yy >= 0 && xx < w && yy < h) grown[(size_t)yy * w + (size_t)xx] = 1;
                }
        }
    for (uint32_t y = 0; y < h; y++) /* erosion, the picture's edge counting as inside */
        for (uint32_t x = 0; x < w; x++) {
            size_t k = (size_t)y * w + x;
            int all = grown[k];
            for (int dy = -r; dy <= r && all; dy++)
                for (int dx = -r; dx <= r && all; dx++) {
                    int64_t xx = (int64_t)x + dx, yy = (int64_t)y + dy;
                    if (xx >= 0 && yy >= 0 && xx < w && yy < h) all = grown[(size_t)yy * w + (size_t)xx];
                }
            out[k] |= (uint8_t)all;
        }
    /* the background reached from the edge, or from what stands nearer than any of the
     * development (a tree in front is no hole of it): 2 in grown; the rest is inside */
    float nearest = INFINITY;
    for (size_t k = 0; k < n; k++)
        if (development_at(f, s, k) && f->depth[k] < nearest) nearest = f->depth[k];
    size_t head = 0, tail = 0;
    memset(grown, 0, n);
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            size_t k = (size_t)y * w + x;
            int edge = x == 0 || y == 0 || x + 1 == w || y + 1 == h;
            if (!out[k] && (edge || f->depth[k] < nearest)) grown[k] = 2, queue[tail++] = (uint32_t)k;
        }
    while (head < tail) {
        size_t k = queue[head++];
        uint32_t x = (uint32_t)(k % w), y = (uint32_t)(k / w);
        size_t next[4];
        int m = 0;
        if (x > 0) next[m++] = k - 1;
        if (x + 1 < w) next[m++] = k + 1;
        if (y > 0) next[m++] = k - w;
        if (y + 1 < h) next[m++] = k + w;
        for (int i = 0; i < m; i++)
            if (!out[next[i]] && !grown[next[i]]) grown[next[i]] = 2, queue[tail++] = (uint32_t)next[i];
    }
    for (size_t k = 0; k < n; k++) out[k] = grown[k] != 2;
    free(grown), free(queue);
    return 0;
}

/* What pixel (x, y) of the silhouette is: the outline when a 4-neighbour is outside it; else, on
 * the development, an inner edge where a neighbour differs (another part, a crease, a step in
 * depth, or a gap of the structure seen through). */
static wireline_kind pixel_kind(const film *f, const scene *s, const camera *c, const uint8_t *inside, uint32_t x,
                                uint32_t y, double cos_crease)
{
    uint32_t nbr[4][2];
    int m = 0;
    if (x > 0) nbr[m][0] = x - 1, nbr[m++][1] = y;
    if (x + 1 < f->width) nbr[m][0] = x + 1, nbr[m++][1] = y;
    if (y > 0) nbr[m][0] = x, nbr[m++][1] = y - 1;
    if (y + 1 < f->height) nbr[m][0] = x, nbr[m++][1] = y + 1;
    for (int i = 0; i < m; i++)
        if (!inside[(size_t)nbr[i][1] * f->width + nbr[i][0]]) return WIRELINE_OUTLINE;
    if (!development_at(f, s, (size_t)y * f->width + x)) return WIRELINE_NONE;
    wireline_kind kind = WIRELINE_NONE;
    for (int i = 0; i < m && kind == WIRELINE_NONE; i++)
        kind = edge_between(f, s, c, x, y, nbr[i][0], nbr[i][1], cos_crease);
    return kind;
}

int wireline_find(wireline *w, const film *f, const scene *s, const camera *c, err_buf *err)
{
    memset(w, 0, sizeof *w);
    size_t n = (size_t)f->width * f->height;
    w->edge = calloc(n ? n : 1, 1);
    uint8_t *inside = w->inside = calloc(n ? n : 1, 1); /* the silhouette, owned by w */
    if (!w->edge || !inside) {
        wireline_free(w);
        return err_nomem(err, "out of memory for a %ux%u wireline", f->width, f->height);
    }
    if (silhouette(f, s, inside, err)) {
        wireline_free(w);
        return -1;
    }
    w->width = f->width, w->height = f->height;
    double cos_crease = cos(WIRELINE_CREASE_DEG * M_PI / 180.0);
    for (uint32_t y = 0; y < f->height; y++)
        for (uint32_t x = 0; x < f->width; x++) {
            size_t k = (size_t)y * f->width + x;
            if (!inside[k]) continue;
            wireline_kind kind = pixel_kind(f, s, c, inside, x, y, cos_crease);
            w->edge[k] = (uint8_t)kind;
            w->outline += kind == WIRELINE_OUTLINE, w->inner += kind == WIRELINE_EDGE;
        }
    return 0;
}

void wireline_free(wireline *w)
{
    free(w->edge);
    free(w->inside);
    memset(w, 0, sizeof *w);
}

void wireline_draw(const wireline *w, uint8_t *rgb, const uint8_t outline_rgb[3], const uint8_t edge_rgb[3])
{
    for (size_t k = 0; k < (size_t)w->width * w->height; k++) {
        if (w->edge[k] == WIRELINE_NONE || (w->edge[k] == WIRELINE_EDGE && !edge_rgb)) continue;
        const uint8_t *c = w->edge[k] == WIRELINE_OUTLINE ? outline_rgb : edge_rgb;
        memcpy(&rgb[3 * k], c, 3);
    }
}
