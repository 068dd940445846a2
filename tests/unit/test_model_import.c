/* test_model_import.c — model_import on small files written by the test, one per format the
 * shared data set lacks (PLY, binary STL, 3DS, FBX) and for the cases it does not show: the
 * same tetrahedron, 1 x 2 x 3 units along x, y, z, must come out 1 x 2 x 3 m with +Z up from
 * every Z-up file, turned from Y-up files, scaled by the file's unit and the caller's scale; an
 * OBJ's points and lines are dropped and its MTL texture read; a mirroring node keeps the
 * triangles facing the way their normals do; bad options and files without triangles give
 * clear errors. */
#include <dirent.h>
#include <stdint.h>

#include "harness.h"
#include "work_dir.h"
#include "io/image_io.h"
#include "geometry/cutout.h"
#include "model/gltf_layout.h"
#include "model/model_import.h"
#include "model/obj_statements.h"
#include "scene/scene.h"

static const float tet_pos[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
static const uint16_t tet_tri[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}; /* outward */

static const char *write_text(const char *name, const char *text)
{
    const char *path = work_path(name);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) fputs(text, f), fclose(f);
    return path;
}

/* The file as bytes: n bytes from p appended to the open file. */
static void put(FILE *f, const void *p, size_t n) { fwrite(p, 1, n, f); }

/* A GLB of the JSON text (its chunk padded with spaces to four bytes) and, when bin_len is not 0,
 * a BIN chunk of bin_len bytes from bin; its path, or NULL when it cannot be written. */
static const char *write_glb(const char *name, const char *json, const void *bin, uint32_t bin_len)
{
    uint32_t len = (uint32_t)(strlen(json) + 3) / 4 * 4, total = 20 + len + (bin_len ? 8 + bin_len : 0);
    uint32_t json_type = 0x4E4F534A, bin_type = 0x004E4942;
    const char *path = work_path(name);
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return NULL;
    put(f, "glTF", 4), put(f, &(uint32_t){2}, 4), put(f, &total, 4), put(f, &len, 4), put(f, &json_type, 4);
    put(f, json, strlen(json)), put(f, "   ", len - strlen(json));
    if (bin_len) put(f, &bin_len, 4), put(f, &bin_type, 4), put(f, bin, bin_len);
    fclose(f);
    return path;
}

static const char *write_binary_stl(void)
{
    const char *path = work_path("tet.stl");
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return path;
    char header[80] = "sylva test tetrahedron";
    uint32_t n = 4;
    put(f, header, sizeof header), put(f, &n, 4);
    for (int t = 0; t < 4; t++) {
        float zero[3] = {0, 0, 0}; /* no facet normal: the reader makes one */
        uint16_t attr = 0;
        put(f, zero, sizeof zero);
        for (int k = 0; k < 3; k++) put(f, tet_pos[tet_tri[t][k]], 12);
        put(f, &attr, 2);
    }
    fclose(f);
    return path;
}

/* A 3DS chunk header: id and length including the header. */
static void chunk(FILE *f, uint16_t id, uint32_t body)
{
    uint32_t len = body + 6;
    put(f, &id, 2), put(f, &len, 4);
}

static const char *write_3ds(void)
{
    const char *path = work_path("tet.3ds");
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return path;
    const uint32_t verts = 2 + 4 * 12, faces = 2 + 4 * 8, trimesh = 6 + verts + 6 + faces;
    const uint32_t named = 4 + 6 + trimesh, version = 4;
    chunk(f, 0x4D4D, 6 + version + 6 + 6 + named);
    chunk(f, 0x0002, version);
    uint32_t v3 = 3;
    put(f, &v3, 4);
    chunk(f, 0x3D3D, 6 + named);
    chunk(f, 0x4000, named);
    put(f, "tet", 4);
    chunk(f, 0x4100, trimesh);
    chunk(f, 0x4110, verts);
    uint16_t n = 4;
    put(f, &n, 2);
    put(f, tet_pos, sizeof tet_pos);
    chunk(f, 0x4120, faces);
    put(f, &n, 2);
    for (int t = 0; t < 4; t++) {
        uint16_t flags = 0;
        put(f, tet_tri[t], 6), put(f, &flags, 2);
    }
    fclose(f);
    return path;
}

/* An ASCII FBX 7.4 with the given up axis (1: Y, 2: Z) and centimetres per unit. */
static const char *write_fbx(const char *name, int up_axis, double cm_per_unit)
{
    char text[2048];
    snprintf(text, sizeof text,
             "; FBX 7.4.0 project file\n"
             "FBXHeaderExtension:  {\n\tFBXHeaderVersion: 1003\n\tFBXVersion: 7400\n}\n"
             "GlobalSettings:  {\n\tVersion: 1000\n\tProperties70:  {\n"
             "\t\tP: \"UpAxis\", \"int\", \"Integer\", \"\",%d\n"
             "\t\tP: \"UpAxisSign\", \"int\", \"Integer\", \"\",1\n"
             "\t\tP: \"UnitScaleFactor\", \"double\", \"Number\", \"\",%g\n\t}\n}\n"
             "Objects:  {\n\tGeometry: 1000, \"Geometry::tet\", \"Mesh\" {\n"
             "\t\tVertices: *12 {\n\t\t\ta: 0,0,0,1,0,0,0,2,0,0,0,3\n\t\t}\n"
             "\t\tPolygonVertexIndex: *12 {\n\t\t\ta: 0,2,-2,0,1,-4,0,3,-3,1,2,-4\n\t\t}\n"
             "\t\tGeometryVersion: 124\n\t}\n"
             "\tModel: 2000, \"Model::tet\", \"Mesh\" {\n\t\tVersion: 232\n\t}\n}\n"
             "Connections:  {\n\tC: \"OO\",2000,0\n\tC: \"OO\",1000,2000\n}\n",
             up_axis, cm_per_unit);
    return write_text(name, text);
}

static const char *ply_text =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 2 0\n0 0 3\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

/* Imports path; the test fails when it does not load. */
static mesh *load(scene *s, const char *path, double scale, model_up up, model_import_info *info)
{
    err_buf err = {{0}};
    model_import_options o = {.scale = scale, .up = up};
    mesh *m = NULL;
    int rc = model_import(s, path, &o, &m, info, &err);
    CHECK_INT(rc, 0);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    return m;
}

/* The mesh's extent along x, y, z. */
static void check_extent(const mesh *m, double x, double y, double z)
{
    float lo[3], hi[3];
    mesh_bounds(m, lo, hi);
    CHECK_NEAR(hi[0] - lo[0], x, 1e-5);
    CHECK_NEAR(hi[1] - lo[1], y, 1e-5);
    CHECK_NEAR(hi[2] - lo[2], z, 1e-5);
}

/* The mesh is one convex body (the tetrahedron, moved and turned): every triangle's winding
 * faces away from the body's centre, and every vertex normal is unit length and points away
 * from it too. */
