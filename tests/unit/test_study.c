/* test_study.c — the pieces of `sylva study` (study/): the frames' sizes by the rule of
 * docs/study.md and their lenses (the single frame's field of view is the scene file's 50 mm
 * lens to the bit), the viewpoints picked and ranked, a product's record, and the scene marked
 * and rewound as each viewpoint's ground cover comes and goes (scene/scene_mark.h), the scene's
 * digest (what it leaves out and what it keeps). The command
 * end to end is tests/cli/study_test.sh. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "scene/scene_mark.h"
#include "scene_file/scene_file.h"
#include "study/study_frames.h"
#include "study/study_manifest.h"
#include "study/study_views.h"
#include "util/name_list.h"
#include "work_dir.h"

static const char *views_scene =
    "camera: {position: [0, 0, 2]}\n"
    "viewpoints:\n"
    "  a: {position: [0, -50, 2], heading: 0, focal_length: 50}\n"
    "  b: {position: [50, 0, 2], heading: 270}\n"
    "  c: {position: [0, 50, 2], heading: 180}\n"
    "objects:\n"
    "  - {name: mast, shape: box, size: [1, 1, 20], position: [0, 0, 10], development: true}\n";

/* Frame f of z is w x h pixels. */
static void check_size(int f, const study_sizing *z, uint32_t w, uint32_t h)
{
    uint32_t px[2];
    study_frame_size(f, z, px);
    CHECK_INT(px[0], w);
    CHECK_INT(px[1], h);
}

TEST(frame_sizes)
{
    study_sizing z = {.dpi = 300, .image_width = 72};
    check_size(STUDY_SINGLE, &z, 72, 48);
    check_size(STUDY_PLANAR_53, &z, 72, 23); /* 72 * 260 / 820 = 22.8 */
    z.print_width_mm = 420;                  /* A3 landscape at 300 dpi */
    check_size(STUDY_SINGLE, &z, 4961, 3307);
    check_size(STUDY_CYLINDRICAL_90, &z, 4961, 1573);
    z.size[0] = 480; /* the width alone: each frame's own height */
    check_size(STUDY_SINGLE, &z, 480, 320);
    check_size(STUDY_CYLINDRICAL_90, &z, 480, 152);
    z.size[1] = 200; /* both: every frame that size */
    check_size(STUDY_PLANAR_53, &z, 480, 200);
}

TEST(frame_lenses)
{
    err_buf err;
    scene_file *sf = scene_file_load(work_file("views.yaml", views_scene), NULL, &err);
    CHECK(sf != NULL);
    if (!sf) return;
    camera_settings c = sf->viewpoints[1].camera; /* no focal length given */
    study_frame_lens(STUDY_SINGLE, &c);
    CHECK(c.fov_deg == sf->viewpoints[0].camera.fov_deg); /* a's focal_length: 50, to the bit */
    CHECK_NEAR(c.fov_deg, 39.5978, 1e-4);
    CHECK_INT(c.cylindrical, 0);
    study_frame_lens(STUDY_CYLINDRICAL_90, &c);
    CHECK_INT(c.cylindrical, 1);
    CHECK(c.fov_deg == 90.0);
    CHECK(c.direction[0] == sf->viewpoints[1].camera.direction[0]); /* the view kept */
    scene_file_free(sf);
}

static int names_are(const study_views *v, const char *want)
{
    char got[64] = "";
    for (uint32_t i = 0; i < v->n; i++) strcat(strcat(got, i ? " " : ""), v->views[i]->name);
    if (strcmp(got, want)) fprintf(stderr, "viewpoints '%s', expected '%s'\n", got, want);
    return !strcmp(got, want);
}

