/* test_wp_config.c — the tree_weber_penn block read as the plugin reads it: the schema follows
 * wp_param_table, `model` alone is a species over Arbaro's defaults, `model` keys replace a
 * file's values, a file's species is picked by name (Arbaro's and Helios' shared files, skipped
 * without them), and every kind of bad input is refused with one sentence at its key's place. */
#include <math.h>
#include <string.h>

#include "harness.h"
#include "wp_fixture.h"
#include "wp_schema.h"

/* Opens a fixture on `yaml`, expects failure with `status` (-1: the schema) and a message holding
 * both needles (needle2 may be NULL). */
static void expect_refused(const char *yaml, int status, const char *needle1, const char *needle2)
{
    wp_fixture fx;
    int rc = wp_fixture_open(&fx, yaml, WP_TEST_DIR);
    if (rc != status) fprintf(stderr, "for:\n%sgot status %d (%s)\n", yaml, rc, fx.err.msg);
    CHECK_INT(rc, status);
    CHECK_STR_CONTAINS(fx.err.msg, needle1);
    if (needle2) CHECK_STR_CONTAINS(fx.err.msg, needle2);
    wp_fixture_close(&fx);
}

/* Opens a fixture that must read; the caller closes it. */
static int open_ok(wp_fixture *fx, const char *yaml)
{
    int rc = wp_fixture_open(fx, yaml, WP_TEST_DIR);
    if (rc) fprintf(stderr, "for:\n%sgot status %d (%s)\n", yaml, rc, fx->err.msg);
    CHECK_INT(rc, 0);
    return rc;
}

/* Every member of `model` is the row of wp_param_table it names: its type, default, range (the
 * per-level lists also take 0 where the row's minimum is above it: a level not grown) and
 * meaning; and every row Arbaro's growth reads has its member. */
TEST(schema_follows_the_table)
{
    size_t rows = 0;
    for (size_t i = 0; i < WP_MODEL_SCHEMA_COUNT; i++) {
        const sylva_param_spec *s = &wp_model_schema[i];
        const wp_param_def *d = wp_param_find(wp_model_arbaro[i]);
        CHECK(d != NULL);
        if (!d) continue;
        CHECK_STR_CONTAINS(s->help, d->meaning);
        if (d->type == WP_TEXT) {
            CHECK_INT(s->type, SYLVA_P_STRING);
            CHECK(!strcmp(s->def_str, d->text_deflt));
            continue;
        }
        double lo = d->per_level && d->min > 0 ? 0 : d->min;
        CHECK_INT(!!(s->flags & SYLVA_PARAM_HAS_MIN), isfinite(lo));
        CHECK_INT(!!(s->flags & SYLVA_PARAM_HAS_MAX), isfinite(d->max));
        if (isfinite(lo)) CHECK_NEAR(s->min, lo, 0);
        if (isfinite(d->max)) CHECK_NEAR(s->max, d->max, 0);
        if (d->per_level) {
            CHECK_INT(s->type, SYLVA_P_LIST);
            CHECK_INT(s->def_len, WP_LEVELS);
            for (int l = 0; l < WP_LEVELS && s->def_list; l++) CHECK_NEAR(s->def_list[l], d->deflt[l], 0);
        } else {
            CHECK_INT(s->type, d->type == WP_INT ? SYLVA_P_INT : SYLVA_P_REAL);
            CHECK_NEAR(s->def, d->deflt[0], 0);
        }
    }
    static const char *const left_out[] = {"Species", "ZScale", "ZScaleV", "BaseSplitSize", "BarkTexture",
                                           "LeafTexture", "LeafTextureRotation"};
    for (size_t k = 0; k < wp_param_count; k++) {
        int found = 0;
        for (size_t i = 0; i < WP_MODEL_SCHEMA_COUNT; i++) found |= !strcmp(wp_model_arbaro[i], wp_param_table[k].name);
        for (size_t j = 0; j < sizeof left_out / sizeof left_out[0]; j++)
            found |= !strcmp(left_out[j], wp_param_table[k].name);
        if (!found) fprintf(stderr, "row %s has no member of model\n", wp_param_table[k].name);
        CHECK(found);
        rows += found;
    }
    CHECK_INT(rows, wp_param_count);
}

/* `model` alone: Arbaro's defaults, with the keys given (a short list sets its first levels). */
TEST(model_alone_over_arbaro_defaults)
{
    wp_fixture fx;
    if (open_ok(&fx, "model:\n  scale: 13\n  levels: 2\n  length: [1, 0.3, 0.6, 0]\n  curve_res: [5]\n"
                     "  leaf_shape: disc\n"))
        return wp_fixture_close(&fx);
    wp_params d;
    wp_params_defaults(&d);
    const wp_params *p = &fx.cfg.species;
    CHECK_NEAR(p->scale, 13, 0);
    CHECK_INT(p->levels, 2);
    CHECK_NEAR(p->level[1].length, 0.3, 0);
    CHECK_NEAR(p->level[2].length, 0.6, 0);
    CHECK_NEAR(p->level[3].length, 0, 0); /* not grown: 0 is accepted */
    CHECK_INT(p->level[0].curve_res, 5);
    CHECK_INT(p->level[1].curve_res, d.level[1].curve_res);
    CHECK(!strcmp(p->leaf_shape, "disc"));
    CHECK_NEAR(p->ratio, d.ratio, 0);
    CHECK_NEAR(p->level[1].down_angle, d.level[1].down_angle, 0);
    CHECK_INT(fx.cfg.seed, 13);
    CHECK_INT(fx.cfg.leaf, WP_LEAF_OWN);
    CHECK(!strcmp(fx.cfg.where_key, "model"));
    wp_fixture_close(&fx);
}