static void check_outward(const mesh *m)
{
    double c[3] = {0, 0, 0};
    for (uint32_t v = 0; v < m->nv; v++)
        for (int d = 0; d < 3; d++) c[d] += m->pos[v * 3 + d] / m->nv;
    int bad = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
        const uint32_t *k = m->tri + t * 3;
        const float *a = m->pos + k[0] * 3, *b = m->pos + k[1] * 3, *p = m->pos + k[2] * 3;
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
        double g[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        double out = 0;
        for (int d = 0; d < 3; d++) out += g[d] * ((a[d] + b[d] + p[d]) / 3 - c[d]);
        bad += out <= 0;
    }
    for (uint32_t v = 0; v < m->nv; v++) {
        const float *n = m->nrm + v * 3, *p = m->pos + v * 3;
        bad += n[0] * (p[0] - c[0]) + n[1] * (p[1] - c[1]) + n[2] * (p[2] - c[2]) <= 0;
        bad += fabs(sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0) > 1e-5;
    }
    CHECK_INT(bad, 0);
}

TEST(z_up_formats_keep_their_axes)
{
    for (int i = 0; i < 4; i++) {
        char path[1200]; /* work_path's buffer is reused by the next call */
        snprintf(path, sizeof path, "%s",
                 i == 0 ? write_binary_stl() : i == 1 ? write_text("tet.ply", ply_text)
                 : i == 2 ? write_3ds() : write_fbx("metres.fbx", 2, 100.0));
        int before = harness_failures;
        scene *s = scene_new();
        mesh *m = load(s, path, 0, MODEL_UP_FILE, NULL);
        if (m) {
            CHECK_INT(m->nt, 4);
            check_extent(m, 1, 2, 3);
            check_outward(m);
        }
        if (harness_failures > before) fprintf(stderr, "  (in %s)\n", path);
        mesh_free(m);
        scene_free(s);
    }
}

/* A Y-up PLY (the caller says so) and a Y-up FBX in centimetres: file y becomes +z, file z
 * becomes -y. */
TEST(y_up_files_are_turned)
{
    scene *s = scene_new();
    mesh *m = load(s, write_text("tet-y.ply", ply_text), 0, MODEL_UP_Y, NULL);
    if (m) check_extent(m, 1, 3, 2), check_outward(m);
    mesh_free(m);
    m = load(s, write_fbx("centimetres.fbx", 1, 1.0), 0, MODEL_UP_FILE, NULL);
    if (m) check_extent(m, 0.01, 0.03, 0.02), check_outward(m);
    mesh_free(m);
    scene_free(s);
}

/* Points and lines are dropped; the MTL's texture is read beside the OBJ, its alpha asks for
 * the mask; the caller's scale applies; missing normals are made. */
TEST(obj_with_mtl_texture_points_lines)
{
    uint8_t px[2 * 2 * 4] = {255, 0, 0, 255, 0, 255, 0, 0, 0, 0, 255, 255, 255, 255, 255, 128};
    err_buf err = {{0}};
    CHECK_INT(image_write_u8(work_path("leaf.png"), 2, 2, 4, px, &err), 0);
    write_text("tet.mtl", "newmtl Bark\nKd 0.5 0.25 0.125\nmap_Kd leaf.png\n");
    const char *obj = write_text("tet.obj",
                                 "mtllib tet.mtl\nv 0 0 0\nv 1 0 0\nv 0 2 0\nv 0 0 3\n"
                                 "vt 0 0\nvt 1 0\nvt 0 1\nusemtl Bark\n"
                                 "f 1/1 3/3 2/2\nf 1/1 2/2 4/3\nf 1/1 4/3 3/3\nf 2/2 3/3 4/1\n"
                                 "l 1 2\np 3\n");
    scene *s = scene_new();
    model_import_info info;
    mesh *m = load(s, obj, 2.0, MODEL_UP_FILE, &info);
    if (m) {
        CHECK_INT(m->nt, 4);
        check_extent(m, 2, 4, 6);
        check_outward(m);
        CHECK_INT(info.materials, 1);
        CHECK_INT(info.textures, 1);
        const material *mat = &s->materials[m->mat[0]];
        CHECK_STR_CONTAINS(mat->name, "tet.obj:Bark");
        CHECK_NEAR(mat->albedo.y, 0.25, 1e-6);
        CHECK(mat->texture >= 0);
        CHECK(cutout_material(s, mat));
    }
    mesh_free(m);
    scene_free(s);
}

