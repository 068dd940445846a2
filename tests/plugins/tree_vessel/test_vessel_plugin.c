/* test_vessel_plugin.c — the tree_vessel module through the real host: scene files with good and
 * bad blocks are loaded and built as `sylva render` does, so every message is checked where the
 * user sees it (file:line:column), and the variants the host asks for are the model's. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "harness.h"
#include "plugin_module.h"
#include "work_dir.h"
#include "plugin/plugin_host.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "vessel_mesh.h"
#include "vessel_test_util.h"

static plugin_registry *registry(void) { return plugin_module_registry(SYLVA_PLUGIN_BUILD_DIR "/tree_vessel.so"); }

/* Writes a scene whose species block holds `keys` (YAML flow mapping members) and loads and
 * builds it. Returns the scene, or NULL with err set. */
static scene *load(const plugin_registry *reg, const char *keys, uint32_t variants, err_buf *err)
{
    char yaml[4096];
    snprintf(yaml, sizeof yaml,
             "camera: {position: [0, -40, 10]}\n"
             "species:\n"
             "  tree: {plugin: tree_vessel, variants: %u%s%s}\n"
             "plants:\n"
             "  - {species: tree, position: [0, 0, 0]}\n",
             variants, keys[0] ? ", " : "", keys);
    const char *path = work_file("scene.yaml", yaml);
    if (!path) return NULL;
    scene *s = plugin_module_scene(reg, path, err);
    unlink(path);
    return s;
}

TEST(variants_are_the_model_at_their_ages)
{
    plugin_registry *reg = registry();
    CHECK(reg != NULL);
    if (!reg) return;
    err_buf err = {{0}};
    scene *s = load(reg, "preset: maple, vessels: 400", 4, &err);
    CHECK(s != NULL);
    if (!s) {
        fprintf(stderr, "%s\n", err.msg);
        plugin_registry_free(reg);
        return;
    }
    CHECK_INT(s->n_prototypes, 4);
    vessel_params p = preset(VESSEL_PRESET_MAPLE);
    p.vessels = 400;
    double last = 0;
    for (uint32_t v = 0; v < s->n_prototypes; v++) {
        const prototype *pr = &s->prototypes[v];
        CHECK_NEAR(pr->age, (v + 1) / 4.0, 1e-12);
        vessel_tree t = {0};
        vessel_mesh m = {0};
        plugin_err verr = {0};
        CHECK_INT(grow(&p, pr->age, 0, &t), 0);
        CHECK_INT(vessel_mesh_build(&t, &p, 0, 1, &m, &verr), 0);
        CHECK_INT(pr->mesh->nt, m.nt); /* the variant is S' = t^2 S */
        CHECK_INT(pr->mesh->nv, m.nv);
        CHECK_NEAR(pr->height, m.top, 1e-9);
        CHECK(pr->height > last);
        last = pr->height;
        vessel_mesh_release(&m);
        vessel_tree_release(&t);
    }
    /* bark and leaf materials: the leaf is two-sided, alpha-masked and textured */
    int leaf = -1;
    for (uint32_t i = 0; i < s->n_materials; i++)
        if (s->materials[i].bsdf == SYLVA_BSDF_LEAF) leaf = (int)i;
    CHECK(leaf >= 0);
    if (leaf >= 0) {
        CHECK_INT(s->materials[leaf].alpha_mask, 1);
        CHECK(s->materials[leaf].texture >= 0);
    }
    scene_free(s);
    plugin_registry_free(reg);
}

TEST(the_same_scene_gives_the_same_mesh)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    err_buf err = {{0}};
    const char *keys = "preset: weeping_willow, vessels: 300, wind_sway: 2, wind_strength: 1";
    scene *a = load(reg, keys, 2, &err), *b = load(reg, keys, 2, &err);
    CHECK(a && b);
    if (a && b) {
        for (uint32_t v = 0; v < 2; v++) {
            const mesh *ma = a->prototypes[v].mesh, *mb = b->prototypes[v].mesh;
            CHECK_INT(ma->nv, mb->nv);
            CHECK(ma->nv == mb->nv && !memcmp(ma->pos, mb->pos, (size_t)ma->nv * 3 * sizeof(float)));
        }
    }
    scene_free(a);
    scene_free(b);
    plugin_registry_free(reg);
}

/* Each bad block stops the build with a sentence at the key's place in the file. */
TEST(bad_blocks_are_refused_with_clear_messages)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    static const struct {
        const char *keys, *expect[2];
    } cases[] = {
        {"vessels: 0", {":3:", "'vessels'"}},
        {"vessels: 100001", {"100000", "'vessels'"}},
        {"trunk_length: -1", {"'trunk_length'", "-1"}},
        {"angle_g: [[0, 45], [15, 200]]", {"'angle_g'", "200"}},
        {"split_g: []", {"'split_g'", "at least 1 point"}},
        {"split_g: [[5, 0.8], [2, 0.9]]", {"'split_g'", "must not decrease"}},
        {"split_g: [[0, 0.8], [20, 0.9]]", {"'split_g'", "orders run from 0 to 15"}},
        {"gravimorphism_w: [[0, 1], [51, 1]]", {"'gravimorphism_w'", "orders run from 0 to 50"}},
        {"preset: oak", {"'preset'", "weeping_willow"}},
        {"sides: 3", {"'sides'", "[4, 15]"}},
        {"leaf: oak", {":3:", "'leaf': 'oak' is not a leaf"}},
        {"leaf: '0.5 0 0 0.5 0 x'", {"'leaf'", "column"}},
        {"leaf: '1.2 0 0 0.5 0 0'", {"'leaf'", "every map must shrink"}},
        {"leaf: '0.5 0 0 0.5 0.8 0'", {"'leaf'", "unit square"}},
        {"leaf: [1, 2]", {":3:", "'leaf'"}},
        {"bark: bumpy", {":3:", "'bark'"}},
        {"leaf_spray: 0", {"'leaf_spray'", "[1, 9]"}},
        {"leaf_spray: 10", {"'leaf_spray'", "[1, 9]"}},
        {"bark: scaly, bark_angle: 400", {"'bark_angle'", "[-360, 360]"}},
        {"vessels: 100000, leaf_density: 300", {"would need", "at most 20000000"}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        err_buf err = {{0}};
        scene *s = load(reg, cases[i].keys, 1, &err);
        CHECK(s == NULL);
        scene_free(s);
        CHECK_STR_CONTAINS(err.msg, cases[i].expect[0]);
        CHECK_STR_CONTAINS(err.msg, cases[i].expect[1]);
        CHECK_STR_CONTAINS(err.msg, work_path("scene.yaml")); /* names the scene file */
    }
    plugin_registry_free(reg);
}

TEST_LIST(TEST_CASE(variants_are_the_model_at_their_ages), TEST_CASE(the_same_scene_gives_the_same_mesh),
          TEST_CASE(bad_blocks_are_refused_with_clear_messages))
