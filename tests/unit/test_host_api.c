/* test_host_api.c — the host API table as plugins see it: every misuse becomes a sentence, never
 * a crash; streams are keyed; ownership stays with the scene. */
#include <sys/stat.h>

#include "harness.h"
#include "work_dir.h"

#include "scene_build/host.h"
#include "scene/scene.h"
#include "util/file_check.h"

TEST(rng_streams_are_keyed)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    sylva_host h;
    host_init(&h, s, "/tmp", 42, "test", &err);
    sylva_rng a, b, c;
    host_api_table()->rng_init(&h, &a, "placement", 3);
    host_api_table()->rng_init(&h, &b, "placement", 3);
    host_api_table()->rng_init(&h, &c, "placement", 4);
    int same_c = 0;
    for (int i = 0; i < 100; i++) {
        uint64_t x = host_api_table()->rng_u64(&a), y = host_api_table()->rng_u64(&b), z = host_api_table()->rng_u64(&c);
        CHECK(x == y);
        same_c += x == z;
    }
    CHECK_INT(same_c, 0);
    double u = host_api_table()->rng_uniform(&a);
    CHECK(u >= 0 && u < 1);
    host_release(&h);
    scene_free(s);
}

TEST(heightfield_only_for_terrain)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    sylva_host h;
    host_init(&h, s, "/tmp", 1, "tree plugin 'x'", &err);
    h.kind = SYLVA_KIND_TREE;
    CHECK(host_api_table()->heightfield_new(&h, 4, 4, 0) == NULL);
    CHECK_STR_CONTAINS(err.msg, "for terrain plugins");
    h.kind = SYLVA_KIND_TERRAIN;
    CHECK(host_api_table()->heightfield_new(&h, 1, 4, 0) == NULL);
    CHECK_STR_CONTAINS(err.msg, "each side must be 2 to 65536");
    sylva_heightfield *hf = host_api_table()->heightfield_new(&h, 3, 2, 1);
    CHECK(hf != NULL && s->terrain == hf);
    if (hf) CHECK_INT(hf->material[5], -1);
    host_release(&h);
    scene_free(s); /* frees the heightfield */
}

TEST(plants_only_for_ecology_and_checked)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    sylva_host h;
    host_init(&h, s, "/tmp", 1, "ecology plugin 'x'", &err);
    h.kind = SYLVA_KIND_TERRAIN;
    sylva_plant p = {.size = sizeof p, .species = 0, .age = 0.5};
    CHECK(host_api_table()->plant_add(&h, &p) != SYLVA_OK);
    CHECK_STR_CONTAINS(err.msg, "for ecology plugins");
    h.kind = SYLVA_KIND_ECOLOGY;
    h.n_species = 1;
    p.species = 1;
    CHECK(host_api_table()->plant_add(&h, &p) != SYLVA_OK);
    CHECK_STR_CONTAINS(err.msg, "species 1 does not exist");
    p.species = 0, p.age = 1.5;
    CHECK(host_api_table()->plant_add(&h, &p) != SYLVA_OK);
    CHECK_STR_CONTAINS(err.msg, "outside (0, 1]");
    p.age = 1.0;
    CHECK(host_api_table()->plant_add(&h, &p) == SYLVA_OK);
    CHECK_INT(h.n_plants, 1);
    host_release(&h);
    scene_free(s);
}

TEST(mesh_and_material_misuse)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    sylva_host h;
    host_init(&h, s, "/tmp", 1, "tree plugin 'x'", &err);
    mesh *m = mesh_new();
    float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    uint32_t tri[3] = {0, 1, 2};
    int32_t bad_mat[1] = {99};
    CHECK(host_api_table()->mesh_append(&h, m, pos, NULL, NULL, 3, tri, bad_mat, 1) != SYLVA_OK);
    CHECK_STR_CONTAINS(err.msg, "material id 99");
    CHECK(host_api_table()->mesh_append(&h, NULL, pos, NULL, NULL, 3, tri, NULL, 1) != SYLVA_OK);
    CHECK(host_api_table()->mesh_append(&h, m, pos, NULL, NULL, 3, tri, NULL, 1) == SYLVA_OK);
    CHECK_INT(host_api_table()->mesh_triangle_count(m), 1);
    sylva_material_desc leaf = {.size = sizeof leaf, .name = "glow", .bsdf = SYLVA_BSDF_LEAF,
                                .albedo = {0.7f, 0.5f, 0.5f}, .transmittance = {0.5f, 0.2f, 0.2f}, .texture = -1};
    CHECK(host_api_table()->material_new(&h, &leaf) < 0);
    CHECK_STR_CONTAINS(err.msg, "cannot scatter more than it receives");
    leaf.albedo[0] = 0.4f;
    int32_t id = host_api_table()->material_new(&h, &leaf);
    CHECK(id > 0);
    leaf.texture = 7;
    CHECK(host_api_table()->material_new(&h, &leaf) < 0);
    uint8_t texel[4] = {10, 20, 30, 0};
    CHECK(host_api_table()->texture_new(&h, "t", 0, 1, texel) < 0);
    CHECK(host_api_table()->texture_new(&h, "t", 1, 1, texel) == 0);
    CHECK(s->textures[0].has_alpha);
    mesh_free(m);
    host_release(&h);
    scene_free(s);
}

