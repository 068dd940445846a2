/* test_eco_planted.c — a planting plan's blocks and belts grown by the scene's ecology through
 * the real host (scene_build/planting_ecology.h, the plugin's eco_planted.c): the plants
 * standing at a later year are some of those standing at an earlier one, each in the same
 * place with the same number; a block planted far closer than its crowns loses plants by year
 * 30 where a sparse one keeps more; the same plants stand on one thread and on two; a plan
 * with `ecology: false` keeps every plant; single trees never die of it; `age_existing: true`
 * grows the scene's own ecology on through the plan's years; no plant is lost during the
 * plan's maintenance_years; a row of the prairie's post oaks (scenes/species/prairie.yaml) outlives
 * its maintenance on the prairie's ground. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "plugin/plugin_host.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "work_dir.h"

/* A flat site 120 m by 60 m with an oak grown by the ecology's beech profile (no deaths from
 * the site's conditions: env_death 0), a 6 m sphere; a dense block at 1 m (its plants' crowns
 * overlap from planting), a sparse block at 9 m, a single tree; `extra` in the plan. */
static const char *plan_text(const char *extra, uint32_t ecology_years)
{
    static char text[8192];
    snprintf(text, sizeof text,
             "earth: {curvature: false}\n"
             "terrain:\n  origin: [0, 0]\n  spacing: [20, 20]\n  grid:\n"
             "    - [0, 0, 0, 0, 0, 0, 0]\n    - [0, 0, 0, 0, 0, 0, 0]\n    - [0, 0, 0, 0, 0, 0, 0]\n"
             "    - [0, 0, 0, 0, 0, 0, 0]\n"
             "species:\n  oak: {shape: sphere, radius: 3, ecology: {profile: beech, env_death: 0}}\n"
             "ecology: {plugin: ecology, years: %u, patches: 24}\n"
             "planting:\n  year: 2027\n  seed: 4\n%s"
             "  blocks:\n"
             "    - {name: dense, polygon: [[5, 5], [25, 5], [25, 25], [5, 25]], species: oak, spacing: 1}\n"
             "    - {name: sparse, polygon: [[60, 5], [110, 5], [110, 55], [60, 55]], species: oak, spacing: 9}\n"
             "  trees:\n    - {position: [40, 40], species: oak}\n",
             ecology_years, extra);
    return text;
}

static plugin_registry *registry(void)
{
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open_path(SYLVA_PLUGIN_BUILD_DIR, &err);
    CHECK(reg != NULL);
    return reg;
}

/* The plan built at `year` on `threads` threads, the scene's ecology grown `ecology_years`, or
 * NULL (the sentence printed). */
static scene *plan_grown(plugin_registry *reg, const char *extra, uint32_t ecology_years, double year,
                         unsigned threads)
{
    err_buf err = {{0}};
    const char *path = work_file("planted.yaml", plan_text(extra, ecology_years));
    scene_file *sf = path ? scene_file_load_with(path, reg, SCENE_FILE_NO_CAMERA, &err) : NULL;
    build_options bo = {.analysis = 1, .quiet = 1, .planting_shown = 1, .planting_years = year, .threads = threads};
    scene *s = sf ? scene_build(sf, reg, &bo, &err) : NULL;
    if (!s) fprintf(stderr, "  %s\n", err.msg);
    scene_file_free(sf);
    return s;
}

static scene *plan_at(plugin_registry *reg, const char *extra, double year, unsigned threads)
{
    return plan_grown(reg, extra, 0, year, threads);
}

/* The instance with plan number `planted`, or NULL. */
static const instance *planted_plant(const scene *s, uint32_t planted)
{
    for (uint32_t i = 0; i < s->n_instances; i++)
        if (s->instances[i].planted == planted) return &s->instances[i];
    return NULL;
}

/* Plants of the block (dense: x < 30; sparse: x > 50 except the tree at 40) standing. */
static uint32_t count_in(const scene *s, double x0, double x1)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->n_instances; i++) {
        double x = s->instances[i].xf.m[0][3];
        n += s->instances[i].planted && x >= x0 && x < x1;
    }
    return n;
}

/* Year 20's plants are some of year 10's, and year 10's some of year 1's: the same numbers in
 * the same places; the dense block loses plants from year to year. */
TEST(survivors_are_some_of_the_years_before_in_their_places)
{
    plugin_registry *reg = registry();
    scene *y[3] = {plan_at(reg, "", 1, 0), plan_at(reg, "", 10, 0), plan_at(reg, "", 20, 0)};
    CHECK(y[0] && y[1] && y[2]);
    for (int k = 1; k < 3 && y[0] && y[1] && y[2]; k++) {
        uint32_t planted = 0;
        for (uint32_t i = 0; i < y[k]->n_instances; i++) {
            const instance *later = &y[k]->instances[i];
            if (!later->planted) continue;
            planted++;
            const instance *before = planted_plant(y[k - 1], later->planted);
            CHECK(before != NULL);
            if (!before) continue;
            CHECK_NEAR(later->xf.m[0][3], before->xf.m[0][3], 1e-9);
            CHECK_NEAR(later->xf.m[1][3], before->xf.m[1][3], 1e-9);
        }
        CHECK(planted > 0);
        fprintf(stderr, "  dense block: %u plants in year %s, %u in year %s\n", count_in(y[k - 1], 0, 30),
                k == 1 ? "1" : "10", count_in(y[k], 0, 30), k == 1 ? "10" : "20");
        CHECK(count_in(y[k], 0, 30) < count_in(y[k - 1], 0, 30));
    }
    for (int k = 0; k < 3; k++) scene_free(y[k]);
    plugin_registry_free(reg);
}

