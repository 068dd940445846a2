/* test_tree_variants.c — a species' age variants made on several threads
 * (scene_build/scene_tree_variants.h): the same prototypes, materials and textures, byte for byte, for
 * 1, 2 and 5 threads, with the plugins that allow concurrent generate() (tree_vessel,
 * tree_aono_kunii, tree_weber_penn) and with one that does not (tree_lsystem). */
#include <stdio.h>

#include "harness.h"
#include "plugin/plugin_host.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

static scene *build_with(plugin_registry *reg, unsigned threads, phase_times *times)
{
    err_buf err = {{0}};
    scene_file *sf = scene_file_load(SYLVA_TEST_DATA_DIR "/scenes/tree_variants.yaml", reg, &err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    build_options bo = {.quiet = 1, .threads = threads, .times = times};
    scene *s = sf ? scene_build(sf, reg, &bo, &err) : NULL;
    if (sf && !s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    scene_file_free(sf);
    return s;
}

static int same_bytes(const void *a, const void *b, size_t n) { return n == 0 || !memcmp(a, b, n); }

static void check_same_scene(const scene *a, const scene *b)
{
    CHECK_INT(b->n_prototypes, a->n_prototypes);
    CHECK_INT(b->n_materials, a->n_materials);
    CHECK_INT(b->n_textures, a->n_textures);
    if (a->n_prototypes != b->n_prototypes || a->n_materials != b->n_materials || a->n_textures != b->n_textures)
        return;
    for (uint32_t i = 0; i < a->n_species; i++) {
        CHECK_INT(b->species[i].first_prototype, a->species[i].first_prototype);
        CHECK_INT(b->species[i].n_variants, a->species[i].n_variants);
    }
    for (uint32_t p = 0; p < a->n_prototypes; p++) {
        const prototype *x = &a->prototypes[p], *y = &b->prototypes[p];
        CHECK_INT(y->species, x->species);
        CHECK_INT(y->variant, x->variant);
        CHECK(y->age == x->age && y->height == x->height);
        const mesh *m = x->mesh, *n = y->mesh;
        CHECK_INT(n->nv, m->nv);
        CHECK_INT(n->nt, m->nt);
        if (m->nv != n->nv || m->nt != n->nt) continue;
        CHECK(same_bytes(m->pos, n->pos, 3 * sizeof(float) * m->nv));
        CHECK(same_bytes(m->nrm, n->nrm, 3 * sizeof(float) * m->nv));
        CHECK(same_bytes(m->uv, n->uv, 2 * sizeof(float) * m->nv));
        CHECK(same_bytes(m->tri, n->tri, 3 * sizeof(uint32_t) * m->nt));
        CHECK(same_bytes(m->mat, n->mat, sizeof(int32_t) * m->nt));
    }
    for (uint32_t k = 0; k < a->n_materials; k++) {
        CHECK(!strcmp(a->materials[k].name, b->materials[k].name));
        CHECK_INT(b->materials[k].texture, a->materials[k].texture);
    }
    for (uint32_t k = 0; k < a->n_textures; k++) {
        const texture *x = &a->textures[k], *y = &b->textures[k];
        CHECK(x->width == y->width && x->height == y->height);
        if (x->width == y->width && x->height == y->height)
            CHECK(same_bytes(x->rgba, y->rgba, (size_t)4 * x->width * x->height));
    }
}

TEST(same_bytes_for_any_thread_count)
{
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open_path(SYLVA_PLUGIN_BUILD_DIR, &err);
    CHECK(reg != NULL);
    if (!reg) return;
    phase_times times = {{0}};
    scene *one = build_with(reg, 1, &times);
    if (one) {
        CHECK_INT(one->n_species, 4);
        CHECK_INT(one->n_prototypes, 4 + 3 + 3 + 3);
        CHECK(times.seconds[PHASE_TREES] > 0); /* the variants' time is reported */
    }
    const unsigned counts[] = {2, 5};
    for (size_t i = 0; one && i < sizeof counts / sizeof counts[0]; i++) {
        scene *more = build_with(reg, counts[i], NULL);
        if (more) check_same_scene(one, more);
        scene_free(more);
    }
    scene_free(one);
    plugin_registry_free(reg);
}

TEST_LIST(TEST_CASE(same_bytes_for_any_thread_count))