static void base64(const uint8_t *in, size_t n, char *out)
{
    static const char tab[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t o = 0;
    for (size_t i = 0; i < n; i += 3) {
        uint32_t v = (uint32_t)in[i] << 16 | (i + 1 < n ? (uint32_t)in[i + 1] << 8 : 0) | (i + 2 < n ? in[i + 2] : 0);
        out[o++] = tab[v >> 18 & 63], out[o++] = tab[v >> 12 & 63];
        out[o++] = i + 1 < n ? tab[v >> 6 & 63] : '=';
        out[o++] = i + 2 < n ? tab[v & 63] : '=';
    }
    out[o] = '\0';
}

/* A glTF whose node mirrors x (scale -1, 1, 1) under a parent lifted 5 units: the triangles
 * must still face the way their normals point, and glTF's +Y must become +Z. */
static void expect_error(const char *path, const model_import_options *o, err_status status, const char *want);

/* The tetrahedron's vertices in a glTF whose mesh node has the scale `scale` ("x,y,z") under a
 * lift of 5 m, and one primitive of mode `mode` with the n 16-bit indices (at most 12). */
static const char *write_tet_gltf(const char *name, const char *scale, int mode, const uint16_t *indices, int n)
{
    uint8_t buf[48 + 24];
    memcpy(buf, tet_pos, 48);
    memcpy(buf + 48, indices, 2 * (size_t)n);
    char b64[200], text[2048];
    base64(buf, 48 + 2 * (size_t)n, b64);
    snprintf(text, sizeof text,
             "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
             "\"nodes\":[{\"translation\":[0,5,0],\"children\":[1]},{\"mesh\":0,\"scale\":[%s]}],"
             "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"mode\" : %d}]}],"
             "\"buffers\":[{\"byteLength\":%d,\"uri\":\"data:application/octet-stream;base64,%s\"}],"
             "\"bufferViews\":[{\"buffer\":0,\"byteLength\":48},{\"buffer\":0,\"byteOffset\":48,\"byteLength\":%d}],"
             "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\","
             "\"min\":[0,0,0],\"max\":[1,2,3]},{\"bufferView\":1,\"componentType\":5123,\"count\":%d,"
             "\"type\":\"SCALAR\"}]}",
             scale, mode, 48 + 2 * n, b64, 2 * n, n);
    return write_text(name, text);
}

/* The tetrahedron's triangles so. */
static const char *write_scaled_gltf(const char *name, const char *scale)
{
    return write_tet_gltf(name, scale, 4, &tet_tri[0][0], 12);
}

static const char *write_mirrored_gltf(void) { return write_scaled_gltf("mirrored.gltf", "-1,1,1"); }

/* Positions finite in the file that a node's scale carries beyond single precision are refused,
 * not handed on as infinities. */
TEST(gltf_node_scale_beyond_single_precision)
{
    expect_error(write_scaled_gltf("huge.gltf", "2e38,2e38,2e38"), NULL, ERR_INPUT,
                 "beyond 3.40282e+38 once placed by its node's transform");
}

TEST(gltf_mirrored_node_keeps_winding)
{
    scene *s = scene_new();
    mesh *m = load(s, write_mirrored_gltf(), 0, MODEL_UP_FILE, NULL);
    if (m) {
        CHECK_INT(m->nt, 4);
        float lo[3], hi[3];
        mesh_bounds(m, lo, hi);
        CHECK_NEAR(lo[0], -1, 1e-6); /* mirrored */
        CHECK_NEAR(lo[2], 5, 1e-6);  /* glTF +Y lift is +Z */
        CHECK_NEAR(hi[2], 7, 1e-6);
        CHECK_NEAR(hi[1] - lo[1], 3, 1e-6); /* glTF z extent 3 lies along y */
        check_outward(m);
    }
    mesh_free(m);
    scene_free(s);
}

/* Assimp 5.2 reads a line loop's lines, leaving out a line whose indices are past the vertices,
 * and closes the loop from its first line without looking whether it wrote one: a GLB whose line
 * loop indexed no vertex that exists crashed the program on a null pointer (found by fuzzing). A
 * primitive of mode 2 is refused; triangles with such indices are refused by Assimp's own check,
 * and a mode of 20 is no line loop to this check. */
TEST(gltf_line_loop)
{
    static const uint16_t past[4] = {9, 10, 11, 12}, loop[4] = {0, 1, 2, 3};
    expect_error(write_tet_gltf("line_loop_past.gltf", "1,1,1", 2, past, 4), NULL, ERR_INPUT,
                 "line_loop_past.gltf: a mesh primitive is a line loop (mode 2), on which the model reader can crash; "
                 "sylva draws triangles: export the mesh as triangles (mode 4) or leave the line loop out");
    expect_error(write_tet_gltf("line_loop.gltf", "1,1,1", 2, loop, 4), NULL, ERR_INPUT, "is a line loop (mode 2)");
    expect_error(write_tet_gltf("triangles_past.gltf", "1,1,1", 4, past, 4), NULL, ERR_INPUT, "cannot read the model");
    expect_error(write_tet_gltf("mode_20.gltf", "1,1,1", 20, loop, 4), NULL, ERR_INPUT,
                 "mode_20.gltf:1:214: mesh 0 primitive 0's \"mode\" is 20; a whole number from 0 to 6");
}

/* The file at path with its first `from` replaced by `to`. */
static void replace_in_file(const char *path, const char *from, const char *to)
{
    char text[4096], out[4096 + 256];
    FILE *f = fopen(path, "r");
    CHECK(f != NULL);
    if (!f) return;
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    char *at = strstr(text, from);
    CHECK(at != NULL);
    CHECK(strlen(to) <= 256 + strlen(from));
    if (!at || strlen(to) > 256 + strlen(from)) return;
    snprintf(out, sizeof out, "%.*s%s%s", (int)(at - text), text, to, at + strlen(from));
    f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) fputs(out, f), fclose(f);
}

/* A key written with an escape is the key Assimp's JSON reader decodes ("mod\u0065" is "mode")
 * but not the one gltf_check searches for: a line loop past the vertices so keyed crashed the
 * reader as the plain one did. Such keys are refused, in a glTF and in a GLB's JSON chunk;
 * escapes in values are not. */
TEST(gltf_escaped_key)
{
    static const uint16_t past[4] = {9, 10, 11, 12};
    const char *path = write_tet_gltf("escaped_mode.gltf", "1,1,1", 2, past, 4);
    replace_in_file(path, "\"mode\"", "\"mod\\u0065\"");
    expect_error(path, NULL, ERR_INPUT,
                 "escaped_mode.gltf:1:205: the key \"mod\\u0065\" is written with an escape; a glTF's keys are plain "
                 "names (\"uri\", \"mode\", \"mimeType\"): write it without one");

    path = write_scaled_gltf("escaped_uri.gltf", "1,1,1");
    replace_in_file(path, "{\"byteLength\"", "\n{\"byteLength\"");
    replace_in_file(path, "\"uri\"", "\"\\u0075ri\"");
    expect_error(path, NULL, ERR_INPUT, "escaped_uri.gltf:2:18: the key \"\\u0075ri\" is written with an escape");

    path = write_scaled_gltf("escaped_value.gltf", "1,1,1");
    replace_in_file(path, "{\"mesh\":0", "{\"name\":\"a \\\"tet\\\": \\u0041\",\"mesh\":0");
    scene *s = scene_new();
    mesh *m = load(s, path, 0, MODEL_UP_FILE, NULL);
    if (m) CHECK_INT(m->nt, 4);
    mesh_free(m);
    scene_free(s);

    /* the same JSON as a GLB's one chunk */
    path = write_glb("escaped.glb", "{\"asset\":{\"version\":\"2.0\"},\"me\\u0073hes\":[]}", NULL, 0);
    if (!path) return;
    expect_error(path, NULL, ERR_INPUT, "escaped.glb: the JSON chunk, line 1, column 28: the key \"me\\u0073hes\"");
}

/* gltf_layout_check on the JSON text: refused with a message containing want, or passed (NULL). */
static void expect_layout(const char *json, const char *want)
{
    err_buf err = {{0}};
    CHECK_INT(gltf_layout_check(json, strlen(json), GLTF_NO_BIN, "t.gltf", &err), want ? -1 : 0);
    if (want) CHECK_STR_CONTAINS(err.msg, want);
    else CHECK_INT(err.msg[0], 0);
}

/* Assimp 5.2 recurses down a node hierarchy, and reads an animation sampler's output one value
 * (three for a cubic spline) for each of its input's times whatever its count */
