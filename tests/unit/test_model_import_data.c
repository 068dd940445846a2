/* test_model_import_data.c — every model of the shared data set (models/README.md) read
 * through model_import: triangle counts (instances counted), size and orientation in metres
 * with +Z up after the file's unit and up axis, materials and textures (embedded, beside the
 * model, glTF MASK cutoffs; one small render shows the embedded texture), and clear errors for
 * a truncated copy, a missing texture and an unsupported format. Without the shared data the
 * test reports itself skipped (status 77). */
#include <stdint.h>
#include <sys/stat.h>

#include "harness.h"
#include "work_dir.h"
#include "render/render.h"
#include "model/model_import.h"
#include "scene/scene.h"

#define MODELS SYLVA_SHARED_DATA_DIR "/models/"

typedef struct loaded {
    scene *s;
    mesh *m;
    model_import_info info;
    float lo[3], hi[3];
} loaded;

/* Imports MODELS/rel with the given scale (0: none) and the files it refers to in MODELS/root
 * (NULL: its own folder); the test fails when it does not load or misses a file it names. */
static int load_within(const char *rel, const char *root, double scale, loaded *l)
{
    *l = (loaded){0};
    l->s = scene_new();
    err_buf err = {{0}};
    char root_path[1024];
    if (root) snprintf(root_path, sizeof root_path, "%s%s", MODELS, root);
    model_import_options o = {.scale = scale, .root = root ? root_path : NULL};
    char path[1024];
    snprintf(path, sizeof path, "%s%s", MODELS, rel);
    int rc = model_import(l->s, path, &o, &l->m, &l->info, &err);
    CHECK_INT(rc, 0);
    if (rc) {
        fprintf(stderr, "%s\n", err.msg);
        return -1;
    }
    if (l->info.missing[0]) fprintf(stderr, "%s names '%s', which did not open\n", rel, l->info.missing);
    CHECK(!l->info.missing[0]); /* every file these models name is there */
    mesh_bounds(l->m, l->lo, l->hi);
    return 0;
}

static int load(const char *rel, double scale, loaded *l) { return load_within(rel, NULL, scale, l); }

static void unload(loaded *l)
{
    mesh_free(l->m);
    scene_free(l->s);
}

/* The model's extent along x, y, z within tol metres. */
static void check_extent(const loaded *l, double x, double y, double z, double tol)
{
    CHECK_NEAR(l->hi[0] - l->lo[0], x, tol);
    CHECK_NEAR(l->hi[1] - l->lo[1], y, tol);
    CHECK_NEAR(l->hi[2] - l->lo[2], z, tol);
}

/* The scene material of the model's triangle t. */
static const material *material_of(const loaded *l, uint32_t t) { return &l->s->materials[l->m->mat[t]]; }

/* The number of distinct materials the mesh's triangles use. */
static int materials_used(const loaded *l)
{
    int n = 0;
    for (uint32_t i = 0; i < l->s->n_materials; i++)
        for (uint32_t t = 0; t < l->m->nt; t++)
            if (l->m->mat[t] == (int32_t)i) {
                n++;
                break;
            }
    return n;
}

TEST(stl_tower)
{
    loaded l;
    if (load("wind-turbine/iea-15-240-rwt/IEA-15-240-RWT_tower.stl", 0, &l)) return;
    CHECK_INT(l.m->nt, 946);
    CHECK_NEAR(l.lo[2], 0.0, 1e-3);
    CHECK_NEAR(l.hi[2], 144.386, 1e-3);
    CHECK_NEAR(l.hi[0] - l.lo[0], 10.0, 0.05); /* 10 m across at the base */
    unload(&l);
}

TEST(stl_blade)
{
    loaded l;
    if (load("wind-turbine/iea-15-240-rwt/IEA-15-240-RWT_blade.stl", 0, &l)) return;
    CHECK_INT(l.m->nt, 21730);
    CHECK_NEAR(l.lo[2], 0.0, 1e-3);
    CHECK_NEAR(l.hi[2], 117.0, 0.01);
    unload(&l);
}

/* Inches (<unit meter="0.0254">) and Z_UP: 44.2 m tall, 11.7 x 13.4 m, base at z = 0; two
 * JPEG textures beside it, of which the diffuse one is used. */
