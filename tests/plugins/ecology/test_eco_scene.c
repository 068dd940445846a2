/* test_eco_scene.c — the plugin through the real host: scene files with bad ecology input stop
 * with located sentences; a small forest becomes instances standing on the terrain; the
 * "sylva.ecology.v1" session gives the plants scene_build places and continues a saved run
 * exactly; the host's instancing picks the variant by age, scales by height and turns; the
 * succession scene passes through the stages of 004 ch. 6. */
#include <stdio.h>
#include <unistd.h>

#include "harness.h"
#include "plugin/plugin_host.h"
#include "scene_build/ecology_session.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "sylva/ecology_ext.h"

#define SCENES SYLVA_TEST_DATA_DIR "/plugins/ecology/scenes"

static plugin_registry *registry(void)
{
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open_path(SYLVA_PLUGIN_BUILD_DIR, &err);
    CHECK(reg != NULL);
    err_buf lookup = {{0}};
    CHECK(plugin_registry_find(reg, "ecology", SYLVA_KIND_ECOLOGY, &lookup) != NULL);
    return reg;
}

/* Loads and builds `name`; returns the error sentence (empty on success) in err. */
static scene *load_and_build(plugin_registry *reg, const char *name, scene_file **sf_out, err_buf *err)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", SCENES, name);
    build_options bo = {.quiet = 1};
    scene_file *sf = scene_file_load(path, reg, err);
    scene *s = sf ? scene_build(sf, reg, &bo, err) : NULL;
    if (sf_out) *sf_out = sf;
    else scene_file_free(sf);
    return s;
}

/* The text after "# expect: " on the scene's first line. */
static void expected(const char *name, char *out, size_t n)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", SCENES, name);
    FILE *f = fopen(path, "r");
    out[0] = '\0';
    if (f && fgets(out, (int)n, f) && !strncmp(out, "# expect: ", 10)) {
        memmove(out, out + 10, strlen(out + 10) + 1);
        out[strcspn(out, "\n")] = '\0';
    }
    if (f) fclose(f);
}

TEST(bad_input_is_refused_with_its_place)
{
    plugin_registry *reg = registry();
    const char *bad[] = {"unknown_species.yaml", "negative_age.yaml", "ages_out_of_order.yaml",
                         "growth_area_outside.yaml", "even_sun_samples.yaml", "unknown_species_key.yaml"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        err_buf err = {{0}};
        char want[256];
        expected(bad[i], want, sizeof want);
        CHECK(want[0] != '\0');
        scene *s = load_and_build(reg, bad[i], NULL, &err);
        CHECK(s == NULL);
        CHECK_STR_CONTAINS(err.msg, want);
        CHECK_STR_CONTAINS(err.msg, bad[i]); /* located in the scene file */
        fprintf(stderr, "  %s -> %s\n", bad[i], err.msg);
        scene_free(s);
    }
    plugin_registry_free(reg);
}