TEST(gltf_nodes_and_animations_checked)
{
    /* a chain of nodes 1000 deep is read, 1001 deep refused; a node of 100,000 children is read */
    size_t cap = 16 * 100001 + 256;
    char *json = malloc(cap);
    CHECK(json != NULL);
    if (!json) return;
    for (int levels = 1000; levels <= 1001; levels++) {
        size_t n = (size_t)snprintf(json, cap, "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[");
        for (int i = 0; i < levels; i++)
            n += (size_t)snprintf(json + n, cap - n, i + 1 < levels ? "{\"children\":[%d]}," : "{}", i + 1);
        snprintf(json + n, cap - n, "]}");
        expect_layout(json, levels == 1000 ? NULL : "the node hierarchy is deeper than 1000 levels");
    }
    size_t n = (size_t)snprintf(json, cap, "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"children\":[");
    for (int i = 1; i <= 100000; i++) n += (size_t)snprintf(json + n, cap - n, i < 100000 ? "%d," : "%d", i);
    n += (size_t)snprintf(json + n, cap - n, "]}");
    for (int i = 1; i <= 100000; i++) n += (size_t)snprintf(json + n, cap - n, ",{}");
    snprintf(json + n, cap - n, "]}");
    expect_layout(json, NULL);
    free(json);

    expect_layout("{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"children\":[1]},{\"children\":[0]}]}",
                  "t.gltf:1:67: node 1 has node 0 for a child, which is its ancestor or itself");
    expect_layout("{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"children\":[2]}]}",
                  "node 0 has a child that is not one of the file's 1 nodes");

    /* animations: 3 times, and outputs of 2, 6 and 9 values */
    static const struct { const char *sampler, *channel, *want; } cases[] = {
        {"{\"input\":0,\"output\":1}", "{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"translation\"}}",
         "animation 0 sampler 0 has 3 times and 2 values; it needs one for each time"},
        {"{\"input\":0,\"output\":2,\"interpolation\":\"CUBICSPLINE\"}", "{\"sampler\":0,\"target\":{\"node\":0}}",
         "animation 0 sampler 0 has 3 times and 6 values; it needs three"},
        {"{\"input\":0,\"output\":3,\"interpolation\":\"CUBICSPLINE\"}", "{\"sampler\":0,\"target\":{\"node\":0}}",
         NULL},
        {"{\"input\":0,\"output\":2}", "{\"sampler\":1,\"target\":{\"node\":0}}",
         "animation 0 channel 0's \"sampler\" is 1; a whole number from 0 to 0"},
        {"{\"input\":0,\"output\":2}", "{\"sampler\":0}", "animation 0 channel 0 has no target object"},
        {"{\"input\":0,\"output\":2}", "{\"sampler\":0,\"target\":{\"node\":1}}",
         "animation 0 channel 0's \"node\" is 1; a whole number from 0 to 0"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char text[1024];
        snprintf(text, sizeof text,
                 "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{}],\"accessors\":[{\"componentType\":5126,\"count\":3,"
                 "\"type\":\"SCALAR\"},{\"componentType\":5126,\"count\":2,\"type\":\"VEC3\"},{\"componentType\":5126,"
                 "\"count\":6,\"type\":\"VEC3\"},{\"componentType\":5126,\"count\":9,\"type\":\"VEC3\"}],"
                 "\"animations\":[{\"samplers\":[%s],\"channels\":[%s]}]}",
                 cases[i].sampler, cases[i].channel);
        expect_layout(text, cases[i].want);
    }
}

/* Assimp 5.2 bounds an accessor by its component size times its count and then copies whole
 * elements from its offset: an accessor one byte past its view read past the end of its buffer
 * (a heap overflow under ASan; tests/fuzz/regressions/model_import/glb_accessor_one_byte_past_its_view).
 * The layout is checked against the file's bytes first (model/gltf_layout.h). */
TEST(gltf_layout_checked)
{
    /* each a change to the tetrahedron's glTF and what the refusal says */
    static const struct { const char *name, *from, *to, *want; } cases[] = {
        {"offset_past.gltf", "{\"bufferView\":0,", "{\"bufferView\":0,\"byteOffset\":1,",
         "offset_past.gltf:1:495: accessor 0 reads bytes 1 to 49 of buffer view 0 (4 elements of 12 bytes, 12 apart), "
         "which holds 48"},
        {"view_past.gltf", "\"byteOffset\":48,\"byteLength\":24", "\"byteOffset\":50,\"byteLength\":24",
         "buffer view 1 takes bytes 50 to 74 of buffer 0, which holds 72"},
        {"wrapping.gltf", "\"byteOffset\":48,", "\"byteOffset\":18446744073709551608,",
         "buffer view 1's \"byteOffset\" is 18446744073709551608; a whole number from 0 to 9007199254740992"},
        {"fraction.gltf", "\"count\":4,", "\"count\":4.0,",
         "accessor 0's \"count\" is 4.0; a whole number from 1 to 4294967295"},
        {"sparse.gltf", "\"min\":[0,0,0]",
         "\"sparse\":{\"count\":1,\"indices\":{\"bufferView\":1,\"componentType\":5123},\"values\":{\"bufferView\":0}},"
         "\"min\":[0,0,0]",
         "accessor 0 is sparse"},
        {"version1.gltf", "\"version\":\"2.0\"", "\"version\":\"1.0\"",
         "version1.gltf:1:21: the file states no glTF version 2"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *path = write_scaled_gltf(cases[i].name, "1,1,1");
        replace_in_file(path, cases[i].from, cases[i].to);
        expect_error(path, NULL, ERR_INPUT, cases[i].want);
    }

    /* Assimp makes count - 2 faces of a fan and writes the first: a fan of two indices wrote past
     * an array of none, a line strip of one likewise, a strip of one asked for 2^64 faces */
    static const uint16_t few[2] = {0, 1};
    expect_error(write_tet_gltf("fan_of_two.gltf", "1,1,1", 6, few, 2), NULL, ERR_INPUT,
                 "fan_of_two.gltf:1:164: mesh 0 primitive 0 draws a triangle fan of 2 vertices, and a triangle fan needs "
                 "at least 3");
    expect_error(write_tet_gltf("line_strip_of_one.gltf", "1,1,1", 3, few, 1), NULL, ERR_INPUT,
                 "draws a line strip of 1 vertex, and a line strip needs at least 2");
    expect_error(write_tet_gltf("strip_of_one.gltf", "1,1,1", 5, few, 1), NULL, ERR_INPUT,
                 "draws a triangle strip of 1 vertex");
    const char *path = write_scaled_gltf("paired_indices.gltf", "1,1,1");
    replace_in_file(path, "\"componentType\":5123", "\"componentType\":5121");
    replace_in_file(path, "\"type\":\"SCALAR\"", "\"type\":\"VEC2\"");
    expect_error(path, NULL, ERR_INPUT, "accessor 1, the indices of mesh 0 primitive 0, is not a SCALAR of "
                                        "componentType 5121, 5123 or 5125");
    path = write_scaled_gltf("no_position.gltf", "1,1,1");
    replace_in_file(path, "{\"POSITION\":0}", "{\"NORMAL\":0}");
    expect_error(path, NULL, ERR_INPUT, "mesh 0 primitive 0 has no POSITION attribute");
    path = write_scaled_gltf("far_indices.gltf", "1,1,1");
    replace_in_file(path, "\"indices\":1", "\"indices\":2");
    expect_error(path, NULL, ERR_INPUT, "mesh 0 primitive 0's \"indices\" is 2; a whole number from 0 to 1");

    /* Assimp reads the matrices of a skin a node uses without looking whether there are any (a
     * segfault), and one for each joint, and looks the node's skin up unchecked */
    static const struct { const char *name, *skins, *want; } skins[] = {
        {"skin_missing.gltf", "", "skin_missing.gltf:1:111: node 1 names a skin, and the file has none"},
        {"skin_without_matrices.gltf", "\"skins\":[{\"joints\":[0]}],", "skin 0 has no inverseBindMatrices"},
        {"skin_vec3_matrices.gltf", "\"skins\":[{\"joints\":[0],\"inverseBindMatrices\":0}],",
         "accessor 0, the inverse bind matrices of skin 0, is not 1 MAT4 of floats (5126), one for each joint"},
    };
    for (size_t i = 0; i < sizeof skins / sizeof skins[0]; i++) {
        const char *skinned = write_scaled_gltf(skins[i].name, "1,1,1");
        replace_in_file(skinned, "{\"mesh\":0,", "{\"skin\":0,\"mesh\":0,");
        char with_skins[160];
        snprintf(with_skins, sizeof with_skins, "%s\"meshes\":", skins[i].skins);
        replace_in_file(skinned, "\"meshes\":", with_skins);
        expect_error(skinned, NULL, ERR_INPUT, skins[i].want);
    }

    /* an interleaved view is read: normals 12 bytes into a view of stride 24 end with it */
    const char *interleaved = "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":96}],\"bufferViews\":"
                              "[{\"buffer\":0,\"byteLength\":96,\"byteStride\":24}],\"accessors\":[{\"bufferView\":0,"
                              "\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"},{\"bufferView\":0,\"byteOffset\":12,"
                              "\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"}]}";
    expect_layout(interleaved, NULL);

    /* a GLB: buffer 0 is the BIN chunk, here 36 bytes, whatever the JSON states of it */
    const char *json = "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
                       "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"buffers\":[{\"byteLength\":"
                       "40}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],\"accessors\":[{\"bufferView\":0,"
                       "\"byteOffset\":1,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}]}";
    path = write_glb("past.glb", json, tet_pos, 36);
    if (!path) return;
    expect_error(path, NULL, ERR_INPUT, "past.glb (its JSON chunk):1:");
    expect_error(path, NULL, ERR_INPUT, "accessor 0 reads bytes 1 to 37 of buffer view 0");
}