TEST(param_error_is_located)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    sylva_host h;
    host_init(&h, s, "/tmp", 1, "terrain plugin 'x'", &err);
    static const sylva_param_spec spec[] = {{.name = "alpha", .type = SYLVA_P_REAL, .help = "a"}};
    sylva_value v[1] = {{.is_set = 1, .r = 2.0, .line = 7, .column = 12}};
    sylva_params p = {.spec = spec, .n = 1, .values = v, .file = "scene.yaml", .line = 5, .column = 1};
    CHECK(host_api_table()->param_error(&h, &p, "alpha", "must be below %g", 1.0) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "scene.yaml:7:12: 'alpha': must be below 1");
    CHECK(h.error_set);
    const char *r = host_api_table()->resolve_path(&h, "dem/a.tif");
    CHECK(r && !strcmp(r, "/tmp/dem/a.tif"));
    host_release(&h);
    scene_free(s);
}

TEST(api_table_versions)
{
    CHECK_INT(host_api_table()->size, sizeof(sylva_host_api));
    CHECK_INT(host_api_table()->abi_major, SYLVA_ABI_MAJOR);
    CHECK_INT(host_api_table()->abi_minor, SYLVA_ABI_MINOR);
    CHECK_INT(SYLVA_ABI_MINOR, 7);
}

TEST(param_by_unknown_name_is_an_error)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    sylva_host h;
    host_init(&h, s, "/tmp", 1, "tree plugin 'x'", &err);
    static const sylva_param_spec spec[] = {{.name = "alpha", .type = SYLVA_P_REAL, .help = "a"},
                                            {.name = "beta", .type = SYLVA_P_INT, .help = "b"}};
    sylva_value v[2] = {{.is_set = 1, .r = 2.5}, {.i = 4}};
    sylva_params p = {.spec = spec, .n = 2, .values = v, .file = "scene.yaml", .line = 5, .column = 1};
    const sylva_host_api *api = host_api_table();
    const sylva_value *got = api->param(&h, &p, "beta");
    CHECK(got == &v[1]);
    CHECK(!h.error_set);
    CHECK(api->param(&h, &p, "alpah") == NULL);
    CHECK(h.error_set);
    CHECK_STR_CONTAINS(err.msg, "tree plugin 'x' read parameter 'alpah', which its schema does not have");
    CHECK_STR_CONTAINS(err.msg, "the parameters are: alpha, beta");
    sylva_params none = {.n = 0};
    CHECK(api->param(&h, &none, "alpha") == NULL);
    CHECK_STR_CONTAINS(err.msg, "the schema has no parameters");
    host_release(&h);
    scene_free(s);
}

TEST(allocation_through_the_host)
{
    const sylva_host_api *api = host_api_table();
    CHECK(SYLVA_API_HAS(api, mem_alloc) && SYLVA_API_HAS(api, mem_free) && SYLVA_API_HAS(api, param));
    unsigned char *a = api->mem_calloc(16, 2);
    CHECK(a != NULL);
    int zero = 1;
    for (int i = 0; a && i < 32; i++) zero &= a[i] == 0;
    CHECK(zero);
    unsigned char *b = api->mem_realloc(a, 4096);
    CHECK(b != NULL);
    api->mem_free(b ? b : a);
    api->mem_free(NULL);
    void *c = api->mem_alloc(100);
    CHECK(c != NULL);
    api->mem_free(c);
}

/* A table as an ABI 1.0 host laid it out: SYLVA_API_HAS sees no 1.1 function in it, and a
 * size-versioned struct from an older writer has no newer field. */