TEST(forest_stands_on_the_terrain)
{
    plugin_registry *reg = registry();
    err_buf err = {{0}};
    scene_file *sf = NULL;
    scene *s = load_and_build(reg, "small_forest.yaml", &sf, &err);
    CHECK(s != NULL);
    if (!s) {
        fprintf(stderr, "%s\n", err.msg);
        plugin_registry_free(reg);
        return;
    }
    CHECK(s->n_instances > 50);
    uint32_t per_species[3] = {0};
    for (uint32_t i = 0; i < s->n_instances; i++) {
        const instance *in = &s->instances[i];
        per_species[s->prototypes[in->prototype].species]++;
        double z;
        CHECK_INT(scene_terrain_height(s, in->xf.m[0][3], in->xf.m[1][3], &z), 0);
        CHECK_NEAR(in->xf.m[2][3], z, 1e-3);
    }
    CHECK(per_species[0] > 0 && per_species[1] > 0);
    CHECK_INT(per_species[2], 0); /* crate takes no part: `species: beech shrub` */

    /* The session, stepped to the scene's year, holds the same plants (min_height is 0). */
    build_options bo = {.quiet = 1, .no_ecology = 1};
    scene *bare = scene_build(sf, reg, &bo, &err);
    CHECK(bare != NULL && bare->n_instances == 0);
    ecology_session *e = ecology_session_open(sf, bare, reg, &bo, &err);
    CHECK(e != NULL);
    CHECK_INT(ecology_session_years_wanted(e), 40);
    CHECK_INT(ecology_session_step(e, 40, &err), 0);
    sylva_ecology_plant_record *p = NULL;
    uint32_t n = 0;
    CHECK_INT(ecology_session_plants(e, &p, &n, &err), 0);
    uint32_t grown = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (!(p[i].height > 0)) continue;
        const xform3x4 *xf = &s->instances[grown].xf;
        CHECK_NEAR(xf->m[0][3], p[i].position[0], 1e-3);
        CHECK_NEAR(xf->m[1][3], p[i].position[1], 1e-3);
        CHECK_INT(s->prototypes[s->instances[grown].prototype].species, p[i].species);
        grown++;
    }
    CHECK_INT(grown, s->n_instances);
    free(p);
    ecology_session_free(e);
    scene_free(bare);
    scene_free(s);
    scene_file_free(sf);
    plugin_registry_free(reg);
}

static int same_records(const sylva_ecology_plant_record *a, uint32_t na, const sylva_ecology_plant_record *b,
                        uint32_t nb)
{
    if (na != nb) return 0;
    for (uint32_t i = 0; i < na; i++)
        if (a[i].species != b[i].species || a[i].position[0] != b[i].position[0] ||
            a[i].position[1] != b[i].position[1] || a[i].age != b[i].age || a[i].height != b[i].height ||
            a[i].radius != b[i].radius || a[i].vigour != b[i].vigour)
            return 0;
    return 1;
}

TEST(session_save_load_continue)
{
    plugin_registry *reg = registry();
    err_buf err = {{0}};
    char path[512], state[256];
    snprintf(path, sizeof path, "%s/small_forest.yaml", SCENES);
    snprintf(state, sizeof state, "/tmp/sylva_eco_session_%ld.state", (long)getpid());
    scene_file *sf = scene_file_load(path, reg, &err);
    build_options bo = {.quiet = 1, .no_ecology = 1};
    scene *s = scene_build(sf, reg, &bo, &err);
    ecology_session *whole = ecology_session_open(sf, s, reg, &bo, &err);
    ecology_session *part = ecology_session_open(sf, s, reg, &bo, &err);
    ecology_session *rest = ecology_session_open(sf, s, reg, &bo, &err);
    CHECK(whole && part && rest);
    CHECK_INT(ecology_session_step(whole, 50, &err), 0);
    CHECK_INT(ecology_session_step(part, 20, &err), 0);
    CHECK_INT(ecology_session_save(part, state, &err), 0);
    CHECK_INT(ecology_session_load(rest, state, &err), 0);
    CHECK_INT(ecology_session_year(rest), 20);
    CHECK_INT(ecology_session_step(rest, 30, &err), 0);
    sylva_ecology_plant_record *a = NULL, *b = NULL;
    uint32_t na = 0, nb = 0;
    CHECK_INT(ecology_session_plants(whole, &a, &na, &err), 0);
    CHECK_INT(ecology_session_plants(rest, &b, &nb, &err), 0);
    CHECK(na > 50);
    CHECK(same_records(a, na, b, nb));
    CHECK(ecology_session_load(rest, "/nonexistent/x.state", &err) != 0);
    CHECK_STR_CONTAINS(err.msg, "ecology plugin 'ecology'");
    CHECK_STR_CONTAINS(err.msg, "cannot read the ecology state");
    free(a), free(b);
    remove(state);
    ecology_session_free(whole), ecology_session_free(part), ecology_session_free(rest);
    scene_free(s);
    scene_file_free(sf);
    plugin_registry_free(reg);
}

