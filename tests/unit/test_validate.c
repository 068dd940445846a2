/* test_validate.c — params_validate against a schema with every parameter type: values read,
 * defaults filled, ranges and shapes enforced, messages with line:column; plus yaml_doc's own
 * refusals (limits, duplicate keys) on text in memory. */
#include <string.h>

#include "harness.h"
#include "params/validate.h"
#include "params/yaml_doc.h"

#define F_MIN SYLVA_PARAM_HAS_MIN
#define F_MAX SYLVA_PARAM_HAS_MAX
#define F_MIN_X (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE)
#define F_MAX_X (SYLVA_PARAM_HAS_MAX | SYLVA_PARAM_MAX_EXCLUSIVE)

static const char *const modes[] = {"fast", "fine", "exact", NULL};
static const double tint_default[3] = {0.5, 0.25, 1};
static const double weights_default[2] = {1, 2};
static const double profile_default[4] = {0, 1, 10, 0.5};

static const sylva_param_spec layer_spec[] = {
    {.name = "depth", .type = SYLVA_P_REAL, .flags = F_MIN_X, .def = 1, .min = 0, .help = "d"},
    {.name = "kind", .type = SYLVA_P_STRING, .def_str = "soil", .help = "k"},
};

static const sylva_param_spec spec[] = {
    {.name = "flag", .type = SYLVA_P_BOOL, .def = 1, .help = "a bool"},
    {.name = "count", .type = SYLVA_P_INT, .flags = F_MIN | F_MAX, .def = 4, .min = 1, .max = 10,
     .help = "an int"},
    {.name = "alpha", .type = SYLVA_P_REAL, .flags = F_MIN_X | F_MAX_X, .def = 0.5, .min = -1,
     .max = 1, .help = "a real"},
    {.name = "label", .type = SYLVA_P_STRING, .def_str = "none", .help = "a string"},
    {.name = "mode", .type = SYLVA_P_ENUM, .def_str = "fine", .choices = modes, .help = "an enum"},
    {.name = "texture", .type = SYLVA_P_PATH, .help = "a path"},
    {.name = "tint", .type = SYLVA_P_VEC3, .flags = F_MIN, .min = 0, .def_list = tint_default,
     .def_len = 3, .help = "a vec3"},
    {.name = "weights", .type = SYLVA_P_LIST, .flags = F_MIN, .min = 0, .min_len = 2, .max_len = 4,
     .def_list = weights_default, .def_len = 2, .help = "a list"},
    {.name = "profile", .type = SYLVA_P_POLYLINE, .flags = F_MIN | F_MAX, .min = 0, .max = 1,
     .min_len = 2, .def_list = profile_default, .def_len = 2, .help = "a polyline"},
    {.name = "heights", .type = SYLVA_P_GRID, .help = "a grid"},
    {.name = "top", .type = SYLVA_P_GROUP, .group = layer_spec, .n_group = 2, .help = "a group"},
    {.name = "layers", .type = SYLVA_P_GROUP_LIST, .min_len = 0, .max_len = 3, .group = layer_spec,
     .n_group = 2, .help = "a group list"},
    {.name = "needed", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_REQUIRED, .help = "required"},
};
#define N_SPEC ((uint32_t)(sizeof spec / sizeof spec[0]))

enum {
    FLAG,
    COUNT,
    ALPHA,
    LABEL,
    MODE,
    TEXTURE,
    TINT,
    WEIGHTS,
    PROFILE,
    HEIGHTS,
    TOP,
    LAYERS,
    NEEDED
};

/* Parses text as "t.yaml" and validates its root against spec. Returns params or NULL. */
static const sylva_params *run(arena *a, const char *text, const char *const *host_keys,
                               uint32_t n_host, err_buf *err)
{
    yaml_doc doc;
    err_clear(err);
    if (yaml_doc_parse(a, text, strlen(text), "t.yaml", &doc, err)) return NULL;
    param_scope scope = {"t.yaml", "/scenes/here", "block", host_keys, n_host, 1, 1};
    const sylva_params *p = NULL;
    if (params_validate(a, doc.root, spec, N_SPEC, &scope, &p, err)) return NULL;
    return p;
}

