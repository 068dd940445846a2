/* test_scene_objects.c — objects of a scene file built into the scene graph: model files
 * placed by position, heading and height above ground or snapped to the terrain at their
 * footprint; one shared model however many objects use it; groups placed as one and CSV
 * layouts; clear errors naming the file; the id.object and development layers of a render; the
 * POV-Ray export declaring a model once. The models are small files the test writes. */
#include <stdint.h>

#include "scene_text.h"
#include "pov/pov_write.h"
#include "site/scene_probe.h"

/* A tetrahedron 1 x 2 x 3 m (x, y, z) with a corner at the origin, as ASCII STL. */
static const char *tet_stl =
    "solid tet\n"
    " facet normal 0 0 -1\n  outer loop\n   vertex 0 0 0\n   vertex 0 2 0\n   vertex 1 0 0\n  endloop\n endfacet\n"
    " facet normal 0 -1 0\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 0 3\n  endloop\n endfacet\n"
    " facet normal -1 0 0\n  outer loop\n   vertex 0 0 0\n   vertex 0 0 3\n   vertex 0 2 0\n  endloop\n endfacet\n"
    " facet normal 1 1 1\n  outer loop\n   vertex 1 0 0\n   vertex 0 2 0\n   vertex 0 0 3\n  endloop\n endfacet\n"
    "endsolid tet\n";

/* The same tetrahedron as an ASCII PLY drawn Y-up: its 3 m edge along +Y, its 2 m edge along -Z. */
static const char *tet_ply_y_up =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 0 -2\n0 3 0\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

/* A scene header: a 101 x 101 m terrain around the origin rising 0.1 m per metre eastward. */
static void terrain_header(char *buf, size_t n)
{
    size_t used = (size_t)snprintf(buf, n,
                                   "camera: {position: [0, -80, 30], look_at: [0, 0, 0]}\n"
                                   "terrain:\n  origin: [-50, -50]\n  spacing: [10, 10]\n  grid:\n");
    for (int r = 0; r < 11 && used < n; r++) {
        used += (size_t)snprintf(buf + used, n - used, "    - [");
        for (int c = 0; c < 11 && used < n; c++)
            used += (size_t)snprintf(buf + used, n - used, "%s%g", c ? ", " : "", 0.1 * (-50 + 10 * c));
        used += (size_t)snprintf(buf + used, n - used, "]\n");
    }
}

/* Builds the terrain header followed by body; NULL with err on failure. */
static scene *build(const char *body, err_buf *err)
{
    static char text[1 << 16];
    terrain_header(text, sizeof text);
    size_t used = strlen(text);
    snprintf(text + used, sizeof text - used, "%s", body);
    return scene_text_build(text, err);
}

static scene *build_ok(const char *body)
{
    static char text[1 << 16];
    terrain_header(text, sizeof text);
    size_t used = strlen(text);
    snprintf(text + used, sizeof text - used, "%s", body);
    return scene_text_build_ok(text);
}

static void check_bounds(const scene *s, uint32_t o, double x0, double x1, double y0, double y1, double z0,
                         double z1)
{
    double lo[3], hi[3];
    scene_text_object_bounds(s, o, lo, hi);
    CHECK_NEAR(lo[0], x0, 1e-4);
    CHECK_NEAR(hi[0], x1, 1e-4);
    CHECK_NEAR(lo[1], y0, 1e-4);
    CHECK_NEAR(hi[1], y1, 1e-4);
    CHECK_NEAR(lo[2], z0, 1e-4);
    CHECK_NEAR(hi[2], z1, 1e-4);
}

static void write_models(void)
{
    CHECK(work_file("tet.stl", tet_stl) != NULL);
    CHECK(work_file("tet_y.ply", tet_ply_y_up) != NULL);
}

/* A given z; a height above the ground at the origin; snapped at the footprint's lowest ground
 * (the slope rises eastward, so the west edge decides); a heading of 90 turns +Y to the east. */