TEST(version_markers)
{
    sylva_host_api old = *host_api_table();
    old.size = (uint32_t)SYLVA_HOST_API_SIZE_1_0;
    CHECK(SYLVA_API_HAS(&old, resolve_path));
    CHECK(!SYLVA_API_HAS(&old, mem_alloc));
    CHECK(!SYLVA_API_HAS(&old, param));
    old.size = (uint32_t)SYLVA_HOST_API_SIZE_1_1;
    CHECK(SYLVA_API_HAS(&old, mem_alloc) && SYLVA_API_HAS(&old, param));
    old.mem_alloc = NULL;
    CHECK(!SYLVA_API_HAS(&old, mem_alloc));
    CHECK(SYLVA_HOST_API_SIZE_1_0 < SYLVA_HOST_API_SIZE_1_1);
    CHECK(SYLVA_HOST_API_SIZE_1_1 <= sizeof(sylva_host_api));

    sylva_plugin d = {.size = (uint32_t)SYLVA_PLUGIN_SIZE_1_0};
    CHECK(SYLVA_HAS_FIELD(&d, sylva_plugin, extension));
    CHECK(!SYLVA_HAS_FIELD(&d, sylva_plugin, preset_param));
    CHECK(!SYLVA_HAS_FIELD(&d, sylva_plugin, n_presets));
    d.size = sizeof d;
    CHECK(SYLVA_HAS_FIELD(&d, sylva_plugin, n_presets));
    sylva_tree_out o = {.size = (uint32_t)offsetof(sylva_tree_out, height)};
    CHECK(SYLVA_HAS_FIELD(&o, sylva_tree_out, mesh) && !SYLVA_HAS_FIELD(&o, sylva_tree_out, height));
}

/* Paths a plugin resolves follow the scene's rules: no FIFO, device or folder, and GDAL virtual
 * paths only when the command line allowed them. */
TEST(resolve_path_refuses_special_files)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    sylva_host h;
    host_init(&h, s, work_dir(), 1, "tree plugin 'x'", &err);
    CHECK(mkfifo(work_path("shrub.ls"), 0600) == 0);
    CHECK(host_api_table()->resolve_path(&h, "shrub.ls") == NULL);
    CHECK_STR_CONTAINS(err.msg, "shrub.ls: not a regular file: it is a FIFO (named pipe)");
    CHECK(host_api_table()->resolve_path(&h, "/dev/zero") == NULL);
    CHECK_STR_CONTAINS(err.msg, "/dev/zero: not a regular file: it is a character device");
    CHECK(host_api_table()->resolve_path(&h, "/vsicurl/http://127.0.0.1:9/a.ls") == NULL);
    CHECK_STR_CONTAINS(err.msg, "run with --allow-gdal-virtual");
    file_allow_gdal_virtual(1);
    const char *v = host_api_table()->resolve_path(&h, "/vsicurl/http://127.0.0.1:9/a.ls");
    file_allow_gdal_virtual(0);
    CHECK(v && !strcmp(v, "/vsicurl/http://127.0.0.1:9/a.ls"));
    const char *missing = host_api_table()->resolve_path(&h, "not_yet.ls"); /* reported by its reader */
    CHECK(missing && strstr(missing, "/not_yet.ls"));
    host_release(&h);
    scene_free(s);
}

/* A host calling a generate() that runs beside others on one state refuses new materials and
 * textures (their ids would follow the threads' order); api->threads gives the run's bound. */
TEST(concurrent_host_refuses_materials_and_tells_threads)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    sylva_host h;
    host_init(&h, s, "/tmp", 1, "tree plugin 'x'", &err);
    const sylva_host_api *api = host_api_table();
    CHECK(SYLVA_API_HAS(api, threads));
    CHECK(api->threads(&h) >= 1); /* 0: one per processor */
    h.threads = 3;
    CHECK_INT(api->threads(&h), 3);
    uint32_t before = s->n_materials;
    h.concurrent = 1;
    sylva_material_desc d = {.size = sizeof d, .name = "bark", .bsdf = SYLVA_BSDF_LAMBERT, .texture = -1};
    CHECK(api->material_new(&h, &d) < 0);
    CHECK_STR_CONTAINS(err.msg, "make materials and textures in create()");
    uint8_t texel[4] = {1, 2, 3, 4};
    CHECK(api->texture_new(&h, "t", 1, 1, texel) < 0);
    CHECK_INT(s->n_materials, before);
    CHECK_INT(s->n_textures, 0);
    h.concurrent = 0;
    CHECK(api->material_new(&h, &d) >= 0);
    host_release(&h);
    scene_free(s);
}

TEST_LIST(TEST_CASE(concurrent_host_refuses_materials_and_tells_threads), TEST_CASE(api_table_versions), TEST_CASE(param_by_unknown_name_is_an_error),
          TEST_CASE(allocation_through_the_host), TEST_CASE(version_markers), TEST_CASE(rng_streams_are_keyed), TEST_CASE(heightfield_only_for_terrain),
          TEST_CASE(plants_only_for_ecology_and_checked), TEST_CASE(mesh_and_material_misuse),
          TEST_CASE(param_error_is_located), TEST_CASE(resolve_path_refuses_special_files))
