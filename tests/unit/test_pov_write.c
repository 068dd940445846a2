/* test_pov_write.c — the POV-Ray exporter on scenes built in memory: identifiers and comment
 * text, the main file's camera, light and settings, plant matrices as the columns of sylva's
 * transforms, mesh2 declarations with texture lists, textured materials' images (albedo and
 * alpha cut), the single-species export, and refusals that leave no file behind. */
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>

#include "harness.h"
#include "work_dir.h"
#include "io/image_io.h"
#include "pov/pov_names.h"
#include "pov/pov_write.h"
#include "geometry/texture_lookup.h"
#include "scene_build/scene_build.h"
#include "scene_build/shapes.h"

static int count_files(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    if (!d) return -1;
    for (struct dirent *e; (e = readdir(d));) n += e->d_name[0] != '.';
    closedir(d);
    return n;
}

static void empty_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) return;
    char path[512];
    for (struct dirent *e; (e = readdir(d));)
        if (e->d_name[0] != '.') {
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            remove(path);
        }
    closedir(d);
}

/* The whole file, NUL-terminated; caller frees. */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = malloc((size_t)n + 1);
    if (s && fread(s, 1, (size_t)n, f) != (size_t)n) n = 0;
    if (s) s[n] = '\0';
    fclose(f);
    return s;
}

/* The 12 numbers after the first occurrence of prefix; returns how many were read. */
static int matrix_of(const char *text, const char *prefix, double out[12])
{
    const char *p = text ? strstr(text, prefix) : NULL;
    if (!p) return 0;
    p += strlen(prefix);
    int k = 0;
    for (; k < 12; k++) {
        char *end;
        out[k] = strtod(p, &end);
        if (end == p) break;
        p = end;
        if (*p == ',') p++;
    }
    return *p == '>' ? k : -1;
}

static void add_species(scene *s, const char *name, uint32_t first, uint32_t n)
{
    species *sp = realloc(s->species, (s->n_species + 1) * sizeof(species));
    if (!sp) return;
    s->species = sp;
    sp[s->n_species++] = (species){.name = strdup(name), .first_prototype = first, .n_variants = n};
}

/* A 2x2 texture: texel (0,0) green and opaque, (1,0) transparent, the bottom row grey with
 * alpha 127 and 128 (just below and at one half). */
static const uint8_t texels[16] = {0, 200, 0, 255, 255, 0, 0, 0, 100, 100, 100, 127, 100, 100, 100, 128};

static scene *small_scene(void)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    s->image = (image_settings){.width = 96, .height = 64, .spp = 9, .max_depth = 2};
    s->camera = (camera_settings){.position = {9, -9, 7}, .has_look_at = 1, .look_at = {0, 0, 0.5}, .up = {0, 0, 1},
                                  .fov_deg = 45};
    s->sun = (sun_settings){.enabled = 1, .direction = {0, 0, 1}, .azimuth_deg = 0, .elevation_deg = 90,
                            .irradiance = 2, .color = {1, 1, 1}};
    s->sky = (sky_settings){.model = SKY_CONSTANT, .scale = 1, .color = {0.25f, 0.5f, 0.75f}, .ambient = {0.2, 0.3, 0.4}};
    int32_t tex = scene_add_texture(s, "leaf.png", 2, 2, texels, &err);
    sylva_material_desc leaf = {.size = sizeof leaf, .name = "leaf \"green\"", .bsdf = SYLVA_BSDF_LEAF,
                                .albedo = {0.5f, 1.0f, 0.25f}, .texture = tex, .alpha_mask = 1};
    sylva_material_desc wood = {.size = sizeof wood, .name = "wood", .bsdf = SYLVA_BSDF_LAMBERT,
                                .albedo = {0.5f, 0.25f, 0.125f}, .texture = -1};
    int32_t m_leaf = scene_add_material(s, &leaf, &err), m_wood = scene_add_material(s, &wood, &err);
    /* species "crate" with two variants: a box of wood, and a box whose top is leaf */
    for (uint32_t v = 0; v < 2; v++) {
        mesh *m = mesh_new();
        shape_spec box = {.kind = SHAPE_BOX, .size = {1, 1, 1}};
        shape_build(&box, m_wood, m, &err);
        if (v == 1) m->mat[0] = m->mat[1] = m_leaf;
        scene_add_prototype(s, 0, v, v + 1.0, 1.0, m, &err);
    }
    add_species(s, "crate", 0, 2);
    double p1[3] = {1, 2, 3}, p2[3] = {-4, 5.5, 0};
    xform3x4 a = plant_transform(p1, 30, 2), b = plant_transform(p2, 0, 1);
    scene_add_instance(s, 0, &a, &err);
    scene_add_instance(s, 1, &b, &err);
    mesh *om = mesh_new();
    shape_spec quad = {.kind = SHAPE_QUAD, .size = {2, 2}};
    shape_build(&quad, m_leaf, om, &err);
    scene_add_object(s, "sign // post", om, &err);
    CHECK(!err.msg[0]);
    return s;
}