TEST(collada_radio_tower)
{
    loaded l;
    if (load("pylon/gazebo-radio-tower/radio_tower.dae", 0, &l)) return;
    CHECK_INT(l.m->nt, 4892);
    check_extent(&l, 11.7, 13.4, 44.2, 0.05);
    CHECK_NEAR(l.lo[2], 0.0, 1e-3);
    const material *m = material_of(&l, 0);
    CHECK(m->texture >= 0);
    if (m->texture >= 0) CHECK_STR_CONTAINS(l.s->textures[m->texture].name, "radio_tower_diffuse.jpg");
    unload(&l);
}

TEST(collada_post_office)
{
    loaded l;
    if (load("building/gazebo-post-office/post_office.dae", 0, &l)) return;
    CHECK_INT(l.m->nt, 1046);
    check_extent(&l, 10.4, 7.3, 3.9, 0.05);
    CHECK_INT(l.info.textures, 1);
    unload(&l);
}

/* The node turns the span -90 degrees about Z and scales it (0.627, 0.593, 0.593) before the
 * inch unit: the raw 24.9 x 14.3 x 8.2 m becomes 0.593*14.3 x 0.627*24.9 x 0.593*8.2. */
TEST(collada_truss_bridge_node_transform)
{
    loaded l;
    if (load("bridge/gazebo-truss-bridge/truss_bridge.dae", 0, &l)) return;
    CHECK_INT(l.m->nt, 3404);
    check_extent(&l, 0.592594 * 562.837 * 0.0254, 0.627454 * 979.685 * 0.0254,
                 0.592594 * 324.313 * 0.0254, 0.01);
    unload(&l);
}

/* The root node carries a Z-up → Y-up matrix; undone by the glTF Y-up → Z-up turn, the pole
 * stands 20.5 m along +Z with 12 m cross-arms. 11 meshes, 3 plain-colour materials used. */
TEST(gltf_simple_pole)
{
    loaded l;
    if (load("pylon/trimesh-simple-pole/simple_pole.glb", 0, &l)) return;
    CHECK_INT(l.m->nt, 580);
    CHECK_NEAR(l.lo[2], 0.0, 1e-3);
    CHECK_NEAR(l.hi[2], 20.5, 1e-3);
    CHECK_NEAR(fmax(l.hi[0] - l.lo[0], l.hi[1] - l.lo[1]), 12.0, 1e-3);
    CHECK_INT(l.info.meshes, 11);
    CHECK_INT(materials_used(&l), 3);
    unload(&l);
}

/* No index buffers, no materials; a -90 degree root rotation about X: 9 m high along +Z. */
TEST(gltf_building_no_indices)
{
    loaded l;
    if (load("building/trimesh-3storybuilding/no_indices_3storybuilding.glb", 0, &l)) return;
    CHECK_INT(l.m->nt, 72);
    CHECK_NEAR(l.lo[2], 0.0, 1e-3);
    CHECK_NEAR(l.hi[2], 9.0, 1e-3);
    CHECK_NEAR(l.hi[0] - l.lo[0], 56.08, 0.01);
    CHECK_NEAR(l.hi[1] - l.lo[1], 63.36, 0.01);
    unload(&l);
}

/* Inches by the caller's scale; CRLF lines, "../materials/textures" paths in the MTL, read with
 * the Gazebo model's folder (meshes/ and materials/) as the model's root. */
TEST(obj_cloverleaf)
{
    loaded l;
    if (load_within("structure/gazebo-cloverleaf-interchange/meshes/cloverleaf.obj", "structure/gazebo-cloverleaf-interchange",
                    0.0254, &l))
        return;
    CHECK_INT(l.m->nt, 1564);
    check_extent(&l, 355.6, 355.9, 6.7, 0.1);
    CHECK_INT(l.info.textures, 4);
    int found_road = 0;
    for (uint32_t i = 0; i < l.s->n_textures; i++)
        found_road |= strstr(l.s->textures[i].name, "materials/textures/road.png") != NULL;
    CHECK(found_road);
    unload(&l);
}