static void expect_error(const char *path, const model_import_options *o, err_status status, const char *want)
{
    scene *s = scene_new();
    mesh *m = NULL;
    err_buf err = {{0}};
    CHECK_INT(model_import(s, path, o, &m, NULL, &err), -1);
    CHECK(m == NULL);
    CHECK_INT(err.status, status);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, want);
    scene_free(s);
}

TEST(clear_errors)
{
    expect_error(write_text("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\n"), NULL, ERR_INPUT,
                 "cannot read the model");
    model_import_options up_y = {.up = MODEL_UP_Y};
    expect_error(write_mirrored_gltf(), &up_y, ERR_INPUT, "states its own up axis");
    model_import_options negative = {.scale = -2};
    expect_error(write_text("scaled.ply", ply_text), &negative, ERR_INPUT, "a finite number above 0");
    expect_error(write_text("broken.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"),
                 NULL, ERR_INPUT, "broken.ply:5:1: the PLY header has no end_header line");
    expect_error(write_text("model.xyz", "0 0 0\n"), NULL, ERR_INPUT, "not a model format sylva reads");
    CHECK(model_import_supports("a/b/Model.GLB"));
    CHECK(!model_import_supports("a.b/model"));
}

/* Assimp's PLY reader hangs, aborts or crashes on a cut PLY; every cut of a binary and an
 * ASCII PLY must instead give a sentence (the walk in ply_check). */
TEST(cut_ply_files)
{
    char whole[2][1200]; /* ASCII, binary */
    snprintf(whole[0], sizeof whole[0], "%s", write_text("whole.ply", ply_text));
    snprintf(whole[1], sizeof whole[1], "%s", work_path("whole-binary.ply"));
    FILE *f = fopen(whole[1], "wb");
    CHECK(f != NULL);
    if (f) {
        const char *h = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
                        "property float y\nproperty float z\nelement face 4\n"
                        "property list uchar int vertex_indices\nend_header\n";
        put(f, h, strlen(h));
        put(f, tet_pos, sizeof tet_pos);
        for (int t = 0; t < 4; t++) {
            uint8_t three = 3;
            int32_t k[3] = {tet_tri[t][0], tet_tri[t][1], tet_tri[t][2]};
            put(f, &three, 1), put(f, k, sizeof k);
        }
        fclose(f);
    }
    for (int w = 0; w < 2; w++) {
        FILE *in = fopen(whole[w], "rb");
        char bytes[1024];
        size_t n = in ? fread(bytes, 1, sizeof bytes, in) : 0;
        if (in) fclose(in);
        scene *s = scene_new();
        mesh *m = load(s, whole[w], 0, MODEL_UP_FILE, NULL); /* the whole file reads */
        if (m) CHECK_INT(m->nt, 4);
        mesh_free(m);
        scene_free(s);
        for (size_t cut = 1; cut + 1 < n; cut += 7) {
            const char *path = work_path("cut.ply");
            FILE *out = fopen(path, "wb");
            if (out) put(out, bytes, w == 0 && bytes[cut - 1] == '\n' ? cut - 1 : cut), fclose(out);
            s = scene_new();
            m = NULL;
            err_buf err = {{0}};
            CHECK_INT(model_import(s, path, NULL, &m, NULL, &err), -1);
            CHECK_INT(err.status, ERR_INPUT);
            CHECK_STR_CONTAINS(err.msg, "cut.ply");
            scene_free(s);
        }
    }
}

/* A face that lists no vertices (Assimp aborts the process on one) is refused with a sentence,
 * in an ASCII and in a binary PLY; one or two vertices (a point, a line) are dropped as before. */
TEST(empty_ply_face)
{
    const char *header = "ply\nformat %s 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
    char text[512];
    snprintf(text, sizeof text, header, "ascii");
    snprintf(text + strlen(text), sizeof text - strlen(text), "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0\n");
    expect_error(write_text("empty_face.ply", text), NULL, ERR_INPUT, "empty_face.ply:14:1: face 2 lists no vertices");
    const char *path = work_path("empty_face_binary.ply");
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (f) {
        snprintf(text, sizeof text, header, "binary_little_endian");
        put(f, text, strlen(text));
        put(f, tet_pos, 3 * sizeof tet_pos[0]);
        uint8_t three = 3, none = 0;
        int32_t k[3] = {0, 1, 2};
        put(f, &three, 1), put(f, k, sizeof k), put(f, &none, 1);
        fclose(f);
        expect_error(path, NULL, ERR_INPUT, "face 2 lists no vertices");
    }
    snprintf(text, sizeof text, header, "ascii");
    snprintf(text + strlen(text), sizeof text - strlen(text), "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n2 0 1\n");
    scene *s = scene_new();
    mesh *m = load(s, write_text("line_face.ply", text), 0, MODEL_UP_FILE, NULL);
    if (m) CHECK_INT(m->nt, 1);
    mesh_free(m);
    scene_free(s);
}

/* A binary PLY whose header's last line runs on in NUL bytes to its newline: Assimp takes the
 * data from just past "end_header" (a NUL ends its line), so it read a face of no vertices where
 * the file's own face lists three, and triangulation aborted the program on it. The header is
 * refused where Assimp's reading of it parts from the file's (a face of no vertices in what Assimp
 * read is also refused, whatever the format). */
