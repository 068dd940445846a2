/* lsys_test_util.h — helpers shared by the tree_lsystem tests: reading an inline L-system,
 * deriving it, and a turtle sink that records segments and polygons. */
#ifndef LSYS_TEST_UTIL_H
#define LSYS_TEST_UTIL_H

#include <stdlib.h>
#include <string.h>

#include "lsys_derive.h"
#include "lsys_system.h"
#include "lsys_turtle.h"

/* Reads `text` strictly; NULL (and the message on stderr) when it fails. */
static inline lsys_system *test_read(const char *text)
{
    lsys_system *s = NULL;
    plugin_err e = {0};
    if (lsys_read(text, strlen(text), "test", NULL, &s, &e)) {
        fprintf(stderr, "read failed: %s\n", e.msg);
        return NULL;
    }
    return s;
}

/* The string after `steps` derivation steps, NUL-terminated (caller frees); NULL on failure. */
static inline char *test_derive(const lsys_system *s, uint32_t steps)
{
    unsigned char *out = NULL;
    size_t n = 0;
    plugin_err e = {0};
    if (lsys_derive(s, steps, 1u << 24, NULL, NULL, &out, &n, &e)) {
        fprintf(stderr, "derive failed: %s\n", e.msg);
        return NULL;
    }
    char *z = malloc(n + 1);
    if (z) {
        memcpy(z, out, n);
        z[n] = '\0';
    }
    free(out);
    return z;
}

/* A sink that records what the turtle draws. */
#define TEST_MAX_ITEMS 4096
typedef struct test_record {
    uint32_t n_seg;
    double p0[TEST_MAX_ITEMS][3], p1[TEST_MAX_ITEMS][3], radius[TEST_MAX_ITEMS];
    int32_t seg_colour[TEST_MAX_ITEMS];
    lsys_frame frame[TEST_MAX_ITEMS];
    uint32_t n_poly;
    uint32_t poly_n[TEST_MAX_ITEMS];
    double poly_v[TEST_MAX_ITEMS][8][3];
    int32_t poly_colour[TEST_MAX_ITEMS];
    uint32_t n_joint_end;
} test_record;

static inline int test_on_segment(void *ctx, const lsys_segment *s)
{
    test_record *r = ctx;
    if (r->n_seg < TEST_MAX_ITEMS) {
        memcpy(r->p0[r->n_seg], s->p0, sizeof s->p0);
        memcpy(r->p1[r->n_seg], s->p1, sizeof s->p1);
        r->radius[r->n_seg] = s->radius;
        r->seg_colour[r->n_seg] = s->colour;
        r->frame[r->n_seg] = *s->frame;
        r->n_seg++;
    }
    return 0;
}

static inline int test_on_polygon(void *ctx, const double *v, uint32_t n, int32_t colour)
{
    test_record *r = ctx;
    if (r->n_poly < TEST_MAX_ITEMS) {
        r->poly_n[r->n_poly] = n;
        for (uint32_t i = 0; i < n && i < 8; i++) memcpy(r->poly_v[r->n_poly][i], v + 3 * i, 3 * sizeof *v);
        r->poly_colour[r->n_poly] = colour;
        r->n_poly++;
    }
    return 0;
}

/* A fixed sequence for `~`: a linear congruential generator. */
static inline double test_random(void *ctx)
{
    uint64_t *s = ctx;
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

static inline lsys_turtle_config test_config(double angle, double thickness, uint64_t *rng_state)
{
    return (lsys_turtle_config){.angle_deg = angle, .thickness = thickness, .base_length = 1.0, .colour = 2,
                                .max_segments = 1000000, .max_polygons = 1000000, .max_polygon_vertices = 4096,
                                .max_depth = 1024, .tube_corners = 8, .random = test_random,
                                .random_ctx = rng_state};
}

/* Interprets `str` into `rec` (zeroed first); returns the status. */
static inline int test_turtle(const char *str, const lsys_turtle_config *cfg, test_record *rec, lsys_turtle_stats *st,
                              plugin_err *e)
{
    memset(rec, 0, sizeof *rec);
    lsys_sink sink = {.ctx = rec, .segment = test_on_segment, .polygon = test_on_polygon};
    return lsys_interpret((const unsigned char *)str, strlen(str), cfg, &sink, 1, st, e);
}

#endif