/* The texture lives in the GLB's binary chunk; the box is 1 m on each side. */
TEST(gltf_embedded_texture)
{
    loaded l;
    if (load("gltf-edge-cases/BoxTextured/BoxTextured.glb", 0, &l)) return;
    CHECK_INT(l.m->nt, 12);
    check_extent(&l, 1, 1, 1, 1e-4);
    const material *m = material_of(&l, 0);
    CHECK(m->texture >= 0);
    if (m->texture >= 0) {
        const texture *t = &l.s->textures[m->texture];
        CHECK_STR_CONTAINS(t->name, "BoxTextured.glb#*0");
        CHECK_INT(t->width, 211); /* the Cesium logo PNG */
        CHECK_INT(t->height, 211);
    }
    unload(&l);
}

/* alphaMode MASK with cutoffs 0.25, 0.5 (default) and 0.75: each gets its texture cut at its
 * own cutoff, so sylva's cut at one half reproduces it; OPAQUE asks for no mask. */
TEST(gltf_alpha_mask_cutoffs)
{
    loaded l;
    if (load("gltf-edge-cases/AlphaBlendModeTest/AlphaBlendModeTest.glb", 0, &l)) return;
    CHECK_INT(l.m->nt, 61);
    int cut[3] = {0, 0, 0}, opaque_unmasked = 0;
    for (uint32_t i = 0; i < l.s->n_materials; i++) {
        const material *m = &l.s->materials[i];
        if (m->texture < 0) continue;
        const char *tn = l.s->textures[m->texture].name;
        if (strstr(tn, "?alpha_cutoff=0.25")) cut[0] += m->alpha_mask;
        if (strstr(tn, "?alpha_cutoff=0.5")) cut[1] += m->alpha_mask;
        if (strstr(tn, "?alpha_cutoff=0.75")) cut[2] += m->alpha_mask;
        if (strstr(m->name, "Opaque") && !m->alpha_mask) opaque_unmasked++;
    }
    CHECK(cut[0] >= 1);
    CHECK(cut[1] >= 1);
    CHECK(cut[2] >= 1);
    CHECK(opaque_unmasked >= 1);
    /* A cut texture holds alpha 0 or 255 only; the three test images share one alpha ramp,
     * so a lower cutoff keeps more of it. */
    long kept[3] = {0, 0, 0};
    for (uint32_t i = 0; i < l.s->n_textures; i++) {
        const texture *t = &l.s->textures[i];
        const char *c = strstr(t->name, "?alpha_cutoff=");
        if (!c) continue;
        int other = 0, k = !strcmp(c, "?alpha_cutoff=0.25") ? 0 : !strcmp(c, "?alpha_cutoff=0.5") ? 1 : 2;
        for (size_t px = 3; px < (size_t)t->width * t->height * 4; px += 4) {
            other += t->rgba[px] != 0 && t->rgba[px] != 255;
            kept[k] += t->rgba[px] == 255;
        }
        CHECK_INT(other, 0);
    }
    fprintf(stderr, "texels kept at cutoffs 0.25, 0.5, 0.75: %ld %ld %ld\n", kept[0], kept[1], kept[2]);
    CHECK(kept[0] > kept[1]);
    CHECK(kept[1] > kept[2]);
    CHECK(kept[2] > 0);
    unload(&l);
}

/* The wheel mesh is used by two nodes: 2 856 unique triangles, 3 624 placed. */
TEST(gltf_instanced_mesh)
{
    loaded l;
    if (load("gltf-edge-cases/CesiumMilkTruck/CesiumMilkTruck.glb", 0, &l)) return;
    CHECK_INT(l.m->nt, 3624);
    CHECK_INT(l.info.meshes, 5);
    CHECK(l.lo[2] > -0.01 && l.lo[2] < 0.01); /* wheels on the ground: glTF +Y became +Z */
    unload(&l);
}

TEST(gltf_external_buffer_and_textures)
{
    loaded l;
    if (load("gltf-edge-cases/TextureTransformTest/TextureTransformTest.gltf", 0, &l)) return;
    CHECK_INT(l.m->nt, 24);
    CHECK(l.info.textures >= 1);
    unload(&l);
}

