/* edit_distance.c — Levenshtein distance over one working row. */
#include "util/edit_distance.h"

#include <stdlib.h>
#include <string.h>

/* Rows up to this many cells live on the stack; longer strings take one malloc'ed row. */
#define EDIT_DISTANCE_STACK_ROW 128

size_t edit_distance(const char *a, const char *b)
{
    if (!a) a = "";
    if (!b) b = "";
    size_t na = strlen(a), nb = strlen(b);
    if (nb > na) {
        const char *t = a;
        a = b, b = t;
        size_t tn = na;
        na = nb, nb = tn;
    }
    /* b is now the shorter string: row[j] is the distance between a's prefix and b[0..j). */
    size_t stack_row[EDIT_DISTANCE_STACK_ROW];
    size_t *row = stack_row;
    if (nb + 1 > EDIT_DISTANCE_STACK_ROW) {
        if (nb + 1 > SIZE_MAX / sizeof *row) return SIZE_MAX;
        row = malloc((nb + 1) * sizeof *row); /* owned here, freed below */
        if (!row) return SIZE_MAX;
    }
    for (size_t j = 0; j <= nb; j++) row[j] = j;
    for (size_t i = 1; i <= na; i++) {
        size_t diagonal = row[0]; /* distance(a[0..i-1), b[0..j-1)) */
        row[0] = i;
        for (size_t j = 1; j <= nb; j++) {
            size_t above = row[j];
            size_t best = diagonal + (a[i - 1] != b[j - 1]);
            if (above + 1 < best) best = above + 1;
            if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
            row[j] = best;
            diagonal = above;
        }
    }
    size_t d = row[nb];
    if (row != stack_row) free(row);
    return d;
}

size_t edit_distance_near_limit(const char *word)
{
    size_t third = word ? strlen(word) / 3 : 0;
    return third > 2 ? third : 2;
}
