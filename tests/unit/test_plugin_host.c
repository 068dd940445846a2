/* test_plugin_host.c — the plugin registry against the modules in tests/plugins (built into
 * SYLVA_TEST_PLUGIN_DIR), and plugin_schema_check / plugin_schema_print on static tables. */
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "harness.h"
#include "work_dir.h"
#include "plugin/plugin_host.h"
#include "plugin/plugin_manifest.h"

#define PLUGIN_DIR SYLVA_TEST_PLUGIN_DIR

/* The problems whose file ends in "/<module>"; the last one's message in *msg. */
static int problems_for(const plugin_registry *reg, const char *module, const char **msg)
{
    int n = 0;
    size_t ml = strlen(module);
    *msg = NULL;
    for (uint32_t i = 0; i < plugin_registry_problem_count(reg); i++) {
        const plugin_problem *p = plugin_registry_problem_at(reg, i);
        size_t fl = strlen(p->file);
        if (fl > ml && p->file[fl - ml - 1] == '/' && !strcmp(p->file + fl - ml, module)) {
            n++;
            *msg = p->message;
        }
    }
    return n;
}

static int listed_from(const plugin_registry *reg, const char *module)
{
    int n = 0;
    for (uint32_t i = 0; i < plugin_registry_count(reg); i++)
        if (strstr(plugin_registry_at(reg, i)->file, module)) n++;
    return n;
}

/* The test modules, every one opened (as `sylva plugins` does). */
static plugin_registry *open_test_plugins(void)
{
    err_buf err;
    err_clear(&err);
    plugin_registry *reg = plugin_registry_open_path(PLUGIN_DIR, &err);
    CHECK(reg != NULL);
    if (reg) CHECK_INT(plugin_registry_load_all(reg, &err), 0);
    if (!reg) fprintf(stderr, "open_path: %s\n", err.msg);
    return reg;
}

/* --------------------------------------------------------------------------------------------
 * The registry on the test modules
 */

TEST(example_is_listed_with_schema)
{
    plugin_registry *reg = open_test_plugins();
    if (!reg) return;
    err_buf err;
    const loaded_plugin *lp =
        plugin_registry_find(reg, "example_terrain", SYLVA_KIND_TERRAIN, &err);
    CHECK(lp != NULL);
    if (lp) {
        CHECK_STR_CONTAINS(lp->file, "/example_terrain.so");
        CHECK(lp->file[0] == '/');
        CHECK_INT(lp->desc->kind, SYLVA_KIND_TERRAIN);
        CHECK_INT(lp->desc->abi_major, SYLVA_ABI_MAJOR);
        CHECK_STR_CONTAINS(lp->desc->version, "1.0");
        CHECK_STR_CONTAINS(lp->desc->summary, "Gaussian hills");
        CHECK_INT(lp->desc->n_params, 4);
        if (lp->desc->n_params == 4) {
            const char *names[] = {"nx", "ny", "node_spacing", "amplitude"};
            for (int k = 0; k < 4; k++) CHECK(!strcmp(lp->desc->params[k].name, names[k]));
            CHECK_NEAR(lp->desc->params[0].def, 65, 0);
            CHECK_STR_CONTAINS(lp->desc->params[3].unit, "m");
        }
        CHECK(plugin_schema_check(lp->desc->params, lp->desc->n_params, &err) == 0);
        CHECK_INT(lp->desc->size, sizeof(sylva_plugin));
    }
    CHECK_INT(listed_from(reg, "/example_terrain.so"), 1);
    CHECK_INT(problems_for(reg, "example_terrain.so", &(const char *){0}), 0);
    plugin_registry_free(reg);
}

TEST(failing_operations_still_load)
{
    plugin_registry *reg = open_test_plugins();
    if (!reg) return;
    err_buf err;
    const char *msg;
    const loaded_plugin *c = plugin_registry_find(reg, "broken_create", SYLVA_KIND_TERRAIN, &err);
    const loaded_plugin *g = plugin_registry_find(reg, "broken_generate", SYLVA_KIND_TERRAIN, &err);
    CHECK(c != NULL);
    CHECK(g != NULL);
    if (c) CHECK(c->desc->create && c->desc->generate && c->desc->destroy);
    if (g) CHECK_INT(g->desc->n_params, 1);
    CHECK_INT(problems_for(reg, "broken_create.so", &msg), 0);
    CHECK_INT(problems_for(reg, "broken_generate.so", &msg), 0);
    plugin_registry_free(reg);
}

typedef struct broken_case {
    const char *module;
    const char *fragments[4];
} broken_case;

TEST(each_broken_module_gives_one_problem)
{
    static const broken_case cases[] = {
        {"broken_abi.so",
         {"sylva_plugin_get(0)", "built against sylva plugin ABI 99.0, this host speaks 1.7; "
                                 "rebuild the plugin"}},
        {"broken_manifest.so",
         {"not opened: its manifest ", "broken_manifest.sylva-plugin says plugin "
          "'broken_manifest' is built against sylva plugin ABI 2.0, this host speaks 1.7"}},
        {"broken_noentry.so", {"no entry point [sylva_plugin_get] in shared library [/",
                               "broken_noentry.so]"}},
        {"broken_schema.so",
         {"sylva_plugin_get(0)", "plugin 'broken_schema'", "parameter 'amplitude'",
          "the default 5 m is outside the range [0, 1] m"}},
        {"broken_size.so", {"sylva_plugin_get(0)", "param_spec_size is", "sylva_param_spec is"}},
        {"broken_null.so", {"sylva_plugin_get(0)", "the plugin name NULL is not valid"}},
        {"broken_endless.so",
         {"sylva_plugin_get", "must return NULL past its last descriptor"}},
    };
    plugin_registry *reg = open_test_plugins();
    if (!reg) return;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *msg = NULL;
        int n = problems_for(reg, cases[i].module, &msg);
        if (n != 1) fprintf(stderr, "module %s:\n", cases[i].module);
        CHECK_INT(n, 1);
        CHECK_STR_CONTAINS(msg, cases[i].module); /* names the file */
        for (int k = 0; k < 4 && cases[i].fragments[k]; k++)
            CHECK_STR_CONTAINS(msg, cases[i].fragments[k]);
        CHECK_INT(listed_from(reg, cases[i].module), 0);
    }
    /* the size message gives both sizes */
    const char *msg;
    if (problems_for(reg, "broken_size.so", &msg) == 1) {
        char want[128];
        snprintf(want, sizeof want, "param_spec_size is %zu bytes, but this host's "
                 "sylva_param_spec is %zu bytes", sizeof(sylva_param_spec) - sizeof(double),
                 sizeof(sylva_param_spec));
        CHECK_STR_CONTAINS(msg, want);
    }
    plugin_registry_free(reg);
}

