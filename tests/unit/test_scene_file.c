/* test_scene_file.c — scene_file_load on the good scenes in tests/scenes (values and defaults
 * as read), on every file of the bad-scene corpus tests/scenes/bad (each names the message
 * fragment it must produce in its first line, "# expect: <fragment>"), and on the corpus that
 * needs the test plugins (tests/scenes/bad_plugins, with SYLVA_TEST_PLUGIN_DIR's registry). */
#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "harness.h"
#include "work_dir.h"
#include "plugin/plugin_host.h"
#include "scene_file/host_schema.h"
#include "scene_file/scene_file.h"
#include "params/yaml_doc.h"
#include "util/file_check.h"

#define SCENES SYLVA_TEST_DATA_DIR "/scenes"

static scene_file *load_ok(const char *path, const plugin_registry *reg)
{
    err_buf err;
    scene_file *sf = scene_file_load(path, reg, &err);
    if (!sf) fprintf(stderr, "loading %s failed: %s\n", path, err.msg);
    CHECK(sf != NULL);
    return sf;
}

TEST(scene_minimal_defaults)
{
    scene_file *sf = load_ok(SCENES "/minimal.yaml", NULL);
    if (!sf) return;
    CHECK_INT(sf->image.width, 640);
    CHECK_INT(sf->image.height, 360);
    CHECK_INT(sf->image.spp, 16);
    CHECK_INT(sf->image.seed, 0);
    CHECK_INT(sf->image.max_depth, 6);
    CHECK_NEAR(sf->image.exposure, 0, 0);
    CHECK_NEAR(sf->camera.position[1], -10, 0);
    CHECK_NEAR(sf->camera.position[2], 2, 0);
    CHECK_INT(sf->camera.has_look_at, 0);
    CHECK_NEAR(sf->camera.direction[0], 0, 0);
    CHECK_NEAR(sf->camera.direction[1], 1, 0);
    CHECK_NEAR(sf->camera.up[2], 1, 0);
    CHECK_NEAR(sf->camera.fov_deg, 60, 0);
    CHECK_NEAR(sf->camera.focal_length_mm, 0, 0);
    CHECK_INT(sf->sun.enabled, 1);
    CHECK_NEAR(sf->sun.azimuth_deg, 180, 0);
    CHECK_NEAR(sf->sun.elevation_deg, 45, 0);
    CHECK_NEAR(sf->sun.direction[0], 0, 1e-12);            /* sin 180 cos 45 */
    CHECK_NEAR(sf->sun.direction[1], -sqrt(0.5), 1e-12);   /* cos 180 cos 45 */
    CHECK_NEAR(sf->sun.direction[2], sqrt(0.5), 1e-12);
    CHECK_NEAR(sf->sun.irradiance, 1, 0);
    CHECK_NEAR(sf->sun.angular_diameter_deg, 0.53, 0);
    CHECK_NEAR(sf->sun.color[1], 1, 0);
    CHECK_INT(sf->sky.model, SKY_PREETHAM);
    CHECK_NEAR(sf->sky.turbidity, 3, 0);
    CHECK_NEAR(sf->sky.scale, 1, 0);
    CHECK_NEAR(sf->sky.ground_albedo, 0.2, 0);
    CHECK_NEAR(sf->sky.ambient[0], 0.2, 0);
    CHECK_INT(sf->terrain.source, TERRAIN_NONE);
    CHECK_INT(sf->n_species, 0);
    CHECK_INT(sf->n_plants, 0);
    CHECK_INT(sf->n_objects, 0);
    CHECK_INT(sf->n_materials, 0);
    CHECK(sf->ecology.plugin == NULL);
    CHECK(sf->dir[0] == '/');
    CHECK_STR_CONTAINS(sf->dir, "tests/scenes");
    CHECK(!strcmp(sf->path, SCENES "/minimal.yaml"));
    scene_file_free(sf);
}

