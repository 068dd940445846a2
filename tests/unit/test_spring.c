/* test_spring.c — spring (scene_spring.h): a species flowers only on its blossom days, as a
 * separate "blossom <species>" species whose petals come after every plant, so the plants'
 * instances are the summer ones; the petals of a scene and seed are the same in every build;
 * a flowering species out of leaf still flowers where its leaves will be; new leaves are a
 * lighter green that reaches the summer colour fresh_days after leaf_out; bad blossom keys are
 * refused at their place in the file. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "scene_fixture.h"
#include "work_dir.h"
#include "season/phenology.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "season/scene_spring.h"

/* A deciduous "cherry" in flower from day 100 to 120 (a leaf quad 3 m up, in leaf from day 110),
 * a deciduous "oak" that does not flower, an evergreen "pine" flowering in June: two cherries,
 * one oak, one pine. */
static const char *scene_text =
    "image: {width: 16, height: 12, spp: 1, seed: %d}\n"
    "camera: {position: [0, -30, 5], look_at: [0, 0, 3]}\n"
    "%s"
    "materials:\n"
    "  foliage: {type: leaf, albedo: [0.1, 0.3, 0.05], transmittance: [0.05, 0.2, 0.02]}\n"
    "species:\n"
    "  cherry: {shape: quad, size: [2, 2], material: foliage, phenology: {habit: deciduous, leaf_out: 110,\n"
    "           leaf_fall: 300, fresh_color: [0.4, 0.5, 0.1], fresh_days: 20,\n"
    "           blossom: {first_day: 100, last_day: 120, per_point: 300, size: 0.05}}}\n"
    "  oak: {shape: quad, size: [2, 2], material: foliage, phenology: {habit: deciduous, leaf_out: 110, leaf_fall: 300}}\n"
    "  pine: {shape: quad, size: [2, 2], material: foliage, phenology: {habit: evergreen,\n"
    "         blossom: {first_day: 150, last_day: 170, per_point: 300}}}\n"
    "plants:\n"
    "  - {species: cherry, position: [0, 0, 3], rotation: 30}\n"
    "  - {species: oak, position: [10, 0, 3]}\n"
    "  - {species: pine, position: [20, 0, 3], scale: 1.5}\n"
    "  - {species: cherry, position: [30, 0, 3], age: 0.5}\n";

static scene_file *load_text(const char *text, err_buf *err)
{
    static int k;
    char name[64];
    snprintf(name, sizeof name, "spring_%d.yaml", k++);
    const char *path = work_file(name, text);
    CHECK(path != NULL);
    return path ? scene_file_load(path, NULL, err) : NULL;
}

static scene *build(const char *season_line, int seed)
{
    static char text[4096];
    static int k;
    char name[64];
    snprintf(text, sizeof text, scene_text, seed, season_line);
    snprintf(name, sizeof name, "spring_scene_%d.yaml", k++);
    const char *path = work_file(name, text);
    CHECK(path != NULL);
    return path ? fixture_scene(path) : NULL;
}

static int32_t species_named(const scene *s, const char *name)
{
    for (uint32_t i = 0; i < s->n_species; i++)
        if (s->species[i].name && !strcmp(s->species[i].name, name)) return (int32_t)i;
    return -1;
}

/* The number of instances of species sp. */
static uint32_t count_of(const scene *s, int32_t sp)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->n_instances; i++) n += (int32_t)s->prototypes[s->instances[i].prototype].species == sp;
    return n;
}

TEST(blossom_days_round_the_year)
{
    phenology cherry = {.habit = HABIT_DECIDUOUS, .blossom = {.given = 1, .first = 100, .last = 120, .size = 0.02}};
    CHECK_INT(phenology_blossom_day(&cherry, 99), -1);
    CHECK_INT(phenology_blossom_day(&cherry, 100), 0);
    CHECK_INT(phenology_blossom_day(&cherry, 120), 20);
    CHECK_INT(phenology_blossom_day(&cherry, 121), -1);
    phenology south = {.blossom = {.given = 1, .first = 350, .last = 10}}; /* over new year */
    CHECK_INT(phenology_blossom_day(&south, 5), 21);
    CHECK_INT(phenology_blossom_day(&south, 200), -1);
    phenology none = {.blossom = {.given = 0, .first = 100, .last = 120}};
    CHECK_INT(phenology_blossom_day(&none, 110), -1);
    /* every flower lives within the blossom days */
    blossom_params p;
    double clock;
    CHECK_INT(scene_blossom_params(&cherry, 130, &p, &clock), 0);
    CHECK_INT(scene_blossom_params(&cherry, 105, &p, &clock), 1);
    CHECK_NEAR(clock, 105.5, 1e-12);
    CHECK(p.first_day == 100 && p.last_day + p.lifetime_max <= 121 + 1e-9);
    err_buf err = {{0}};
    CHECK_INT(blossom_params_check(&p, &err), 0);
}