TEST(clean_names)
{
    char c[POV_CLEAN_MAX + 1];
    pov_clean_name("oak tree", c);
    CHECK(!strcmp(c, "Oak_tree"));
    pov_clean_name("  __x-- y__ ", c);
    CHECK(!strcmp(c, "X_y"));
    pov_clean_name("", c);
    CHECK(!strcmp(c, "Unnamed"));
    pov_clean_name(NULL, c);
    CHECK(!strcmp(c, "Unnamed"));
    pov_clean_name("F\xc3\xb6hre", c);
    CHECK(!strcmp(c, "F_hre"));
    pov_clean_name("abcdefghij abcdefghij abcdefghij", c);
    CHECK(!strcmp(c, "Abcdefghij_abcdefghij_ab")); /* at most POV_CLEAN_MAX characters */
    pov_clean_name("abcdefghij abcdefghij a bcd", c);
    CHECK(!strcmp(c, "Abcdefghij_abcdefghij_a")); /* a cut before an underscore drops it */
    char t[16];
    pov_comment_text("a\nb\tc\x7f" "d", t, sizeof t);
    CHECK(!strcmp(t, "a?b?c?d"));
    pov_comment_text("0123456789abcdef", t, 8);
    CHECK(!strcmp(t, "0123456"));
}

TEST(identifiers_never_collide)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    const char *names[] = {"oak tree", "oak-tree", "3 birches", "M1_lookalike", "pine", "Oak_tree__0"};
    for (uint32_t i = 0; i < 6; i++) {
        mesh *m = mesh_new();
        shape_spec box = {.kind = SHAPE_BOX, .size = {1, 1, 1}};
        shape_build(&box, -1, m, &err);
        scene_add_prototype(s, i, 0, 1, 1, m, &err);
        add_species(s, names[i], i, 1);
    }
    char id[6][POV_IDENT_MAX];
    for (uint32_t p = 0; p < 6; p++) pov_prototype_identifier(s, p, id[p]);
    CHECK(!strcmp(id[0], "Oak_tree__0_0"));
    CHECK(!strcmp(id[1], "Oak_tree__1_0"));
    CHECK(!strcmp(id[2], "S__3_birches_0"));
    CHECK(!strcmp(id[3], "S__M1_lookalike_0"));
    CHECK(!strcmp(id[4], "Pine_0"));
    CHECK(!strcmp(id[5], "Oak_tree_0_0")); /* clean names hold no "__": no clash with species 0 */
    for (int a = 0; a < 6; a++)
        for (int b = a + 1; b < 6; b++) CHECK(strcmp(id[a], id[b]));
    char m[POV_IDENT_MAX];
    pov_material_identifier(s, 0, m);
    CHECK(!strcmp(m, "M0_Default"));
    scene_free(s);
}