TEST(gltf_vertex_colours_default_material)
{
    loaded l;
    if (load("gltf-edge-cases/cubevc/cubevc.glb", 0, &l)) return;
    CHECK_INT(l.m->nt, 48);
    check_extent(&l, 2, 2, 2, 1e-4);
    unload(&l);
}

/* Distinct albedo colours (to 1/64) among the pixels that see the box, in a small top-down
 * render of the scene. */
static int distinct_albedos(const scene *s)
{
    render_options ro = {.threads = 1, .quiet = 1, .spp = 1, .width = 24, .height = 24};
    err_buf err = {{0}};
    film *f = render_scene(s, &ro, NULL, &err);
    CHECK(f != NULL);
    if (!f) {
        fprintf(stderr, "%s\n", err.msg);
        return -1;
    }
    uint32_t seen[24 * 24];
    int n = 0, hits = 0;
    for (uint32_t i = 0; i < f->width * f->height; i++) {
        if (f->coverage[i] < 0.99f) continue;
        hits++;
        uint32_t key = 0;
        for (int c = 0; c < 3; c++) key = key * 64 + (uint32_t)lrintf(f->albedo[i * 3 + c] * 63.0f);
        int known = 0;
        for (int k = 0; k < n; k++) known |= seen[k] == key;
        if (!known) seen[n++] = key;
    }
    CHECK(hits > 100); /* the box fills the middle of the view */
    film_free(f);
    return n;
}

/* Image test: the embedded texture reaches the renderer. Seen from above, the textured box
 * shows many albedo colours; with its material's texture taken away, one. */
TEST(gltf_embedded_texture_renders)
{
    loaded l;
    if (load("gltf-edge-cases/BoxTextured/BoxTextured.glb", 0, &l)) return;
    err_buf err = {{0}};
    l.s->image = (image_settings){.width = 24, .height = 24, .spp = 1, .seed = 1, .max_depth = 1};
    l.s->camera = (camera_settings){.position = {0, 0, 3}, .has_look_at = 1, .look_at = {0, 0, 0},
                                    .up = {0, 1, 0}, .fov_deg = 30};
    l.s->sky = (sky_settings){.model = SKY_CONSTANT, .scale = 1, .color = {1, 1, 1}, .ambient = {1, 1, 1}};
    int32_t mat = l.m->mat[0];
    CHECK_INT(scene_add_object(l.s, "box", l.m, &err), 0);
    l.m = NULL; /* the scene owns it now */
    int textured = distinct_albedos(l.s);
    l.s->materials[mat].texture = -1;
    int plain = distinct_albedos(l.s);
    fprintf(stderr, "albedo colours seen: %d textured, %d plain\n", textured, plain);
    CHECK(textured >= 4);
    CHECK_INT(plain, 1);
    unload(&l);
}

/* Copies the first `keep` bytes (all when 0) of src into the work folder as name. */
static const char *copy_prefix(const char *src, const char *name, long keep)
{
    FILE *in = fopen(src, "rb");
    const char *dst = work_path(name);
    FILE *out = fopen(dst, "wb");
    CHECK(in && out);
    if (in && out) {
        char buf[65536];
        size_t n;
        long left = keep ? keep : -1;
        while (left != 0 && (n = fread(buf, 1, left > 0 && left < (long)sizeof buf ? (size_t)left : sizeof buf, in)) > 0) {
            fwrite(buf, 1, n, out);
            if (left > 0) left -= (long)n;
        }
    }
    if (in) fclose(in);
    if (out) fclose(out);
    return dst;
}

static void expect_error_within(const char *path, const char *root, err_status status, const char *want1,
                                const char *want2)
{
    scene *s = scene_new();
    mesh *m = NULL;
    err_buf err = {{0}};
    model_import_options o = {.root = root};
    CHECK_INT(model_import(s, path, &o, &m, NULL, &err), -1);
    CHECK(m == NULL);
    CHECK_INT(err.status, status);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, want1);
    if (want2) CHECK_STR_CONTAINS(err.msg, want2);
    scene_free(s);
}

static void expect_error(const char *path, err_status status, const char *want1, const char *want2)
{
    expect_error_within(path, NULL, status, want1, want2);
}

/* The first 40 % of each GLB and of the COLLADA: each is refused with a sentence naming the file
 * (a GLB's chunks are checked against its length before Assimp reads it). */
