/* test_edit_distance.c — Levenshtein distances and the "near" limit. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "util/edit_distance.h"

TEST(identical_and_empty)
{
    CHECK_INT(edit_distance("terrain", "terrain"), 0);
    CHECK_INT(edit_distance("", ""), 0);
    CHECK_INT(edit_distance("", "abc"), 3);
    CHECK_INT(edit_distance("abcd", ""), 4);
    CHECK_INT(edit_distance(NULL, "ab"), 2);
    CHECK_INT(edit_distance("ab", NULL), 2);
}

TEST(single_edits)
{
    CHECK_INT(edit_distance("terain", "terrain"), 1);  /* insertion */
    CHECK_INT(edit_distance("terrrain", "terrain"), 1); /* deletion */
    CHECK_INT(edit_distance("terrein", "terrain"), 1); /* substitution */
    CHECK_INT(edit_distance("Terrain", "terrain"), 1); /* case counts */
}

TEST(classic_pairs)
{
    CHECK_INT(edit_distance("kitten", "sitting"), 3);
    CHECK_INT(edit_distance("flaw", "lawn"), 2);
    CHECK_INT(edit_distance("sunday", "saturday"), 3);
    CHECK_INT(edit_distance("abc", "cba"), 2);
}

TEST(symmetric)
{
    const char *w[] = {"oak", "birch", "spruce", "fbm_terrain", "", "x"};
    for (size_t i = 0; i < 6; i++)
        for (size_t j = 0; j < 6; j++)
            CHECK_INT(edit_distance(w[i], w[j]), edit_distance(w[j], w[i]));
}

TEST(long_strings_use_heap_row)
{
    size_t n = 300;
    char *a = malloc(n + 1), *b = malloc(n + 1);
    CHECK(a && b);
    if (!a || !b) {
        free(a), free(b);
        return;
    }
    memset(a, 'a', n), a[n] = '\0';
    memcpy(b, a, n + 1);
    b[10] = 'b', b[200] = 'c';
    CHECK_INT(edit_distance(a, b), 2);
    b[n - 1] = '\0';
    CHECK_INT(edit_distance(a, b), 3);
    free(a), free(b);
}

TEST(near_limit)
{
    CHECK_INT(edit_distance_near_limit("oak"), 2);
    CHECK_INT(edit_distance_near_limit(""), 2);
    CHECK_INT(edit_distance_near_limit(NULL), 2);
    CHECK_INT(edit_distance_near_limit("example_terrain"), 5);
}

TEST_LIST(TEST_CASE(identical_and_empty), TEST_CASE(single_edits), TEST_CASE(classic_pairs),
          TEST_CASE(symmetric), TEST_CASE(long_strings_use_heap_row), TEST_CASE(near_limit))
