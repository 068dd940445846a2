/* edit_distance.h — how far apart two names are, for "did you mean ...?" suggestions.
 *
 * The distance is Levenshtein's: the fewest single-byte insertions, deletions and substitutions
 * that turn one string into the other. Comparison is byte-wise and case-sensitive.
 */
#ifndef SYLVA_EDIT_DISTANCE_H
#define SYLVA_EDIT_DISTANCE_H

#include <stddef.h>
#include <stdint.h>

/* The distance between a and b (NULL counts as ""). Returns SIZE_MAX when the working row for
 * a long string cannot be allocated, which callers treat as "not near". */
size_t edit_distance(const char *a, const char *b);

/* The largest distance at which a candidate still counts as a likely misspelling of `word`:
 * a third of its length, but at least 2. */
size_t edit_distance_near_limit(const char *word);

#endif