TEST(truncated_files)
{
    struct { const char *src, *name, *why; } cases[] = {
        {MODELS "gltf-edge-cases/CesiumMilkTruck/CesiumMilkTruck.glb", "truck.glb", "the GLB is damaged or cut short"},
        {MODELS "pylon/gazebo-radio-tower/radio_tower.dae", "tower.dae", "cannot read the model"},
        {MODELS "pylon/trimesh-simple-pole/simple_pole.glb", "pole.glb", "the GLB is damaged or cut short"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        struct stat st;
        if (stat(cases[i].src, &st) != 0) {
            CHECK(0);
            continue;
        }
        const char *path = copy_prefix(cases[i].src, cases[i].name, (long)(st.st_size * 2 / 5));
        expect_error(path, ERR_INPUT, cases[i].why, NULL);
    }
}

/* The cloverleaf OBJ and MTL copied without the textures folder. */
TEST(missing_texture)
{
    const char *d = MODELS "structure/gazebo-cloverleaf-interchange/meshes/";
    char src[1024];
    mkdir(work_path("meshes"), 0700);
    snprintf(src, sizeof src, "%scloverleaf.mtl", d);
    copy_prefix(src, "meshes/cloverleaf.mtl", 0);
    snprintf(src, sizeof src, "%scloverleaf.obj", d);
    const char *obj = copy_prefix(src, "meshes/cloverleaf.obj", 0);
    expect_error_within(obj, work_dir(), ERR_INPUT, "names the texture '../materials/textures/",
                        "No such file or directory");
    /* without a root that holds materials/, the MTL's "../" leaves the model's folder */
    expect_error(obj, ERR_INPUT, "refers to the file '../materials/textures/road.png', which climbs out of the model's folder",
                 "/meshes and below");
}

TEST(unsupported_format_and_missing_file)
{
    const char *txt = work_path("notes.txt");
    FILE *f = fopen(txt, "w");
    if (f) fputs("not a model\n", f), fclose(f);
    expect_error(txt, ERR_INPUT, "not a model format sylva reads", ".obj, .gltf, .glb");
    expect_error(work_path("absent.glb"), ERR_INPUT, "cannot read the model", "No such file or directory");
}

/* The triangle limit is checked before the mesh is made. */
TEST(triangle_limit)
{
    scene *s = scene_new();
    mesh *m = NULL;
    err_buf err = {{0}};
    model_import_options o = {.max_triangles = 1000};
    CHECK_INT(model_import(s, MODELS "wind-turbine/iea-15-240-rwt/IEA-15-240-RWT_blade.stl", &o, &m,
                           NULL, &err), -1);
    CHECK_INT(err.status, ERR_LIMIT);
    CHECK_STR_CONTAINS(err.msg, "21730 triangles");
    CHECK_STR_CONTAINS(err.msg, "at most 1000");
    scene_free(s);
}

/* The harness's main is renamed so that this file's main can skip without the data. */
#define main model_import_data_tests
TEST_LIST(TEST_CASE(stl_tower), TEST_CASE(stl_blade), TEST_CASE(collada_radio_tower),
          TEST_CASE(collada_post_office), TEST_CASE(collada_truss_bridge_node_transform),
          TEST_CASE(gltf_simple_pole), TEST_CASE(gltf_building_no_indices), TEST_CASE(obj_cloverleaf),
          TEST_CASE(gltf_embedded_texture), TEST_CASE(gltf_embedded_texture_renders),
          TEST_CASE(gltf_alpha_mask_cutoffs),
          TEST_CASE(gltf_instanced_mesh), TEST_CASE(gltf_external_buffer_and_textures),
          TEST_CASE(gltf_vertex_colours_default_material), TEST_CASE(truncated_files),
          TEST_CASE(missing_texture), TEST_CASE(unsupported_format_and_missing_file),
          TEST_CASE(triangle_limit))
#undef main

int main(int argc, char **argv)
{
    struct stat st;
    if (stat(MODELS "README.md", &st) != 0) {
        fprintf(stderr, "skipped: the shared data set is not at %s\n", MODELS);
        return 77;
    }
    return model_import_data_tests(argc, argv);
}