TEST(scene_export)
{
    const char *dir = work_dir();
    CHECK(dir[0]);
    empty_dir(dir);
    scene *s = small_scene();
    char path[512], file[512];
    snprintf(path, sizeof path, "%s/t.pov", dir);
    pov_export_options po = {.width = 120, .height = 80, .spp = 10, .source = "small.yaml"};
    pov_export_stats st;
    err_buf err = {{0}};
    CHECK_INT(pov_export_scene(s, path, &po, &st, &err), 0);
    CHECK(!err.msg[0]);
    /* main, materials, objects, species, plants, the leaf image; no terrain file */
    CHECK_INT(st.files, 6);
    CHECK_INT(count_files(dir), 6);
    CHECK_INT(st.instances, 2);

    char *main = slurp(path);
    CHECK_STR_CONTAINS(main, "#version 3.7;");
    CHECK_STR_CONTAINS(main, "assumed_gamma 1.0");
    CHECK_STR_CONTAINS(main, "ambient_light rgb <0.2, 0.3, 0.4>");
    CHECK_STR_CONTAINS(main, "background { rgbt <0.25, 0.5, 0.75, Sylva_sky_transmit> }");
    CHECK_STR_CONTAINS(main, "location <9, -9, 7>");
    CHECK_STR_CONTAINS(main, "sky <0, 0, 1>");
    CHECK_STR_CONTAINS(main, "right -x * 1.5");
    CHECK_STR_CONTAINS(main, "angle 45");
    CHECK_STR_CONTAINS(main, "look_at <0, 0, 0.5>");
    /* right before look_at: POV-Ray fixes the handedness from the vectors given before it */
    CHECK(main && strstr(main, "right -x") < strstr(main, "look_at"));
    CHECK_STR_CONTAINS(main, "color rgb <2, 2, 2>");
    CHECK_STR_CONTAINS(main, "parallel");
    CHECK_STR_CONTAINS(main, "+W120 +H80 +A0.0 +AM1 +R3 -J");
    CHECK_STR_CONTAINS(main, "object { O0_Sign_post }  // \"sign // post\"");
    CHECK_STR_CONTAINS(main, "#include \"t_plants.inc\"");
    CHECK(main && !strstr(main, "t_terrain.inc"));
    CHECK(main && !strstr(main, "aperture")); /* a pinhole: no focal blur */
    free(main);

    /* a thin lens: 50 mm at f/2 (a 25 mm pupil) focused 10 m along the view; the vignette named */
    s->camera.focal_length_mm = 50, s->camera.sensor_width_mm = 36, s->camera.f_number = 2;
    s->camera.focus_distance = 10, s->camera.vignette = 0.5;
    CHECK_INT(pov_export_scene(s, path, &po, &st, &err), 0);
    main = slurp(path);
    CHECK_STR_CONTAINS(main, "aperture 0.025");
    CHECK_STR_CONTAINS(main, "blur_samples 64");
    CHECK_STR_CONTAINS(main, "// camera.vignette 0.5");
    double fw[3] = {-9, 9, -6.5}, fl = sqrt(81 + 81 + 6.5 * 6.5), focus_want[3], focus_got[3] = {0, 0, 0};
    for (int d = 0; d < 3; d++) focus_want[d] = s->camera.position[d] + fw[d] / fl * 10;
    const char *fp = main ? strstr(main, "focal_point <") : NULL;
    CHECK(fp && sscanf(fp, "focal_point <%lf, %lf, %lf>", &focus_got[0], &focus_got[1], &focus_got[2]) == 3);
    for (int d = 0; d < 3; d++) CHECK_NEAR(focus_got[d], focus_want[d], 1e-4);
    free(main);

    /* plant matrices: the columns of the transform; translate (1,2,3), 30 degrees, scale 2 */
    snprintf(file, sizeof file, "%s/t_plants.inc", dir);
    char *plants = slurp(file);
    double got[12];
    const double c = 2 * cos(M_PI / 6), sn = 2 * sin(M_PI / 6);
    const double want[12] = {c, sn, 0, -sn, c, 0, 0, 0, 2, 1, 2, 3};
    CHECK_INT(matrix_of(plants, "object { Crate_0 matrix <", got), 12);
    for (int k = 0; k < 12; k++) CHECK_NEAR(got[k], want[k], 1e-6);
    CHECK_STR_CONTAINS(plants, "object { Crate_1 matrix <1,0,0,0,1,0,0,0,1,-4,5.5,0> }\n");
    free(plants);

    snprintf(file, sizeof file, "%s/t_species.inc", dir);
    char *decl = slurp(file);
    CHECK_STR_CONTAINS(decl, "#declare Crate_0 = mesh2 {");
    CHECK_STR_CONTAINS(decl, "#declare Crate_1 = mesh2 {");
    CHECK_STR_CONTAINS(decl, "texture_list {\n    2,\n    texture { M1_Leaf_green },\n    texture { M2_Wood }");
    CHECK_STR_CONTAINS(decl, "  uv_vectors {\n    24");
    CHECK_STR_CONTAINS(decl, "  face_indices {\n    12,\n    <0,1,2>,0, <0,2,3>,0, <4,5,6>,1");
    CHECK_STR_CONTAINS(decl, "  texture { M2_Wood }\n}"); /* variant 0: one material, no list */
    free(decl);

    snprintf(file, sizeof file, "%s/t_materials.inc", dir);
    char *mats = slurp(file);
    CHECK_STR_CONTAINS(mats, "#declare Sylva_finish = finish { ambient 1 diffuse 1 }");
    CHECK_STR_CONTAINS(mats, "#declare M2_Wood = texture { pigment { rgb <0.5, 0.25, 0.125> } finish { Sylva_finish } }");
    CHECK_STR_CONTAINS(mats, "image_map { png \"t_M1_Leaf_green.png\" gamma srgb }");
    free(mats);

    /* the leaf's image: albedo multiplied in (it is not grey), alpha cut at one half */
    snprintf(file, sizeof file, "%s/t_M1_Leaf_green.png", dir);
    image_f32 img = {0};
    CHECK_INT(image_read(file, &img, &err), 0);
    CHECK_INT(img.channels, 4);
    if (img.pixels && img.channels == 4) {
        const float albedo[3] = {0.5f, 1.0f, 0.25f};
        for (int k = 0; k < 4; k++)
            for (int ch = 0; ch < 3; ch++) {
                float expected = albedo[ch] * texture_srgb_to_linear(texels[k * 4 + ch]);
                float stored = texture_srgb_to_linear((uint8_t)lrintf(img.pixels[k * 4 + ch] * 255.0f));
                CHECK_NEAR(stored, expected, 0.01 * expected + 0.002); /* within half an 8-bit sRGB step */
            }
        CHECK_NEAR(img.pixels[3], 1.0, 0);
        CHECK_NEAR(img.pixels[7], 0.0, 0);
        CHECK_NEAR(img.pixels[11], 0.0, 0); /* 127: below one half */
        CHECK_NEAR(img.pixels[15], 1.0, 0); /* 128: kept */
    }
    image_free(&img);
    scene_free(s);
    empty_dir(dir);
}

