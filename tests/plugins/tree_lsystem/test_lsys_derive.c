/* test_lsys_derive.c — derivation: parallel rewriting, `_`, rules on drawing symbols, digits and
 * Latin-1 bytes as rule names, arguments carried as text, and the size guards. */
#include "harness.h"

#include "lsys_test_util.h"

TEST(algae_sequence_of_seed_003)
{
    /* 003 §1: axiom b, a -> ab, b -> a gives b, a, ab, aba, abaab, abaababa. */
    lsys_system *s = test_read("5\n0\n0\nb\na=ab\nb=a\n@\n");
    CHECK(s != NULL);
    if (!s) return;
    static const char *const want[] = {"b", "a", "ab", "aba", "abaab", "abaababa"};
    for (uint32_t k = 0; k <= 5; k++) {
        char *got = test_derive(s, k);
        CHECK(got && !strcmp(got, want[k]));
        if (got && strcmp(got, want[k])) fprintf(stderr, "step %u: got %s, want %s\n", k, got, want[k]);
        free(got);
    }
    lsys_system_free(s);
}

TEST(seed_001_section_2_example)
{
    /* 001 §2: ab with a -> ab, b -> aba gives ababa, then ababaababaab. */
    lsys_system *s = test_read("2\n0\n0\nab\na=ab\nb=aba\n");
    char *one = s ? test_derive(s, 1) : NULL, *two = s ? test_derive(s, 2) : NULL;
    CHECK(one && !strcmp(one, "ababa"));
    CHECK(two && !strcmp(two, "ababaababaab"));
    free(one), free(two);
    lsys_system_free(s);
}

TEST(fig3_strings_of_seed_001)
{
    /* 001 §3: A=FA, F='(2)F'(0.5): step II is '(2)F'(0.5)FA. */
    lsys_system *s = test_read("2\n30\n10\nA\nA=FA\nF='(2)F'(0.5)\n@\n");
    char *one = s ? test_derive(s, 1) : NULL, *two = s ? test_derive(s, 2) : NULL, *three = s ? test_derive(s, 3) : NULL;
    CHECK(one && !strcmp(one, "FA"));
    CHECK(two && !strcmp(two, "'(2)F'(0.5)FA"));
    CHECK(three && !strcmp(three, "'(2)'(2)F'(0.5)'(0.5)'(2)F'(0.5)FA"));
    free(one), free(two), free(three);
    lsys_system_free(s);
}

TEST(empty_successor_and_drawing_symbols_as_rules)
{
    /* `_` deletes; F, f, {, } and ~ may be rewritten (tree.ls: f=z, z=_; flower.ls: ~=_). */
    lsys_system *s = test_read("1\n30\n10\nF{f~z}X\nF=FF\nf=z\nz=_\n{=_\n}=_\n~=_\nX=\n@\n");
    char *got = s ? test_derive(s, 1) : NULL;
    CHECK(got && !strcmp(got, "FFz"));
    free(got);
    lsys_system_free(s);
}

TEST(digits_and_latin1_bytes_name_rules)
{
    /* large-spiral-plant2.ls: 1=2, 2=3, 3=F; cees-3dartist.ls names rules with 0xF2, 0xE4. */
    lsys_system *s = test_read("3\n30\n10\n1\xf2\n1=2\n2=3\n3=F\n\xf2=[\xe4]\n\xe4=c(12)\n@\n");
    char *got = s ? test_derive(s, 3) : NULL;
    CHECK(got && !strcmp(got, "F[c(12)]"));
    free(got);
    lsys_system_free(s);
}

TEST(arguments_are_not_rewritten)
{
    /* A digit rule leaves the digits of an argument alone. */
    lsys_system *s = test_read("1\n30\n10\n1c(12)+(-1.5)\n1=F\n2=G\n@\n");
    char *got = s ? test_derive(s, 1) : NULL;
    CHECK(got && !strcmp(got, "Fc(12)+(-1.5)"));
    free(got);
    lsys_system_free(s);
}

