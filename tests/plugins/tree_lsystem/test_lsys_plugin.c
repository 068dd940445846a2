/* test_lsys_plugin.c — the tree_lsystem module through the real host: scene files validated
 * against its schema, create/generate with the host API, age variants chosen by the branch-number
 * law, scaling, materials from the palette, bark and leaf textures chosen by key, the statistics
 * interface, determinism and the errors a scene author sees. */
#include "harness.h"
#include "work_dir.h"

#include <math.h>
#include <stdio.h>
#include <unistd.h>

#include "branch_law.h"
#include "lsys_derive.h"
#include "plugin/plugin_host.h"
#include "scene_build/host.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "sylva/tree_stats.h"

static plugin_registry *registry(void)
{
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open_path(TREE_LSYSTEM_PLUGIN_DIR, &err);
    if (!reg) fprintf(stderr, "registry: %s\n", err.msg);
    return reg;
}

/* Writes the YAML into a file of its own and loads it; NULL with err set when loading fails. */
static scene_file *load(plugin_registry *reg, const char *yaml, err_buf *err)
{
    const char *path = work_file("scene.yaml", yaml);
    if (!path) return NULL;
    scene_file *sf = scene_file_load(path, reg, err);
    unlink(path);
    return sf;
}

/* A scene with one tree_lsystem species whose own keys are `keys` (YAML lines, indented 4). */
static scene_file *species_scene(plugin_registry *reg, const char *keys, err_buf *err)
{
    char yaml[8192];
    snprintf(yaml, sizeof yaml,
             "camera: {position: [0, -20, 5]}\n"
             "species:\n"
             "  t:\n"
             "    plugin: tree_lsystem\n"
             "%s",
             keys);
    return load(reg, yaml, err);
}

typedef struct run {
    scene *sc;
    sylva_host host;
    err_buf err;
    const sylva_plugin *desc;
    const sylva_tree_stats_v1 *stats;
    void *state;
} run;

/* create() for species 0 of sf; returns its status. */
static int run_create(run *r, plugin_registry *reg, const scene_file *sf)
{
    memset(r, 0, sizeof *r);
    const loaded_plugin *lp = plugin_registry_find(reg, "tree_lsystem", SYLVA_KIND_TREE, &r->err);
    if (!lp) return -100;
    r->desc = lp->desc;
    r->stats = lp->desc->extension ? lp->desc->extension(SYLVA_TREE_STATS_V1) : NULL;
    r->sc = scene_new();
    host_init(&r->host, r->sc, sf->dir, 42, "tree plugin 'tree_lsystem' for species 't'", &r->err);
    r->host.kind = SYLVA_KIND_TREE, r->host.quiet = 1;
    return r->desc->create(host_api_table(), &r->host, sf->species[0].params, &r->state);
}

static int run_generate(run *r, double age, uint64_t seed, mesh *m, double *height)
{
    r->host.seed = seed;
    sylva_tree_request req = {.size = sizeof req, .age = age, .variant = 0, .n_variants = 1, .seed = seed};
    sylva_tree_out out = {.size = sizeof out, .mesh = m};
    int rc = r->desc->generate(r->state, host_api_table(), &r->host, &req, &out);
    if (height) *height = out.height;
    return rc;
}

static void run_end(run *r)
{
    if (r->desc) r->desc->destroy(r->state);
    host_release(&r->host);
    scene_free(r->sc);
}

TEST(descriptor_and_schema)
{
    plugin_registry *reg = registry();
    CHECK(reg != NULL);
    if (!reg) return;
    err_buf err = {{0}};
    const loaded_plugin *lp = plugin_registry_find(reg, "tree_lsystem", SYLVA_KIND_TREE, &err);
    CHECK(lp != NULL);
    CHECK_INT(plugin_registry_problem_count(reg), 0);
    if (lp) {
        CHECK(lp->desc->extension && lp->desc->extension(SYLVA_TREE_STATS_V1) != NULL);
        CHECK(lp->desc->extension("sylva.unknown.v1") == NULL);
    }
    plugin_registry_free(reg);
}