TEST(model_placement)
{
    write_models();
    scene *s = build_ok("objects:\n"
                        "  - {name: at_z, model: tet.stl, position: [10, 20, 5], heading: 90}\n"
                        "  - {name: above, model: tet.stl, position: [20, 0], height_above_ground: 4}\n"
                        "  - {name: snapped, model: tet.stl, position: [20, 0]}\n"
                        "  - {name: snapped_turned, model: tet.stl, position: [20, 0], heading: 180}\n"
                        "  - {name: y_up, model: tet_y.ply, up_axis: y, scale: 2, position: [-20, -20, 0]}\n");
    if (!s) return;
    CHECK_INT(s->n_objects, 5);
    check_bounds(s, 0, 10, 12, 19, 20, 5, 8);           /* +Y (2 m) now points east */
    check_bounds(s, 1, 20, 21, 0, 2, 6, 9);             /* ground at x = 20 is 2 m; 4 m above it */
    check_bounds(s, 2, 20, 21, 0, 2, 2, 5);             /* lowest ground under x in [20, 21]: 2 m */
    check_bounds(s, 3, 19, 20, -2, 0, 1.9, 4.9);        /* turned west: x in [19, 20], lowest 1.9 m */
    check_bounds(s, 4, -20, -18, -20, -16, 0, 6);       /* the PLY's +Y is up, doubled: 6 m tall */
    CHECK_STR_CONTAINS(s->objects[2].name, "snapped");
    scene_free(s);
}

/* A probe finds a placed model's top over a point through the object's transform: the
 * tetrahedron at [10, 20, 5] has its slanted face x + (y - 20) / 2 + (z - 5) / 3 = 1 there. */
TEST(probe_finds_a_placed_model)
{
    write_models();
    scene *s = build_ok("objects:\n  - {name: tet, model: tet.stl, position: [10, 20, 5]}\n");
    if (!s) return;
    probe_result r;
    err_buf err = {{0}};
    CHECK_INT(scene_probe(s, 10.1, 20.1, 5.0, &r, &err), 0);
    CHECK_INT(r.n_objects, 1);
    if (r.n_objects) CHECK_NEAR(r.objects[0].top, 5.0 + 3.0 * (1.0 - 0.1 - 0.05), 1e-4);
    probe_result_free(&r);
    CHECK_INT(scene_probe(s, 12.0, 20.1, 5.0, &r, &err), 0);
    CHECK_INT(r.n_objects, 0);
    probe_result_free(&r);
    scene_free(s);
}

/* Twenty objects of one file share one model and one mesh; another scale is another model. */
TEST(instances_share_one_mesh)
{
    write_models();
    char body[8192] = "objects:\n";
    for (int i = 0; i < 20; i++) {
        size_t used = strlen(body);
        snprintf(body + used, sizeof body - used, "  - {model: tet.stl, position: [%d, 0], heading: %d}\n",
                 -40 + 4 * i, 18 * i);
    }
    strcat(body, "  - {model: tet.stl, scale: 2, position: [0, 30]}\n");
    scene *s = build_ok(body);
    if (!s) return;
    CHECK_INT(s->n_objects, 21);
    CHECK_INT(s->n_models, 2);
    uint64_t triangles = 0;
    for (uint32_t m = 0; m < s->n_models; m++) triangles += s->models[m].mesh->nt;
    CHECK_INT(triangles, 8); /* two meshes of 4 triangles, not 21 */
    for (uint32_t o = 0; o < 20; o++) {
        CHECK(s->objects[o].mesh == NULL);
        CHECK_INT(s->objects[o].model, 0);
    }
    CHECK_INT(s->objects[20].model, 1);
    scene_free(s);
}

static const char *group_yaml =
    "materials:\n  white: {albedo: [0.8, 0.8, 0.8]}\n"
    "groups:\n"
    "  mast:\n"
    "    - {name: base, shape: box, size: [2, 2, 2], position: [0, 0, 1], material: white}\n"
    "    - {name: top, model: tet.stl, position: [0, 0, 10]}\n";

/* A group placed by a layout: one object per part and row, named row/part, development set on
 * every part; the parts' meshes built once; the rows' headings turn each placement. */