TEST(empty_face_as_assimp_reads_it)
{
    static const uint8_t tail[] = {
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 10,
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 128, 63, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
        128, 63, 0, 0, 0, 0, 3, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0};
    const char *header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                         "property float y\nproperty float z\nelement face 1\n"
                         "property list uchar int vertex_indices\nend_header";
    const char *path = work_path("header_run_on.ply");
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return;
    put(f, header, strlen(header)), put(f, tail, sizeof tail);
    fclose(f);
    expect_error(path, NULL, ERR_INPUT, "header_run_on.ply:9:11: a PLY header line holds the control character 0x00");
}

/* Assimp reads an ASCII PLY a line per item: a vertex whose numbers run onto the next line would
 * make it take a face's length from a coordinate (it aborted on one), and extra numbers on a
 * line are skipped by it, so both are refused with the line and column. */
TEST(ply_items_hold_their_lines)
{
    const char *header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    char text[512];
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0\n0 1\n0\n3 0 1 2\n", header);
    expect_error(write_text("split_item.ply", text), NULL, ERR_INPUT,
                 "split_item.ply:12:4: item 3 of element 'vertex' ends before all its numbers");
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0 9\n0 1 0\n3 0 1 2\n", header);
    expect_error(write_text("extra_number.ply", text), NULL, ERR_INPUT,
                 "extra_number.ply:11:8: item 2 of element 'vertex' is followed by more numbers");
    /* A list length past what an integer holds is refused before it is converted (undefined). */
    snprintf(text, sizeof text, "%s0 0 0\n1 0 0\n0 1 0\n66666666666666666666 0 1 2\n", header);
    expect_error(write_text("list_length_past_integers.ply", text), NULL, ERR_INPUT,
                 "list_length_past_integers.ply:13:21: item 1 of element 'face' holds something that is not "
                 "a number (or a list length that is not a whole number up to 10^9)");
    snprintf(text, sizeof text, "%s0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n", header);
    scene *s = scene_new();
    mesh *m = load(s, write_text("crlf.ply", text), 0, MODEL_UP_FILE, NULL);
    if (m) CHECK_INT(m->nt, 1);
    mesh_free(m);
    scene_free(s);
}

/* A binary PLY element of 77,777,777,732 items and no property hung the check (found by fuzzing:
 * each item takes no bytes, so the walk never reached the file's end). An element with items
 * declares a property; one of no items may have none. */
TEST(ply_element_without_properties)
{
    static const char header[] = "ply\nformat binary_little_endian 1.0\nelement vertnffob 77777777732\n\n\n"
                                 "end_header\n\001\002";
    char path[1200];
    snprintf(path, sizeof path, "%s", write_text("no_properties.ply", header));
    expect_error(path, NULL, ERR_INPUT,
                 "no_properties.ply:3:1: element 'vertnffob' has 77777777732 items but no property; an element "
                 "with items declares at least one property");
    const char *empty = "ply\nformat ascii 1.0\nelement note 0\nelement vertex 3\nproperty float x\n"
                        "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                        "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    scene *s = scene_new();
    mesh *m = load(s, write_text("empty_element.ply", empty), 0, MODEL_UP_FILE, NULL);
    CHECK(m != NULL);
    if (m) CHECK_INT(m->nt, 1);
    mesh_free(m);
    scene_free(s);
}

/* Assimp takes the count of an element whose name it does not know from the name's leading
 * digits: a 265-byte PLY whose element was named 4444...4#face took it to 11 GB (found by
 * fuzzing). An element's name starts with a letter. */
TEST(ply_element_name_of_digits)
{
    static const char digits[] = "ply\nformat binary_little_endian 1.0\nelement 4444444444#face 1\n"
                                 "property list uchar int vertex_indices\nend_header\n\001\000\000\000\000";
    expect_error(write_text("digit_name.ply", digits), NULL, ERR_INPUT,
                 "digit_name.ply:3:1: element name '4444444444#face' starts with a digit, which Assimp reads as "
                 "the element's count; start the name with a letter");
}

/* Assimp reads the items of an element it does not know as none, so a scanner's 'camera' element
 * before the vertices had its number read as the first vertex's (refused, with a sentence about
 * faces); after the elements Assimp knows it is read past. Assimp ends an element's properties
 * at an obj_info line and drops the rest: a triangle whose y and z followed one was read flat,
 * without a word. Both are refused. */
TEST(ply_header_parts_assimp_misreads)
{
    static const char tail[] = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    static const char xyz[] = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    static const char body[] = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    char text[1024];
    snprintf(text, sizeof text, "ply\nformat ascii 1.0\nelement camera 1\nproperty float k\n%s%s0.5\n%s", xyz,
             tail, body);
    expect_error(write_text("camera.ply", text), NULL, ERR_INPUT,
                 "camera.ply:3:1: element 'camera' has 1 item, which Assimp's reader reads as none, as it does "
                 "for every element but vertex, face, tristrips, edge and material, so it would read element 'vertex' "
                 "from the wrong place; leave 'camera' out or declare it after the elements it knows");
    snprintf(text, sizeof text, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nobj_info scanner 7\n"
             "property float y\nproperty float z\n%s%s", tail, body);
    expect_error(write_text("obj_info.ply", text), NULL, ERR_INPUT,
                 "obj_info.ply:6:1: a property of element 'vertex' follows an obj_info line (line 5), after which "
                 "Assimp's reader drops the element's properties; put obj_info lines before the first element");
    /* read alike: the unknown element last, obj_info between elements, comments anywhere */
    snprintf(text, sizeof text, "ply\nformat ascii 1.0\nobj_info scanner 7\ncomment 2 lines\n%sobj_info a\n"
             "comment vertex 5\nelement face 1\nproperty list uchar int vertex_indices\nelement camera 1\n"
             "property float k\nend_header\n%s0.5\n", xyz, body);
    scene *s = scene_new();
    mesh *m = load(s, write_text("read_alike.ply", text), 0, MODEL_UP_FILE, NULL);
    if (m) check_extent(m, 1, 1, 0);
    mesh_free(m);
    scene_free(s);
}

/* Assimp sizes an element's array by its first declaration and fills it from every declaration
 * of that name: a second, longer 'vertex' element was written past the first's array (found by
 * fuzzing; valgrind saw the write). Each element is declared once. */
TEST(ply_element_declared_twice)
{
    const char *text = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nelement vertex 3\n"
                       "property float x\nproperty float y\nproperty float z\nend_header\n0\n0 0 0\n1 0 0\n0 1 0\n";
    expect_error(write_text("vertex_twice.ply", text), NULL, ERR_INPUT,
                 "vertex_twice.ply:5:1: element 'vertex' is declared again (first on line 3); a PLY declares "
                 "each element once");
    /* a name longer than the header's words are read: refused as such, not as a line of too many
     * words (nor two names told apart by their first 63 characters alone) */
    char long_name[200];
    snprintf(long_name, sizeof long_name, "ply\nformat ascii 1.0\nelement v%070d 1\nproperty float x\n"
             "end_header\n0\n", 0);
    expect_error(write_text("long_name.ply", long_name), NULL, ERR_INPUT,
                 "long_name.ply:3:9: a word of a PLY header line is longer than 63 characters (a name, a type or a count)");
}