/* The shares of the living plants by species group at a year of the succession scene: beech
 * and maple (broadleaves), spruce, shrub; counted as `sylva simulate --stats` counts (004
 * Fig. C.13). */
typedef struct succession_shares {
    double broadleaf, spruce, shrub;
    uint32_t plants;
} succession_shares;

static succession_shares shares_of(const scene_file *sf, const sylva_ecology_plant_record *p, uint32_t n)
{
    uint32_t broadleaf = 0, spruce = 0, shrub = 0;
    for (uint32_t k = 0; k < n; k++) {
        const char *name = sf->species[p[k].species].name;
        if (!strcmp(name, "beech") || !strcmp(name, "maple")) broadleaf++;
        else if (!strcmp(name, "spruce")) spruce++;
        else if (!strcmp(name, "shrub")) shrub++;
    }
    double all = n ? n : 1;
    return (succession_shares){broadleaf / all, spruce / all, shrub / all, n};
}

/* The thesis's succession (004 ch. 6) on scenes/succession_180.yaml, in bands read from its
 * text (docs/models/ecology.md, "Succession timing"): at 20 years the shrubs have spread over the
 * terrain and are nearly every plant (Fig. 6.2); at 60 they begin to give way and the larger
 * broadleaves begin to settle (Fig. 6.3); at 80 the spruce advances (Fig. 6.4); at 180 all four
 * grow, the trees outnumber the shrubs and the shrubs keep a share (Fig. 6.5). */
TEST(succession_follows_the_thesis)
{
    plugin_registry *reg = registry();
    err_buf err = {{0}};
    const char *path = SYLVA_TEST_DATA_DIR "/../scenes/succession_180.yaml";
    scene_file *sf = scene_file_load(path, reg, &err);
    build_options bo = {.quiet = 1, .no_ecology = 1};
    scene *s = sf ? scene_build(sf, reg, &bo, &err) : NULL;
    ecology_session *e = s ? ecology_session_open(sf, s, reg, &bo, &err) : NULL;
    CHECK(e != NULL);
    if (!e) fprintf(stderr, "%s\n", err.msg);
    static const uint32_t years[4] = {20, 60, 80, 180};
    succession_shares at[4] = {{0}};
    for (int k = 0; e && k < 4; k++) {
        CHECK_INT(ecology_session_step(e, years[k] - (k ? years[k - 1] : 0), &err), 0);
        sylva_ecology_plant_record *p = NULL;
        uint32_t n = 0;
        CHECK_INT(ecology_session_plants(e, &p, &n, &err), 0);
        at[k] = shares_of(sf, p, n);
        fprintf(stderr, "  year %3u: %6u plants, broadleaves %5.1f %%, spruce %5.1f %%, shrubs %5.1f %%\n",
                years[k], n, 100 * at[k].broadleaf, 100 * at[k].spruce, 100 * at[k].shrub);
        free(p);
    }
    if (e) {
        /* 20 (Fig. 6.2): the shrubs spread first and fastest */
        CHECK(at[0].plants >= 500);
        CHECK(at[0].shrub >= 0.9);
        /* 60 (Fig. 6.3): the broadleaves begin to settle, the shrubs begin to give way */
        CHECK(at[1].broadleaf >= 0.005 && at[1].broadleaf <= 0.5);
        CHECK(at[1].broadleaf > 2 * at[0].broadleaf);
        CHECK(at[1].shrub < at[0].shrub);
        CHECK(at[1].plants > 5 * at[0].plants); /* the terrain is overgrown */
        /* 80 (Fig. 6.4): the spruce advances, the broadleaves go on gaining */
        CHECK(at[2].spruce > 2 * at[1].spruce);
        CHECK(at[2].broadleaf >= 0.05 && at[2].broadleaf <= 0.6);
        CHECK(at[2].shrub < at[1].shrub);
        /* 180 (Fig. 6.5): all four grow; the trees hold most of the terrain */
        CHECK(at[3].broadleaf >= 0.2 && at[3].spruce >= 0.1);
        CHECK(at[3].shrub >= 0.05 && at[3].shrub <= 0.3);
        CHECK(at[3].broadleaf + at[3].spruce >= 0.6);
    }
    ecology_session_free(e);
    scene_free(s);
    scene_file_free(sf);
    plugin_registry_free(reg);
}