TEST(group_layout)
{
    write_models();
    CHECK(work_file("layout.csv", "# three masts\nid,x,y,heading\nM1,-20,0,0\n\"M2\", 0, 0, 90\n\nM3,20,0,\n") != NULL);
    char body[4096];
    snprintf(body, sizeof body, "%sobjects:\n  - {layout: layout.csv, group: mast, development: true}\n"
                                "  - {name: single, group: mast, position: [0, 30, 7]}\n", group_yaml);
    scene *s = build_ok(body);
    if (!s) return;
    CHECK_INT(s->n_objects, 8);
    CHECK_INT(s->n_models, 2);
    CHECK_STR_CONTAINS(s->objects[0].name, "M1/base");
    CHECK_STR_CONTAINS(s->objects[3].name, "M2/top");
    CHECK_STR_CONTAINS(s->objects[6].name, "single/base");
    for (uint32_t o = 0; o < 8; o++) CHECK_INT(s->objects[o].development, o < 6);
    /* M1 snapped: the box's bottom on the lowest ground under [-21, -19], -2.1 m */
    check_bounds(s, 0, -21, -19, -1, 1, -2.1, -0.1);
    check_bounds(s, 1, -20, -19, 0, 2, 7.9, 10.9);
    /* M2 turned to the east: its top's 2 m edge runs along +x */
    check_bounds(s, 3, 0, 2, -1, 0, 9.9, 12.9);
    check_bounds(s, 6, -1, 1, 29, 31, 7, 9); /* at a given z */
    scene_free(s);
}

/* Built-in shapes of one kind, size and material share one mesh as models do: a layout of 30
 * boxes and a box written alone hold one box; another size, another material, a sphere and an
 * inline mesh are models of their own. Each object is an instance of its shape, snapped to the
 * slope as before. */
TEST(shapes_share_one_mesh)
{
    char csv[2048] = "id,x,y\n";
    for (int i = 0; i < 30; i++) {
        size_t used = strlen(csv);
        snprintf(csv + used, sizeof csv - used, "B%d,%d,%d\n", i, -29 + 2 * i, 10);
    }
    CHECK(work_file("boxes.csv", csv) != NULL);
    scene *s = build_ok("materials:\n  red: {type: lambert, albedo: [0.8, 0.1, 0.1]}\n"
                        "objects:\n"
                        "  - {layout: boxes.csv, shape: box, size: [1, 1, 3], material: red}\n"
                        "  - {name: alone, shape: box, size: [1, 1, 3], material: red, position: [0, -20]}\n"
                        "  - {name: grey, shape: box, size: [1, 1, 3], position: [5, -20]}\n"
                        "  - {name: tall, shape: box, size: [1, 1, 4], material: red, position: [10, -20]}\n"
                        "  - {name: ball, shape: sphere, radius: 1, position: [15, -20, 1]}\n"
                        "  - {name: tri, shape: mesh, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]],"
                        " triangles: [[0, 1, 2]], position: [20, -20, 0]}\n");
    if (!s) return;
    CHECK_INT(s->n_objects, 35);
    CHECK_INT(s->n_models, 5);
    uint64_t triangles = 0;
    for (uint32_t m = 0; m < s->n_models; m++) triangles += s->models[m].mesh->nt;
    CHECK_INT(triangles - s->models[s->objects[33].model].mesh->nt, 3 * 12 + 1); /* three boxes, a triangle */
    for (uint32_t o = 0; o < s->n_objects; o++) CHECK(s->objects[o].mesh == NULL);
    for (uint32_t o = 0; o < 31; o++) CHECK_INT(s->objects[o].model, 0);
    CHECK(s->objects[31].model != 0 && s->objects[32].model != 0 && s->objects[31].model != s->objects[32].model);
    /* B0 at x = -29 snapped: its bottom on the lowest ground under [-29.5, -28.5], -2.95 m */
    check_bounds(s, 0, -29.5, -28.5, 9.5, 10.5, -2.95, 0.05);
    check_bounds(s, 30, -0.5, 0.5, -20.5, -19.5, -0.05, 2.95);
    scene_free(s);
}