static int count_level(void *ctx, uint32_t level, const unsigned char *s, size_t n)
{
    plugin_err e = {0};
    return branch_count(s, n, &((uint64_t *)ctx)[level], &e);
}

TEST(variants_follow_the_branch_law)
{
    plugin_registry *reg = registry();
    err_buf err = {{0}};
    /* Fig. 2's three-branched tree: (3^k - 1) / 2 segments at level k. */
    scene_file *sf = reg ? species_scene(reg,
                                         "    height: 8\n"
                                         "    source: |\n"
                                         "      7\n      30\n      10\n      A\n"
                                         "      A=F[&A][>(120)&A]<(120)&A\n      @\n",
                                         &err)
                         : NULL;
    CHECK(sf != NULL);
    if (!sf) {
        fprintf(stderr, "%s\n", err.msg);
        plugin_registry_free(reg);
        return;
    }
    /* N1: the branches of the full-grown string, counted on their own. */
    const char *text = "7\n30\n10\nA\nA=F[&A][>(120)&A]<(120)&A\n";
    lsys_system *sys = NULL;
    plugin_err le = {0};
    unsigned char *full = NULL;
    size_t full_n = 0;
    CHECK(!lsys_read(text, strlen(text), "t", NULL, &sys, &le));
    uint64_t level_branches[8] = {0};
    CHECK(sys && !lsys_derive(sys, 7, 1u << 24, count_level, level_branches, &full, &full_n, &le));
    uint64_t n1 = 0;
    CHECK_INT(full ? branch_count(full, full_n, &n1, &le) : LSYS_ERR_NOMEM, LSYS_OK);
    CHECK_INT(level_branches[7], n1);
    free(full);
    lsys_system_free(sys);
    run r;
    CHECK_INT(run_create(&r, reg, sf), SYLVA_OK);
    CHECK(r.stats != NULL);
    uint32_t prev_level = 0;
    uint64_t prev_tri = 0;
    double ages[4] = {0.25, 0.5, 0.75, 1.0};
    for (int v = 0; v < 4 && r.stats; v++) {
        mesh *m = mesh_new();
        double h = 0;
        CHECK_INT(run_generate(&r, ages[v], 7, m, &h), SYLVA_OK);
        sylva_tree_stats st = {.size = sizeof st};
        CHECK_INT(r.stats->last_stats(r.state, &st), SYLVA_OK);
        /* Linear height_by_age: the variant is scaled to age * height. */
        CHECK_NEAR(h, 8 * ages[v], 1e-9);
        float lo[3], hi[3];
        mesh_bounds(m, lo, hi);
        CHECK_NEAR(hi[2] - lo[2], 8 * ages[v], 1e-3 * 8);
        CHECK_INT(st.triangles, m->nt);
        CHECK_NEAR(st.age, ages[v], 0);
        CHECK(st.recursion >= prev_level);
        CHECK(m->nt >= prev_tri);
        CHECK_INT(st.branches, level_branches[st.recursion]);
        if (ages[v] < 1) {
            /* eq. 6 from the full-grown tree, and the level nearest to it. */
            CHECK(st.law_dimension > 1.0 && st.law_dimension < 2.0);
            CHECK_NEAR(st.target_branches, branch_law_count(n1, 8, 8 * ages[v], st.law_dimension),
                       1e-6 * st.target_branches);
            CHECK_INT(st.recursion, branch_law_level(level_branches, 8, st.target_branches));
            if (ages[v] == 0.25) CHECK(st.recursion < 7);
        } else {
            CHECK_INT(st.recursion, 7);
            CHECK(st.target_branches == 0);
        }
        CHECK(st.box_dimension > 1.0 && st.box_dimension < 2.0);
        CHECK_INT(st.segments, (uint64_t)(pow(3, st.recursion) - 1) / 2);
        prev_level = st.recursion, prev_tri = m->nt;
        mesh_free(m);
    }
    run_end(&r);
    scene_file_free(sf);
    plugin_registry_free(reg);
}