TEST(scene_full)
{
    scene_file *sf = load_ok(SCENES "/full.yaml", NULL);
    if (!sf) return;
    CHECK_INT(sf->image.width, 320);
    CHECK_INT(sf->image.height, 200);
    CHECK_INT(sf->image.spp, 4);
    CHECK_INT(sf->image.seed, 7);
    CHECK_INT(sf->image.max_depth, 3);
    CHECK_NEAR(sf->image.exposure, -1.5, 0);

    CHECK_INT(sf->camera.has_look_at, 1);
    CHECK_NEAR(sf->camera.look_at[1], 12, 0);
    CHECK_NEAR(sf->camera.direction[1], 1, 1e-15);
    CHECK_NEAR(sf->camera.focal_length_mm, 50, 0);
    CHECK_NEAR(sf->camera.sensor_width_mm, 36, 0);
    CHECK_NEAR(sf->camera.fov_deg, 2 * atan(36.0 / 100.0) * 180 / M_PI, 1e-12); /* 39.598 */

    CHECK_NEAR(sf->sun.azimuth_deg, 90, 1e-12);   /* toward +X is east */
    CHECK_NEAR(sf->sun.elevation_deg, 45, 1e-12);
    CHECK_NEAR(sf->sun.direction[0], sqrt(0.5), 1e-12);
    CHECK_NEAR(sf->sun.irradiance, 2.5, 0);
    CHECK_NEAR(sf->sun.color[2], 0.8, 0);
    CHECK_NEAR(sf->sun.angular_diameter_deg, 1, 0);

    CHECK_INT(sf->sky.model, SKY_CONSTANT);
    CHECK_NEAR(sf->sky.color[2], 0.3, 0);
    CHECK_NEAR(sf->sky.scale, 2, 0);
    CHECK_NEAR(sf->sky.ground_albedo, 0.3, 0);
    CHECK_NEAR(sf->sky.ambient[1], 0.25, 0);

    CHECK_INT(sf->n_materials, 3);
    int leaf = scene_file_material_index(sf, "leaf");
    CHECK_INT(leaf, 1);
    CHECK_INT(scene_file_material_index(sf, "gold"), -1);
    if (leaf == 1) {
        const material_spec *m = &sf->materials[1];
        CHECK_INT(m->bsdf, SYLVA_BSDF_LEAF);
        CHECK_NEAR(m->albedo[1], 0.4, 0);
        CHECK_NEAR(m->transmittance[1], 0.3, 0);
        CHECK_INT(m->alpha_mask, 1);
        CHECK(m->texture_path && m->texture_path[0] == '/');
        CHECK_STR_CONTAINS(m->texture_path, "tests/scenes/textures/leaf.png");
        CHECK_INT(m->line, 17);
    }
    CHECK_INT(sf->materials[2].bsdf, SYLVA_BSDF_LAMBERT);
    CHECK_NEAR(sf->materials[2].albedo[0], 0.6, 0);

    CHECK_INT(sf->terrain.source, TERRAIN_GRID);
    CHECK_INT(sf->terrain.nx, 3);
    CHECK_INT(sf->terrain.ny, 2);
    CHECK_NEAR(sf->terrain.grid[4], 2, 0); /* row 1 (north), column 1 */
    CHECK_NEAR(sf->terrain.origin[0], -50, 0);
    CHECK_NEAR(sf->terrain.origin[1], -25, 0);
    CHECK_NEAR(sf->terrain.spacing[1], 25, 0);
    CHECK(sf->terrain.material && !strcmp(sf->terrain.material, "grass"));

    /* included species come where the include stands, nested ones inside */
    CHECK_INT(sf->n_species, 4);
    if (sf->n_species == 4) {
        CHECK(!strcmp(sf->species[0].name, "crate"));
        CHECK(!strcmp(sf->species[1].name, "sign"));
        CHECK(!strcmp(sf->species[2].name, "stone"));
        CHECK(!strcmp(sf->species[3].name, "bush"));
        CHECK_INT(sf->species[0].shape.kind, SHAPE_BOX);
        CHECK_NEAR(sf->species[0].shape.size[2], 2, 0);
        CHECK(!strcmp(sf->species[0].material, "steel"));
        CHECK_INT(sf->species[0].line, 3); /* in library.yaml */
        CHECK_INT(sf->species[1].shape.kind, SHAPE_QUAD);
        CHECK_NEAR(sf->species[1].shape.size[1], 0.5, 0);
        CHECK_INT(sf->species[2].shape.kind, SHAPE_DISK);
        CHECK_INT(sf->species[2].shape.subdivisions, 8);
        CHECK_NEAR(sf->species[2].shape.radius, 0.3, 0);
        CHECK_INT(sf->species[3].shape.kind, SHAPE_SPHERE);
        CHECK_INT(sf->species[3].shape.subdivisions, 2);
        CHECK_NEAR(sf->species[3].shape.radius, 0.75, 0);
        CHECK(sf->species[3].plugin == NULL && sf->species[3].params == NULL);
        CHECK(sf->species[3].ecology == NULL);
        CHECK_INT(sf->species[3].variants, 1);
    }
    CHECK_INT(scene_file_species_index(sf, "bush"), 3);
    CHECK_INT(scene_file_species_index(sf, "oak"), -1);

    CHECK_INT(sf->n_plants, 2);
    if (sf->n_plants == 2) {
        const plant_spec *p = &sf->plants[0];
        CHECK_INT(p->species, 3);
        CHECK_INT(p->snap_to_terrain, 1);
        CHECK_NEAR(p->position[1], 20, 0);
        CHECK_NEAR(p->rotation_deg, 30, 0);
        CHECK_NEAR(p->scale, 2, 0);
        CHECK_NEAR(p->age, 0.5, 0);
        CHECK_INT(p->line, 37);
        CHECK_INT(p->column, 5);
        CHECK_INT(sf->plants[1].species, 0);
        CHECK_INT(sf->plants[1].snap_to_terrain, 0);
        CHECK_NEAR(sf->plants[1].position[2], 3, 0);
        CHECK_NEAR(sf->plants[1].age, 1, 0);
        CHECK_NEAR(sf->plants[1].scale, 1, 0);
    }

    CHECK_INT(sf->n_objects, 4);
    if (sf->n_objects == 4) {
        const object_spec *o = &sf->objects[0];
        CHECK(!strcmp(o->name, "tower"));
        CHECK_INT(o->shape.kind, SHAPE_BOX);
        CHECK_NEAR(o->shape.size[2], 30, 0);
        CHECK_NEAR(o->position[2], 15, 0);
        CHECK_NEAR(o->rotation_deg[2], 45, 0);
        CHECK_NEAR(o->scale[0], 1, 0);
        CHECK(!strcmp(o->material, "steel"));
        const object_spec *m = &sf->objects[1];
        CHECK(!strcmp(m->name, "objects[1]"));
        CHECK_INT(m->shape.kind, SHAPE_MESH);
        CHECK_INT(m->shape.n_vertices, 3);
        CHECK_INT(m->shape.n_triangles, 1);
        CHECK_INT(m->shape.n_uvs, 3);
        CHECK_NEAR(m->shape.vertices[3], 1, 0);
        CHECK_NEAR(m->shape.triangles[2], 2, 0);
        CHECK_NEAR(m->shape.uvs[5], 1, 0);
        CHECK(m->material == NULL);
        CHECK_NEAR(m->scale[2], 1, 0);
        CHECK_INT(sf->objects[2].shape.kind, SHAPE_QUAD);
        CHECK_NEAR(sf->objects[2].shape.size[1], 4, 0);
        CHECK_INT(sf->objects[3].shape.kind, SHAPE_DISK);
        CHECK_INT(sf->objects[3].shape.subdivisions, 12);
    }
    scene_file_free(sf);
}

