/* test_vessel_config.c — the tree_vessel schema: the host accepts it, its defaults are the beech
 * preset, and a block reads as its preset with the given keys replaced one by one. */
#include <math.h>
#include <string.h>

#include "harness.h"
#include "plugin/plugin_host.h"
#include "vessel_config.h"
#include "vessel_test_util.h"

/* A block in which every key is given with the schema's default; `preset` as named. */
typedef struct block {
    sylva_value values[VESSEL_SCHEMA_COUNT];
    sylva_params params;
} block;

static void block_from_defaults(block *b, const char *preset_name)
{
    memset(b, 0, sizeof *b);
    for (uint32_t i = 0; i < VESSEL_SCHEMA_COUNT; i++) {
        const sylva_param_spec *s = &vessel_schema[i];
        sylva_value *v = &b->values[i];
        v->is_set = 1;
        v->r = s->def, v->i = (int64_t)s->def;
        v->list = s->def_list, v->len = s->def_len, v->s = s->def_str;
        if (!strcmp(s->name, "bark_angle")) v->is_set = 0; /* absent: the bark preset's own angle */
        if (s->type == SYLVA_P_ENUM) {
            const char *want = !strcmp(s->name, "preset") ? preset_name : s->def_str;
            for (int64_t k = 0; s->choices[k]; k++)
                if (!strcmp(s->choices[k], want)) v->i = k, v->s = s->choices[k];
        }
    }
    b->params = (sylva_params){.spec = vessel_schema, .n = VESSEL_SCHEMA_COUNT, .values = b->values};
}

/* vessel_config_read of b through a reader without a host. */
static int read_block(const block *b, vessel_params *out, plugin_err *err)
{
    plugin_params r = plugin_params_open(NULL, NULL, &b->params);
    return vessel_config_read(&r, out, err);
}

/* Field by field: the structs' padding bytes are not part of their value. */
static int same_leaf(const leaf_affine_maps *a, const leaf_affine_maps *b)
{
    int same = a->n == b->n;
    for (uint32_t i = 0; same && i < a->n; i++) {
        const leaf_affine_map *p = &a->map[i], *q = &b->map[i];
        same = p->a == q->a && p->b == q->b && p->c == q->c && p->d == q->d && p->e == q->e && p->f == q->f &&
               p->p == q->p;
    }
    return same;
}

static int same_bark(const bark_fractal_params *a, const bark_fractal_params *b)
{
    int same = a->theta == b->theta && a->centre_re == b->centre_re && a->centre_im == b->centre_im &&
               a->radius_inner == b->radius_inner && a->radius_outer == b->radius_outer &&
               a->iterations == b->iterations && a->crack_width == b->crack_width;
    for (int k = 0; k < 3; k++) same = same && a->furrow[k] == b->furrow[k] && a->plate[k] == b->plate[k];
    return same;
}

static int same_params(const vessel_params *a, const vessel_params *b)
{
    int same = a->vessels == b->vessels && a->trunk_length == b->trunk_length &&
               a->thickness == b->thickness && a->gravicentralism == b->gravicentralism &&
               a->phyllotaxis == b->phyllotaxis && a->leaf_size == b->leaf_size &&
               a->leaf_density == b->leaf_density && a->leaf_type == b->leaf_type &&
               same_leaf(&a->leaf, &b->leaf) && a->leaf_preset == b->leaf_preset &&
               same_bark(&a->bark, &b->bark) && a->bark_preset == b->bark_preset &&
               a->sides == b->sides &&
               a->wind_sway == b->wind_sway && a->wind_strength == b->wind_strength &&
               a->flexibility == b->flexibility && a->wind_time == b->wind_time;
    for (int k = 0; k < 3; k++)
        same = same && a->wind_direction[k] == b->wind_direction[k] &&
               a->bark_albedo[k] == b->bark_albedo[k] && a->leaf_albedo[k] == b->leaf_albedo[k] &&
               a->leaf_transmittance[k] == b->leaf_transmittance[k];
    for (int k = 0; k < VESSEL_LOCALS; k++) {
        const vessel_polyline *lines[4] = {&a->by_g[k], &b->by_g[k], &a->by_w[k], &b->by_w[k]};
        for (int j = 0; j < 4; j += 2) {
            same = same && lines[j]->n == lines[j + 1]->n;
            for (uint32_t i = 0; same && i < lines[j]->n; i++)
                same = lines[j]->x[i] == lines[j + 1]->x[i] && lines[j]->y[i] == lines[j + 1]->y[i];
        }
    }
    return same;
}