/* One way to build the plan: the plan's extra keys, the year, the threads. */
typedef struct plan_case {
    const char *extra;
    double year;
    unsigned threads;
} plan_case;

/* Builds the plan both ways and hands both scenes to `check`. */
static void with_two_plans(plan_case first, plan_case second, void (*check)(const scene *, const scene *))
{
    plugin_registry *reg = registry();
    scene *a = plan_at(reg, first.extra, first.year, first.threads);
    scene *b = plan_at(reg, second.extra, second.year, second.threads);
    CHECK(a && b);
    if (a && b) check(a, b);
    scene_free(a), scene_free(b);
    plugin_registry_free(reg);
}

static void dense_and_sparse(const scene *drawn, const scene *grown)
{
    double dense0 = count_in(drawn, 0, 30), sparse0 = count_in(drawn, 50, 120);
    double dense = count_in(grown, 0, 30), sparse = count_in(grown, 50, 120);
    fprintf(stderr, "  year 30: dense %.0f of %.0f, sparse %.0f of %.0f\n", dense, dense0, sparse, sparse0);
    CHECK(dense0 >= 400 && sparse0 >= 30);
    CHECK(dense < 0.5 * dense0);
    CHECK(sparse / sparse0 > 0.8);
    CHECK(sparse / sparse0 > 2 * dense / dense0);
    CHECK(count_in(grown, 35, 45) == 1 && count_in(drawn, 35, 45) == 1); /* the single tree */
}

/* By year 30 the dense block (1 m apart, crowns 1.5 m across at planting) keeps a small share
 * of its plants, the sparse one (9 m apart) nearly all; the single tree stands; with
 * `ecology: false` every plant stands. */
TEST(dense_block_thins_and_sparse_keeps_more)
{
    with_two_plans((plan_case){"  ecology: false\n", 30, 0}, (plan_case){"", 30, 0}, dense_and_sparse);
}

static void the_same_plants(const scene *one, const scene *two)
{
    CHECK_INT(one->n_instances, two->n_instances);
    for (uint32_t i = 0; i < one->n_instances && i < two->n_instances; i++) {
        CHECK_INT(one->instances[i].planted, two->instances[i].planted);
        CHECK(!memcmp(&one->instances[i].xf, &two->instances[i].xf, sizeof one->instances[i].xf));
    }
}

static void all_stand(const scene *drawn, const scene *maintained)
{
    fprintf(stderr, "  year 8 of 8 maintained: dense %u of %u, sparse %u of %u\n", count_in(maintained, 0, 30),
            count_in(drawn, 0, 30), count_in(maintained, 50, 120), count_in(drawn, 50, 120));
    CHECK(count_in(drawn, 0, 30) >= 400);
    CHECK_INT(count_in(maintained, 0, 30), count_in(drawn, 0, 30));
    CHECK_INT(count_in(maintained, 50, 120), count_in(drawn, 50, 120));
}

static void fewer_after(const scene *drawn, const scene *later)
{
    fprintf(stderr, "  year 16, maintained to 8: dense %u of %u\n", count_in(later, 0, 30), count_in(drawn, 0, 30));
    CHECK(count_in(later, 0, 30) < count_in(drawn, 0, 30));
}

/* Through the establishment period (maintenance_years: 8) a dead plant is replaced in kind: in
 * year 8 every plant of the dense block stands; from then on it thins. */
TEST(no_plant_lost_during_maintenance_years)
{
    with_two_plans((plan_case){"  ecology: false\n", 8, 0}, (plan_case){"  maintenance_years: 8\n", 8, 0}, all_stand);
    with_two_plans((plan_case){"  ecology: false\n", 16, 0}, (plan_case){"  maintenance_years: 8\n", 16, 0}, fewer_after);
}

/* One thread and two: the same plants stand, as tall. */
TEST(same_survivors_on_one_and_two_threads)
{
    with_two_plans((plan_case){"", 25, 1}, (plan_case){"", 25, 2}, the_same_plants);
}

/* A flat site 200 m by 40 m at the wind farm's latitude (flat ground there is as sunny as
 * scenes/wind_farm.yaml's uplands; altitude and humidity, without spread, take the middle value)
 * with the prairie's species file, post oak alone in the ecology, and a row of ten feathered post
 * oaks 10 m apart (their ecological circles apart well past year 30); `extra` in the plan. */
