/* fuzz_weber_penn.c — libFuzzer target for tree_weber_penn's species reader and model: each input
 * is read as a species file (Arbaro's <arbaro> or Helios' <helios>, chosen by its root element).
 * A refusal must come with a sentence placed in the file; an accepted file must hold at least one
 * species whose every value the tree uses is finite and inside its row's range. Its first species
 * is then grown (seed 13, small limits): a refusal must come with a sentence and leave the model
 * empty; a tree must keep the limits, index only its own points and have finite ones. A crash, a
 * sanitizer report, a leak or a hang is a finding. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wp_model.h"
#include "wp_species_read.h"

static void fail(const char *what, const char *detail)
{
    fprintf(stderr, "fuzz_weber_penn: %s%s%s\n", what, detail ? ": " : "", detail ? detail : "");
    abort();
}

/* Every numeric value of p that Arbaro reads is finite and within its row's range. */
static void check_species(wp_params *p)
{
    for (size_t row = 0; row < wp_param_count; row++) {
        const wp_param_def *d = &wp_param_table[row];
        for (int l = 0; d->type != WP_TEXT && l < (d->per_level ? WP_LEVELS : 1); l++) {
            if (!wp_param_used(d, p->levels, l)) continue;
            const void *slot = wp_param_slot(d, p, l);
            double v = d->type == WP_INT ? *(const int *)slot : *(const double *)slot;
            if (!isfinite(v) || v < d->min || v > d->max) fail("a value out of its range accepted", d->name);
        }
    }
    if (!memchr(p->species, '\0', sizeof p->species)) fail("a species name without its end", NULL);
}

#define FUZZ_MAX_TRIANGLES 20000
#define FUZZ_MAX_LEAVES 4000

/* Grows p and checks the model or the refusal. */
static void check_growth(const wp_params *p)
{
    wp_model m;
    plugin_err err = { 0 };
    int rc = wp_model_grow(p, 13, FUZZ_MAX_TRIANGLES, FUZZ_MAX_LEAVES, &m, &err);
    if (rc) {
        if (!err.msg[0]) fail("a tree refused without a sentence", NULL);
        if (m.vertex || m.triangle || m.leaf || m.n_vertices || m.n_leaves) fail("a refused tree kept its parts", err.msg);
        return;
    }
    if (m.n_triangles > FUZZ_MAX_TRIANGLES || m.n_leaves > FUZZ_MAX_LEAVES) fail("a tree past its limits", NULL);
    for (size_t i = 0; i < m.n_triangles; i++)
        for (int c = 0; c < 3; c++)
            if (m.triangle[i][c] >= m.n_vertices) fail("a triangle past the points", NULL);
    for (size_t i = 0; i < m.n_vertices; i++)
        if (!isfinite(m.vertex[i][0] + m.vertex[i][1] + m.vertex[i][2])) fail("a point not finite", NULL);
    if (!isfinite(m.height)) fail("a height not finite", NULL);
    wp_model_release(&m);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    wp_species_list list;
    plugin_err err = { 0 };
    int rc = wp_species_read_buffer("fuzz.xml", (const char *)data, size, &list, &err);
    if (rc) {
        if (!err.msg[0]) fail("a refusal without a sentence", NULL);
        if (strncmp(err.msg, "fuzz.xml:", 9) != 0) fail("a refusal without its place", err.msg);
        if (list.count || list.items) fail("a refusal that kept species", err.msg);
        return 0;
    }
    if (list.count == 0) fail("a file accepted without species", NULL);
    for (size_t i = 0; i < list.count; i++) check_species(&list.items[i]);
    check_growth(&list.items[0]);
    wp_species_list_free(&list);
    return 0;
}
