/* test_json_read.c — the JSON reader: the tree, the look-ups and the refusals with their places. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "util/json_read.h"

/* Reads text (its strlen) expecting a refusal containing want, of the given status. */
static void expect_refused(const char *text, size_t n, err_status status, const char *want)
{
    json_doc d;
    err_buf err = {{0}};
    CHECK_INT(json_read(&d, text, n, "t.json", &err), -1);
    CHECK_INT(err.status, status);
    CHECK_STR_CONTAINS(err.msg, want);
    CHECK(d.values == NULL);
}

TEST(tree_and_lookups)
{
    const char *text = "{\"a\": [1, 2.5, -3e2, \"x\\\"y\"],\n \"b\": {\"c\": null, \"c\": true}, \"n\": 9007199254740993}";
    json_doc d;
    err_buf err = {{0}};
    CHECK_INT(json_read(&d, text, strlen(text), "t.json", &err), 0);
    CHECK_INT(d.values[0].kind, JSON_OBJECT);
    uint32_t a = json_member(&d, 0, "a");
    CHECK_INT(d.values[a].kind, JSON_ARRAY);
    uint32_t one = d.values[a].first, two = d.values[one].next, three = d.values[two].next, four = d.values[three].next;
    uint64_t x = 0;
    CHECK(json_whole(&d, one, &x) && x == 1);
    CHECK(!json_whole(&d, two, &x));   /* a fraction */
    CHECK(!json_whole(&d, three, &x)); /* a sign and an exponent */
    CHECK(json_string_is(&d, four, "x\\\"y"));
    CHECK_INT(d.values[four].next, 0);
    uint32_t b = json_member(&d, 0, "b"), c = json_member(&d, b, "c");
    CHECK_INT(d.values[c].kind, JSON_NULL); /* the first of a repeated key */
    CHECK(!json_whole(&d, json_member(&d, 0, "n"), &x)); /* beyond 2^53 */
    CHECK_INT(json_member(&d, 0, "missing"), 0);
    CHECK_INT(json_member(&d, a, "a"), 0); /* an array has no members */
    uint32_t line, column;
    json_line_column(&d, d.values[b].at, &line, &column);
    CHECK_INT(line, 2);
    CHECK_INT(column, 7);
    json_free(&d);
}

TEST(text_ends_at_nul)
{
    static const char text[] = "{\"a\":1}\0garbage";
    json_doc d;
    err_buf err = {{0}};
    CHECK_INT(json_read(&d, text, sizeof text - 1, "t.json", &err), 0);
    json_free(&d);
}

TEST(refusals_with_places)
{
    static const struct { const char *text, *want; } cases[] = {
        {"{\"a\":1,}", "t.json:1:8: an object's member must start with its key"},
        {"[1,\n 2 3]", "t.json:2:4: expected ',' or ']'"},
        {"{\"a\":NaN}", "t.json:1:6: not a JSON value"},
        {"{\"a\":1} x", "t.json:1:9: more text after the JSON value"},
        {"\"abc", "t.json:1:1: a string has no closing quote"},
        {"\"a\\x\"", "t.json:1:3: a bad escape"},
        {"\"\\u12g4\"", "t.json:1:2: a \\u escape without four hexadecimal digits"},
        {"\"a\tb\"", "t.json:1:3: a control character"},
        {"1.", "t.json:1:3: a number's '.' is not followed by a digit"},
        {"1e+", "t.json:1:4: a number's exponent has no digits"},
        {"", "t.json:1:1: the text ends where a value was expected"},
        {"  ", "t.json:1:3: the text ends where a value was expected"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        expect_refused(cases[i].text, strlen(cases[i].text), ERR_INPUT, cases[i].want);
}

TEST(nesting_is_bounded)
{
    char deep[2 * 100000 + 1];
    for (int i = 0; i < 100000; i++) deep[i] = '[', deep[100000 + i] = ']';
    deep[200000] = 0;
    expect_refused(deep, 200000, ERR_LIMIT, "t.json:1:65: arrays and objects nested more than 64 deep");
    /* 64 deep is read */
    json_doc d;
    err_buf err = {{0}};
    CHECK_INT(json_read(&d, deep + 100000 - 64, 128, "t.json", &err), 0);
    CHECK_INT(d.count, 64);
    json_free(&d);
}

TEST_LIST(TEST_CASE(tree_and_lookups), TEST_CASE(text_ends_at_nul), TEST_CASE(refusals_with_places),
          TEST_CASE(nesting_is_bounded))