static const char *prairie_row_text(const char *extra)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "earth: {curvature: false}\n"
             "terrain:\n  origin: [0, 0]\n  spacing: [40, 40]\n  grid:\n"
             "    - [0, 0, 0, 0, 0, 0]\n    - [0, 0, 0, 0, 0, 0]\n"
             "species: {include: [%s]}\n"
             "ecology: {plugin: ecology, years: 0, patches: 20, latitude: 32.7, species: post_oak}\n"
             "planting:\n  year: 2027\n  seed: 4\n%s"
             "  belts:\n"
             "    - {name: row, line: [[50, 20], [150, 20]], species: post_oak, spacing: 10, stock: feathered}\n",
             SYLVA_TEST_DATA_DIR "/../scenes/species/prairie.yaml", extra);
    return text;
}

static scene *prairie_row_at(plugin_registry *reg, const char *extra, double year)
{
    err_buf err = {{0}};
    const char *path = work_file("prairie_row.yaml", prairie_row_text(extra));
    scene_file *sf = path ? scene_file_load_with(path, reg, SCENE_FILE_NO_CAMERA, &err) : NULL;
    build_options bo = {.analysis = 1, .quiet = 1, .planting_shown = 1, .planting_years = year};
    scene *s = sf ? scene_build(sf, reg, &bo, &err) : NULL;
    if (!s) fprintf(stderr, "  %s\n", err.msg);
    scene_file_free(sf);
    return s;
}

/* The prairie's post oak is at home on the prairie: a row set out apart, no crown touching
 * another, still stands 20 years after planting, 15 after its maintenance (the default five
 * years) ended; only a death of age (4.26: about one in fifty by then) may take one. A species
 * whose optima are not the prairie's loses most of such a row to the site's conditions
 * (env_death) once its failures are no longer replaced. */
TEST(prairie_post_oak_row_outlives_its_maintenance)
{
    plugin_registry *reg = registry();
    scene *drawn = prairie_row_at(reg, "  ecology: false\n", 20), *grown = prairie_row_at(reg, "", 20);
    CHECK(drawn && grown);
    if (drawn && grown) {
        uint32_t planted = count_in(drawn, 0, 200), standing = count_in(grown, 0, 200);
        fprintf(stderr, "  year 20: %u of %u post oaks stand\n", standing, planted);
        CHECK_INT(planted, 10);
        CHECK(standing >= 9);
    }
    scene_free(drawn), scene_free(grown);
    plugin_registry_free(reg);
}

/* The scene's own plants (no plan number) of a, the same as b's: as many, in the same places. */
static int same_existing(const scene *a, const scene *b)
{
    uint32_t i = 0, k = 0, same = 1;
    for (;; i++, k++) {
        while (i < a->n_instances && a->instances[i].planted) i++;
        while (k < b->n_instances && b->instances[k].planted) k++;
        if (i >= a->n_instances || k >= b->n_instances) return same && i >= a->n_instances && k >= b->n_instances;
        same = same && a->instances[i].xf.m[0][3] == b->instances[k].xf.m[0][3] &&
               a->instances[i].xf.m[1][3] == b->instances[k].xf.m[1][3] &&
               a->instances[i].xf.m[2][2] == b->instances[k].xf.m[2][2];
    }
}

static uint32_t existing_count(const scene *s)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->n_instances; i++) n += !s->instances[i].planted;
    return n;
}

/* With age_existing the scene's ecology of 12 years shown 6 years after planting is the
 * ecology of 18 years, plant for plant; without, the ecology of 12. */
TEST(age_existing_grows_the_scenes_ecology_on)
{
    plugin_registry *reg = registry();
    scene *aged = plan_grown(reg, "  age_existing: true\n", 12, 6, 0), *kept = plan_grown(reg, "", 12, 6, 0);
    scene *of12 = plan_grown(reg, "", 12, 0, 0), *of18 = plan_grown(reg, "", 18, 0, 0);
    CHECK(aged && kept && of12 && of18);
    if (aged && kept && of12 && of18) {
        fprintf(stderr, "  the ecology's plants: %u aged, %u kept; %u of 12 years, %u of 18\n", existing_count(aged),
                existing_count(kept), existing_count(of12), existing_count(of18));
        CHECK(existing_count(of12) > 0 && existing_count(of18) > 0);
        CHECK(same_existing(aged, of18));
        CHECK(same_existing(kept, of12));
        CHECK(!same_existing(aged, kept));
    }
    scene_free(aged), scene_free(kept), scene_free(of12), scene_free(of18);
    plugin_registry_free(reg);
}

TEST_LIST(TEST_CASE(age_existing_grows_the_scenes_ecology_on), TEST_CASE(survivors_are_some_of_the_years_before_in_their_places),
          TEST_CASE(dense_block_thins_and_sparse_keeps_more), TEST_CASE(same_survivors_on_one_and_two_threads),
          TEST_CASE(no_plant_lost_during_maintenance_years),
          TEST_CASE(prairie_post_oak_row_outlives_its_maintenance))