TEST(descriptor_rules_one_problem_each)
{
    static const struct {
        unsigned index;
        const char *fragment;
    } cases[] = {
        {1, "unknown kind 7"},
        {2, "the operation create is NULL"},
        {3, "species_section \"Ecology\" is not a valid section name"},
        {4, "a terrain plugin has no species section"},
        {5, "plugin 'mixed_ecology': the module already declares a plugin of this name"},
        {6, "the summary is more than one line"},
        {7, "declares size 8, too small to hold its ABI version"},
        {8, "but sylva plugin ABI 1.7 defines"},
        {9, "parameter 'spacing' takes a key the host keeps for itself"},
        {10, "species_section \"shape\" is a key the host keeps for itself"},
    };
    plugin_registry *reg = open_test_plugins();
    if (!reg) return;
    const char *last;
    CHECK_INT(problems_for(reg, "mixed_descriptors.so", &last), 10);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char symbol[64];
        snprintf(symbol, sizeof symbol, "sylva_plugin_get(%u)", cases[i].index);
        int found = 0;
        for (uint32_t p = 0; p < plugin_registry_problem_count(reg); p++) {
            const char *m = plugin_registry_problem_at(reg, p)->message;
            if (strstr(m, "mixed_descriptors.so") && strstr(m, symbol)) {
                found++;
                CHECK_STR_CONTAINS(m, cases[i].fragment);
            }
        }
        if (found != 1) fprintf(stderr, "descriptor %u:\n", cases[i].index);
        CHECK_INT(found, 1);
    }
    err_buf err;
    const loaded_plugin *eco = plugin_registry_find(reg, "mixed_ecology", SYLVA_KIND_ECOLOGY, &err);
    CHECK(eco != NULL);
    if (eco) {
        CHECK_STR_CONTAINS(eco->desc->species_section, "ecology");
        CHECK_INT(eco->desc->n_species_params, 2);
    }
    /* a newer minor with a longer descriptor is accepted; the host reads only what it knows */
    const loaded_plugin *future = plugin_registry_find(reg, "mixed_future", 0, &err);
    CHECK(future != NULL);
    if (future) {
        CHECK_INT(future->desc->abi_minor, SYLVA_ABI_MINOR + 5);
        CHECK_INT(future->desc->size, sizeof(sylva_plugin));
    }
    CHECK_INT(listed_from(reg, "/mixed_descriptors.so"), 2);
    plugin_registry_free(reg);
}

TEST(problems_in_file_order)
{
    plugin_registry *a = open_test_plugins(), *b = open_test_plugins();
    if (!a || !b) {
        plugin_registry_free(a), plugin_registry_free(b);
        return;
    }
    CHECK_INT(plugin_registry_problem_count(a), plugin_registry_problem_count(b));
    CHECK_INT(plugin_registry_count(a), plugin_registry_count(b));
    for (uint32_t i = 0; i < plugin_registry_problem_count(a); i++) {
        CHECK(!strcmp(plugin_registry_problem_at(a, i)->message,
                      plugin_registry_problem_at(b, i)->message));
        if (i) CHECK(strcmp(plugin_registry_problem_at(a, i - 1)->file,
                            plugin_registry_problem_at(a, i)->file) <= 0);
    }
    for (uint32_t i = 1; i < plugin_registry_count(a); i++)
        CHECK(strcmp(plugin_registry_at(a, i - 1)->file, plugin_registry_at(a, i)->file) <= 0);
    plugin_registry_free(a);
    plugin_registry_free(b);
}

