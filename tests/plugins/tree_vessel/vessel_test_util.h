/* vessel_test_util.h — small helpers the tree_vessel tests share: presets by name, polylines
 * from literal points, and a fixed stand-in for the host's random stream. */
#ifndef VESSEL_TEST_UTIL_H
#define VESSEL_TEST_UTIL_H

#include <stdint.h>
#include <stdio.h>

#include "vessel_presets.h"
#include "vessel_structure.h"

static inline vessel_params preset(vessel_preset which)
{
    vessel_params p;
    vessel_preset_get(which, &p);
    return p;
}

/* Replaces a polyline by n (order, value) points. */
static inline void set_line(vessel_polyline *line, const double *xy, uint32_t n)
{
    line->n = n;
    for (uint32_t i = 0; i < n; i++) line->x[i] = xy[2 * i], line->y[i] = xy[2 * i + 1];
}

/* A counter hashed to [0, 1): what the host's stream gives, without the host. */
typedef struct test_stream {
    uint64_t key, counter;
} test_stream;

static inline double test_uniform(void *ctx)
{
    test_stream *s = ctx;
    uint64_t z = s->key + 0x9e3779b97f4a7c15ull * ++s->counter;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return (z >> 11) * (1.0 / 9007199254740992.0);
}

/* Grows p at age and lod into *t; prints the message when it fails. */
static inline int grow(const vessel_params *p, double age, uint32_t lod, vessel_tree *t)
{
    vessel_growth g = {.age = age, .lod = lod};
    plugin_err err = {0};
    int rc = vessel_tree_grow(p, &g, t, &err);
    if (rc) fprintf(stderr, "vessel_tree_grow: %s\n", err.msg);
    return rc;
}

#endif