/* A PLY named as another format: Assimp reads it as PLY when the extension's reader refuses it,
 * so it is checked as a .ply file is (here a face of no vertices, on which Assimp aborts). */
TEST(read_by_its_extension_alone)
{
    /* Assimp hands a file its own readers refuse to its other readers: this OBJ named .gltf used
     * to be imported as a triangle */
    const char *obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    expect_error(write_text("triangle.gltf", obj), NULL, ERR_INPUT, "triangle.gltf:1:1: not a JSON value");
    expect_error(write_text("triangle.stl", obj), NULL, ERR_INPUT, "triangle.stl: cannot read the model");
    const char *ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    expect_error(write_text("triangle_ply.glb", ply), NULL, ERR_INPUT, "triangle_ply.glb:1:1: not a JSON value");
    /* and the same files under their own names are read */
    scene *s = scene_new();
    mesh *m = NULL;
    err_buf err = {{0}};
    CHECK_INT(model_import(s, write_text("triangle.obj", obj), NULL, &m, NULL, &err), 0);
    CHECK(m && m->nt == 1);
    mesh_free(m);
    m = NULL;
    CHECK_INT(model_import(s, write_text("triangle.ply", ply), NULL, &m, NULL, &err), 0);
    CHECK(m && m->nt == 1);
    mesh_free(m);
    scene_free(s);
}

/* Assimp 5.2's OBJ reader counts no vertex for a line statement of one vertex but stores one, so
 * a later line's duplicated corner lands one vertex past the mesh's arrays (a heap overflow that
 * unit.model_import_valgrind sees in its regression input). Point and line statements reach it as
 * comments: the file's triangle alone is read. */
TEST(obj_line_of_one_vertex)
{
    const char *obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1\nl 1\nl 1 2 3\np 2\n";
    scene *s = scene_new();
    mesh *m = NULL;
    err_buf err = {{0}};
    CHECK_INT(model_import(s, write_text("line_of_one.obj", obj), NULL, &m, NULL, &err), 0);
    CHECK(m && m->nt == 1);
    mesh_free(m);
    scene_free(s);
}

/* The statements' first letters become '#' wherever Assimp starts a statement: at the file's
 * start, after '\n', '\r', '\f' and NUL, across the pieces a file is read in. */
TEST(obj_points_lines_become_comments)
{
    char text[] = "l 1 2\nv 1 2 3\r\np 1\fpx\n  l 3\nf 1 l 2\n\\\nl 4\nvl\n";
    const char *want = "# 1 2\nv 1 2 3\r\n# 1\f#x\n  l 3\nf 1 l 2\n\\\n# 4\nvl\n";
    for (size_t cut = 0; cut <= sizeof text - 1; cut++) {
        char copy[sizeof text];
        memcpy(copy, text, sizeof text);
        obj_points_lines_as_comments(copy, cut, -1);
        obj_points_lines_as_comments(copy + cut, sizeof text - 1 - cut, cut ? (unsigned char)text[cut - 1] : -1);
        CHECK(!strcmp(copy, want));
    }
}

/* The model at path imports as one triangle. */
static void expect_one_triangle(const char *path)
{
    scene *s = scene_new(); /* owned here, with the mesh */
    mesh *m = NULL;
    err_buf err = {{0}};
    CHECK_INT(model_import(s, path, NULL, &m, NULL, &err), 0);
    CHECK(m && m->nt == 1);
    mesh_free(m);
    scene_free(s);
}

/* Assimp 5.2's filter of the paths a model refers to reads past the end of one ending with "://":
 * such an OBJ material library or glTF buffer uri crashed the program; both are refused first,
 * an OBJ statement continued over a line included; a model whose library is named otherwise is
 * read as before. */
TEST(references_ending_with_colon_slashes)
{
    const char *tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    char obj[256];
    snprintf(obj, sizeof obj, "# a triangle\nmtllib file://\n%s", tri);
    expect_error(write_text("url_mtl.obj", obj), NULL, ERR_INPUT,
                 "url_mtl.obj:2: the material library's name ends with \"://\"");
    snprintf(obj, sizeof obj, "mtllib \\\nhttp://\r\n%s", tri);
    expect_error(write_text("continued_mtl.obj", obj), NULL, ERR_INPUT, "ends with \"://\"");
    /* a backslash at the very end continues the statement into nothing: Assimp drops it (found by
     * fuzzing: "mtllib \file://\" at the end reached the filter as "\file://") */
    expect_error(write_text("end_backslash_mtl.obj", "v 0 0 0\nmtllib \\file://\\"), NULL, ERR_INPUT,
                 "end_backslash_mtl.obj:2: the file ends with a backslash, which Assimp's OBJ reader takes for a "
                 "line continued past the end of the file");
    /* the byte after a continuation is taken into the statement as it is, a backslash or a line end
     * too (found by fuzzing: a backslash there, then a line end, ended the statement, and the
     * next line's "mtllib file://" reached the filter) */
    snprintf(obj, sizeof obj, "v 0 0 0\\\n\\\nmtllib file://\n%s", tri);
    expect_error(write_text("literal_after_continuation.obj", obj), NULL, ERR_INPUT,
                 "literal_after_continuation.obj:3: the material library's name ends with \"://\"");
    /* a line end taken so ends the library's name, and before the name leaves none */
    snprintf(obj, sizeof obj, "mtllib \\\n\nfile://\nmtllib x\\\r\n\r://\n%s", tri);
    expect_one_triangle(write_text("line_end_after_continuation.obj", obj));
    const char *gltf = "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":36,\"uri\":\"file:\\/\\/\"}]}";
    expect_error(write_text("url_buffer.gltf", gltf), NULL, ERR_INPUT, "a uri ends with \"://\"");
    write_text("red.mtl", "newmtl red\nKd 1 0 0\n");
    snprintf(obj, sizeof obj, "mtllib red.mtl\nusemtl red\n%s", tri);
    expect_one_triangle(write_text("named_mtl.obj", obj));
}

/* A PLY header is refused where Assimp would read it otherwise than the file's own walk does
 * (its lines end at \r, \f and NUL too, its words are split by spaces and tabs alone and start
 * at the line's first byte): a binary PLY whose end_header line carried a vertical tab made
 * Assimp read its data from elsewhere, past the end of the file, and crashed the program (found
 * by fuzzing); an end_header ending with \r\n in a binary file, and a property line indented,
 * likewise. An ASCII file with \r\n line ends is read (ply_items_hold_their_lines). */