/* A scene with one species of four age variants (heights 2, 4, 6, 8 m) over a tilted plane. */
static scene *variant_scene(void)
{
    scene *s = scene_new();
    sylva_heightfield *hf = calloc(1, sizeof *hf);
    float *z = malloc(4 * sizeof *z);
    z[0] = 0, z[1] = 10, z[2] = 0, z[3] = 10; /* z = x / 10 over [0, 100]^2 */
    *hf = (sylva_heightfield){.size = sizeof *hf, .nx = 2, .ny = 2, .dx = 100, .dy = 100, .z = z, .water_material = -1};
    s->terrain = hf;
    s->species = calloc(1, sizeof(species));
    s->species[0] = (species){.name = strdup("tree"), .first_prototype = 0, .n_variants = 4};
    s->n_species = 1;
    err_buf err;
    for (uint32_t v = 0; v < 4; v++) scene_add_prototype(s, 0, v, (v + 1) / 4.0, 2.0 * (v + 1), mesh_new(), &err);
    return s;
}

TEST(instancing_by_age_height_and_turn)
{
    scene *s = variant_scene();
    err_buf err = {{0}};
    sylva_plant p[3] = {
        {.size = sizeof(sylva_plant), .position = {50, 20, 0}, .snap_to_terrain = 1, .rotation = M_PI / 2,
         .height = 3, .age = 0.3},
        {.size = sizeof(sylva_plant), .position = {10, 10, 7}, .snap_to_terrain = 0, .rotation = 0, .height = 16,
         .age = 1.0},
        {.size = sizeof(sylva_plant), .position = {0, 0, 0}, .snap_to_terrain = 1, .height = 0, .age = 0.1}};
    CHECK_INT(scene_place_plants(s, p, 3, &err), 0);
    CHECK_INT(s->n_instances, 3);
    /* age 0.3: the youngest variant at least as old, 0.5 (4 m), scaled to 3 m and turned by 90 degrees */
    CHECK_INT(s->instances[0].prototype, 1);
    vec3 q = xf_point(&s->instances[0].xf, v3(1, 0, 0));
    CHECK_NEAR(q.x, 50, 1e-5);
    CHECK_NEAR(q.y, 20 + 0.75, 1e-5);
    CHECK_NEAR(q.z, 5, 1e-5); /* on the terrain: z = 50 / 10 */
    /* full grown, 16 m from the 8 m variant, at its own z */
    CHECK_INT(s->instances[1].prototype, 3);
    CHECK_NEAR(s->instances[1].xf.m[2][2], 2.0, 1e-6);
    CHECK_NEAR(s->instances[1].xf.m[2][3], 7.0, 1e-6);
    /* height 0: unscaled */
    CHECK_INT(s->instances[2].prototype, 0);
    CHECK_NEAR(s->instances[2].xf.m[0][0], 1.0, 1e-6);
    /* bad plants name themselves */
    sylva_plant bad = p[0];
    bad.position[0] = NAN;
    CHECK(scene_place_plants(s, &bad, 1, &err) != 0);
    CHECK_STR_CONTAINS(err.msg, "plant 0:");
    bad = p[0], bad.position[0] = 500;
    CHECK(scene_place_plants(s, &bad, 1, &err) != 0);
    CHECK_STR_CONTAINS(err.msg, "outside the terrain");
    scene_free(s);
}

TEST_LIST(TEST_CASE(bad_input_is_refused_with_its_place), TEST_CASE(succession_follows_the_thesis), TEST_CASE(forest_stands_on_the_terrain),
          TEST_CASE(session_save_load_continue), TEST_CASE(instancing_by_age_height_and_turn))