TEST(flowers_only_on_the_blossom_days)
{
    scene *summer = build("", 1), *spring = build("season: 2026-04-15\n", 1), *june = build("season: 2026-06-10\n", 1);
    CHECK(summer && spring && june);
    if (summer && spring && june) {
        CHECK_INT(summer->n_instances, 4); /* no species flowers in July */
        CHECK_INT(species_named(summer, "blossom cherry"), -1);
        int32_t cherry = species_named(spring, "blossom cherry");
        CHECK(cherry >= 0);
        CHECK(count_of(spring, cherry) > 100);
        CHECK_INT(species_named(spring, "blossom oak"), -1);
        CHECK_INT(species_named(spring, "blossom pine"), -1);
        CHECK(species_named(june, "blossom pine") >= 0); /* an evergreen may flower too */
        CHECK_INT(species_named(june, "blossom cherry"), -1);
        CHECK(spring->species[cherry].ground_cover); /* no canopy, no crown proxy */
    }
    scene_free(summer), scene_free(spring), scene_free(june);
}

/* The plants are the summer plants, first and in order; every instance after them is a petal. */
TEST(plants_keep_their_instances)
{
    scene *summer = build("", 1), *spring = build("season: 2026-04-15\n", 1);
    CHECK(summer && spring);
    if (summer && spring) {
        CHECK(spring->n_instances > summer->n_instances);
        for (uint32_t i = 0; i < summer->n_instances; i++) {
            CHECK_INT(spring->instances[i].prototype, summer->instances[i].prototype);
            CHECK(!memcmp(&spring->instances[i].xf, &summer->instances[i].xf, sizeof summer->instances[i].xf));
            CHECK_INT(spring->instances[i].development, summer->instances[i].development);
        }
        for (uint32_t i = summer->n_instances; i < spring->n_instances; i++)
            CHECK(!strncmp(spring->species[spring->prototypes[spring->instances[i].prototype].species].name,
                           "blossom ", 8));
        for (uint32_t k = 0; k < summer->n_species; k++) CHECK(!strcmp(spring->species[k].name, summer->species[k].name));
    }
    scene_free(summer), scene_free(spring);
}

/* The same scene and seed give the same petals; another seed others. */
TEST(petals_the_same_for_a_seed)
{
    scene *a = build("season: 2026-04-15\n", 1), *b = build("season: 2026-04-15\n", 1),
          *c = build("season: 2026-04-15\n", 2);
    CHECK(a && b && c);
    if (a && b && c) {
        CHECK_INT(b->n_instances, a->n_instances);
        int same = a->n_instances == b->n_instances, other = a->n_instances == c->n_instances;
        for (uint32_t i = 0; same && i < a->n_instances; i++)
            same = a->instances[i].prototype == b->instances[i].prototype &&
                   !memcmp(&a->instances[i].xf, &b->instances[i].xf, sizeof a->instances[i].xf);
        for (uint32_t i = 4; other && i < a->n_instances; i++)
            other = !memcmp(&a->instances[i].xf, &c->instances[i].xf, sizeof a->instances[i].xf);
        CHECK(same);
        CHECK(!other);
    }
    scene_free(a), scene_free(b), scene_free(c);
}

/* On day 105 the cherry is out of leaf (its leaf triangles dropped) but in flower: the flowers
 * stand where its leaves will be, on the 2 m quad 3 m up. */
