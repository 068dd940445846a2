/* fuzz_weber_penn.c — libFuzzer target for tree_weber_penn's species reader: each input is read
 * as a species file (Arbaro's <arbaro> or Helios' <helios>, chosen by its root element). A
 * refusal must come with a sentence placed in the file; an accepted file must hold at least one
 * species whose every value the tree uses is finite and inside its row's range. A crash, a
 * sanitizer report, a leak or a hang is a finding. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
    wp_species_list_free(&list);
    return 0;
}