/* An Arbaro file's only species; each model key replaces the file's value, the rest stays. */
TEST(model_overrides_arbaro_file)
{
    const char *path = harness_shared_data("weber-penn/arbaro/quaking_aspen.xml");
    if (!path) SKIP("no ../shared/data/weber-penn");
    char yaml[1024];
    snprintf(yaml, sizeof yaml, "file: %s\nseed: 7\nmodel: {scale: 20, branches: [1, 40]}\n", path);
    wp_fixture fx;
    if (open_ok(&fx, yaml)) return wp_fixture_close(&fx);
    const wp_params *p = &fx.cfg.species;
    CHECK(!strcmp(p->species, "quaking_aspen"));
    CHECK_NEAR(p->scale, 20, 0);
    CHECK_NEAR(p->scale_v, 3, 0);      /* the file's */
    CHECK_NEAR(p->ratio, 0.015, 1e-15); /* the file's */
    CHECK_INT(p->level[1].branches, 40);
    CHECK_INT(p->leaves, 25);
    CHECK_INT(fx.cfg.seed, 7);
    wp_fixture_close(&fx);
}

/* Helios' library holds several species: name picks one; a wrong name is refused with the
 * names the file has, and so is a missing one. */
TEST(helios_library_by_name)
{
    const char *found = harness_shared_data("weber-penn/helios/WeberPennTreeLibrary.xml");
    if (!found) SKIP("no ../shared/data/weber-penn");
    char path[4096], yaml[4200];
    snprintf(path, sizeof path, "%s", found);
    snprintf(yaml, sizeof yaml, "file: %s\nname: Olive\n", path);
    wp_fixture fx;
    if (!open_ok(&fx, yaml)) CHECK(!strcmp(fx.cfg.species.species, "Olive"));
    wp_fixture_close(&fx);
    snprintf(yaml, sizeof yaml, "file: %s\nname: Oliv\n", path);
    expect_refused(yaml, SYLVA_ERR_PARAM, "test.yaml:2:7: 'name': species 'Oliv' is not in",
                   "which holds 'Almond', 'Apple', 'Avocado', 'Lemon', 'Olive'");
    snprintf(yaml, sizeof yaml, "file: %s\n", path);
    expect_refused(yaml, SYLVA_ERR_PARAM, "test.yaml:1:7: 'file':",
                   "holds 9 species ('Almond', 'Apple', 'Avocado', 'Lemon', 'Olive', 'Orange', 'Peach', 'Pistachio', "
                   "'Walnut'); choose one with name");
}

/* Neither file nor model; name without file; a file that is not there or not a species file. */
TEST(species_missing_refused)
{
    expect_refused("seed: 3\n", SYLVA_ERR_PARAM, "test.yaml:1:1: 'file': the species is missing",
                   "give file (an Arbaro species file or Helios' WeberPennTreeLibrary.xml");
    expect_refused("name: Olive\nmodel: {levels: 2}\n", SYLVA_ERR_PARAM, "test.yaml:1:7: 'name': name picks a species "
                   "of file, and no file is given", NULL);
    expect_refused("file: no_such.xml\n", SYLVA_ERR_IO, "test.yaml:1:7: 'file':", "no_such.xml");
    expect_refused("file: test_wp_config.c\n", SYLVA_ERR_PARAM, "test.yaml:1:7: 'file':", "test_wp_config.c:");
}

/* The schema's ranges (the table's) and what create() adds: whole numbers in integer lists,
 * the table's range at every level the tree grows, at the member that gave the value or at
 * model.levels when it made a level grow. */
