/* test_scene_models_data.c — the models of the shared data set (models/README.md) as objects of
 * a scene file: each format loads with its triangle count, its height along +Z (the up axis
 * turned where the file states one) and its size, standing on the ground; the IEA 15 MW
 * turbine as a group (tower, box nacelle, sphere hub, three blades at 120 degrees) placed by a
 * three-row layout, its blade mesh read once for nine blades; a textured model's texture in a
 * render; a truncated model refused naming the file. Without the shared data the test reports
 * itself skipped (status 77). */
#include <stdint.h>
#include <sys/stat.h>

#include "scene_text.h"

#define MODELS SYLVA_SHARED_DATA_DIR "/models/"
#define TURBINE MODELS "wind-turbine/iea-15-240-rwt/"

/* 1 when the shared data set is there; otherwise the running test is skipped. */
#define NEED_MODELS()                                                                               \
    do {                                                                                            \
        struct stat st_;                                                                            \
        if (stat(MODELS "README.md", &st_) != 0) SKIP("the shared data set is not at %s", MODELS);   \
    } while (0)

/* Every format of the data set in one scene, each snapped onto flat ground (no terrain: z = 0). */
TEST(each_format_in_a_scene)
{
    NEED_MODELS();
    static const struct {
        const char *file, *keys;
        uint32_t triangles;
        double height, x, y; /* extents; < 0: not checked */
    } models[] = {
        {"wind-turbine/iea-15-240-rwt/IEA-15-240-RWT_tower.stl", "", 946, 144.386, 10, 10},
        {"pylon/gazebo-radio-tower/radio_tower.dae", "", 4892, 44.2, -1, -1},
        {"pylon/trimesh-simple-pole/simple_pole.glb", "", 580, 20.5, -1, -1},
        {"building/trimesh-3storybuilding/no_indices_3storybuilding.glb", "", 72, 9, 56.08, 63.36},
        {"building/gazebo-post-office/post_office.dae", ", heading: 90", 1046, 3.9, 7.3, 10.4},
        {"structure/gazebo-cloverleaf-interchange/meshes/cloverleaf.obj",
         ", scale: 0.0254, model_root: " MODELS "structure/gazebo-cloverleaf-interchange", 1564, 6.7, 355.6, 355.9},
        {"gltf-edge-cases/BoxTextured/BoxTextured.glb", ", scale: 10", 12, 10, 10, 10},
        {"bridge/gazebo-truss-bridge/truss_bridge.dae", "", 3404, 0.592594 * 324.313 * 0.0254, -1, -1},
        {"gltf-edge-cases/CesiumMilkTruck/CesiumMilkTruck.glb", "", 3624, -1, -1, -1},
        {"gltf-edge-cases/TextureTransformTest/TextureTransformTest.gltf", "", 24, -1, -1, -1},
        {"gltf-edge-cases/AlphaBlendModeTest/AlphaBlendModeTest.glb", "", 61, -1, -1, -1},
        {"gltf-edge-cases/cubevc/cubevc.glb", "", 48, 2, 2, 2},
    };
    const size_t n = sizeof models / sizeof models[0];
    static char text[16384];
    size_t used = (size_t)snprintf(text, sizeof text, "camera: {position: [0, -500, 100], look_at: [0, 0, 0]}\nobjects:\n");
    for (size_t i = 0; i < n; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, "  - {model: %s%s, position: [%d, 0]%s}\n", MODELS,
                                 models[i].file, (int)i * 500, models[i].keys);
    scene *s = scene_text_build_ok(text);
    if (!s) return;
    CHECK_INT(s->n_objects, n);
    CHECK_INT(s->n_models, n);
    for (uint32_t i = 0; i < s->n_objects && i < n; i++) {
        double lo[3], hi[3];
        scene_text_object_bounds(s, i, lo, hi);
        fprintf(stderr, "%s: %u triangles, %.3f x %.3f x %.3f m\n", models[i].file, s->models[i].mesh->nt,
                hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
        CHECK_INT(s->models[s->objects[i].model].mesh->nt, models[i].triangles);
        if (models[i].height > 0) CHECK_NEAR(hi[2] - lo[2], models[i].height, 0.05);
        CHECK_NEAR(lo[2], 0, 1e-3); /* standing on the ground */
        if (models[i].x > 0) {
            CHECK_NEAR(hi[0] - lo[0], models[i].x, 0.05);
            CHECK_NEAR(hi[1] - lo[1], models[i].y, 0.05);
        }
    }
    scene_free(s);
}

static const char *turbine_yaml =
    "camera: {position: [0, -900, 60], look_at: [0, 0, 120]}\n"
    "materials:\n  white: {albedo: [0.8, 0.8, 0.8]}\n"
    "terrain: {grid: [[0, 20], [0, 20]], origin: [-1000, -1000], spacing: [2000, 2000]}\n"
    "groups:\n"
    "  turbine:\n"
    "    - {name: tower, model: " TURBINE "IEA-15-240-RWT_tower.stl}\n"
    "    - {name: nacelle, shape: box, size: [7, 18, 7], position: [0, 2.5, 147.9], material: white}\n"
    "    - {name: hub, shape: sphere, radius: 4, position: [0, 11.35, 150], material: white}\n"
    "    - {name: blade1, model: " TURBINE "IEA-15-240-RWT_blade.stl, position: [0, 11.35, 153]}\n"
    "    - {name: blade2, model: " TURBINE "IEA-15-240-RWT_blade.stl, position: [2.598, 11.35, 148.5], "
    "rotation: [0, 120, 0]}\n"
    "    - {name: blade3, model: " TURBINE "IEA-15-240-RWT_blade.stl, position: [-2.598, 11.35, 148.5], "
    "rotation: [0, 240, 0]}\n"
    "objects:\n  - {layout: farm.csv, group: turbine, development: true}\n";

/* Three turbines from a layout: 18 objects over 4 meshes (the blade file read once for nine
 * blades); blade 1 points straight up to 150 + 3 + 117 m over the tower's foot; a turbine
 * facing east (heading 90) has its hub 11.35 m east of its tower's axis. */
TEST(turbine_layout)
{
    NEED_MODELS();
    CHECK(work_file("farm.csv", "id,x,y,heading\nT1,-400,0,0\nT2,0,150,90\nT3,400,300,200\n") != NULL);
    scene *s = scene_text_build_ok(turbine_yaml);
    if (!s) return;
    CHECK_INT(s->n_objects, 18);
    CHECK_INT(s->n_models, 4);
    uint64_t triangles = 0;
    for (uint32_t m = 0; m < s->n_models; m++) triangles += s->models[m].mesh->nt;
    fprintf(stderr, "3 turbines: %u objects, %u meshes, %llu triangles held\n", s->n_objects, s->n_models,
            (unsigned long long)triangles);
    CHECK(triangles < 946 + 21730 + 2000); /* one tower, one blade, a box and a sphere */
    for (uint32_t t = 0; t < 3; t++) {
        double tlo[3], thi[3], blo[3], bhi[3], hlo[3], hhi[3];
        scene_text_object_bounds(s, t * 6 + 0, tlo, thi); /* tower */
        scene_text_object_bounds(s, t * 6 + 3, blo, bhi); /* blade1 */
        scene_text_object_bounds(s, t * 6 + 2, hlo, hhi); /* hub */
        double ground = 0;
        CHECK_INT(scene_terrain_height(s, (tlo[0] + thi[0]) / 2, (tlo[1] + thi[1]) / 2, &ground), 0);
        CHECK_NEAR(thi[2] - tlo[2], 144.386, 0.01);
        CHECK(tlo[2] <= ground + 0.01); /* the foot on (or, uphill, in) the ground: nothing floats */
        CHECK_NEAR(bhi[2] - tlo[2], 270.0, 0.5);
        CHECK(s->objects[t * 6 + 3].development);
        if (t == 1) {
            CHECK_NEAR((hlo[0] + hhi[0]) / 2 - (tlo[0] + thi[0]) / 2, 11.35, 0.05);
            CHECK_NEAR((hlo[1] + hhi[1]) / 2 - (tlo[1] + thi[1]) / 2, 0, 0.05);
        }
    }
    CHECK_STR_CONTAINS(s->objects[9].name, "T2/blade1");
    scene_free(s);
}

/* Image test: the embedded texture of a model reaches a render of the scene: the box's pixels
 * carry its object id, full development coverage and many albedo colours. */
TEST(textured_model_renders)
{
    NEED_MODELS();
    scene *s = scene_text_build_ok("image: {width: 32, height: 32, spp: 4, seed: 1, max_depth: 1}\n"
                        "camera: {position: [0, 0, 30], look_at: [0, 0, 0], up: [0, 1, 0], fov: 30}\n"
                        "sky: {model: constant, color: [1, 1, 1]}\n"
                        "objects:\n  - {model: " MODELS "gltf-edge-cases/BoxTextured/BoxTextured.glb, scale: 10, "
                        "development: true}\n");
    if (!s) return;
    film *f = scene_text_render(s);
    if (!f) {
        scene_free(s);
        return;
    }
    uint32_t seen[32 * 32], n = 0, inside = 0;
    for (uint32_t i = 0; i < f->width * f->height; i++) {
        if (f->object_id[i] != 1 || f->development[i] < 1.0f) continue;
        inside++;
        uint32_t key = 0;
        for (int c = 0; c < 3; c++) key = key * 64 + (uint32_t)lrintf(f->albedo[i * 3 + c] * 63.0f);
        int known = 0;
        for (uint32_t k = 0; k < n; k++) known |= seen[k] == key;
        if (!known) seen[n++] = key;
    }
    fprintf(stderr, "textured box: %u pixels, %u albedo colours\n", inside, n);
    CHECK(inside > 100);
    CHECK(n >= 4);
    film_free(f);
    scene_free(s);
}

/* A model cut short is refused naming the model and the scene line that places it. */
TEST(truncated_model_in_a_scene)
{
    NEED_MODELS();
    FILE *in = fopen(MODELS "pylon/trimesh-simple-pole/simple_pole.glb", "rb");
    FILE *out = fopen(work_path("pole.glb"), "wb");
    CHECK(in && out);
    if (in && out) {
        char buf[4096];
        size_t got = fread(buf, 1, sizeof buf, in);
        fwrite(buf, 1, got / 2, out);
    }
    if (in) fclose(in);
    if (out) fclose(out);
    err_buf err = {{0}};
    scene *s = scene_text_build("camera: {position: [0, -50, 10]}\nobjects:\n  - {name: pole, model: pole.glb}\n", &err);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(err.msg, "scene.yaml:3:5: object 'pole': ");
    CHECK_STR_CONTAINS(err.msg, "pole.glb: the GLB is damaged or cut short");
    scene_free(s);
}

TEST_LIST(TEST_CASE(each_format_in_a_scene), TEST_CASE(turbine_layout), TEST_CASE(textured_model_renders),
          TEST_CASE(truncated_model_in_a_scene))