/* Expects validation of text to fail with a message containing want. */
static void expect_error(const char *text, const char *want)
{
    arena *a = arena_new();
    err_buf err;
    const sylva_params *p = run(a, text, NULL, 0, &err);
    CHECK(p == NULL);
    CHECK_STR_CONTAINS(err.msg, want);
    arena_free(a);
}

TEST(validate_every_type)
{
    arena *a = arena_new();
    err_buf err;
    const sylva_params *p = run(a,
                                "flag: no\n"
                                "count: 7\n"
                                "alpha: -0.25\n"
                                "label: 'hello world'\n"
                                "mode: exact\n"
                                "texture: ./tex/bark.png\n"
                                "tint: [1, 2, 3.5]\n"
                                "weights: [0, 1, 2]\n"
                                "profile: [[0, 0.1], [5, 0.2], [5, 0.9], [7, 1]]\n"
                                "heights: [[1, 2, 3], [4, 5, 6]]\n"
                                "top: {depth: 2.5}\n"
                                "layers:\n"
                                "  - {depth: 1, kind: sand}\n"
                                "  - {kind: clay}\n"
                                "needed: 3\n",
                                NULL, 0, &err);
    CHECK(p != NULL);
    if (!p) {
        fprintf(stderr, "%s\n", err.msg);
        arena_free(a);
        return;
    }
    const sylva_value *v = p->values;
    CHECK_INT(p->n, N_SPEC);
    CHECK_STR_CONTAINS(p->file, "t.yaml");
    CHECK_INT(v[FLAG].i, 0);
    CHECK_INT(v[FLAG].is_set, 1);
    CHECK_INT(v[COUNT].i, 7);
    CHECK_NEAR(v[COUNT].r, 7.0, 0);
    CHECK_INT(v[COUNT].line, 2);
    CHECK_INT(v[COUNT].column, 8);
    CHECK_NEAR(v[ALPHA].r, -0.25, 0);
    CHECK(!strcmp(v[LABEL].s, "hello world"));
    CHECK_INT(v[MODE].i, 2);
    CHECK(!strcmp(v[MODE].s, "exact"));
    CHECK(!strcmp(v[TEXTURE].s, "/scenes/here/tex/bark.png"));
    CHECK_INT(v[TINT].len, 3);
    CHECK_NEAR(v[TINT].list[2], 3.5, 0);
    CHECK_INT(v[WEIGHTS].len, 3);
    CHECK_NEAR(v[WEIGHTS].list[2], 2, 0);
    CHECK_INT(v[PROFILE].len, 4);
    CHECK_NEAR(v[PROFILE].list[4], 5, 0);   /* x of point 2: a step at x = 5 */
    CHECK_NEAR(v[PROFILE].list[5], 0.9, 0);
    CHECK_INT(v[HEIGHTS].rows, 2);
    CHECK_INT(v[HEIGHTS].cols, 3);
    CHECK_NEAR(v[HEIGHTS].list[3], 4, 0);    /* row-major: row 1, column 0 */
    CHECK(v[TOP].group != NULL);
    CHECK_NEAR(v[TOP].group->values[0].r, 2.5, 0);
    CHECK(!strcmp(v[TOP].group->values[1].s, "soil")); /* default inside a group */
    CHECK_INT(v[TOP].group->values[1].is_set, 0);
    CHECK_INT(v[LAYERS].len, 2);
    CHECK(!strcmp(v[LAYERS].items[0].values[1].s, "sand"));
    CHECK_NEAR(v[LAYERS].items[1].values[0].r, 1, 0); /* default depth */
    CHECK_INT(v[LAYERS].items[1].values[1].line, 14);
    CHECK_NEAR(v[NEEDED].r, 3, 0);
    /* the plugin.h readers work on what the validator made */
    CHECK_INT(sylva_param_int(p, "count"), 7);
    CHECK(!strcmp(sylva_param_str(p, "mode"), "exact"));
    arena_free(a);
}