TEST(arguments_travel_as_text)
{
    /* cees-3dartist.ls: R=(10) turns +R into +(10); cees-koch.ls: m(54.7) keeps its argument
     * after whatever m becomes. */
    lsys_system *s = test_read("1\n30\n10\n+RE\nR=(10)\n@\n");
    char *got = s ? test_derive(s, 1) : NULL;
    CHECK(got && !strcmp(got, "+(10)E"));
    free(got);
    lsys_system_free(s);
    s = test_read("1\n30\n10\nm(54.7)\nm=+F-\n@\n");
    got = s ? test_derive(s, 1) : NULL;
    CHECK(got && !strcmp(got, "+F-(54.7)"));
    free(got);
    lsys_system_free(s);
}

TEST(string_limit_is_reported_before_allocation)
{
    lsys_system *s = test_read("40\n30\n10\nA\nA=AA\n@\n");
    CHECK(s != NULL);
    if (!s) return;
    unsigned char *out = NULL;
    size_t n = 0;
    plugin_err e = {0};
    int rc = lsys_derive(s, 40, 1000000, NULL, NULL, &out, &n, &e);
    CHECK_INT(rc, LSYS_ERR_LIMIT);
    CHECK(out == NULL);
    CHECK_STR_CONTAINS(e.msg, "max_string = 1000000");
    CHECK_STR_CONTAINS(e.msg, "step 20 of 40");
    /* Below the limit the same system derives. */
    rc = lsys_derive(s, 19, 1000000, NULL, NULL, &out, &n, &e);
    CHECK_INT(rc, LSYS_OK);
    CHECK_INT(n, 1u << 19);
    free(out);
    lsys_system_free(s);
}

TEST(work_limit_stops_long_steady_derivations)
{
    /* A string that does not grow but is rewritten 1000 times. */
    lsys_system *s = test_read("1000\n30\n10\nABABABABAB\nA=B\nB=A\n@\n");
    unsigned char *out = NULL;
    size_t n = 0;
    plugin_err e = {0};
    int rc = s ? lsys_derive(s, 1000, 100, NULL, NULL, &out, &n, &e) : -99;
    CHECK_INT(rc, LSYS_ERR_LIMIT);
    CHECK_STR_CONTAINS(e.msg, "16 times");
    free(out);
    lsys_system_free(s);
}

static int record_level(void *ctx, uint32_t level, const unsigned char *str, size_t n)
{
    size_t *lengths = ctx;
    lengths[level] = n;
    return 0;
}

TEST(each_level_is_reported)
{
    lsys_system *s = test_read("4\n30\n10\nb\na=ab\nb=a\n");
    size_t lengths[5] = {0};
    unsigned char *out = NULL;
    size_t n = 0;
    plugin_err e = {0};
    CHECK(s && lsys_derive(s, 4, 1000, record_level, lengths, &out, &n, &e) == LSYS_OK);
    /* Fibonacci lengths 1 1 2 3 5. */
    CHECK_INT(lengths[0], 1);
    CHECK_INT(lengths[1], 1);
    CHECK_INT(lengths[2], 2);
    CHECK_INT(lengths[3], 3);
    CHECK_INT(lengths[4], 5);
    free(out);
    lsys_system_free(s);
}

TEST_LIST(TEST_CASE(algae_sequence_of_seed_003), TEST_CASE(seed_001_section_2_example), TEST_CASE(fig3_strings_of_seed_001),
          TEST_CASE(empty_successor_and_drawing_symbols_as_rules), TEST_CASE(digits_and_latin1_bytes_name_rules),
          TEST_CASE(arguments_are_not_rewritten), TEST_CASE(arguments_travel_as_text),
          TEST_CASE(string_limit_is_reported_before_allocation), TEST_CASE(work_limit_stops_long_steady_derivations),
          TEST_CASE(each_level_is_reported))