/* Map coordinates: easting and northing less the site origin (none here: the origin is 0). */
TEST(layout_in_map_coordinates)
{
    write_models();
    CHECK(work_file("map.csv", "id,easting,northing,height_above_ground\nA,5,6,3\n") != NULL);
    scene *s = build_ok("objects:\n  - {layout: map.csv, model: tet.stl}\n");
    if (!s) return;
    CHECK_INT(s->n_objects, 1);
    check_bounds(s, 0, 5, 6, 6, 8, 3.5, 6.5);
    scene_free(s);
}

static void expect_error(const char *body, const char *want1, const char *want2)
{
    err_buf err = {{0}};
    scene *s = build(body, &err);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(err.msg, want1);
    if (want2) CHECK_STR_CONTAINS(err.msg, want2);
    scene_free(s);
}

/* A layout saved by a spreadsheet starts with a UTF-8 byte-order mark: read as if it had none.
 * A quote left open is refused where it opens. */
TEST(layout_with_byte_order_mark_and_open_quote)
{
    write_models();
    CHECK(work_file("bom.csv", "\xef\xbb\xbfid,x,y\nA,5,6\n") != NULL);
    scene *s = build_ok("objects:\n  - {layout: bom.csv, model: tet.stl}\n");
    if (s) CHECK_STR_CONTAINS(s->objects[0].name, "A");
    scene_free(s);
    CHECK(work_file("open_quote.csv", "id,x,y\n\"A,5,6\nB, \"7, 8\n") != NULL);
    expect_error("objects:\n  - {layout: open_quote.csv, model: tet.stl}\n", "open_quote.csv:2:1: this field "
                 "opens a double quote that is not closed", NULL);
    CHECK(work_file("open_quote2.csv", "id,x,y\nB, \"7, 8\n") != NULL);
    expect_error("objects:\n  - {layout: open_quote2.csv, model: tet.stl}\n", "open_quote2.csv:2:4:", NULL);
}