TEST(validate_defaults)
{
    arena *a = arena_new();
    err_buf err;
    const sylva_params *p = run(a, "needed: 1\n", NULL, 0, &err);
    CHECK(p != NULL);
    if (!p) {
        arena_free(a);
        return;
    }
    const sylva_value *v = p->values;
    CHECK_INT(v[FLAG].i, 1);
    CHECK_INT(v[FLAG].is_set, 0);
    CHECK_INT(v[FLAG].line, 0);
    CHECK_INT(v[COUNT].i, 4);
    CHECK_NEAR(v[COUNT].r, 4, 0);
    CHECK_NEAR(v[ALPHA].r, 0.5, 0);
    CHECK(!strcmp(v[LABEL].s, "none"));
    CHECK_INT(v[MODE].i, 1);
    CHECK(!strcmp(v[MODE].s, "fine"));
    CHECK(v[TEXTURE].s == NULL);
    CHECK_NEAR(v[TINT].list[1], 0.25, 0);
    CHECK(v[TINT].list != tint_default); /* copied, not borrowed from the schema */
    CHECK_INT(v[WEIGHTS].len, 2);
    CHECK_INT(v[PROFILE].len, 2);
    CHECK_NEAR(v[PROFILE].list[2], 10, 0);
    CHECK_INT(v[HEIGHTS].rows, 0);
    CHECK(v[TOP].group != NULL);
    CHECK_NEAR(v[TOP].group->values[0].r, 1, 0);
    CHECK_INT(v[LAYERS].len, 0);
    arena_free(a);
}

TEST(validate_bool_words)
{
    static const char *const yes[] = {"true", "yes", "True", "YES"};
    static const char *const no[] = {"false", "no", "False", "NO"};
    for (int k = 0; k < 4; k++) {
        char text[64];
        arena *a = arena_new();
        err_buf err;
        snprintf(text, sizeof text, "flag: %s\nneeded: 0\n", yes[k]);
        const sylva_params *p = run(a, text, NULL, 0, &err);
        CHECK(p && p->values[FLAG].i == 1);
        snprintf(text, sizeof text, "flag: %s\nneeded: 0\n", no[k]);
        p = run(a, text, NULL, 0, &err);
        CHECK(p && p->values[FLAG].i == 0);
        arena_free(a);
    }
    expect_error("flag: 1\nneeded: 0\n", "t.yaml:1:7: 'flag' must be true or false, got '1'");
    expect_error("flag: 'true'\nneeded: 0\n",
                 "'flag' must be true or false, got the quoted string");
}

TEST(validate_numbers)
{
    expect_error("count: -3\nneeded: 0\n",
                 "t.yaml:1:8: 'count' must be an integer in [1, 10], got -3");
    expect_error("count: 2.5\nneeded: 0\n",
                 "t.yaml:1:8: 'count' must be an integer in [1, 10], got 2.5");
    expect_error("count: abc\nneeded: 0\n", "t.yaml:1:8: 'count': expected an integer, got 'abc'");
    expect_error("alpha: 1.5\nneeded: 0\n", "t.yaml:1:8: 'alpha' must be in (-1, 1), got 1.5");
    expect_error("alpha: -1\nneeded: 0\n", "'alpha' must be in (-1, 1), got -1");
    expect_error("alpha: abc\nneeded: 0\n", "t.yaml:1:8: 'alpha': expected a number, got 'abc'");
    expect_error("alpha: 0x10\nneeded: 0\n", "'alpha': expected a number, got '0x10'");
    expect_error("alpha: .inf\nneeded: 0\n", "'alpha': expected a finite number, got '.inf'");
    expect_error("needed: 1e400\n",
                 "t.yaml:1:9: 'needed': the number 1e400 is too large to represent");
    expect_error("needed: [1]\n", "'needed': expected a number, got a sequence");
    /* integral reals are integers; 1e1 is 10 */
    arena *a = arena_new();
    err_buf err;
    const sylva_params *p = run(a, "count: 1e1\nalpha: +.5\nneeded: -0\n", NULL, 0, &err);
    CHECK(p != NULL);
    if (p) {
        CHECK_INT(p->values[COUNT].i, 10);
        CHECK_NEAR(p->values[ALPHA].r, 0.5, 0);
        CHECK(!signbit(p->values[NEEDED].r));
    }
    arena_free(a);
}