TEST(refusals_leave_nothing)
{
    const char *dir = work_dir();
    empty_dir(dir);
    scene *s = small_scene();
    err_buf err = {{0}};
    char path[512];
    snprintf(path, sizeof path, "%s/t.txt", dir);
    CHECK_INT(pov_export_scene(s, path, NULL, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "must end in .pov");
    snprintf(path, sizeof path, "%s/a\"b.pov", dir);
    CHECK_INT(pov_export_scene(s, path, NULL, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "quotes");
    snprintf(path, sizeof path, "%s/missing/t.pov", dir);
    CHECK_INT(pov_export_scene(s, path, NULL, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "cannot");
    CHECK_INT(count_files(dir), 0);

    /* a non-finite plant transform: no plants file, no temporary left, no main file */
    s->instances[1].xf.m[0][3] = NAN;
    snprintf(path, sizeof path, "%s/t.pov", dir);
    CHECK_INT(pov_export_scene(s, path, NULL, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "non-finite");
    DIR *d = opendir(dir);
    for (struct dirent *e; d && (e = readdir(d));) {
        CHECK(!strstr(e->d_name, ".tmp-"));
        CHECK(strcmp(e->d_name, "t.pov") && strcmp(e->d_name, "t_plants.inc"));
    }
    if (d) closedir(d);
    scene_free(s);
    empty_dir(dir);
}

TEST(singular_plants_are_left_out)
{
    const char *dir = work_dir();
    empty_dir(dir);
    scene *s = small_scene();
    memset(&s->instances[0].xf, 0, sizeof s->instances[0].xf); /* scale 0 */
    char path[512];
    snprintf(path, sizeof path, "%s/t.pov", dir);
    pov_export_stats st;
    err_buf err = {{0}};
    CHECK_INT(pov_export_scene(s, path, NULL, &st, &err), 0);
    CHECK_INT(st.instances, 1);
    CHECK_INT(st.skipped, 1);
    snprintf(path, sizeof path, "%s/t_plants.inc", dir);
    char *plants = slurp(path);
    CHECK_STR_CONTAINS(plants, "1 plants left out");
    free(plants);
    scene_free(s);
    empty_dir(dir);
}

TEST(species_export)
{
    const char *dir = work_dir();
    empty_dir(dir);
    scene *s = small_scene();
    err_buf err = {{0}};
    char path[512];
    snprintf(path, sizeof path, "%s/crate.inc", dir);
    CHECK_INT(pov_export_species(s, 0, 0, path, "small.yaml", NULL, &err), 0);
    CHECK_INT(count_files(dir), 1); /* variant 0 uses no texture */
    char *inc = slurp(path);
    CHECK_STR_CONTAINS(inc, "#declare Sylva_to_y_up = transform { matrix <1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0> }");
    CHECK_STR_CONTAINS(inc, "#declare Crate_0 = mesh2 {");
    CHECK(inc && !strstr(inc, "Crate_1"));
    CHECK(inc && !strstr(inc, "M1_Leaf_green")); /* only the materials the variant uses */
    free(inc);
    empty_dir(dir);

    snprintf(path, sizeof path, "%s/crate.pov", dir);
    CHECK_INT(pov_export_species(s, 0, -1, path, NULL, NULL, &err), 0);
    CHECK_INT(count_files(dir), 3); /* crate.pov, crate.inc, the leaf image */
    char *pov = slurp(path);
    CHECK_STR_CONTAINS(pov, "#include \"crate.inc\"");
    CHECK_STR_CONTAINS(pov, "object { Crate_1 translate <");
    free(pov);
    empty_dir(dir);

    CHECK_INT(pov_export_species(s, 0, 2, path, NULL, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "has variants 0 to 1");
    CHECK_INT(pov_export_species(s, 5, -1, path, NULL, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "does not exist");
    CHECK_INT(count_files(dir), 0);
    scene_free(s);
    rmdir(dir);
}

TEST_LIST(TEST_CASE(clean_names), TEST_CASE(identifiers_never_collide), TEST_CASE(scene_export),
          TEST_CASE(refusals_leave_nothing), TEST_CASE(singular_plants_are_left_out), TEST_CASE(species_export))