TEST(palette_and_file_colours_make_materials)
{
    plugin_registry *reg = registry();
    err_buf err = {{0}};
    scene_file *sf = reg ? species_scene(reg,
                                         "    source: |\n"
                                         "      recursion 1\n      color 4 255 128 0\n"
                                         "      axiom c(9)F[c(3){+f-(90)f-(90)f}]c(4)F[c(5){+f-(90)f-(90)f}]\n"
                                         "    palette:\n"
                                         "      - {index: 9, albedo: [0.13, 0.08, 0.05]}\n"
                                         "      - {index: 3, albedo: [0.1, 0.3, 0.05], transmittance: [0.05, 0.2, 0.02]}\n",
                                         &err)
                         : NULL;
    CHECK(sf != NULL);
    if (!sf) {
        fprintf(stderr, "%s\n", err.msg);
        plugin_registry_free(reg);
        return;
    }
    run r;
    CHECK_INT(run_create(&r, reg, sf), SYLVA_OK);
    mesh *m = mesh_new();
    CHECK_INT(run_generate(&r, 1.0, 1, m, NULL), SYLVA_OK);
    int seen_bark = 0, seen_leaf = 0, seen_file = 0, seen_default_leaf = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
        const material *mat = &r.sc->materials[m->mat[t]];
        if (strstr(mat->name, "colour 9 wood")) {
            seen_bark = 1;
            CHECK_NEAR(mat->albedo.x, 0.13, 1e-6);
            CHECK_INT(mat->bsdf, SYLVA_BSDF_LAMBERT);
        } else if (strstr(mat->name, "colour 3 leaf")) {
            seen_leaf = 1;
            CHECK_INT(mat->bsdf, SYLVA_BSDF_LEAF);
            CHECK_NEAR(mat->transmittance.y, 0.2, 1e-6);
        } else if (strstr(mat->name, "colour 4 wood")) {
            seen_file = 1; /* sRGB (255, 128, 0) from the file, capped at 0.9 */
            CHECK_NEAR(mat->albedo.x, 0.9, 1e-6);
            CHECK_NEAR(mat->albedo.y, 0.2158605, 1e-5);
            CHECK_NEAR(mat->albedo.z, 0, 1e-6);
        } else if (strstr(mat->name, "colour 5 leaf")) {
            seen_default_leaf = 1; /* the default turquoise; transmittance half the albedo */
            CHECK_NEAR(mat->transmittance.y, 0.5 * mat->albedo.y, 1e-6);
        }
    }
    CHECK(seen_bark && seen_leaf && seen_file && seen_default_leaf);
    mesh_free(m);
    run_end(&r);
    scene_file_free(sf);
    plugin_registry_free(reg);
}

TEST(same_seed_same_tree)
{
    plugin_registry *reg = registry();
    err_buf err = {{0}};
    scene_file *sf = reg ? species_scene(reg,
                                         "    source: |\n      5\n      25\n      12\n      A\n"
                                         "      A=~(15)F[&A][^A]\n",
                                         &err)
                         : NULL;
    CHECK(sf != NULL);
    if (!sf) {
        plugin_registry_free(reg);
        return;
    }
    run r;
    CHECK_INT(run_create(&r, reg, sf), SYLVA_OK);
    mesh *a = mesh_new(), *b = mesh_new(), *c = mesh_new();
    CHECK_INT(run_generate(&r, 1.0, 11, a, NULL), SYLVA_OK);
    CHECK_INT(run_generate(&r, 1.0, 11, b, NULL), SYLVA_OK);
    CHECK_INT(run_generate(&r, 1.0, 12, c, NULL), SYLVA_OK);
    CHECK(a->nv == b->nv && !memcmp(a->pos, b->pos, 3 * sizeof(float) * a->nv));
    CHECK(a->nv == b->nv && !memcmp(a->uv, b->uv, 2 * sizeof(float) * a->nv));
    CHECK(a->nv == c->nv && memcmp(a->pos, c->pos, 3 * sizeof(float) * a->nv) != 0);
    mesh_free(a), mesh_free(b), mesh_free(c);
    run_end(&r);
    scene_file_free(sf);
    plugin_registry_free(reg);
}