TEST(validate_enum_and_path)
{
    expect_error(
        "mode: exakt\nneeded: 0\n",
        "t.yaml:1:7: 'mode' must be one of fast, fine, exact; got 'exakt' (did you mean 'exact'?)");
    expect_error("mode: banana\nneeded: 0\n",
                 "'mode' must be one of fast, fine, exact; got 'banana'");
    expect_error("texture: ''\nneeded: 0\n",
                 "t.yaml:1:10: 'texture' must be a file path, got an empty string");
    arena *a = arena_new();
    err_buf err;
    const sylva_params *p = run(a, "texture: /abs/leaf.png\nneeded: 0\n", NULL, 0, &err);
    CHECK(p && !strcmp(p->values[TEXTURE].s, "/abs/leaf.png"));
    p = run(a, "texture: ../up.png\nneeded: 0\n", NULL, 0, &err);
    CHECK(p && !strcmp(p->values[TEXTURE].s, "/scenes/here/../up.png"));
    CHECK(!strcmp(param_resolve_path(a, "/", "x.png"), "/x.png"));
    CHECK(!strcmp(param_resolve_path(a, "/d/", "./././x.png"), "/d/x.png"));
    arena_free(a);
}

TEST(validate_lists)
{
    expect_error("tint: [1, 2]\nneeded: 0\n",
                 "t.yaml:1:7: 'tint' must be a list of 3 numbers [x, y, z], got 2 numbers");
    expect_error("tint: [1, -2, 3]\nneeded: 0\n", "t.yaml:1:11: 'tint'[1] must be >= 0, got -2");
    expect_error("tint: [1, x, 3]\nneeded: 0\n",
                 "t.yaml:1:11: 'tint'[1]: expected a number, got 'x'");
    expect_error("weights: [1]\nneeded: 0\n",
                 "'weights' must be a list of 2 to 4 numbers, got 1 number");
    expect_error("weights: [1, 2, 3, 4, 5]\nneeded: 0\n", "got 5 numbers");
    expect_error("weights: 3\nneeded: 0\n", "'weights' must be a list of 2 to 4 numbers, got '3'");
}

TEST(validate_polyline)
{
    expect_error(
        "profile: [[0, 0.5], [2, 0.5], [1, 0.5]]\nneeded: 0\n",
        "t.yaml:1:32: 'profile'[2]: x must not decrease along the polyline, got 1 after 2");
    expect_error("profile: [[0, 0.5], [1, 1.5]]\nneeded: 0\n",
                 "t.yaml:1:25: 'profile'[1] y must be in [0, 1], got 1.5");
    expect_error("profile: [[0, 0.5]]\nneeded: 0\n",
                 "t.yaml:1:10: 'profile' needs at least 2 points [x, y], got 1");
    expect_error("profile: [[0, 0.5], [1]]\nneeded: 0\n",
                 "t.yaml:1:21: 'profile'[1] must be a point [x, y], got 1 number");
    expect_error("profile: [0, 1]\nneeded: 0\n", "'profile'[0] must be a point [x, y], got '0'");
}

TEST(validate_grid)
{
    expect_error("heights: [[1, 2], [3]]\nneeded: 0\n",
                 "t.yaml:1:19: 'heights'[1] has 1 numbers but row 0 has 2; every row must have the "
                 "same length");
    expect_error("heights: []\nneeded: 0\n",
                 "t.yaml:1:10: 'heights' needs at least one row of numbers");
    expect_error("heights: [[]]\nneeded: 0\n", "t.yaml:1:11: 'heights'[0] is an empty row");
    expect_error("heights: [[1, 2], [3, b]]\nneeded: 0\n",
                 "t.yaml:1:23: 'heights'[1][1]: expected a number, got 'b'");
    expect_error("heights: [1, 2]\nneeded: 0\n",
                 "'heights'[0] must be a row of numbers [a, b, ...], got '1'");
}

TEST(validate_groups)
{
    expect_error("top: {depht: 1}\nneeded: 0\n",
                 "t.yaml:1:7: unknown key 'depht' in 'block.top'; did you mean 'depth'?");
    expect_error("top: {depth: 0}\nneeded: 0\n", "t.yaml:1:14: 'depth' must be > 0, got 0");
    expect_error("top: 5\nneeded: 0\n",
                 "t.yaml:1:6: 'block.top' must be a mapping (key: value), got '5'");
    expect_error("layers: [{kind: a}, 3]\nneeded: 0\n",
                 "t.yaml:1:21: 'block.layers[1]' must be a mapping (key: value), got '3'");
    expect_error("layers: [{}, {}, {}, {}]\nneeded: 0\n",
                 "'layers' must be a list of 0 to 3 mappings, got 4 items");
    expect_error("layers:\n  - {kind: a}\n  - {knd: b}\nneeded: 0\n",
                 "t.yaml:3:6: unknown key 'knd' in 'block.layers[1]'; did you mean 'kind'?");
}