TEST(model_values_out_of_range_refused)
{
    expect_refused("model: {scale: -3}\n", -1, "test.yaml:1:16: 'scale' must be >= 1e-06, got -3", NULL);
    expect_refused("model: {shape: 9}\n", -1, "'shape' must be an integer in [0, 8], got 9", NULL);
    expect_refused("model: {leaf_bend: 1.5}\n", -1, "'leaf_bend'", "[0, 1]");
    expect_refused("model: {taper: [1, 3]}\n", -1, "'taper'", "2.99999999");
    expect_refused("model: {length: [1, 0.5, 0.5, 0.5, 0.5]}\n", -1, "'length'", "4");
    expect_refused("model: {lenght: [1]}\n", -1, "unknown key 'lenght'", "did you mean 'length'");
    expect_refused("model: {levels: 5}\n", SYLVA_ERR_PARAM, "test.yaml:1:17: 'levels': Levels is 5; Arbaro 1.9 grows at "
                   "most 4 stem levels", NULL);
    expect_refused("model: {curve_res: [3, 2.5]}\n", SYLVA_ERR_PARAM,
                   "test.yaml:1:20: 'curve_res': model.curve_res gives 2.5 at level 1; curve_res takes whole numbers",
                   NULL);
    expect_refused("model: {length: [1, 0.3, 0]}\n", SYLVA_ERR_PARAM,
                   "test.yaml:1:17: 'length': model.length gives 0 at level 2, a level the tree grows",
                   "at least 1e-07");
}

/* Zeros at levels the tree does not grow are what Helios writes: accepted. A model.levels that
 * makes such a level grow is refused at levels. */
TEST(levels_not_grown_take_zero)
{
    wp_fixture fx;
    if (!open_ok(&fx, "model: {levels: 2, curve_res: [3, 3, 0, 0], length: [1, 0.4, 0, 0]}\n"))
        CHECK_INT(fx.cfg.species.level[2].curve_res, 0);
    wp_fixture_close(&fx);
    const char *path = harness_shared_data("weber-penn/helios/WeberPennTreeLibrary.xml");
    if (!path) SKIP("no ../shared/data/weber-penn");
    char yaml[4200];
    snprintf(yaml, sizeof yaml, "file: %s\nname: Apple\nmodel: {levels: 4}\n", path);
    expect_refused(yaml, SYLVA_ERR_PARAM, "test.yaml:3:17: 'levels': model.levels 4 grows level 3", "give model.");
}

/* The look: own, a preset or maps on a card; wrong names and maps at `leaf`; the bark; a leaf
 * that would scatter more than it receives. */
TEST(look_keys)
{
    wp_fixture fx;
    if (!open_ok(&fx, "model: {levels: 1}\nleaf: maple\nbark: fissured\nbark_angle: -35.5\n")) {
        CHECK_INT(fx.cfg.leaf, WP_LEAF_CARD);
        leaf_affine_maps maple;
        leaf_affine_preset_maps(LEAF_AFFINE_MAPLE, &maple);
        CHECK_INT(fx.cfg.leaf_maps.n, maple.n);
        CHECK(fabs(fx.cfg.bark.theta - -35.5 * M_PI / 180.0) < 1e-12);
    }
    wp_fixture_close(&fx);
    if (!open_ok(&fx, "model: {levels: 1}\nleaf: \"0.5 0 0 0.5 0.25 0; 0.5 0 0 0.5 0.25 0.5\"\n"))
        CHECK_INT(fx.cfg.leaf_maps.n, 2);
    wp_fixture_close(&fx);
    expect_refused("model: {levels: 1}\nleaf: oak\n", SYLVA_ERR_PARAM, "test.yaml:2:7: 'leaf': 'oak' is not a leaf; "
                   "give own (the species' LeafShape), a preset (beech, maple, spruce, shrub, willow)", NULL);
    expect_refused("model: {levels: 1}\nleaf: \"0.5 0 0 0.5 0.8 0\"\n", SYLVA_ERR_PARAM, "test.yaml:2:7: 'leaf'",
                   "unit square");
    expect_refused("model: {levels: 1}\nbark: bumpy\n", -1, "test.yaml:2:7: 'bark'", "smooth");
    expect_refused("model: {levels: 1}\nleaf_color: [0.6, 0.5, 0.4]\nleaf_transmittance: [0.5, 0.4, 0.3]\n",
                   SYLVA_ERR_PARAM, "'leaf_transmittance'", "at most 1");
}

/* docs/models/tree_weber_penn.md has a row for every key of the block and of `model`. */
TEST(doc_lists_every_key)
{
    static char doc[1 << 17];
    int found = harness_read_text(WP_DOC_PATH, doc, sizeof doc);
    CHECK(found);
    if (!found) return;
    char row[96];
    for (size_t i = 0; i < WP_SCHEMA_COUNT; i++) {
        snprintf(row, sizeof row, "| `%s` |", wp_schema[i].name);
        CHECK_STR_CONTAINS(doc, row);
    }
    for (size_t i = 0; i < WP_MODEL_SCHEMA_COUNT; i++) {
        snprintf(row, sizeof row, "| `%s` | `%s` |", wp_model_schema[i].name, wp_model_arbaro[i]);
        CHECK_STR_CONTAINS(doc, row);
    }
}

TEST_LIST(TEST_CASE(schema_follows_the_table), TEST_CASE(model_alone_over_arbaro_defaults),
          TEST_CASE(model_overrides_arbaro_file), TEST_CASE(helios_library_by_name), TEST_CASE(species_missing_refused),
          TEST_CASE(model_values_out_of_range_refused), TEST_CASE(levels_not_grown_take_zero), TEST_CASE(look_keys),
          TEST_CASE(doc_lists_every_key))