/* The text after "# expect: " on the file's first line, or "" when there is none. */
static void expected_fragment(const char *path, char *buf, size_t size)
{
    buf[0] = '\0';
    FILE *f = fopen(path, "r");
    if (!f) return;
    char line[1024];
    if (fgets(line, sizeof line, f) && !strncmp(line, "# expect: ", 10)) {
        line[strcspn(line, "\r\n")] = '\0';
        snprintf(buf, size, "%s", line + 10);
    }
    fclose(f);
}

static int yaml_name(const struct dirent *e)
{
    size_t n = strlen(e->d_name);
    return n > 5 && !strcmp(e->d_name + n - 5, ".yaml");
}

/* Loads every *.yaml of folder and checks each fails with its expected fragment. Returns the
 * number of files checked. */
static int run_corpus(const char *folder, const plugin_registry *reg)
{
    struct dirent **names;
    int n = scandir(folder, &names, yaml_name, alphasort);
    CHECK(n > 0);
    for (int i = 0; i < n; i++) {
        char path[1024], want[1024];
        snprintf(path, sizeof path, "%s/%s", folder, names[i]->d_name);
        expected_fragment(path, want, sizeof want);
        if (!want[0]) {
            fprintf(stderr, "%s: first line has no '# expect: ' fragment\n", path);
            harness_failures++;
        }
        err_buf err;
        scene_file *sf = scene_file_load(path, reg, &err);
        if (sf) {
            fprintf(stderr, "%s: loaded, but should fail with \"%s\"\n", path, want);
            harness_failures++;
            scene_file_free(sf);
        } else if (!strstr(err.msg, want)) {
            fprintf(stderr, "%s:\n  got      %s\n  expected %s\n", path, err.msg, want);
            harness_failures++;
        }
        free(names[i]);
    }
    free(names);
    return n;
}