TEST(validate_keys)
{
    expect_error("count: 1\n", "t.yaml:1:1: missing required key 'needed' in 'block'");
    expect_error("needed: 1\ncuont: 2\n",
                 "t.yaml:2:1: unknown key 'cuont' in 'block'; did you mean 'count'?");
    expect_error(
        "needed: 1\nzebra: 2\n",
        "t.yaml:2:1: unknown key 'zebra' in 'block'; valid keys are flag, count, alpha, label, "
        "mode, texture, tint, weights, profile, heights, top, layers, needed");
    expect_error("- 1\n", "t.yaml:1:1: 'block' must be a mapping (key: value), got a sequence");

    /* host keys are skipped, and offered as suggestions */
    static const char *const host[] = {"plugin", "material"};
    arena *a = arena_new();
    err_buf err;
    const sylva_params *p = run(a, "plugin: x\nneeded: 1\nmaterial: {any: thing}\n", host, 2, &err);
    CHECK(p != NULL);
    CHECK(p && p->line == 1 && p->column == 1);
    p = run(a, "plugn: x\nneeded: 1\n", host, 2, &err);
    CHECK(p == NULL);
    CHECK_STR_CONTAINS(err.msg,
                       "t.yaml:1:1: unknown key 'plugn' in 'block'; did you mean 'plugin'?");
    arena_free(a);

    /* an absent block is all defaults, located where the caller says */
    a = arena_new();
    param_scope scope = {"t.yaml", "/d", "block", NULL, 0, 7, 3};
    const sylva_params *q;
    CHECK(params_validate(a, NULL, layer_spec, 2, &scope, &q, &err) == 0);
    CHECK(q->line == 7 && q->column == 3);
    CHECK_NEAR(q->values[0].r, 1, 0);
    CHECK(params_validate(a, NULL, spec, N_SPEC, &scope, &q, &err) == -1);
    CHECK_STR_CONTAINS(err.msg, "t.yaml:7:3: missing required key 'needed' in 'block'");
    arena_free(a);
}

TEST(validate_range_phrase)
{
    char buf[96];
    sylva_param_spec s = {.name = "x", .type = SYLVA_P_REAL, .flags = F_MIN, .min = 1};
    param_range_phrase(&s, buf, sizeof buf);
    CHECK(!strcmp(buf, " >= 1"));
    s.flags = F_MAX_X, s.max = 2.5;
    param_range_phrase(&s, buf, sizeof buf);
    CHECK(!strcmp(buf, " < 2.5"));
    s.flags = F_MIN_X | F_MAX, s.min = 0, s.max = 9007199254740992.0;
    param_range_phrase(&s, buf, sizeof buf);
    CHECK(!strcmp(buf, " in (0, 9007199254740992]"));
    s.flags = 0;
    param_range_phrase(&s, buf, sizeof buf);
    CHECK(!strcmp(buf, ""));
}

TEST(nearest_name)
{
    static const char *const names[] = {"width", "height", "spp", NULL, "seed"};
    CHECK(!strcmp(param_nearest_name("widht", names, 5), "width"));
    CHECK(!strcmp(param_nearest_name("sed", names, 5), "seed"));
    CHECK(param_nearest_name("banana", names, 5) == NULL);
    CHECK(param_nearest_name("x", names, 5) == NULL);
}

/* yaml_doc on text in memory */
static void expect_yaml_error(const char *text, size_t len, const char *want)
{
    arena *a = arena_new();
    err_buf err;
    yaml_doc doc;
    err_clear(&err);
    CHECK(yaml_doc_parse(a, text, len, "y.yaml", &doc, &err) == -1);
    CHECK_STR_CONTAINS(err.msg, want);
    arena_free(a);
}