TEST(flowers_before_leaf_out)
{
    scene *s = build("season: 2026-04-15\n", 1);
    CHECK(s != NULL);
    if (!s) return;
    const species *cherry = &s->species[0];
    CHECK_INT(s->prototypes[cherry->first_prototype].mesh->nt, 0);
    int32_t petals = species_named(s, "blossom cherry");
    CHECK(petals >= 0);
    uint32_t n = 0, near = 0;
    for (uint32_t i = 4; i < s->n_instances; i++) {
        const float *t = (const float[]){s->instances[i].xf.m[0][3], s->instances[i].xf.m[1][3], s->instances[i].xf.m[2][3]};
        double x = fmod(t[0] + 5, 30) - 5; /* the cherries stand at x = 0 and 30 */
        n++;
        near += fabs(x) < 1.5 && fabs(t[1]) < 1.5 && fabs(t[2] - 3) < 0.1;
    }
    CHECK(n > 100);
    CHECK_INT(near, n);
    scene_free(s);
}

/* The albedo of the cherry's leaf material on a day. */
static double leaf_green(const scene *s, uint32_t sp)
{
    const mesh *m = s->prototypes[s->species[sp].first_prototype].mesh;
    return m->nt ? s->materials[scene_triangle_material(s, m, 0)].albedo.y : -1;
}

TEST(fresh_leaves_reach_the_summer_green)
{
    scene *summer = build("", 1), *new_leaves = build("season: 2026-04-20\n", 1),
          *later = build("season: 2026-04-30\n", 1), *month = build("season: 2026-05-15\n", 1);
    CHECK(summer && new_leaves && later && month);
    if (summer && new_leaves && later && month) {
        CHECK_NEAR(leaf_green(summer, 0), 0.3, 1e-6);
        CHECK_NEAR(leaf_green(new_leaves, 0), 0.5, 1e-6);           /* day 110: leaf_out */
        CHECK_NEAR(leaf_green(later, 0), 0.3 + 0.5 * 0.2, 1e-6);    /* day 120: half way */
        CHECK_NEAR(leaf_green(month, 0), 0.3, 1e-6);                /* day 135: summer */
        CHECK_NEAR(leaf_green(new_leaves, 1), 0.2 + 0.1 * 0 + 0.14, 1e-6); /* the oak: default fresh_color */
        CHECK_NEAR(leaf_green(new_leaves, 2), 0.3, 1e-6);           /* the evergreen keeps its needles */
    }
    scene_free(summer), scene_free(new_leaves), scene_free(later), scene_free(month);
}

static void refused(const char *block, const char *where, const char *what)
{
    char text[2048];
    snprintf(text, sizeof text,
             "camera: {position: [0, -30, 5], look_at: [0, 0, 3]}\n"
             "species:\n"
             "  cherry:\n"
             "    shape: quad\n"
             "    phenology: %s\n",
             block);
    err_buf err = {{0}};
    scene_file *sf = load_text(text, &err);
    CHECK(sf == NULL);
    scene_file_free(sf);
    CHECK_STR_CONTAINS(err.msg, where);
    CHECK_STR_CONTAINS(err.msg, what);
}

TEST(bad_blossom_keys_refused_where_written)
{
    refused("{habit: deciduous, blossom: {first_day: 0}}", ":5:56: ", "first_day");
    refused("{habit: deciduous, blossom: {size: 0}}", ":5:51: ", "size");
    refused("{habit: deciduous, blossom: {color: [1, 2, 0]}}", ":5:56: ", "color");
    refused("{habit: deciduous, blossom: {petals: 3}}", ":5:45: ", "petals");
    refused("{habit: deciduous, blossom: yes}", ":5:44: ", "blossom");
    refused("{habit: evergreen, fresh_days: 10}", ":5:47: ", "as do fresh_color and fresh_days");
    refused("{habit: deciduous, fresh_days: 400}", ":5:47: ", "fresh_days");
}

TEST_LIST(TEST_CASE(blossom_days_round_the_year), TEST_CASE(flowers_only_on_the_blossom_days),
          TEST_CASE(plants_keep_their_instances), TEST_CASE(petals_the_same_for_a_seed),
          TEST_CASE(flowers_before_leaf_out), TEST_CASE(fresh_leaves_reach_the_summer_green),
          TEST_CASE(bad_blossom_keys_refused_where_written))