TEST(scene_bad_corpus)
{
    int n = run_corpus(SCENES "/bad", NULL);
    CHECK(n >= 25);
}

static plugin_registry *test_registry(void)
{
    err_buf err;
    plugin_registry *reg = plugin_registry_open_path(SYLVA_TEST_PLUGIN_DIR, &err);
    CHECK(reg != NULL);
    if (reg && plugin_registry_load_all(reg, &err) == 0 && plugin_registry_count(reg) == 0)
        fprintf(stderr, "no plugins in %s: build the test_plugin_* targets first\n",
                SYLVA_TEST_PLUGIN_DIR);
    return reg;
}

TEST(scene_bad_plugin_corpus)
{
    plugin_registry *reg = test_registry();
    if (!reg) return;
    int n = run_corpus(SCENES "/bad_plugins", reg);
    CHECK(n >= 10);
    plugin_registry_free(reg);
}

TEST(scene_plugins)
{
    plugin_registry *reg = test_registry();
    if (!reg) return;
    scene_file *sf = load_ok(SCENES "/plugins_ecology.yaml", reg);
    if (sf) {
        CHECK_INT(sf->terrain.source, TERRAIN_PLUGIN);
        CHECK(!strcmp(sf->terrain.plugin, "mixed_future"));
        CHECK(sf->terrain.params && sf->terrain.params->n == 0);
        CHECK(!strcmp(sf->terrain.material, "ground"));
        CHECK(!strcmp(sf->ecology.plugin, "mixed_ecology"));
        CHECK_NEAR(sylva_param_real(sf->ecology.params, "density"), 0.5, 0);
        CHECK_INT(sf->ecology.line, 9);
        CHECK_INT(sf->n_species, 2);
        if (sf->n_species == 2) {
            const sylva_params *e = sf->species[0].ecology;
            CHECK(e != NULL);
            if (e) {
                CHECK(!strcmp(sylva_param_str(e, "shade"), "intolerant"));
                CHECK_INT(sylva_param_int(e, "shade"), 1);
                CHECK_NEAR(sylva_param_real(e, "max_slope"), 20, 0);
                CHECK_INT(e->line, 15);
            }
            /* no block: the ecology plugin's defaults, all unset */
            const sylva_params *d = sf->species[1].ecology;
            CHECK(d != NULL);
            if (d) {
                CHECK(!strcmp(sylva_param_str(d, "shade"), "tolerant"));
                for (uint32_t k = 0; k < d->n; k++) CHECK(!d->values[k].is_set);
            }
        }
        scene_file_free(sf);
    }
    sf = load_ok(SCENES "/plugins_terrain.yaml", reg);
    if (sf) {
        const sylva_params *p = sf->terrain.params;
        CHECK_INT(sf->terrain.source, TERRAIN_PLUGIN);
        CHECK(!strcmp(sf->terrain.plugin, "example_terrain"));
        CHECK(p != NULL);
        if (p) {
            CHECK_INT(sylva_param_int(p, "nx"), 33);
            CHECK_INT(sylva_param(p, "nx")->is_set, 1);
            CHECK_INT(sylva_param_int(p, "ny"), 65); /* the plugin's default */
            CHECK_INT(sylva_param(p, "ny")->is_set, 0);
            CHECK_NEAR(sylva_param_real(p, "node_spacing"), 1.5, 0);
            CHECK(strstr(p->file, "plugins_terrain.yaml") != NULL);
        }
        CHECK(!strcmp(sf->terrain.material, "ground"));
        scene_file_free(sf);
    }
    plugin_registry_free(reg);
}