TEST(the_host_accepts_the_schema)
{
    err_buf err = {{0}};
    CHECK_INT(plugin_schema_check(vessel_schema, VESSEL_SCHEMA_COUNT, &err), 0);
    if (err.msg[0]) fprintf(stderr, "%s\n", err.msg);
    CHECK(vessel_schema[VESSEL_SCHEMA_COUNT - 1].name != NULL);
}

/* What `sylva plugins --describe` prints as defaults is the beech of 004 §3.4.1. */
TEST(schema_defaults_are_the_beech_preset)
{
    block b;
    block_from_defaults(&b, "beech");
    vessel_params read, beech = preset(VESSEL_PRESET_BEECH);
    plugin_err err = {0};
    CHECK_INT(read_block(&b, &read, &err), 0);
    CHECK(same_params(&read, &beech));
}

TEST(a_preset_with_keys_replaced)
{
    block b;
    block_from_defaults(&b, "spruce");
    for (uint32_t i = 0; i < VESSEL_SCHEMA_COUNT; i++) b.values[i].is_set = !strcmp(vessel_schema[i].name, "preset");
    vessel_params read, spruce = preset(VESSEL_PRESET_SPRUCE);
    plugin_err err = {0};
    CHECK_INT(read_block(&b, &read, &err), 0);
    CHECK(same_params(&read, &spruce)); /* nothing given: the preset itself */

    int vessels = sylva_param_index(&b.params, "vessels"), angle = sylva_param_index(&b.params, "angle_g");
    int leaf_type = sylva_param_index(&b.params, "leaf_type");
    b.values[vessels].is_set = 1, b.values[vessels].i = 321;
    static const double wide[] = {0, 90, 15, 60};
    b.values[angle].is_set = 1, b.values[angle].list = wide, b.values[angle].len = 2;
    b.values[leaf_type].is_set = 1, b.values[leaf_type].i = VESSEL_LEAF_BUNCHED;
    CHECK_INT(read_block(&b, &read, &err), 0);
    CHECK_INT(read.vessels, 321);
    CHECK_INT(read.by_g[VESSEL_ANGLE].n, 2);
    CHECK_NEAR(read.by_g[VESSEL_ANGLE].y[0], 90, 0);
    CHECK_INT(read.leaf_type, VESSEL_LEAF_BUNCHED);
    read.vessels = spruce.vessels, read.by_g[VESSEL_ANGLE] = spruce.by_g[VESSEL_ANGLE];
    read.leaf_type = spruce.leaf_type;
    CHECK(same_params(&read, &spruce)); /* everything else stays the spruce's */
}