/* The material kinds of a generated tree: the texture (by its name, or "" for none) and
 * alpha mask of the first wood and the first leaf material, and the range of the leaves' uvs. */
typedef struct texture_use {
    char wood[64], leaf[64];
    int wood_mask, leaf_mask, leaf_alpha;
    float leaf_uv_lo, leaf_uv_hi;
} texture_use;

static int textures_of(plugin_registry *reg, const char *keys, texture_use *u)
{
    char yaml[1024];
    snprintf(yaml, sizeof yaml, "%s    source: |\n      recursion 1\n      axiom F[c(8){+f-(90)f-(90)f}]F\n", keys);
    err_buf err = {{0}};
    scene_file *sf = species_scene(reg, yaml, &err);
    if (!sf) {
        fprintf(stderr, "%s\n", err.msg);
        return -1;
    }
    memset(u, 0, sizeof *u);
    u->leaf_uv_lo = 1, u->leaf_uv_hi = 0;
    run r;
    int rc = run_create(&r, reg, sf);
    mesh *m = mesh_new();
    if (!rc) rc = run_generate(&r, 1.0, 1, m, NULL);
    for (uint32_t t = 0; !rc && t < m->nt; t++) {
        const material *mat = &r.sc->materials[m->mat[t]];
        int leaf = mat->bsdf == SYLVA_BSDF_LEAF;
        const texture *tex = mat->texture >= 0 ? &r.sc->textures[mat->texture] : NULL;
        snprintf(leaf ? u->leaf : u->wood, sizeof u->leaf, "%s", tex ? tex->name : "");
        if (leaf) {
            u->leaf_mask = mat->alpha_mask, u->leaf_alpha = tex && tex->has_alpha;
            for (int k = 0; k < 3; k++)
                for (int i = 0; i < 2; i++) {
                    float x = m->uv[2 * m->tri[3 * t + k] + i];
                    u->leaf_uv_lo = fminf(u->leaf_uv_lo, x), u->leaf_uv_hi = fmaxf(u->leaf_uv_hi, x);
                }
        } else {
            u->wood_mask = mat->alpha_mask;
        }
    }
    mesh_free(m);
    run_end(&r);
    scene_file_free(sf);
    return rc;
}

/* By default the segments wear the fractal bark and the leaf polygons the affine leaf, opaque
 * (the polygon is the outline) over uvs spanning [0, 1]; the keys choose a preset or none. */
TEST(bark_and_leaf_textures_by_key)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    texture_use u;
    CHECK_INT(textures_of(reg, "", &u), SYLVA_OK);
    CHECK(!strcmp(u.wood, "tree_lsystem bark furrowed"));
    CHECK(!strcmp(u.leaf, "tree_lsystem leaf beech"));
    CHECK(!u.wood_mask && !u.leaf_mask && !u.leaf_alpha);
    CHECK_NEAR(u.leaf_uv_lo, 0, 1e-7);
    CHECK_NEAR(u.leaf_uv_hi, 1, 1e-7);
    CHECK_INT(textures_of(reg, "    leaf: willow\n    bark: scaly\n", &u), SYLVA_OK);
    CHECK(!strcmp(u.wood, "tree_lsystem bark scaly"));
    CHECK(!strcmp(u.leaf, "tree_lsystem leaf willow"));
    CHECK_INT(textures_of(reg, "    leaf: off\n    bark: off\n", &u), SYLVA_OK);
    CHECK(!strcmp(u.wood, "") && !strcmp(u.leaf, ""));
    CHECK_INT(textures_of(reg, "    leaf: spruce\n    bark: off\n", &u), SYLVA_OK);
    CHECK(!strcmp(u.wood, "") && !strcmp(u.leaf, "tree_lsystem leaf spruce"));
    plugin_registry_free(reg);
}