TEST(ply_header_read_as_assimp_reads_it)
{
    static const uint8_t body[] = {1, 0, 64, 97, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0};
    static const struct { const char *name, *header, *want; } cases[] = {
        {"vertical_tab.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
         "property list uchar int vertex_indices\nend_header\v?\n",
         "vertical_tab.ply:6:11: a PLY header line holds the control character 0x0B"},
        {"crlf_binary.ply",
         "ply\r\nformat binary_little_endian 1.0\r\nelement vertex 3\r\nproperty float x\r\n"
         "property list uchar int vertex_indices\r\nend_header\r\n",
         "crlf_binary.ply:6:11: the end_header line of a binary PLY ends with \\r\\n"},
        {"indented.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
         " property list uchar int vertex_indices\nend_header\n",
         "indented.ply:5:1: a PLY header line starts with a space"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *path = work_path(cases[i].name);
        FILE *f = fopen(path, "wb");
        CHECK(f != NULL);
        if (!f) return;
        put(f, cases[i].header, strlen(cases[i].header)), put(f, body, sizeof body);
        fclose(f);
        expect_error(path, NULL, ERR_INPUT, cases[i].want);
    }
}

/* The files a model opened are closed whatever its reader does: Assimp's OBJ reader left its
 * material library open when it could not read it (a library named ".", the model's folder),
 * a descriptor and its buffers lost with every such model; a folder is not opened as a file.
 * A material library that is missing leaves the model to Assimp's default material, as it
 * did not when Assimp's guesses at other places for it were taken for the model's references
 * (refused as absolute paths), and is named for a warning. */
static int open_descriptors(void)
{
    int n = 0;
    DIR *d = opendir("/proc/self/fd");
    if (!d) return -1;
    while (readdir(d)) n++;
    closedir(d);
    return n;
}

TEST(unreadable_material_library_leaves_no_file_open)
{
    const char *obj = "mtllib .\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    char paths[2][1100];
    snprintf(paths[0], sizeof paths[0], "%s", write_text("folder_as_mtl.obj", obj));
    snprintf(paths[1], sizeof paths[1], "%s", write_text("missing_mtl.obj", "mtllib missing.mtl\nv 0 0 0\n"
                                                         "v 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    int before = open_descriptors();
    if (before < 0) {
        SKIP("/proc/self/fd cannot be listed here");
    }
    for (int i = 0; i < 4; i++) {
        const char *path = paths[i % 2];
        scene *s = scene_new();
        mesh *m = NULL;
        err_buf err = {{0}};
        model_import_info info;
        CHECK_INT(model_import(s, path, NULL, &m, &info, &err), 0);
        CHECK(m && m->nt == 1);
        CHECK(!strcmp(info.missing, i % 2 ? "missing.mtl" : "."));
        mesh_free(m);
        scene_free(s);
    }
    CHECK_INT(open_descriptors(), before);
}

/* Without its module (SYLVA_MODEL_MODULE naming a file that is not there) a model is refused
 * with a sentence naming the module; each case runs in a process of its own, so the module has
 * not been opened yet. */
TEST(module_missing)
{
    setenv("SYLVA_MODEL_MODULE", "/nonexistent/sylva_model.so", 1);
    expect_error(write_text("triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), NULL, ERR_INPUT,
                 "models are read through Assimp in the module sylva_model.so, which cannot be loaded");
}

/* A texture coordinate that is not a finite number (a NaN in a glTF buffer) is refused as a
 * position is, with a sentence naming the mesh and the vertex, not handed to the renderer's
 * texture lookup. */
TEST(texture_coordinate_not_finite)
{
    const char *gltf =
        "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0]}],\"scene\":0,\"nodes\":[{\"mesh\":0}],"
        "\"meshes\":[{\"name\":\"tri\",\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":1}}]}],"
        "\"buffers\":[{\"byteLength\":60,\"uri\":\"data:application/octet-stream;base64,"
        "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAMB/AAAAAAAAAAAAAIA/\"}],"
        "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},"
        "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":24}],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
        "\"min\":[0,0,0],\"max\":[1,1,0]},{\"bufferView\":1,\"componentType\":5126,\"count\":3,\"type\":\"VEC2\"}]}";
    expect_error(write_text("nan_uv.gltf", gltf), NULL, ERR_INPUT,
                 "mesh 'tri' vertex 1 has a texture coordinate that is not a finite number");
}

/* A GLB whose JSON chunk states more bytes than the file holds (Assimp allocated all of them,
 * up to 4 GiB, before reading) is refused first, with a sentence. */
TEST(damaged_glb_chunk)
{
    const char *path = work_path("damaged.glb");
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return;
    static const unsigned char glb[] = {'g', 'l', 'T', 'F', 2, 0, 0, 0, 22, 0, 0, 0,
                                        0xff, 0xff, 0x02, 0xa8, 'J', 'S', 'O', 'N', '{', '}'};
    put(f, glb, sizeof glb);
    fclose(f);
    expect_error(path, NULL, ERR_INPUT, "the GLB is damaged or cut short: chunk 'JSON' at byte 12 states 2818768895 "
                                        "bytes of data, and 2 bytes follow it");
}

/* An image whose mimeType holds no '/' (Assimp crashed on one) is refused with a sentence. */
TEST(image_mime_type_without_slash)
{
    const char *gltf = "{\"asset\":{\"version\":\"2.0\"},\"images\":[{\"bufferView\":0,\"mimeType\" : \"png\"}]}";
    expect_error(write_text("mime.gltf", gltf), NULL, ERR_INPUT, "mime.gltf: an image's mimeType is 'png'");
}

TEST_LIST(TEST_CASE(z_up_formats_keep_their_axes), TEST_CASE(cut_ply_files), TEST_CASE(empty_ply_face), TEST_CASE(empty_face_as_assimp_reads_it),
          TEST_CASE(ply_items_hold_their_lines), TEST_CASE(ply_element_declared_twice), TEST_CASE(ply_element_without_properties), TEST_CASE(ply_element_name_of_digits), TEST_CASE(ply_header_parts_assimp_misreads),
          TEST_CASE(image_mime_type_without_slash), TEST_CASE(gltf_line_loop), TEST_CASE(gltf_escaped_key),
          TEST_CASE(read_by_its_extension_alone), TEST_CASE(module_missing), TEST_CASE(obj_line_of_one_vertex), TEST_CASE(obj_points_lines_become_comments), TEST_CASE(references_ending_with_colon_slashes),
          TEST_CASE(ply_header_read_as_assimp_reads_it), TEST_CASE(unreadable_material_library_leaves_no_file_open),
          TEST_CASE(texture_coordinate_not_finite), TEST_CASE(damaged_glb_chunk), TEST_CASE(y_up_files_are_turned),
          TEST_CASE(obj_with_mtl_texture_points_lines), TEST_CASE(gltf_mirrored_node_keeps_winding),
          TEST_CASE(gltf_node_scale_beyond_single_precision), TEST_CASE(gltf_layout_checked), TEST_CASE(gltf_nodes_and_animations_checked),
          TEST_CASE(clear_errors))