/* Each problem stops the build with a sentence naming the file and place. */
TEST(clear_errors)
{
    write_models();
    CHECK(work_file("notes.txt", "not a model\n") != NULL);
    CHECK(work_file("cut.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
                               "end_header\n0 0 0\n1 0 0\n") != NULL);
    CHECK(work_file("textured.obj", "mtllib textured.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                    "usemtl skin\nf 1/1 2/2 3/3\n") != NULL);
    CHECK(work_file("textured.mtl", "newmtl skin\nKd 1 1 1\nmap_Kd missing.png\n") != NULL);
    CHECK(work_file("bad_column.csv", "id,x,y,tilt\nA,1,2,3\n") != NULL);
    CHECK(work_file("bad_number.csv", "id,x,y\nA,1,2\nB,1,two\n") != NULL);
    expect_error("objects:\n  - {model: notes.txt}\n", "scene.yaml:18:5: object 'objects[0]'",
                 "notes.txt: not a model format sylva reads");
    expect_error("objects:\n  - {model: absent.glb}\n", "absent.glb: cannot read the model",
                 "No such file or directory");
    expect_error("objects:\n  - {model: cut.ply}\n", "cut.ply:", "the file is cut short");
    expect_error("objects:\n  - {model: textured.obj}\n", "textured.obj: material 'skin' names the texture "
                 "'missing.png'", "No such file or directory");
    expect_error("objects:\n  - {layout: bad_column.csv, model: tet.stl}\n", "bad_column.csv:1:8: unknown column "
                 "'tilt'", NULL);
    expect_error("objects:\n  - {layout: bad_number.csv, model: tet.stl}\n",
                 "bad_number.csv:3:5: 'y' must be a finite number, got 'two'", NULL);
    expect_error("objects:\n  - {layout: absent.csv, model: tet.stl}\n", "absent.csv", "No such file");
    expect_error("objects:\n  - {model: tet.stl, shape: box}\n", "scene.yaml:18:5: 'objects[0]' gives shape, "
                 "model or group; an object is one of them", NULL);
    expect_error("objects:\n  - {model: tet.stl, position: [1, 2, 3], height_above_ground: 2}\n",
                 "gives both a height", NULL);
    expect_error("objects:\n  - {group: nowhere}\n", "names group 'nowhere'", "no 'groups:' section");
    expect_error("groups:\n  g:\n    - {model: tet.stl, development: true}\nobjects:\n  - {group: g}\n",
                 "'groups.g[0]' is a part of a group: 'development' belongs on the objects entry", NULL);
    expect_error("objects:\n  - {model: tet.stl, position: [80, 0]}\n", "lies outside the terrain", NULL);
    expect_error("groups:\n  g:\n    - {name: top, model: absent.stl}\nobjects:\n  - {name: G1, group: g}\n",
                 "scene.yaml:21:5: object 'G1': group 'g', part 'top': ", "absent.stl: cannot read the model");
}

/* Pixels of the development's model carry its object id and a coverage of 1, the ground none;
 * the model's edges give coverage strictly between 0 and 1 (antialiased). */
TEST(object_id_and_development_layers)
{
    write_models();
    scene *s = build_ok("image: {width: 40, height: 40, spp: 16, seed: 3, max_depth: 1}\n"
                        "objects:\n"
                        "  - {name: marker, shape: box, size: [1, 1, 1], position: [-30, 40, 0]}\n"
                        "  - {name: tet, model: tet.stl, scale: 8, position: [-4, -8], development: true}\n");
    if (!s) return;
    s->camera = (camera_settings){.position = {0, -60, 12}, .has_look_at = 1, .look_at = {0, 0, 8},
                                  .up = {0, 0, 1}, .fov_deg = 30};
    film *f = scene_text_render(s);
    if (!f) {
        scene_free(s);
        return;
    }
    uint32_t on = 0, partial = 0, wrong = 0;
    for (uint32_t i = 0; i < f->width * f->height; i++) {
        float d = f->development[i];
        if (f->object_id[i] == 2 && d == 1.0f) on++;
        if (d > 0.0f && d < 1.0f) partial++;
        if (f->object_id[i] != 2 && d == 1.0f) wrong++;
        if (f->pixel_class[i] == PIXEL_TERRAIN && f->object_id[i]) wrong++;
    }
    fprintf(stderr, "development: %u pixels fully covered, %u partly\n", on, partial);
    CHECK(on > 50);
    CHECK(partial > 10);
    CHECK_INT(wrong, 0);
    film_free(f);
    scene_free(s);
}

static int count(const char *text, const char *needle)
{
    int n = 0;
    for (const char *p = text; (p = strstr(p, needle)); p += strlen(needle)) n++;
    return n;
}

/* The POV-Ray export declares the shared model once and places it by one line per object. */
TEST(pov_export_declares_a_model_once)
{
    write_models();
    char body[8192] = "objects:\n";
    for (int i = 0; i < 20; i++) {
        size_t used = strlen(body);
        snprintf(body + used, sizeof body - used, "  - {model: tet.stl, position: [%d, 0]}\n", -40 + 4 * i);
    }
    scene *s = build_ok(body);
    if (!s) return;
    err_buf err = {{0}};
    int rc = pov_export_scene(s, work_path("farm.pov"), NULL, NULL, &err);
    CHECK_INT(rc, 0);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    FILE *fp = fopen(work_path("farm_objects.inc"), "r");
    CHECK(fp != NULL);
    static char inc[1 << 16];
    size_t n = fp ? fread(inc, 1, sizeof inc - 1, fp) : 0;
    inc[n] = 0;
    if (fp) fclose(fp);
    /* one declaration: a mesh2, or a union of its smooth and its flat triangles' mesh2 */
    CHECK_INT(count(inc, "#declare D0_Tet_stl = "), 1);
    CHECK(count(inc, "mesh2 {") >= 1 && count(inc, "mesh2 {") <= 2);
    CHECK_INT(count(inc, "= object { D0_Tet_stl matrix <"), 20);
    scene_free(s);
}

TEST_LIST(TEST_CASE(model_placement), TEST_CASE(probe_finds_a_placed_model), TEST_CASE(instances_share_one_mesh), TEST_CASE(group_layout),
          TEST_CASE(shapes_share_one_mesh),
          TEST_CASE(layout_in_map_coordinates), TEST_CASE(layout_with_byte_order_mark_and_open_quote),
          TEST_CASE(clear_errors),
          TEST_CASE(object_id_and_development_layers), TEST_CASE(pov_export_declares_a_model_once))