TEST(views_picked_and_ranked)
{
    err_buf err;
    scene_file *sf = scene_file_load(work_file("views.yaml", views_scene), NULL, &err);
    CHECK(sf != NULL);
    if (!sf) return;
    study_views v;
    CHECK_INT(study_views_pick(sf, &(study_view_names){0}, &v, &err), 0);
    CHECK(names_are(&v, "a b c"));
    study_views_free(&v);
    CHECK_INT(study_views_pick(sf, &(study_view_names){.viewpoints = "c, a", .rank = "a"}, &v, &err), 0);
    CHECK(names_are(&v, "a c"));
    study_views_free(&v);
    CHECK_INT(study_views_pick(sf, &(study_view_names){.only = "c b", .rank = "c"}, &v, &err), 0);
    CHECK(names_are(&v, "c b"));
    study_views_free(&v);
    CHECK_INT(study_views_pick(sf, &(study_view_names){.only = "d"}, &v, &err), -1);
    CHECK_INT(err.status, ERR_USAGE);
    CHECK_STR_CONTAINS(err.msg, "--only names 'd', which is no viewpoint of");
    CHECK_STR_CONTAINS(err.msg, "its viewpoints are: a, b, c");
    CHECK_INT(study_views_pick(sf, &(study_view_names){.viewpoints = "a", .only = "b"}, &v, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "--only names 'b', which the study does not render");
    scene_file_free(sf);
}

TEST(record_current)
{
    camera_settings c = {.position = {1, 2, NAN}, .fov_deg = 90, .cylindrical = 1};
    study_record r = {.scene_digest = 0x1234, .viewpoint = "gate", .camera = &c, .product = "wireline",
                      .frame = "cylindrical_90", .width = 96, .height = 30, .spp = 4, .seed = 7};
    char text[STUDY_MANIFEST_MAX], other[STUDY_MANIFEST_MAX];
    study_manifest_text(&r, text);
    CHECK_STR_CONTAINS(text, "scene 0000000000001234\nviewpoint gate\nproduct wireline\nframe cylindrical_90\n");
    const char *png = work_file("w.png", "x"), *exr = work_file("w.exr", "x"), *path = work_path("w.manifest");
    err_buf err;
    CHECK_INT(study_manifest_current(path, text, png, exr), 0); /* no record yet */
    CHECK_INT(study_manifest_write(path, text, &err), 0);
    CHECK_INT(study_manifest_current(path, text, png, exr), 1);
    r.spp = 8;
    study_manifest_text(&r, other);
    CHECK_INT(study_manifest_current(path, other, png, exr), 0); /* another setting */
    CHECK_INT(study_manifest_current(path, text, png, work_path("missing.exr")), 0);
}

TEST(scene_rewound)
{
    err_buf err;
    scene *s = scene_new();
    CHECK(s != NULL);
    if (!s) return;
    sylva_material_desc d = {.size = sizeof d, .name = "bark", .texture = -1};
    CHECK_INT(scene_add_material(s, &d, &err), 1);
    scene_mark m = scene_mark_take(s);
    d.name = "grass";
    CHECK_INT(scene_add_material(s, &d, &err), 2);
    int32_t sp = scene_add_species(s, "tufts", &err);
    CHECK(sp >= 0);
    CHECK(scene_add_prototype(s, (uint32_t)sp, 0, 1, 0.3, mesh_new(), &err) >= 0);
    xform3x4 xf = xf_identity();
    CHECK(scene_add_instance(s, 0, &xf, &err) >= 0);
    CHECK_INT(scene_rewind(s, &m, &err), 0);
    CHECK_INT(s->n_materials, 2);
    CHECK_INT(s->n_species, 0);
    CHECK_INT(s->n_prototypes, 0);
    CHECK_INT(s->n_instances, 0);
    CHECK_INT(scene_find_material(s, "grass"), -1);
    CHECK_INT(scene_find_material(s, "bark"), 1);
    d.name = "grass";
    CHECK_INT(scene_add_material(s, &d, &err), 2); /* the same index again */
    CHECK_INT(scene_find_material(s, "grass"), 2);
    scene_free(s);
}

/* The digest of the views scene with `from` replaced by `to` and `extra` after it, or 0 when it
 * does not load. */
static uint64_t digest_of(const char *from, const char *to, const char *extra)
{
    char text[2048];
    const char *at = strstr(views_scene, from);
    snprintf(text, sizeof text, "%.*s%s%s%s", (int)(at - views_scene), views_scene, to, at + strlen(from), extra);
    err_buf err;
    scene_file *sf = scene_file_load(work_file("digest.yaml", text), NULL, &err);
    CHECK(sf != NULL);
    uint64_t d = sf ? sf->digest : 0;
    scene_file_free(sf);
    return d;
}

/* The scene's digest leaves out its cameras, its study and its comments, not what is drawn. */
TEST(scene_digest)
{
    uint64_t base = digest_of("camera", "camera", "");
    CHECK(base != 0);
    CHECK(digest_of("heading: 270", "heading: 210", "study: {frames: cylindrical_90}\n") == base);
    CHECK(digest_of("camera: {position: [0, 0, 2]}", "camera: {position: [5, 0, 2]}  # moved", "") == base);
    CHECK(digest_of("[1, 1, 20]", "[1,  1,  20]", "") == base); /* the same mast, written otherwise */
    CHECK(digest_of("[1, 1, 20]", "[1, 1, 30]", "") != base);   /* a 30 m mast */
    CHECK(digest_of("camera", "camera", "sun: {azimuth: 90}\n") != base);
}

TEST(name_lists)
{
    const char *text = " existing, proposed ,wireline", *name;
    size_t len;
    CHECK_INT((len = name_list_next(&text, &name)), 8);
    CHECK(!strncmp(name, "existing", len));
    CHECK_INT((len = name_list_next(&text, &name)), 8);
    CHECK(!strncmp(name, "proposed", len));
    CHECK_INT((len = name_list_next(&text, &name)), 8);
    CHECK(!strncmp(name, "wireline", len));
    CHECK_INT(name_list_next(&text, &name), 0);
}

TEST_LIST(TEST_CASE(frame_sizes), TEST_CASE(frame_lenses), TEST_CASE(views_picked_and_ranked),
          TEST_CASE(record_current), TEST_CASE(scene_rewound), TEST_CASE(scene_digest), TEST_CASE(name_lists))
