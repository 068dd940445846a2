/* test_lsys_read.c — the reader: both dialects, comments, CRLF, arguments in every written form,
 * and the errors (file:line:column) and warnings (lenient mode) for what the language lacks. */
#include "harness.h"

#include "lsys_symbols.h"
#include "lsys_test_util.h"

typedef struct warnings {
    int count;
    char last[512];
} warnings;

static void collect(void *ctx, const char *msg)
{
    warnings *w = ctx;
    w->count++;
    snprintf(w->last, sizeof w->last, "%s", msg);
}

static int read_with(const char *text, int lenient, lsys_system **s, plugin_err *e, warnings *w)
{
    lsys_read_options o = {.lenient = lenient, .warn = collect, .warn_ctx = w};
    return lsys_read(text, strlen(text), "t.ls", &o, s, e);
}

TEST(numeric_dialect_with_comments)
{
    const char *text = "# --- L-System Parser/Mutator --- Lj Lapre ---\r\n"
                       "12\t# recursion\r\n5\r\n30\r\n#\r\n"
                       "c(4)FFS                # the actual tree\r\n"
                       "S=FFR>(60)R\t# six branches\r\n"
                       "R=[Ba]\r\n#B=&B (commented out)\r\n"
                       "@\r\nA=never read\r\n";
    lsys_system *s = NULL;
    plugin_err e = {0};
    warnings w = {0};
    CHECK_INT(read_with(text, 0, &s, &e, &w), LSYS_OK);
    if (!s) return;
    CHECK_INT(s->dialect, LSYS_DIALECT_NUMERIC);
    CHECK_INT(s->recursion, 12);
    CHECK_NEAR(s->angle_deg, 5, 0);
    CHECK_NEAR(s->thickness, 30, 0);
    CHECK_NEAR(s->base_length, 100, 0);
    CHECK_INT(s->axiom_length, 7);
    CHECK(!memcmp(s->axiom, "c(4)FFS", 7));
    CHECK(s->rules['S'].defined && s->rules['S'].length == 9);
    CHECK(s->rules['R'].defined && !s->rules['B'].defined && !s->rules['A'].defined);
    CHECK_INT(s->rules['R'].line, 8);
    lsys_system_free(s);
}

TEST(keyword_dialect)
{
    const char *text = "# Lparser example file\r\n\r\nrecursion 20\t\t\t\r\nangle 20   \r\nthickness 15\r\n"
                       "min_thickness 5\r\nshape 1\r\nswitch_yz 1\r\nno_wait 1\r\n"
                       "color 1     90 138 32\r\ncolor 255 255 0 0\r\n"
                       "axiom T cf H cf(1.5) K    \r\n"
                       "rule b = [&(30)A]   \r\n"
                       "rule H = F^\t\t# duh ...\r\n"
                       "rule 1 = 2\r\n";
    lsys_system *s = NULL;
    plugin_err e = {0};
    warnings w = {0};
    CHECK_INT(read_with(text, 0, &s, &e, &w), LSYS_OK);
    if (!s) {
        fprintf(stderr, "%s\n", e.msg);
        return;
    }
    CHECK_INT(s->dialect, LSYS_DIALECT_KEYWORD);
    CHECK_INT(s->recursion, 20);
    CHECK_NEAR(s->angle_deg, 20, 0);
    CHECK_NEAR(s->thickness, 15, 0);
    CHECK_NEAR(s->min_thickness, 5, 0);
    CHECK_INT(s->shape, 1);
    CHECK_NEAR(s->base_length, 1, 0);
    CHECK(s->colour_given[1] && s->colour_given[255] && !s->colour_given[2]);
    CHECK_NEAR(s->colour_srgb[1][1], 138 / 255.0, 1e-6);
    CHECK_INT(s->axiom_length, 12);
    CHECK(!memcmp(s->axiom, "TcfHcf(1.5)K", 12));
    CHECK(s->rules['b'].length == 8 && !memcmp(s->rules['b'].successor, "[&(30)A]", 8));
    CHECK(s->rules['H'].length == 2 && !memcmp(s->rules['H'].successor, "F^", 2));
    CHECK(s->rules['1'].defined);
    CHECK_INT(w.count, 0);
    lsys_system_free(s);
}