/* What the schema cannot express: orders outside a polyline's span. */
TEST(orders_past_the_span_are_refused_at_their_key)
{
    block b;
    block_from_defaults(&b, "beech");
    int k = sylva_param_index(&b.params, "split_g");
    static const double far[] = {0, 0.7, 20, 0.9};
    b.values[k].list = far, b.values[k].len = 2;
    vessel_params read;
    plugin_err err = {0};
    CHECK_INT(read_block(&b, &read, &err), -1);
    CHECK_STR_CONTAINS(err.param, "split_g");
    CHECK_STR_CONTAINS(err.msg, "order 20; orders run from 0 to 15");
    k = sylva_param_index(&b.params, "length_scale_w");
    static const double fine[] = {0, 1, 50, 1}, past_w[] = {0, 1, 60, 1};
    b.values[sylva_param_index(&b.params, "split_g")].list = vessel_schema[sylva_param_index(&b.params, "split_g")].def_list;
    b.values[k].list = past_w;
    CHECK_INT(read_block(&b, &read, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "'length_scale_w' point 1 has order 60; orders run from 0 to 50");
    b.values[k].list = fine;
    CHECK_INT(read_block(&b, &read, &err), 0);
}

/* leaf: names a preset or gives maps; bark: names a preset, whose own angle bark_angle: replaces.
 * The presets keep the textures they had: beech smooth, spruce scaly, willow furrowed, maple
 * fissured. */
TEST(leaf_and_bark_keys)
{
    static const struct { int preset; leaf_affine_preset leaf; bark_fractal_preset bark; } kept[] = {
        {VESSEL_PRESET_BEECH, LEAF_AFFINE_BEECH, BARK_FRACTAL_SMOOTH},
        {VESSEL_PRESET_SPRUCE, LEAF_AFFINE_SPRUCE, BARK_FRACTAL_SCALY},
        {VESSEL_PRESET_WEEPING_WILLOW, LEAF_AFFINE_WILLOW, BARK_FRACTAL_FURROWED},
        {VESSEL_PRESET_MAPLE, LEAF_AFFINE_MAPLE, BARK_FRACTAL_FISSURED},
    };
    for (size_t i = 0; i < sizeof kept / sizeof kept[0]; i++) {
        vessel_params p = preset((vessel_preset)kept[i].preset);
        leaf_affine_maps maps;
        leaf_affine_preset_maps(kept[i].leaf, &maps);
        bark_fractal_params bark = bark_fractal_preset_params(kept[i].bark);
        CHECK(same_leaf(&p.leaf, &maps) && p.leaf_preset == (int)kept[i].leaf);
        CHECK(same_bark(&p.bark, &bark) && p.bark_preset == kept[i].bark);
    }
    block b;
    block_from_defaults(&b, "spruce");
    for (uint32_t i = 0; i < VESSEL_SCHEMA_COUNT; i++) b.values[i].is_set = !strcmp(vessel_schema[i].name, "preset");
    int leaf = sylva_param_index(&b.params, "leaf"), bark = sylva_param_index(&b.params, "bark");
    int angle = sylva_param_index(&b.params, "bark_angle");
    vessel_params read;
    plugin_err err = {0};
    /* a preset's name; a bark preset with its own angle */
    b.values[leaf].is_set = 1, b.values[leaf].s = "shrub";
    b.values[bark].is_set = 1, b.values[bark].i = BARK_FRACTAL_FISSURED;
    CHECK_INT(read_block(&b, &read, &err), 0);
    leaf_affine_maps shrub;
    leaf_affine_preset_maps(LEAF_AFFINE_SHRUB, &shrub);
    CHECK(same_leaf(&read.leaf, &shrub) && read.leaf_preset == LEAF_AFFINE_SHRUB);
    bark_fractal_params fissured = bark_fractal_preset_params(BARK_FRACTAL_FISSURED);
    CHECK(same_bark(&read.bark, &fissured) && read.bark_preset == BARK_FRACTAL_FISSURED);
    /* user maps; the spruce's own bark at another angle */
    b.values[leaf].s = "0.5 0 0 0.5 0.15 0; 0.5 0 0 0.5 0.35 0; 0.5 0 0 0.5 0.15 0.5; 0.5 0 0 0.5 0.35 0.5";
    b.values[bark].is_set = 0;
    b.values[angle].is_set = 1, b.values[angle].r = -90;
    CHECK_INT(read_block(&b, &read, &err), 0);
    CHECK_INT(read.leaf.n, 4);
    CHECK_INT(read.leaf_preset, -1);
    CHECK_NEAR(read.leaf.map[3].f, 0.5, 0);
    bark_fractal_params scaly = bark_fractal_preset_params(BARK_FRACTAL_SCALY);
    CHECK_NEAR(read.bark.theta, -M_PI / 2, 1e-15);
    read.bark.theta = scaly.theta;
    CHECK(same_bark(&read.bark, &scaly));
    /* refused, naming the key */
    static const struct { const char *leaf; const char *key, *why; } bad[] = {
        {"oak", "leaf", "'oak' is not a leaf; give a preset (beech, maple, spruce, shrub, willow)"},
        {"0.5 0 0 0.5 0 x", "leaf", "column"},
        {"1.2 0 0 0.5 0 0", "leaf", "every map must shrink"},
        {"0.5 0 0 0.5 0.8 0", "leaf", "outside the unit square"},
    };
    b.values[angle].is_set = 0;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        b.values[leaf].s = bad[i].leaf;
        memset(&err, 0, sizeof err);
        CHECK_INT(read_block(&b, &read, &err), -1);
        CHECK_STR_CONTAINS(err.param, bad[i].key);
        CHECK_STR_CONTAINS(err.msg, bad[i].why);
    }
}

TEST_LIST(TEST_CASE(leaf_and_bark_keys), TEST_CASE(the_host_accepts_the_schema), TEST_CASE(schema_defaults_are_the_beech_preset),
          TEST_CASE(a_preset_with_keys_replaced), TEST_CASE(orders_past_the_span_are_refused_at_their_key))
