/* test_name_index.c — the name index: finds what was added, keeps the first number of a name,
 * tells absent names (and near misses, prefixes, the empty name) from present ones, and keeps
 * every name through the table's growth. */
#include <stdio.h>
#include <stdlib.h>

#include "harness.h"
#include "util/name_index.h"

TEST(empty_index_finds_nothing)
{
    name_index ix = {0};
    CHECK_INT(name_index_find(&ix, "oak"), -1);
    CHECK_INT(name_index_find(&ix, ""), -1);
    name_index_free(&ix);
    name_index_free(&ix); /* a freed index is zeroed, and freeing it again is harmless */
}

TEST(first_number_of_a_name_is_kept)
{
    name_index ix = {0};
    CHECK_INT(name_index_add(&ix, "oak", 3), 3);
    CHECK_INT(name_index_add(&ix, "beech", 0), 0);
    CHECK_INT(name_index_add(&ix, "oak", 9), 3);
    CHECK_INT(ix.count, 2);
    CHECK_INT(name_index_find(&ix, "oak"), 3);
    CHECK_INT(name_index_find(&ix, "beech"), 0);
    CHECK_INT(name_index_find(&ix, "oa"), -1);
    CHECK_INT(name_index_find(&ix, "oak "), -1);
    CHECK_INT(name_index_find(&ix, "Oak"), -1);
    CHECK_INT(name_index_find(&ix, ""), -1);
    CHECK_INT(name_index_add(&ix, "", 7), 7);
    CHECK_INT(name_index_find(&ix, ""), 7);
    name_index_free(&ix);
    CHECK_INT(name_index_find(&ix, "oak"), -1);
}

/* 200,000 names (the table doubles many times on the way): each is found with its own number;
 * names that differ in one character only are told apart. */
TEST(many_names_survive_growth)
{
    enum { N = 200000 };
    char *text = malloc((size_t)N * 16);
    CHECK(text != NULL);
    if (!text) return;
    name_index ix = {0};
    for (uint32_t i = 0; i < N; i++) {
        snprintf(text + (size_t)i * 16, 16, "species%u", i);
        CHECK_INT(name_index_add(&ix, text + (size_t)i * 16, i), i);
    }
    CHECK_INT(ix.count, N);
    CHECK(ix.cap >= 2 * ix.count);
    int wrong = 0;
    for (uint32_t i = 0; i < N; i++) {
        char name[16];
        snprintf(name, sizeof name, "species%u", i); /* a different pointer, the same text */
        wrong += name_index_find(&ix, name) != i;
    }
    CHECK_INT(wrong, 0);
    CHECK_INT(name_index_find(&ix, "species200000"), -1);
    CHECK_INT(name_index_find(&ix, "species"), -1);
    CHECK_INT(name_index_add(&ix, "species123", 5), 123);
    name_index_free(&ix);
    free(text);
}

TEST_LIST(TEST_CASE(empty_index_finds_nothing), TEST_CASE(first_number_of_a_name_is_kept),
          TEST_CASE(many_names_survive_growth))