TEST(keyword_defaults)
{
    lsys_system *s = NULL;
    plugin_err e = {0};
    warnings w = {0};
    CHECK_INT(read_with("axiom F\n", 0, &s, &e, &w), LSYS_OK);
    if (!s) return;
    CHECK_INT(s->recursion, 1);
    CHECK_NEAR(s->angle_deg, 45, 0);
    CHECK_NEAR(s->thickness, 100, 0);
    CHECK_NEAR(s->min_thickness, 0, 0);
    CHECK_INT(s->shape, -1);
    lsys_system_free(s);
}

TEST(argument_forms)
{
    /* Integers, decimals, leading dot, negatives, explicit plus, exponent. */
    static const struct {
        const char *text;
        double value;
        size_t length;
    } cases[] = {{"(30)", 30, 4}, {"(15.652)", 15.652, 8}, {"(.95)", 0.95, 5}, {"(-90)", -90, 5},
                 {"(+38)", 38, 5}, {"(-.1)", -0.1, 5}, {"(3.)", 3, 4}, {"(1e2)", 100, 5}, {"( 7 )", 7, 5}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double v = -1;
        size_t n = lsys_arg_group((const unsigned char *)cases[i].text, strlen(cases[i].text), &v);
        CHECK_INT(n, cases[i].length);
        CHECK_NEAR(v, cases[i].value, 1e-12);
    }
    /* Not arguments: empty, letters, unclosed, a bare sign. */
    static const char *const bad[] = {"()", "(a*R)", "(12", "(-)", "(1.2.3)"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        CHECK_INT(lsys_arg_group((const unsigned char *)bad[i], strlen(bad[i]), NULL), 0);
    /* Exactly as strtod reads them. */
    double v = 0;
    lsys_parse_number((const unsigned char *)"15.652", 6, &v);
    CHECK(v == 15.652);
    lsys_parse_number((const unsigned char *)"0.87", 4, &v);
    CHECK(v == 0.87);
}

TEST(unknown_symbol_is_located)
{
    lsys_system *s = NULL;
    plugin_err e = {0};
    warnings w = {0};
    /* higgs-butterfly.ls has a stray ')' in a rule. */
    const char *text = "10\n20\n80\nL\n# wings\nB=+(25)[{-(90)&&fff^^f)}]\n@\n";
    CHECK_INT(read_with(text, 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(e.msg, "t.ls:6:23: unknown symbol ')' in rule 'B'");
    /* The same in lenient mode: dropped, with a warning at the same place. */
    CHECK_INT(read_with(text, 1, &s, &e, &w), LSYS_OK);
    CHECK_INT(w.count, 1);
    CHECK_STR_CONTAINS(w.last, "t.ls:6:23: unknown symbol ')'");
    if (s) CHECK(s->rules['B'].length == 22 && !memcmp(s->rules['B'].successor, "+(25)[{-(90)&&fff^^f}]", 22));
    lsys_system_free(s);
    s = NULL;
    /* A byte that is no symbol, in the keyword dialect: the column counts the original line. */
    CHECK_INT(read_with("axiom F\nrule A =  F * F\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "t.ls:2:13: unknown symbol '*' in rule 'A'");
    CHECK_INT(read_with("axiom F(a*R)\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "t.ls:1:8: '(' in the axiom does not start an argument");
}

TEST(header_and_keyword_errors)
{
    lsys_system *s = NULL;
    plugin_err e = {0};
    warnings w = {0};
    CHECK_INT(read_with("2.5\n30\n10\nA\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "t.ls:1:1: recursion level 2.5 is refused");
    CHECK_INT(read_with("2\nthirty\n10\nA\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "t.ls:2:1: expected the standard angle");
    CHECK_INT(read_with("2\n30\n10\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "ends before the axiom");
    CHECK_INT(read_with("2\n30\n10\nA\nAFF\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "t.ls:5:1: expected a rule written X=successor");
    CHECK_INT(read_with("2\n30\n10\nA\nA=F\nA=FF\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "t.ls:6:1: rule 'A' is given twice (first at line 5)");
    CHECK_INT(read_with("recursion 3\nangel 30\naxiom F\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "t.ls:2:1: unknown keyword 'angel'");
    CHECK_INT(read_with("recursion 3\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "no 'axiom' line");
    CHECK_INT(read_with("color 1 300 0 0\naxiom F\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "t.ls:1:9: colour component 300");
    CHECK_INT(read_with("# only a comment\n\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "no L-system found");
    /* tree6.ls says shape 2: an error, or cylinders in lenient mode. */
    CHECK_INT(read_with("shape 2\naxiom F\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "t.ls:1:7: 'shape 2' is not one of Lparser 2.1's shapes");
    CHECK_INT(read_with("shape 2\naxiom F\n", 1, &s, &e, &w), LSYS_OK);
    if (s) CHECK_INT(s->shape, 1);
    lsys_system_free(s);
    s = NULL;
    CHECK_INT(read_with("mutation 3\naxiom F\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "'mutation 3' is not supported");
}

TEST(arguments_beyond_the_range_of_numbers)
{
    lsys_system *s = NULL;
    plugin_err e = {0};
    warnings w = {0};
    /* 0e400 is zero, as strtod reads it, not 0 times infinity. */
    double v = -1;
    CHECK_INT(lsys_arg_group((const unsigned char *)"(0e400)", 7, &v), 7);
    CHECK(v == 0.0 && !signbit(v));
    CHECK_INT(read_with("axiom c(0e400)F\n", 0, &s, &e, &w), LSYS_OK);
    lsys_system_free(s);
    s = NULL;
    /* A number past the largest double is refused where it stands, in both modes. */
    CHECK_INT(lsys_arg_group((const unsigned char *)"(1e400)", 7, &v), 0);
    CHECK_INT(read_with("axiom F c(1e400)F\n", 0, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(e.msg, "t.ls:1:10: the argument (1e400) in the axiom is beyond the range of numbers");
    CHECK_INT(read_with("2\n30\n10\nA\nA=F-(-2e99999)A\n", 1, &s, &e, &w), LSYS_ERR_SYNTAX);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(e.msg, "t.ls:5:5: the argument (-2e99999) in rule 'A' is beyond the range of numbers");
}

TEST(missing_file_is_an_io_error)
{
    lsys_system *s = NULL;
    plugin_err e = {0};
    CHECK_INT(lsys_read_file("/nonexistent/dir/x.ls", NULL, &s, &e), LSYS_ERR_IO);
    CHECK_STR_CONTAINS(e.msg, "/nonexistent/dir/x.ls: cannot open the L-system file");
}

/* A file that is not an L-system (a password list, an image) is refused without repeating
 * its content in the message. */
TEST(foreign_files_are_not_quoted)
{
    lsys_system *s = NULL;
    plugin_err e = {0};
    warnings w = {0};
    CHECK_INT(read_with("root:x:0:0:root:/root:/bin/bash\ndaemon:x:1:1::/usr/sbin\n", 0, &s, &e, &w),
              LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "t.ls:1:1: this line does not start with a keyword");
    CHECK(!strstr(e.msg, "root") && !strstr(e.msg, "bash"));
    const char gif[] = "GIF89a\x01\x00\x01\x00\x80\x00\x00secret";
    lsys_read_options o = {.warn = collect, .warn_ctx = &w};
    CHECK_INT(lsys_read(gif, sizeof gif - 1, "t.ls", &o, &s, &e), LSYS_ERR_SYNTAX);
    CHECK_STR_CONTAINS(e.msg, "t.ls: not a text file (byte 8 is a NUL)");
    CHECK(!strstr(e.msg, "GIF") && !strstr(e.msg, "secret"));
    CHECK(s == NULL);
}

TEST_LIST(TEST_CASE(numeric_dialect_with_comments), TEST_CASE(keyword_dialect), TEST_CASE(keyword_defaults),
          TEST_CASE(argument_forms), TEST_CASE(unknown_symbol_is_located), TEST_CASE(header_and_keyword_errors),
          TEST_CASE(arguments_beyond_the_range_of_numbers),
          TEST_CASE(missing_file_is_an_io_error), TEST_CASE(foreign_files_are_not_quoted))