/* create() + generate(), returning the first failing status and the message. */
static int try_species(plugin_registry *reg, const char *keys, err_buf *msg)
{
    err_buf err = {{0}};
    scene_file *sf = species_scene(reg, keys, &err);
    if (!sf) {
        *msg = err;
        return -100;
    }
    run r;
    int rc = run_create(&r, reg, sf);
    if (!rc) {
        mesh *m = mesh_new();
        rc = run_generate(&r, 1.0, 1, m, NULL);
        mesh_free(m);
    }
    *msg = r.err;
    run_end(&r);
    scene_file_free(sf);
    return rc;
}

TEST(errors_a_scene_author_sees)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    err_buf msg;
    CHECK_INT(try_species(reg, "    height: 5\n", &msg), SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(msg.msg, "give the L-system either inline as source or as a file path");
    CHECK_INT(try_species(reg, "    source: \"axiom F\"\n    file: x.ls\n", &msg), SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(msg.msg, "not both");
    /* The unknown symbol is located in the source and the source in the scene file. */
    CHECK_INT(try_species(reg, "    source: |\n      2\n      30\n      10\n      A\n      A=F*A\n", &msg),
              SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(msg.msg, "'source': source:5:4: unknown symbol '*' in rule 'A'");
    CHECK_STR_CONTAINS(msg.msg, ".yaml:5:13:");
    /* ... unless lenient. */
    CHECK_INT(try_species(reg, "    lenient: true\n    source: |\n      2\n      30\n      10\n      A\n      A=F*A\n", &msg),
              SYLVA_OK);
    CHECK_INT(try_species(reg, "    file: /nonexistent/tree.ls\n", &msg), SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(msg.msg, "/nonexistent/tree.ls: cannot open the L-system file");
    /* Limits name themselves. */
    CHECK_INT(try_species(reg, "    max_string: 100000\n    source: |\n      30\n      30\n      10\n      A\n      A=F[A]A\n",
                          &msg),
              SYLVA_ERR_LIMIT);
    CHECK_STR_CONTAINS(msg.msg, "max_string = 100000");
    CHECK_INT(try_species(reg, "    max_segments: 10\n    recursion: 4\n    source: |\n      1\n      30\n      10\n"
                               "      A\n      A=FF[A]A\n",
                          &msg),
              SYLVA_ERR_LIMIT);
    CHECK_STR_CONTAINS(msg.msg, "max_segments = 10");
    CHECK_INT(try_species(reg, "    source: |\n      3\n      30\n      10\n      A\n      A=+A\n", &msg), SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(msg.msg, "draws nothing");
    /* The schema catches values out of range before any plugin code runs. */
    CHECK_INT(try_species(reg, "    sides: 2\n    source: \"axiom F\"\n", &msg), -100);
    CHECK_STR_CONTAINS(msg.msg, "'sides' must be an integer in [5, 32]");
    /* The texture keys, located in the scene file (line 5, the value's column). */
    CHECK_INT(try_species(reg, "    leaf: oak\n    source: \"axiom F\"\n", &msg), -100);
    CHECK_STR_CONTAINS(msg.msg, ".yaml:5:11: 'leaf' must be one of beech, maple, spruce, shrub, willow, off; got");
    CHECK_INT(try_species(reg, "    bark: Furrowed\n    source: \"axiom F\"\n", &msg), -100);
    CHECK_STR_CONTAINS(msg.msg, ".yaml:5:11: 'bark' must be one of smooth, scaly, furrowed, fissured, off; got");
    CHECK_STR_CONTAINS(msg.msg, "did you mean 'furrowed'?");
    CHECK_INT(try_species(reg, "    bark: [smooth]\n    source: \"axiom F\"\n", &msg), -100);
    CHECK_STR_CONTAINS(msg.msg, ".yaml:5:11: 'bark' must be one of");
    CHECK_INT(try_species(reg, "    bark_tile_length: 0\n    source: \"axiom F\"\n", &msg), -100);
    CHECK_STR_CONTAINS(msg.msg, ".yaml:5:23: 'bark_tile_length' must be");
    plugin_registry_free(reg);
}

TEST(scene_build_with_variants)
{
    plugin_registry *reg = registry();
    err_buf err = {{0}};
    scene_file *sf = reg ? species_scene(reg,
                                         "    variants: 3\n    height: 6\n"
                                         "    height_by_age: [[0, 0.2], [1, 1]]\n"
                                         "    source: |\n      6\n      30\n      10\n      A\n      A=F[&A]^A\n",
                                         &err)
                         : NULL;
    CHECK(sf != NULL);
    if (!sf) {
        fprintf(stderr, "%s\n", err.msg);
        plugin_registry_free(reg);
        return;
    }
    scene *s = scene_build(sf, reg, NULL, &err);
    CHECK(s != NULL);
    if (s) {
        CHECK_INT(s->n_prototypes, 3);
        for (uint32_t v = 0; v < s->n_prototypes && v < 3; v++) {
            double age = (v + 1) / 3.0;
            CHECK_NEAR(s->prototypes[v].height, 6 * (0.2 + 0.8 * age), 1e-9);
            if (v) CHECK(s->prototypes[v].mesh->nt >= s->prototypes[v - 1].mesh->nt);
        }
    }
    scene_free(s);
    scene_file_free(sf);
    plugin_registry_free(reg);
}

/* 002's own direction: a measured tree (H1 = law_height, N1 = law_branches) gives every
 * variant's N2 by eq. 6, the full-grown one too; a variant as high as the measured tree takes
 * the level with its N1. One of the two keys alone is refused at its place. */
TEST(branch_law_from_a_measured_tree)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    const char *text = "8\n30\n10\nA\nA=F[&A]^A\n";
    lsys_system *sys = NULL;
    plugin_err le = {0};
    unsigned char *full = NULL;
    size_t full_n = 0;
    uint64_t level_branches[9] = {0};
    CHECK(!lsys_read(text, strlen(text), "t", NULL, &sys, &le));
    CHECK(sys && !lsys_derive(sys, 8, 1u << 24, count_level, level_branches, &full, &full_n, &le));
    free(full);
    lsys_system_free(sys);
    char keys[512];
    snprintf(keys, sizeof keys,
             "    height: 10\n    box_dimension: 1.5\n    law_height: 5\n    law_branches: %llu\n"
             "    source: |\n      8\n      30\n      10\n      A\n      A=F[&A]^A\n      @\n",
             (unsigned long long)level_branches[4]);
    err_buf err = {{0}};
    scene_file *sf = species_scene(reg, keys, &err);
    CHECK(sf != NULL);
    run r;
    if (sf && !run_create(&r, reg, sf) && r.stats) {
        const double ages[2] = {1.0, 0.5};
        for (int v = 0; v < 2; v++) {
            mesh *m = mesh_new();
            sylva_tree_stats st = {.size = sizeof st};
            CHECK_INT(run_generate(&r, ages[v], 1, m, NULL), SYLVA_OK);
            CHECK_INT(r.stats->last_stats(r.state, &st), SYLVA_OK);
            double want = branch_law_count((double)level_branches[4], 5, 10 * ages[v], 1.5);
            CHECK_NEAR(st.target_branches, want, 1e-9 * want);
            CHECK_INT(st.recursion, branch_law_level(level_branches, 9, want));
            if (ages[v] == 0.5) CHECK_INT(st.recursion, 4); /* as high as the measured tree */
            else CHECK(st.recursion > 4 && st.recursion < 8); /* the law, not the file's level 8 */
            mesh_free(m);
        }
        run_end(&r);
    }
    scene_file_free(sf);
    err_buf msg;
    CHECK_INT(try_species(reg, "    law_height: 5.6\n    source: \"axiom F\"\n", &msg), SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(msg.msg, ".yaml:5:17: 'law_height': the branch-number law's measured tree needs both");
    plugin_registry_free(reg);
}

TEST_LIST(TEST_CASE(descriptor_and_schema), TEST_CASE(variants_follow_the_branch_law),
          TEST_CASE(branch_law_from_a_measured_tree),
          TEST_CASE(palette_and_file_colours_make_materials), TEST_CASE(same_seed_same_tree),
          TEST_CASE(bark_and_leaf_textures_by_key),
          TEST_CASE(errors_a_scene_author_sees), TEST_CASE(scene_build_with_variants))