TEST(find_refused_plugin_says_why)
{
    plugin_registry *reg = open_test_plugins();
    if (!reg) return;
    err_buf err;
    err_clear(&err);
    CHECK(plugin_registry_find(reg, "broken_schema", SYLVA_KIND_TERRAIN, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "plugin 'broken_schema' was found but cannot be used: ");
    CHECK_STR_CONTAINS(err.msg, "parameter 'amplitude'");
    /* refused before its name could be read: found by its module's file name */
    err_clear(&err);
    CHECK(plugin_registry_find(reg, "broken_abi", 0, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "plugin 'broken_abi' was found but cannot be used: ");
    CHECK_STR_CONTAINS(err.msg, "built against sylva plugin ABI 99.0");
    plugin_registry_free(reg);
}

TEST(find_wrong_kind)
{
    plugin_registry *reg = open_test_plugins();
    if (!reg) return;
    err_buf err;
    err_clear(&err);
    CHECK(plugin_registry_find(reg, "example_terrain", SYLVA_KIND_TREE, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "plugin 'example_terrain' is a terrain plugin, not a tree plugin");
    CHECK_STR_CONTAINS(err.msg, "no tree plugin was found in " PLUGIN_DIR);
    err_clear(&err);
    CHECK(plugin_registry_find(reg, "example_terrain", SYLVA_KIND_ECOLOGY, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "not an ecology plugin; the ecology plugins are: mixed_ecology");
    CHECK(plugin_registry_find(reg, "example_terrain", 0, &err) != NULL);
    plugin_registry_free(reg);
}

TEST(find_unknown_suggests_nearest)
{
    plugin_registry *reg = open_test_plugins();
    if (!reg) return;
    err_buf err;
    err_clear(&err);
    CHECK(plugin_registry_find(reg, "exampel_terrain", SYLVA_KIND_TERRAIN, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "no terrain plugin called 'exampel_terrain'");
    CHECK_STR_CONTAINS(err.msg, "(did you mean 'example_terrain'?)");
    CHECK_STR_CONTAINS(err.msg, "the terrain plugins are: ");
    CHECK_STR_CONTAINS(err.msg, "example_terrain");
    CHECK_STR_CONTAINS(err.msg, "came up while loading plugins (`sylva plugins` lists them)");
    /* nothing near: no suggestion, but the list */
    err_clear(&err);
    CHECK(plugin_registry_find(reg, "zzzzzzzz", SYLVA_KIND_TERRAIN, &err) == NULL);
    CHECK(strstr(err.msg, "did you mean") == NULL);
    CHECK_STR_CONTAINS(err.msg, "broken_create");
    /* the suggestion stays within the kind asked for */
    err_clear(&err);
    CHECK(plugin_registry_find(reg, "example_terrain2", SYLVA_KIND_ECOLOGY, &err) == NULL);
    CHECK(strstr(err.msg, "did you mean 'example_terrain'") == NULL);
    err_clear(&err);
    CHECK(plugin_registry_find(reg, NULL, 0, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "no plugin name given");
    plugin_registry_free(reg);
}

TEST(missing_folders_are_fine)
{
    err_buf err;
    plugin_registry *reg = plugin_registry_open_path("/nonexistent/sylva/plugins::", &err);
    CHECK(reg != NULL);
    CHECK_INT(plugin_registry_count(reg), 0);
    CHECK_INT(plugin_registry_problem_count(reg), 0);
    CHECK_INT(plugin_registry_folder_count(reg), 1);
    err_clear(&err);
    CHECK(plugin_registry_find(reg, "example_terrain", SYLVA_KIND_TERRAIN, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "no terrain plugin was found in /nonexistent/sylva/plugins");
    plugin_registry_free(reg);

    reg = plugin_registry_open_path("/nonexistent/sylva/plugins:" PLUGIN_DIR ":" PLUGIN_DIR, &err);
    CHECK(reg != NULL);
    if (!reg) return;
    CHECK_INT(plugin_registry_folder_count(reg), 2); /* the repeated folder counts once */
    CHECK_STR_CONTAINS(plugin_registry_folder_at(reg, 1), PLUGIN_DIR);
    CHECK(plugin_registry_find(reg, "example_terrain", SYLVA_KIND_TERRAIN, &err) != NULL);
    const char *msg;
    CHECK_INT(problems_for(reg, "example_terrain.so", &msg), 0);
    plugin_registry_free(reg);

    /* a file where a folder should be is a problem, not a failure */
    reg = plugin_registry_open_path(SYLVA_TEST_DATA_DIR "/harness.h", &err);
    CHECK(reg != NULL);
    CHECK_INT(plugin_registry_problem_count(reg), 1);
    if (plugin_registry_problem_count(reg) == 1)
        CHECK_STR_CONTAINS(plugin_registry_problem_at(reg, 0)->message, "is not a folder");
    plugin_registry_free(reg);
    plugin_registry_free(NULL);
}

TEST(add_file_tells_no_library_from_cannot_load)
{
    err_buf err;
    plugin_registry *reg = plugin_registry_open_path("", &err);
    CHECK(reg != NULL);
    if (!reg) return;
    err_clear(&err);
    CHECK_INT(plugin_registry_add_file(reg, PLUGIN_DIR "/no_such_plugin.so", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "no_such_plugin.so: no shared library there: No such file");
    err_clear(&err);
    CHECK_INT(plugin_registry_add_file(reg, SYLVA_TEST_DATA_DIR "/harness.h", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "harness.h: cannot load shared library: ");
    err_clear(&err);
    CHECK_INT(plugin_registry_add_file(reg, PLUGIN_DIR "/broken_noentry.so", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "no entry point [sylva_plugin_get] in shared library [");
    CHECK_INT(plugin_registry_problem_count(reg), 3);
    CHECK_INT(plugin_registry_count(reg), 0);

    err_clear(&err);
    CHECK_INT(plugin_registry_add_file(reg, PLUGIN_DIR "/example_terrain.so", &err), 0);
    CHECK_INT(plugin_registry_count(reg), 1);
    /* the same plugin again: ignored, with a notice naming both files */
    CHECK_INT(plugin_registry_add_file(reg, PLUGIN_DIR "/example_terrain.so", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "plugin 'example_terrain' is ignored");
    CHECK_STR_CONTAINS(err.msg, "earlier in the search path, already provides it");
    CHECK_INT(plugin_registry_count(reg), 1);
    CHECK_INT(plugin_registry_add_file(reg, NULL, &err), -1);
    plugin_registry_free(reg);
}

/* Copies a file byte for byte; 0 or -1. */
static int copy_file(const char *from, const char *to)
{
    int in = open(from, O_RDONLY), out = open(to, O_WRONLY | O_CREAT | O_TRUNC, 0755), rc = 0;
    char buf[65536];
    ssize_t n;
    if (in < 0 || out < 0) rc = -1;
    while (rc == 0 && (n = read(in, buf, sizeof buf)) > 0)
        if (write(out, buf, (size_t)n) != n) rc = -1;
    if (in >= 0) close(in);
    if (out >= 0 && close(out)) rc = -1;
    return rc;
}

TEST(earlier_folder_shadows_later)
{
    char dir[1200];
    snprintf(dir, sizeof dir, "%s", work_path("shadow"));
    CHECK(mkdir(dir, 0700) == 0);
    char copy[1300];
    snprintf(copy, sizeof copy, "%s/example_terrain.so", dir);
    CHECK_INT(copy_file(PLUGIN_DIR "/example_terrain.so", copy), 0);
    char path[1024];
    snprintf(path, sizeof path, "%s:%s", dir, PLUGIN_DIR);
    err_buf err;
    plugin_registry *reg = plugin_registry_open_path(path, &err);
    CHECK(reg != NULL);
    if (reg) {
        const loaded_plugin *lp = plugin_registry_find(reg, "example_terrain", 0, &err);
        CHECK(lp != NULL);
        if (lp) CHECK_STR_CONTAINS(lp->file, dir);
        CHECK_INT(plugin_registry_load_all(reg, &err), 0); /* the shadowed one is opened too */
        const char *msg = NULL;
        int n = 0;
        for (uint32_t i = 0; i < plugin_registry_problem_count(reg); i++) {
            const plugin_problem *p = plugin_registry_problem_at(reg, i);
            if (strstr(p->file, PLUGIN_DIR "/example_terrain.so")) n++, msg = p->message;
        }
        CHECK_INT(n, 1);
        CHECK_STR_CONTAINS(msg, "plugin 'example_terrain' is ignored");
        CHECK_STR_CONTAINS(msg, dir);
        plugin_registry_free(reg);
    }
    unlink(copy);
    rmdir(dir);
}

TEST(default_search_path_reads_environment)
{
    const char *old = getenv("SYLVA_PLUGIN_PATH");
    char *saved = old ? strdup(old) : NULL;
    setenv("SYLVA_PLUGIN_PATH", PLUGIN_DIR, 1);
    err_buf err;
    plugin_registry *reg = plugin_registry_open(&err);
    CHECK(reg != NULL);
    if (reg) {
        CHECK(plugin_registry_folder_count(reg) >= 2);
        CHECK_STR_CONTAINS(plugin_registry_folder_at(reg, 0), PLUGIN_DIR);
        int has_build = 0;
        for (uint32_t i = 0; i < plugin_registry_folder_count(reg); i++)
            if (!strcmp(plugin_registry_folder_at(reg, i), SYLVA_PLUGIN_BUILD_DIR)) has_build = 1;
        CHECK(has_build);
        const loaded_plugin *lp = plugin_registry_find(reg, "example_terrain", 0, &err);
        CHECK(lp != NULL);
        if (lp) CHECK_STR_CONTAINS(lp->file, PLUGIN_DIR);
        plugin_registry_free(reg);
    }
    if (saved) setenv("SYLVA_PLUGIN_PATH", saved, 1);
    else unsetenv("SYLVA_PLUGIN_PATH");
    free(saved);
}

TEST(names_and_kinds)
{
    CHECK(plugin_name_is_valid("a"));
    CHECK(plugin_name_is_valid("example_terrain2"));
    CHECK(!plugin_name_is_valid(NULL));
    CHECK(!plugin_name_is_valid(""));
    CHECK(!plugin_name_is_valid("_a"));
    CHECK(!plugin_name_is_valid("2a"));
    CHECK(!plugin_name_is_valid("a-b"));
    CHECK(!plugin_name_is_valid("aB"));
    char longname[PLUGIN_NAME_MAX + 2];
    memset(longname, 'a', sizeof longname);
    longname[PLUGIN_NAME_MAX] = '\0';
    CHECK(plugin_name_is_valid(longname));
    longname[PLUGIN_NAME_MAX] = 'a', longname[PLUGIN_NAME_MAX + 1] = '\0';
    CHECK(!plugin_name_is_valid(longname));
    CHECK_STR_CONTAINS(plugin_kind_name(SYLVA_KIND_TERRAIN), "terrain");
    CHECK_STR_CONTAINS(plugin_kind_name(SYLVA_KIND_TREE), "tree");
    CHECK_STR_CONTAINS(plugin_kind_name(SYLVA_KIND_ECOLOGY), "ecology");
    CHECK_STR_CONTAINS(plugin_kind_name((sylva_kind)0), "unknown");
    CHECK_STR_CONTAINS(plugin_param_type_name(SYLVA_P_GROUP_LIST), "group list");
    CHECK_STR_CONTAINS(plugin_param_type_name(SYLVA_P_REAL), "real");
    CHECK_STR_CONTAINS(plugin_param_type_name((sylva_ptype)0), "unknown");
    CHECK_STR_CONTAINS(plugin_param_type_name((sylva_ptype)13), "unknown");
}

/* --------------------------------------------------------------------------------------------
 * Schema checks on static tables
 */

#define H .help = "Help."
#define RANGE(lo, hi) .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .min = (lo), .max = (hi)

static const double two[] = {1.0, 2.0};
static const double three[] = {1.0, 2.0, 3.0};
static const double not_finite[] = {1.0, NAN};
static const double steps[] = {0.0, 0.0, 1.0, 0.5, 1.0, 1.0, 2.0, 1.0}; /* equal x: a step */
static const double backwards[] = {0.0, 0.0, 2.0, 1.0, 1.0, 1.0};
static const double rising[] = {0.0, 0.0, 1.0, 1.0};
static const char *const ab[] = {"a", "b", NULL};
static const char *const none[] = {NULL};
static const char *const with_empty[] = {"a", "", NULL};
static const char *const twice[] = {"a", "b", "a", NULL};
static const sylva_param_spec member[] = {{.name = "height", .type = SYLVA_P_REAL, H}};
static const sylva_param_spec bad_member[] = {
    {.name = "thickness", .type = SYLVA_P_REAL, RANGE(0, 10), .def = -1, .unit = "m", H}};
static const sylva_param_spec bad_member_name[] = {{.name = "Thickness", .type = SYLVA_P_REAL, H}};

/* Every type, valid, including REQUIRED entries whose defaults would be invalid if read. */
static const sylva_param_spec valid_all[] = {
    {.name = "enabled", .type = SYLVA_P_BOOL, .def = 1, .help = "Whether it is on."},
    {.name = "count", .type = SYLVA_P_INT, RANGE(1, 100), .def = 10, .help = "How many."},
    {.name = "height", .type = SYLVA_P_REAL,
     .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_HAS_MAX |
              SYLVA_PARAM_MAX_EXCLUSIVE,
     .min = 0, .max = 50, .def = 49.5, .unit = "m", .help = "How high."},
    {.name = "label", .type = SYLVA_P_STRING, .def_str = "hill", .help = "A label."},
    {.name = "mode", .type = SYLVA_P_ENUM, .choices = ab, .def_str = "b", .help = "The mode."},
    {.name = "map", .type = SYLVA_P_PATH, .help = "A file."},
    {.name = "offset", .type = SYLVA_P_VEC3, RANGE(0, 3), .def_list = three, .def_len = 3,
     .unit = "m", .help = "Offset."},
    {.name = "weights", .type = SYLVA_P_LIST, .min_len = 2, .max_len = 4, .def_list = two,
     .def_len = 2, .help = "Weights."},
    {.name = "profile", .type = SYLVA_P_POLYLINE, RANGE(0, 1), .def_list = steps, .def_len = 4,
     .help = "Profile."},
    {.name = "heights", .type = SYLVA_P_GRID, .help = "Heights."},
    {.name = "layer", .type = SYLVA_P_GROUP, .group = member, .n_group = 1, .help = "One layer."},
    {.name = "layers", .type = SYLVA_P_GROUP_LIST, .group = member, .n_group = 1, .max_len = 8,
     .help = "Layers."},
    {.name = "seed_depth", .type = SYLVA_P_REAL,
     .flags = SYLVA_PARAM_REQUIRED | SYLVA_PARAM_HAS_MAX, .max = 1, .def = 5,
     .help = "Required: its default is never read."},
    {.name = "kind", .type = SYLVA_P_ENUM, .flags = SYLVA_PARAM_REQUIRED, .choices = ab,
     .help = "Required enum without a default."},
    {.name = "points", .type = SYLVA_P_LIST, .flags = SYLVA_PARAM_REQUIRED, .min_len = 2,
     .help = "Required list longer than its (empty) default."},
    {.name = "zones", .type = SYLVA_P_GROUP_LIST, .flags = SYLVA_PARAM_REQUIRED, .min_len = 1,
     .group = member, .n_group = 1, .help = "Required group list."},
};

TEST(schema_valid_tables_pass)
{
    err_buf err;
    err_clear(&err);
    int rc = plugin_schema_check(valid_all, sizeof valid_all / sizeof valid_all[0], &err);
    if (rc) fprintf(stderr, "unexpected: %s\n", err.msg);
    CHECK_INT(rc, 0);
    CHECK_INT(plugin_schema_check(NULL, 0, &err), 0);
}

typedef struct schema_case {
    sylva_param_spec spec;
    const char *fragment;
} schema_case;

static const schema_case schema_cases[] = {
    /* names */
    {{.type = SYLVA_P_REAL, H}, "parameter at entry 0 has no name (NULL)"},
    {{.name = "Height", .type = SYLVA_P_REAL, H}, "parameter name \"Height\" (entry 0) is not"},
    {{.name = "2d", .type = SYLVA_P_REAL, H}, "is not a valid name"},
    {{.name = "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa",
      .type = SYLVA_P_REAL, H},
     "at most 63 bytes"},
    /* type, help, flags */
    {{.name = "a", .type = (sylva_ptype)99, H}, "parameter 'a': unknown type 99"},
    {{.name = "a", .type = SYLVA_P_REAL}, "parameter 'a': no help sentence"},
    {{.name = "a", .type = SYLVA_P_REAL, .help = ""}, "no help sentence"},
    {{.name = "a", .type = SYLVA_P_REAL, .flags = 0x40, H}, "unknown flag bits 0x40"},
    {{.name = "a", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_MIN_EXCLUSIVE, H},
     "SYLVA_PARAM_MIN_EXCLUSIVE without SYLVA_PARAM_HAS_MIN"},
    {{.name = "a", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_MAX_EXCLUSIVE, H},
     "SYLVA_PARAM_MAX_EXCLUSIVE without SYLVA_PARAM_HAS_MAX"},
    /* fields the type does not read */
    {{.name = "a", .type = SYLVA_P_BOOL, .flags = SYLVA_PARAM_HAS_MIN, H},
     "type bool takes no range"},
    {{.name = "a", .type = SYLVA_P_STRING, .flags = SYLVA_PARAM_HAS_MAX, .max = 1, H},
     "type string takes no range"},
    {{.name = "a", .type = SYLVA_P_STRING, .def = 1, H},
     "type string does not read def (1); give the default in def_str"},
    {{.name = "a", .type = SYLVA_P_LIST, .def = 1, H}, "give the default in def_list/def_len"},
    {{.name = "a", .type = SYLVA_P_REAL, .def_str = "1", H}, "type real does not read def_str"},
    {{.name = "a", .type = SYLVA_P_INT, .def_list = two, .def_len = 2, H},
     "type int does not read def_list/def_len"},
    {{.name = "a", .type = SYLVA_P_GRID, .def_list = two, .def_len = 2, H},
     "type grid does not read def_list/def_len"},
    {{.name = "a", .type = SYLVA_P_LIST, .def_len = 2, H}, "def_len is 2 but def_list is NULL"},
    {{.name = "a", .type = SYLVA_P_LIST, .def_list = two, H}, "def_list is set but def_len is 0"},
    {{.name = "a", .type = SYLVA_P_REAL, .min_len = 1, H}, "type real takes no min_len/max_len"},
    {{.name = "a", .type = SYLVA_P_STRING, .choices = ab, H}, "type string takes no choices"},
    {{.name = "a", .type = SYLVA_P_INT, .group = member, .n_group = 1, H},
     "type int takes no group"},
    /* ranges */
    {{.name = "a", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN, .min = NAN, H},
     "min is not a number"},
    {{.name = "a", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MAX, .max = NAN, H},
     "max is not a number"},
    {{.name = "a", .type = SYLVA_P_REAL, RANGE(2, 1), .def = 1.5, H},
     "the range is empty: min 2, max 1"},
    {{.name = "a", .type = SYLVA_P_REAL,
      .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX | SYLVA_PARAM_MIN_EXCLUSIVE, .min = 1,
      .max = 1, .def = 1, H},
     "the range is empty: min 1, max 1"},
    {{.name = "a", .type = SYLVA_P_LIST, .min_len = 3, .max_len = 2, .flags = SYLVA_PARAM_REQUIRED,
      H},
     "min_len 3 is above max_len 2"},
    /* number defaults */
    {{.name = "a", .type = SYLVA_P_BOOL, .def = 2, H}, "must be 0 (false) or 1 (true), not 2"},
    {{.name = "a", .type = SYLVA_P_INT, .def = 2.5, H}, "an int's default must be a whole number"},
    {{.name = "a", .type = SYLVA_P_REAL, .def = INFINITY, H}, "the default is not a finite number"},
    {{.name = "a", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MAX, .max = 1, .def = 5,
      .unit = "m", H},
     "parameter 'a': the default 5 m is outside the range <= 1 m"},
    {{.name = "a", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE,
      .min = 0, .def = 0, H},
     "the default 0 is outside the range > 0"},
    {{.name = "a", .type = SYLVA_P_INT, RANGE(1, 10), .def = 0, H},
     "the default 0 is outside the range [1, 10]"},
    /* enums */
    {{.name = "a", .type = SYLVA_P_ENUM, H}, "an enum needs at least one choice"},
    {{.name = "a", .type = SYLVA_P_ENUM, .choices = none, H}, "an enum needs at least one choice"},
    {{.name = "a", .type = SYLVA_P_ENUM, .choices = with_empty, .def_str = "a", H},
     "choice 1 is an empty string"},
    {{.name = "a", .type = SYLVA_P_ENUM, .choices = twice, .def_str = "a", H},
     "the choice \"a\" appears twice"},
    {{.name = "a", .type = SYLVA_P_ENUM, .choices = ab, H}, "an optional enum needs a default"},
    {{.name = "a", .type = SYLVA_P_ENUM, .choices = ab, .def_str = "c", H},
     "the default \"c\" is not one of the choices"},
    /* list defaults */
    {{.name = "a", .type = SYLVA_P_VEC3, .def_list = two, .def_len = 2, H},
     "a vec3 default has 3 elements, not 2"},
    {{.name = "a", .type = SYLVA_P_VEC3, .flags = SYLVA_PARAM_HAS_MAX, .max = 2, .def_list = three,
      .def_len = 3, H},
     "default element 2 is 3, outside the range <= 2"},
    {{.name = "a", .type = SYLVA_P_LIST, .min_len = 3, H},
     "the default has 0 elements, fewer than min_len 3"},
    {{.name = "a", .type = SYLVA_P_LIST, .max_len = 1, .def_list = two, .def_len = 2, H},
     "the default has 2 elements, more than max_len 1"},
    {{.name = "a", .type = SYLVA_P_LIST, .flags = SYLVA_PARAM_HAS_MIN, .min = 1.5, .def_list = two,
      .def_len = 2, H},
     "default element 0 is 1, outside the range >= 1.5"},
    {{.name = "a", .type = SYLVA_P_LIST, .def_list = not_finite, .def_len = 2, H},
     "default element 1 is not finite"},
    {{.name = "a", .type = SYLVA_P_POLYLINE, .def_list = backwards, .def_len = 3, H},
     "default point 2 has x 1, less than the previous point's 2"},
    {{.name = "a", .type = SYLVA_P_POLYLINE, .flags = SYLVA_PARAM_HAS_MAX, .max = 0.5,
      .def_list = rising, .def_len = 2, H},
     "default point 1 has y 1, outside the range <= 0.5"},
    {{.name = "a", .type = SYLVA_P_POLYLINE, .min_len = 3, .def_list = rising, .def_len = 2, H},
     "the default has 2 points, fewer than min_len 3"},
    /* groups */
    {{.name = "layer", .type = SYLVA_P_GROUP, H}, "type group needs members"},
    {{.name = "layers", .type = SYLVA_P_GROUP_LIST, .group = member, H},
     "type group list needs members"},
    {{.name = "layers", .type = SYLVA_P_GROUP_LIST, .group = member, .n_group = 1, .min_len = 1,
      H},
     "the default is an empty list but min_len is 1"},
    {{.name = "layers", .type = SYLVA_P_GROUP_LIST, .group = bad_member, .n_group = 1, H},
     "parameter 'layers[].thickness': the default -1 m is outside the range [0, 10] m"},
    {{.name = "layer", .type = SYLVA_P_GROUP, .group = bad_member_name, .n_group = 1, H},
     "parameter name \"Thickness\" (entry 0 of group 'layer') is not a valid name"},
};

TEST(schema_rules_each_fail)
{
    for (size_t i = 0; i < sizeof schema_cases / sizeof schema_cases[0]; i++) {
        err_buf err;
        err_clear(&err);
        int rc = plugin_schema_check(&schema_cases[i].spec, 1, &err);
        if (rc != -1 || !strstr(err.msg, schema_cases[i].fragment)) {
            fprintf(stderr, "schema case %zu: rc %d, message \"%s\", expected \"%s\"\n", i, rc,
                    err.msg, schema_cases[i].fragment);
            harness_failures++;
        }
    }
}

static const sylva_param_spec dup_names[] = {
    {.name = "a", .type = SYLVA_P_REAL, H},
    {.name = "b", .type = SYLVA_P_REAL, H},
    {.name = "a", .type = SYLVA_P_INT, H},
};

/* Nine levels of groups, one more than the limit. */
static const sylva_param_spec deep8[] = {{.name = "leaf", .type = SYLVA_P_REAL, H}};
#define DEEP(n, inner) \
    static const sylva_param_spec n[] = {{.name = "g", .type = SYLVA_P_GROUP, .group = inner, \
                                          .n_group = 1, H}}
DEEP(deep7, deep8);
DEEP(deep6, deep7);
DEEP(deep5, deep6);
DEEP(deep4, deep5);
DEEP(deep3, deep4);
DEEP(deep2, deep3);
DEEP(deep1, deep2);
DEEP(deep0, deep1);

TEST(schema_table_rules)
{
    err_buf err;
    err_clear(&err);
    CHECK_INT(plugin_schema_check(dup_names, 3, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "parameter 'a': the name appears twice (entries 0 and 2)");
    CHECK_INT(plugin_schema_check(NULL, 2, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "the table of 2 parameters is NULL");
    CHECK_INT(plugin_schema_check(member, 257, &err), -1); /* refused before any entry is read */
    CHECK_STR_CONTAINS(err.msg, "257 parameters in one table; the limit is 256");
    CHECK_INT(plugin_schema_check(deep0, 1, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "parameter 'g.g.g.g.g.g.g.g': groups nest deeper than 8 levels");
    CHECK_INT(plugin_schema_check(deep1, 1, &err), 0); /* eight levels are fine */
}

TEST(schema_print_for_people)
{
    char *text = NULL;
    size_t len = 0;
    FILE *out = open_memstream(&text, &len);
    CHECK(out != NULL);
    if (!out) return;
    plugin_schema_print(out, valid_all, sizeof valid_all / sizeof valid_all[0], 2);
    fclose(out);
    CHECK_STR_CONTAINS(text, "  enabled ");
    CHECK_STR_CONTAINS(text, "default true");
    CHECK_STR_CONTAINS(text, "default 10");
    CHECK_STR_CONTAINS(text, "[1, 100]");
    CHECK_STR_CONTAINS(text, "default 49.5 m");
    CHECK_STR_CONTAINS(text, "(0, 50) m");
    CHECK_STR_CONTAINS(text, "default \"hill\"");
    CHECK_STR_CONTAINS(text, "one of: a, b");
    CHECK_STR_CONTAINS(text, "default [1, 2, 3] m");
    CHECK_STR_CONTAINS(text, "2..4 elements");
    CHECK_STR_CONTAINS(text, "default [[0, 0], [1, 0.5], [1, 1], [2, 1]]");
    CHECK_STR_CONTAINS(text, "at most 8 items");
    CHECK_STR_CONTAINS(text, "group list");
    CHECK_STR_CONTAINS(text, "required");
    CHECK_STR_CONTAINS(text, "How high.");
    CHECK_STR_CONTAINS(text, "\n      height "); /* group members, indented under their group */
    /* one line per parameter plus one per member of the three groups */
    int lines = 0;
    for (const char *c = text; c && *c; c++) lines += *c == '\n';
    CHECK_INT(lines, (int)(sizeof valid_all / sizeof valid_all[0]) + 3);
    free(text);
}

/* --------------------------------------------------------------------------------------------
 * Lazy loading and manifests
 */

TEST(opening_the_registry_opens_no_module)
{
    err_buf err;
    plugin_registry *reg = plugin_registry_open_path(PLUGIN_DIR, &err);
    CHECK(reg != NULL);
    if (!reg) return;
    CHECK_INT(plugin_registry_opened_count(reg), 0);
    CHECK_INT(plugin_registry_count(reg), 0);
    /* abi_one_zero.so comes first and has a manifest: finding it opens it alone */
    CHECK(plugin_registry_find(reg, "abi_one_zero", SYLVA_KIND_TERRAIN, &err) != NULL);
    CHECK_INT(plugin_registry_opened_count(reg), 1);
    CHECK(plugin_registry_find(reg, "abi_one_zero", SYLVA_KIND_TERRAIN, &err) != NULL);
    CHECK_INT(plugin_registry_opened_count(reg), 1);
    /* a name no manifest declares opens the modules without one, not those whose manifest
     * names other plugins (probe_open.so, example_terrain.so, ...) */
    CHECK(plugin_registry_find(reg, "mixed_ecology", SYLVA_KIND_ECOLOGY, &err) != NULL);
    uint32_t opened = plugin_registry_opened_count(reg);
    for (uint32_t i = 0; i < plugin_registry_count(reg); i++) {
        CHECK(strstr(plugin_registry_at(reg, i)->file, "/probe_open.so") == NULL);
        CHECK(strstr(plugin_registry_at(reg, i)->file, "/example_terrain.so") == NULL);
    }
    CHECK_INT(plugin_registry_load_all(reg, &err), 0);
    CHECK(plugin_registry_opened_count(reg) > opened);
    CHECK_INT(listed_from(reg, "/probe_open.so"), 1);
    plugin_registry_free(reg);
}

/* A plugin found first stays where it is while later lookups open more modules (more than the
 * registry's first allocation holds). */
TEST(found_plugins_stay_valid)
{
    err_buf err;
    plugin_registry *reg = plugin_registry_open_path(PLUGIN_DIR ":" SYLVA_PLUGIN_BUILD_DIR, &err);
    CHECK(reg != NULL);
    if (!reg) return;
    const loaded_plugin *first = plugin_registry_find(reg, "abi_one_zero", 0, &err);
    CHECK(first != NULL);
    CHECK_INT(plugin_registry_load_all(reg, &err), 0);
    CHECK(plugin_registry_count(reg) > 8);
    CHECK(plugin_registry_find(reg, "abi_one_zero", 0, &err) == first);
    if (first) CHECK(!strcmp(first->desc->name, "abi_one_zero"));
    /* a kind mismatch lists every plugin of the kind asked for, opened or not */
    plugin_registry_free(reg);
    reg = plugin_registry_open_path(PLUGIN_DIR ":" SYLVA_PLUGIN_BUILD_DIR, &err);
    CHECK(reg != NULL);
    if (!reg) return;
    err_clear(&err);
    CHECK(plugin_registry_find(reg, "abi_one_zero", SYLVA_KIND_TREE, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "the tree plugins are: ");
    CHECK_STR_CONTAINS(err.msg, "tree_vessel");
    plugin_registry_free(reg);
}

TEST(abi_1_0_module_loads)
{
    plugin_registry *reg = open_test_plugins();
    if (!reg) return;
    err_buf err;
    const loaded_plugin *lp = plugin_registry_find(reg, "abi_one_zero", SYLVA_KIND_TERRAIN, &err);
    CHECK(lp != NULL);
    if (lp) {
        CHECK_INT(lp->desc->abi_major, 1);
        CHECK_INT(lp->desc->abi_minor, 0);
        CHECK_INT(lp->desc->size, sizeof(sylva_plugin)); /* the host's copy, zero past 1.0 */
        CHECK(lp->desc->preset_param == NULL && lp->desc->presets == NULL);
        CHECK_INT(lp->desc->n_presets, 0);
        CHECK_INT(lp->desc->n_params, 1);
    }
    const char *msg;
    CHECK_INT(problems_for(reg, "abi_one_zero.so", &msg), 0);
    plugin_registry_free(reg);
}

/* Writes text to path; 0 or -1. */
static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    int rc = fputs(text, f) < 0;
    return fclose(f) || rc ? -1 : 0;
}

/* A folder holding a copy of example_terrain.so beside the given manifest text (NULL: none). */
static const char *module_with_manifest(const char *name, const char *manifest)
{
    static char dir[1200];
    snprintf(dir, sizeof dir, "%s", work_path(name));
    CHECK(mkdir(dir, 0700) == 0);
    char path[1400];
    snprintf(path, sizeof path, "%s/example_terrain.so", dir);
    CHECK_INT(copy_file(PLUGIN_DIR "/example_terrain.so", path), 0);
    if (manifest) {
        snprintf(path, sizeof path, "%s/example_terrain.sylva-plugin", dir);
        CHECK_INT(write_text(path, manifest), 0);
    }
    return dir;
}

TEST(manifest_mismatch_and_damage_are_refused)
{
    static const struct {
        const char *manifest;
        int opened;          /* the module is opened to find the mismatch */
        const char *fragment;
    } cases[] = {
        {"sylva-plugin-manifest 1\nplugin example_terrain tree 1.1\n", 1,
         "plugin 'example_terrain' (terrain, ABI 1.7) does not match its manifest, which says "
         "'example_terrain' (tree, ABI 1.1); rewrite the manifest with `sylva plugins --manifest "},
        {"sylva-plugin-manifest 1\nplugin example_terrain terrain 1.0\n", 1,
         "does not match its manifest, which says 'example_terrain' (terrain, ABI 1.0)"},
        {"sylva-plugin-manifest 1\nplugin example_terrain terrain 1.1\nplugin other tree 1.1\n", 1,
         "the module provides 1 plugin, its manifest names 2"},
        {"sylva-plugin-manifest 1\nplugin example_terrain terrain 3.0\n", 0,
         "built against sylva plugin ABI 3.0, this host speaks 1.7"},
        {"# a comment\nsylva-plugin-manifest 1\nplugin example_terrain terrain\n", 0,
         "example_terrain.sylva-plugin:3: expected `plugin NAME KIND MAJOR.MINOR`"},
        {"plugin example_terrain terrain 1.1\n", 0,
         "example_terrain.sylva-plugin:1: a plugin manifest starts with `sylva-plugin-manifest 1`"},
        {"sylva-plugin-manifest 1\nplugin example_terrain forest 1.1\n", 0,
         ":2: unknown kind 'forest'; kinds are terrain, tree and ecology"},
        {"sylva-plugin-manifest 1\n", 0, "the plugin manifest names no plugin"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char name[32];
        snprintf(name, sizeof name, "manifest%zu", i);
        const char *dir = module_with_manifest(name, cases[i].manifest);
        err_buf err;
        plugin_registry *reg = plugin_registry_open_path(dir, &err);
        CHECK(reg != NULL);
        if (!reg) continue;
        err_clear(&err);
        CHECK(plugin_registry_find(reg, "example_terrain", 0, &err) == NULL);
        CHECK_STR_CONTAINS(err.msg, cases[i].fragment);
        CHECK_INT(plugin_registry_opened_count(reg), cases[i].opened);
        if (!strstr(err.msg, cases[i].fragment)) fprintf(stderr, "case %zu: %s\n", i, err.msg);
        plugin_registry_free(reg);
    }
}

TEST(manifest_written_from_the_module)
{
    const char *dir = module_with_manifest("written", NULL);
    char module[1400], manifest[1400];
    snprintf(module, sizeof module, "%s/example_terrain.so", dir);
    snprintf(manifest, sizeof manifest, "%s/example_terrain.sylva-plugin", dir);
    err_buf err;
    CHECK_INT(plugin_manifest_write(module, &err), 0);
    plugin_manifest m;
    CHECK_INT(plugin_manifest_read(manifest, &m, &err), 1);
    CHECK_INT(m.n, 1);
    CHECK(!strcmp(m.plugin[0].name, "example_terrain"));
    CHECK_INT(m.plugin[0].kind, SYLVA_KIND_TERRAIN);
    CHECK_INT(m.plugin[0].abi_major, SYLVA_ABI_MAJOR);
    CHECK_INT(m.plugin[0].abi_minor, SYLVA_ABI_MINOR);
    CHECK(plugin_manifest_declares(&m, "example_terrain") && !plugin_manifest_declares(&m, "x"));
    plugin_registry *reg = plugin_registry_open_path(dir, &err);
    CHECK(reg && plugin_registry_find(reg, "example_terrain", SYLVA_KIND_TERRAIN, &err) != NULL);
    plugin_registry_free(reg);
    /* no manifest for a module without descriptors; nothing for a file that is not a module */
    CHECK_INT(plugin_manifest_write(PLUGIN_DIR "/broken_noentry.so", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "no entry point [sylva_plugin_get]");
    CHECK_INT(plugin_manifest_write(SYLVA_TEST_DATA_DIR "/harness.h", &err), -1);
    CHECK_STR_CONTAINS(err.msg, "ends in .so");
    CHECK_INT(plugin_manifest_read("/nonexistent/x.sylva-plugin", &m, &err), 0);
    CHECK_INT(plugin_manifest_read("/dev/null", &m, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "not a regular file");
}

TEST(build_tree_search_only_from_the_build_tree)
{
    /* this test runs from the build tree: it searches the build tree's plugin folder (the
     * other side, a copy outside the tree, is tests/plugins/probe_loading.sh) */
    CHECK_INT(plugin_running_from_build_tree(), 1);
}

/* --------------------------------------------------------------------------------------------
 * Presets
 */

static const char *const shade_choices[] = {"light", "dark", NULL};
static const sylva_param_spec preset_schema[] = {
    {.name = "shade", .type = SYLVA_P_ENUM, .def_str = "light", .choices = shade_choices, .help = "s"},
    {.name = "height", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .def = 1, .min = 0, .max = 10, .unit = "m", .help = "h"},
    {.name = "count", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN, .def = 1, .min = 1, .help = "c"},
    {.name = "curve", .type = SYLVA_P_POLYLINE, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .min = 0, .max = 1, .min_len = 1, .max_len = 4, .help = "p"},
    {.name = "colour", .type = SYLVA_P_VEC3, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .min = 0, .max = 1, .def_list = (const double[]){0, 0, 0}, .def_len = 3, .help = "c"},
};

static const double light_curve[] = {0, 0.5, 3, 1}, light_colour[] = {0.1, 0.2, 0.3};
static const double curve_backwards[] = {2, 0.5, 1, 0.5}, curve_high[] = {0, 2}, short_colour[] = {0, 0};
static const sylva_preset_value light[] = {{.param = "height", .r = 2.5},
                                           {.param = "curve", .list = light_curve, .len = 2},
                                           {.param = "colour", .list = light_colour, .len = 3}};
static const sylva_preset_value dark[] = {{.param = "count", .r = 3}};

static int check_presets(const sylva_preset *presets, uint32_t n, err_buf *err)
{
    sylva_plugin d = {.size = sizeof d, .params = preset_schema, .n_params = 5,
                      .preset_param = "shade", .presets = presets, .n_presets = n};
    err_clear(err);
    return plugin_presets_check(&d, err);
}

TEST(presets_checked_against_the_schema)
{
    sylva_preset good[] = {{"light", "Light.", light, 3}, {"dark", "Dark.", dark, 1}};
    err_buf err;
    CHECK_INT(check_presets(good, 2, &err), 0);

    sylva_preset swapped[] = {good[1], good[0]};
    CHECK_INT(check_presets(swapped, 2, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "preset 0 is called 'dark', but choice 0 of 'shade' is 'light'");
    CHECK_INT(check_presets(good, 1, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "'shade' has 2 choices but the descriptor describes 1 presets");

    static const struct {
        sylva_preset_value v;
        const char *fragment;
    } bad[] = {
        {{.param = "height", .r = 11}, "preset 'dark': 'height': 11 is outside the parameter's range"},
        {{.param = "count", .r = 2.5}, "'count': 2.5 is not a whole number"},
        {{.param = "weight", .r = 1}, "names 'weight', which is not a parameter of the schema"},
        {{.param = "shade", .s = "dark"}, "which is the preset selector itself"},
        {{.param = "curve", .list = curve_backwards, .len = 2},
         "point 1's x is not at or after the point before it"},
        {{.param = "curve", .list = curve_high, .len = 1},
         "element 0, 2, is outside the parameter's range"},
        {{.param = "colour", .list = short_colour, .len = 2},
         "2 elements is not a length the parameter takes"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        sylva_preset flawed[] = {good[0], {"dark", "Dark.", &bad[i].v, 1}};
        CHECK_INT(check_presets(flawed, 2, &err), -1);
        CHECK_STR_CONTAINS(err.msg, bad[i].fragment);
    }
    sylva_preset_value count_twice[] = {{.param = "count", .r = 2}, {.param = "count", .r = 3}};
    sylva_preset dup[] = {good[0], {"dark", "Dark.", count_twice, 2}};
    CHECK_INT(check_presets(dup, 2, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "'count' is given twice");

    sylva_plugin d = {.size = sizeof d, .params = preset_schema, .n_params = 5,
                      .preset_param = "height", .presets = good, .n_presets = 2};
    CHECK_INT(plugin_presets_check(&d, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "preset_param 'height' is not an enum parameter of the schema");
    d = (sylva_plugin){.size = sizeof d, .params = preset_schema, .n_params = 5};
    CHECK_INT(plugin_presets_check(&d, &err), 0); /* none is fine */
}

TEST(presets_printed_with_values)
{
    sylva_preset presets[] = {{"light", "Light.", light, 3}, {"dark", "Dark.", dark, 1}};
    sylva_plugin d = {.size = sizeof d, .params = preset_schema, .n_params = 5,
                      .preset_param = "shade", .presets = presets, .n_presets = 2};
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    CHECK(f != NULL);
    if (!f) return;
    plugin_presets_print(f, &d, 2);
    fclose(f);
    CHECK_STR_CONTAINS(text, "  light: Light.\n"
                             "      height  2.5 m\n"
                             "      curve   [[0, 0.5], [3, 1]]\n"
                             "      colour  [0.1, 0.2, 0.3]\n"
                             "  dark: Dark.\n"
                             "      count   3\n");
    free(text);
}

TEST_LIST(TEST_CASE(example_is_listed_with_schema), TEST_CASE(failing_operations_still_load),
          TEST_CASE(opening_the_registry_opens_no_module), TEST_CASE(found_plugins_stay_valid),
          TEST_CASE(abi_1_0_module_loads),
          TEST_CASE(manifest_mismatch_and_damage_are_refused),
          TEST_CASE(manifest_written_from_the_module),
          TEST_CASE(build_tree_search_only_from_the_build_tree),
          TEST_CASE(presets_checked_against_the_schema), TEST_CASE(presets_printed_with_values),
          TEST_CASE(each_broken_module_gives_one_problem),
          TEST_CASE(descriptor_rules_one_problem_each), TEST_CASE(problems_in_file_order),
          TEST_CASE(find_refused_plugin_says_why), TEST_CASE(find_wrong_kind),
          TEST_CASE(find_unknown_suggests_nearest), TEST_CASE(missing_folders_are_fine),
          TEST_CASE(add_file_tells_no_library_from_cannot_load),
          TEST_CASE(earlier_folder_shadows_later), TEST_CASE(default_search_path_reads_environment),
          TEST_CASE(names_and_kinds), TEST_CASE(schema_valid_tables_pass),
          TEST_CASE(schema_rules_each_fail), TEST_CASE(schema_table_rules),
          TEST_CASE(schema_print_for_people))