TEST(yaml_doc_tree)
{
    const char *text = "a: 1\nb:\n  - x\n  - 'q'\n  - {c: d}\n\"e\": |\n  block\n";
    arena *a = arena_new();
    err_buf err;
    yaml_doc doc;
    CHECK(yaml_doc_parse(a, text, strlen(text), "y.yaml", &doc, &err) == 0);
    const ynode *r = doc.root;
    CHECK(r && r->kind == YNODE_MAPPING && r->n_pairs == 3);
    if (r && r->n_pairs == 3) {
        CHECK(!strcmp(r->pairs[0].key, "a") && r->pairs[0].key_line == 1 &&
              r->pairs[0].key_column == 1);
        CHECK(r->pairs[0].value->line == 1 && r->pairs[0].value->column == 4);
        const ynode *b = ynode_get(r, "b");
        CHECK(b->kind == YNODE_SEQUENCE && b->n_items == 3);
        CHECK(b->items[0]->quoted == 0 && b->items[1]->quoted == 1);
        CHECK(b->items[2]->kind == YNODE_MAPPING && b->items[2]->line == 5 &&
              b->items[2]->column == 5);
        CHECK(!strcmp(ynode_get(b->items[2], "c")->text, "d"));
        const ynode *e = ynode_get(r, "e");
        CHECK(e && e->quoted == 1 && !strcmp(e->text, "block\n"));
        CHECK(r->pairs[2].key_line == 6 && r->pairs[2].key_column == 1);
    }
    CHECK(ynode_get(r, "zzz") == NULL);
    CHECK(ynode_get(NULL, "a") == NULL);
    arena_free(a);
}

TEST(yaml_doc_refusals)
{
    expect_yaml_error("a: 1\nb: 2\na: 3\n", 13,
                      "y.yaml:3:1: duplicate key 'a'; it was first given at line 1, column 1");
    expect_yaml_error("{b: 1, a: 2, b: 3, a: 4}", 24, "y.yaml:1:14: duplicate key 'b'");
    expect_yaml_error("? [1, 2]\n: x\n", 12,
                      "y.yaml:1:3: a mapping key must be a name (a scalar), not a sequence");
    expect_yaml_error("a: *x\n", 6, "y.yaml:1:4: YAML aliases ('*x') are not supported");
    expect_yaml_error("a: \"nul\\0here\"\n", 15, "y.yaml:1:4: a scalar contains a NUL character");
    expect_yaml_error("a: \xff\xfe\n", 6, "(YAML syntax)");
    expect_yaml_error("a: [1, 2\n", 9, "y.yaml:2:1: did not find expected ',' or ']'");

    /* depth: 64 nested collections are fine, 65 are not */
    char deep[200];
    size_t n = 0;
    for (int k = 0; k < 63; k++) deep[n++] = '[';
    for (int k = 0; k < 63; k++) deep[n++] = ']';
    deep[n] = '\0';
    arena *a = arena_new();
    err_buf err;
    yaml_doc doc;
    CHECK(yaml_doc_parse(a, deep, n, "y.yaml", &doc, &err) == 0); /* 63 + nothing else */
    char deeper[300];
    n = 0;
    deeper[n++] = 'a', deeper[n++] = ':', deeper[n++] = ' ';
    for (int k = 0; k < 64; k++) deeper[n++] = '[';
    for (int k = 0; k < 64; k++) deeper[n++] = ']';
    deeper[n] = '\0';
    expect_yaml_error(deeper, n, "y.yaml:1:67: nesting is deeper than the limit of 64 levels");

    /* scalar length */
    size_t big = YAML_DOC_MAX_SCALAR_BYTES + 10;
    char *text = malloc(big + 8);
    memcpy(text, "a: ", 3);
    memset(text + 3, 'x', big);
    text[3 + big] = '\n';
    expect_yaml_error(
        text, big + 4,
        "y.yaml:1:4: a scalar of 65546 bytes is longer than the limit of 65536 bytes");
    free(text);

    /* an empty or comment-only text has no root */
    CHECK(yaml_doc_parse(a, "# nothing\n", 10, "y.yaml", &doc, &err) == 0);
    CHECK(doc.root == NULL);
    arena_free(a);
}

TEST_LIST(TEST_CASE(validate_every_type), TEST_CASE(validate_defaults),
          TEST_CASE(validate_bool_words), TEST_CASE(validate_numbers),
          TEST_CASE(validate_enum_and_path), TEST_CASE(validate_lists),
          TEST_CASE(validate_polyline), TEST_CASE(validate_grid), TEST_CASE(validate_groups),
          TEST_CASE(validate_keys), TEST_CASE(validate_range_phrase), TEST_CASE(nearest_name),
          TEST_CASE(yaml_doc_tree), TEST_CASE(yaml_doc_refusals))