TEST(scene_file_errors)
{
    err_buf err;
    CHECK(scene_file_load(SCENES "/no_such_scene.yaml", NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "no_such_scene.yaml: cannot open: No such file or directory");
    CHECK(scene_file_load(SCENES, NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "scenes: not a regular file");
    CHECK(scene_file_load("", NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "no scene file was named");
    CHECK(scene_file_load(NULL, NULL, &err) == NULL);
    scene_file_free(NULL);
}

TEST(scene_file_size_limit)
{
    const char *path = work_path("big.yaml");
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    CHECK(fd >= 0);
    if (fd < 0) return;
    /* a sparse file one byte past the limit: nothing is written but its size */
    CHECK(ftruncate(fd, (off_t)YAML_DOC_MAX_FILE_BYTES + 1) == 0);
    close(fd);
    err_buf err;
    CHECK(scene_file_load(path, NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "the file is 67108865 bytes, larger than the limit of 64 MiB");
    unlink(path);
}

TEST(host_schemas_are_well_formed)
{
    int n = 0;
    for (const host_schema *s; (s = host_schema_at((uint32_t)n)); n++) {
        err_buf err;
        err_clear(&err);
        int rc = plugin_schema_check(s->params, s->n_params, &err);
        if (rc) fprintf(stderr, "host schema '%s': %s\n", s->name, err.msg);
        CHECK_INT(rc, 0);
        for (uint32_t k = 0; k < s->n_params; k++) CHECK(s->params[k].help && s->params[k].help[0]);
    }
    CHECK_INT(n, 34);
    CHECK(host_schema_shape(SHAPE_DISK) == &host_schema_shape_disk);
    /* enum orders the loader relies on */
    CHECK(!strcmp(host_sky_models[SKY_PREETHAM], "preetham"));
    CHECK(!strcmp(host_shape_names[SHAPE_SPHERE], "sphere"));
    CHECK(!strcmp(host_material_types[SYLVA_BSDF_LEAF - 1], "leaf"));
    CHECK(!strcmp(host_model_up_axes[1], "y") && !strcmp(host_model_up_axes[2], "z")); /* MODEL_UP_Y, _Z */
    CHECK(!strcmp(host_study_products[STUDY_WIRELINE], "wireline") && !strcmp(host_study_products[STUDY_SHEET], "sheet") &&
          !strcmp(host_study_products[STUDY_ZTV], "ztv") && !host_study_products[STUDY_ZTV + 1]);
    CHECK(!strcmp(host_study_frames[STUDY_CYLINDRICAL_90], "cylindrical_90") && !host_study_frames[STUDY_FRAMES]);
}

TEST(host_reserved_keys)
{
    static const sylva_param_spec clash[] = {
        {.name = "alpha", .type = SYLVA_P_REAL, .help = "a"},
        {.name = "spacing", .type = SYLVA_P_REAL, .help = "b"},
    };
    static const sylva_param_spec eco[] = {
        {.name = "habitat", .type = SYLVA_P_REAL, .help = "a"},
    };
    CHECK(!strcmp(host_reserved_key_clash(clash, 2, NULL), "spacing"));
    CHECK(host_reserved_key_clash(clash, 1, NULL) == NULL);
    CHECK(host_reserved_key_clash(eco, 1, "ecology") == NULL);
    CHECK(!strcmp(host_reserved_key_clash(eco, 1, "habitat"), "habitat"));
}

/* docs/scene-file.md has a table row for every host key, with the schema's help sentence. */
TEST(docs_list_every_key)
{
    static char doc[1 << 17];
    int doc_read = harness_read_text(SYLVA_TEST_DATA_DIR "/../docs/scene-file.md", doc, sizeof doc);
    CHECK(doc_read);
    if (!doc_read) return;
    for (uint32_t i = 0; host_schema_at(i); i++) {
        const host_schema *s = host_schema_at(i);
        for (uint32_t k = 0; k < s->n_params; k++) {
            char row[128];
            snprintf(row, sizeof row, "| `%s` |", s->params[k].name);
            int found = 0;
            for (const char *line = doc; line && *line && !found;) {
                const char *end = strchr(line, '\n');
                size_t len = end ? (size_t)(end - line) : strlen(line);
                const char *r = strstr(line, row), *h = strstr(line, s->params[k].help);
                found = r && h && r < line + len && h < line + len;
                line = end ? end + 1 : NULL;
            }
            if (!found)
                fprintf(stderr, "docs/scene-file.md: no row for '%s' (%s) with its help\n",
                        s->params[k].name, s->name);
            CHECK(found);
        }
    }
}


/* A FIFO named as an include fails at once with a sentence (it used to block in open); an alarm
 * ends the test as a failure should it hang again. */
TEST(scene_include_fifo)
{
    const char *fifo = work_path("species.fifo");
    CHECK(mkfifo(fifo, 0600) == 0);
    const char *scene = work_file("fifo_include.yaml", "camera:\n  position: [0, -10, 2]\n"
                                                      "species:\n  include: species.fifo\n");
    CHECK(scene != NULL);
    if (!scene) return;
    alarm(10);
    double t0 = harness_seconds();
    err_buf err;
    scene_file *sf = scene_file_load(scene, NULL, &err);
    double took = harness_seconds() - t0;
    alarm(0);
    CHECK(sf == NULL);
    scene_file_free(sf);
    CHECK(took < 2.0);
    CHECK_STR_CONTAINS(err.msg, "fifo_include.yaml:4:12: cannot include 'species.fifo'");
    CHECK_STR_CONTAINS(err.msg, "not a regular file: it is a FIFO (named pipe)");
    /* the scene file itself */
    CHECK(scene_file_load(fifo, NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "species.fifo: not a regular file: it is a FIFO");
}

/* A species library's ecology blocks are left unread by a scene without an ecology, so the same
 * library serves scenes that grow plants and scenes that place them; the scene's own block is
 * still refused (tests/scenes/bad/ecology_without_section.yaml). */
TEST(scene_library_ecology_unread)
{
    CHECK(work_file("library_eco.yaml", "species:\n  crate: {shape: box, ecology: {t_m: 40}}\n") != NULL);
    const char *scene = work_file("library_scene.yaml", "camera:\n  position: [0, -10, 2]\n"
                                                        "species:\n  include: library_eco.yaml\n");
    CHECK(scene != NULL);
    if (!scene) return;
    err_buf err;
    scene_file *sf = scene_file_load(scene, NULL, &err);
    CHECK(sf != NULL);
    if (!sf) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    CHECK(sf->n_species == 1);
    scene_file_free(sf);
}

/* A texture (any path parameter) naming a FIFO is refused where it is written. */
TEST(scene_texture_fifo)
{
    const char *fifo = work_path("bark.fifo");
    CHECK(mkfifo(fifo, 0600) == 0);
    const char *scene = work_file("fifo_texture.yaml", "camera:\n  position: [0, -10, 2]\n"
                                                      "materials:\n  bark:\n    texture: bark.fifo\n");
    CHECK(scene != NULL);
    if (!scene) return;
    err_buf err;
    scene_file *sf = scene_file_load(scene, NULL, &err);
    CHECK(sf == NULL);
    scene_file_free(sf);
    CHECK_STR_CONTAINS(err.msg, "fifo_texture.yaml:5:14: 'texture': bark.fifo: not a regular "
                                "file: it is a FIFO (named pipe)");
}

/* A GDAL virtual path is refused by default and kept as written when the command line allowed
 * it. */
TEST(scene_gdal_virtual_opt_in)
{
    const char *scene = work_file("vsi.yaml", "camera:\n  position: [0, -10, 2]\n"
                                              "materials:\n  bark:\n    texture: /vsizip/x.zip/b.png\n");
    CHECK(scene != NULL);
    if (!scene) return;
    err_buf err;
    CHECK(scene_file_load(scene, NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "run with --allow-gdal-virtual");
    file_allow_gdal_virtual(1);
    scene_file *sf = scene_file_load(scene, NULL, &err);
    file_allow_gdal_virtual(0);
    CHECK(sf != NULL);
    if (sf && sf->n_materials > 0)
        CHECK_STR_CONTAINS(sf->materials[0].texture_path, "/vsizip/x.zip/b.png");
    scene_file_free(sf);
    CHECK(file_is_gdal_virtual("PG:dbname=x"));
    CHECK(file_is_gdal_virtual("https://example.org/a.tif"));
    CHECK(file_is_gdal_virtual("/vsicurl/http://a/b.tif"));
    CHECK(!file_is_gdal_virtual("dem/a.tif"));
    CHECK(!file_is_gdal_virtual("C:/dem.tif"));
    CHECK(!file_is_gdal_virtual("./x:y.tif"));
}

/* Directions with huge or tiny components are normalised without overflow: the sun keeps its
 * direction (it used to become zero, and the image black). */
TEST(scene_extreme_directions)
{
    const char *scene = work_file("directions.yaml",
                                  "camera:\n  position: [0, 0, 0]\n  direction: [1e-320, 0, 0]\n"
                                  "sun:\n  direction: [1e300, 1e300, 1e300]\n");
    CHECK(scene != NULL);
    if (!scene) return;
    scene_file *sf = load_ok(scene, NULL);
    if (!sf) return;
    for (int k = 0; k < 3; k++) CHECK_NEAR(sf->sun.direction[k], 1.0 / sqrt(3.0), 1e-12);
    CHECK_NEAR(sf->sun.elevation_deg, asin(1.0 / sqrt(3.0)) * 180.0 / M_PI, 1e-9);
    CHECK_NEAR(sf->camera.direction[0], 1.0, 0);
    scene_file_free(sf);
}

/* 3,000 finely subdivided spheres of as many sizes (a 220 KB file) would need far more memory
 * than allowed: refused at load, before any mesh is built. */
TEST(scene_shapes_beyond_memory)
{
    static char text[260000];
    size_t n = (size_t)snprintf(text, sizeof text, "camera:\n  position: [0, -50, 5]\nobjects:\n");
    for (int i = 0; i < 3000; i++)
        n += (size_t)snprintf(text + n, sizeof text - n,
                              "  - {shape: sphere, subdivisions: 7, radius: %d, position: [%d, 0, 1]}\n", i + 1, i);
    const char *scene = work_file("spheres.yaml", text);
    CHECK(scene != NULL);
    if (!scene) return;
    setenv("SYLVA_MEMORY_LIMIT", "4G", 1);
    err_buf err;
    scene_file *sf = scene_file_load(scene, NULL, &err);
    CHECK(sf == NULL);
    scene_file_free(sf);
    CHECK_STR_CONTAINS(err.msg, "spheres.yaml:4:5: building the scene's shapes (983040000 "
                                "triangles) and 3000 placements of objects needs about 131.8 GiB of memory, "
                                "more than the 4.0 GiB");
    /* one such sphere fits */
    sf = load_ok(work_file("few_spheres.yaml", "camera:\n  position: [0, -50, 5]\nobjects:\n"
                                               "  - {shape: sphere, subdivisions: 7}\n"), NULL);
    scene_file_free(sf);
    unsetenv("SYLVA_MEMORY_LIMIT");
}

/* A scene file whose node tree cannot fit is refused before it is read. */
TEST(scene_file_beyond_memory)
{
    const char *path = work_path("plants.yaml");
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    fputs("camera:\n  position: [0, -10, 2]\nplants:\n", f);
    for (int i = 0; i < 60000; i++) fputs("  - {species: oak, position: [1, 2, 3]}\n", f);
    fclose(f);
    setenv("SYLVA_MEMORY_LIMIT", "64M", 1);
    err_buf err;
    scene_file *sf = scene_file_load(path, NULL, &err);
    unsetenv("SYLVA_MEMORY_LIMIT");
    CHECK(sf == NULL);
    scene_file_free(sf);
    CHECK_STR_CONTAINS(err.msg, "plants.yaml: reading this 2.3 MiB file needs about 137 MiB of "
                                "memory, more than the 64 MiB SYLVA_MEMORY_LIMIT allows");
}

TEST_LIST(TEST_CASE(scene_minimal_defaults), TEST_CASE(scene_full), TEST_CASE(scene_bad_corpus),
          TEST_CASE(scene_bad_plugin_corpus), TEST_CASE(scene_plugins),
          TEST_CASE(scene_file_errors), TEST_CASE(scene_file_size_limit),
          TEST_CASE(host_schemas_are_well_formed), TEST_CASE(host_reserved_keys),
          TEST_CASE(docs_list_every_key), TEST_CASE(scene_include_fifo), TEST_CASE(scene_library_ecology_unread),
          TEST_CASE(scene_texture_fifo), TEST_CASE(scene_gdal_virtual_opt_in),
          TEST_CASE(scene_extreme_directions), TEST_CASE(scene_shapes_beyond_memory),
          TEST_CASE(scene_file_beyond_memory))
