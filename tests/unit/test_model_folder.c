/* test_model_folder.c — a model reads only files in its own folder (model/model_folder.h): a glTF
 * buffer or image, an OBJ material library or map given as "../" climbing out, as an absolute
 * path, or through a symbolic link that leads out are refused with the model and the reference
 * named; files below the folder are read, and model_root widens the folder. The files outside
 * are real (a triangle's buffer, a material library, a texture), so that only the refusal tells
 * the cases apart from an import that works. */
#include <stdint.h>
#include <sys/stat.h>
#include <unistd.h>

#include "harness.h"
#include "work_dir.h"
#include "io/image_io.h"
#include "model/model_import.h"
#include "scene/scene.h"

/* path of name in the work folder, in one of four rotating buffers */
static const char *at(const char *name)
{
    static char paths[4][1200];
    static int next;
    char *p = paths[next++ % 4];
    snprintf(p, sizeof paths[0], "%s/%s", work_dir(), name);
    return p;
}

static void write_bytes(const char *name, const void *bytes, size_t n)
{
    FILE *f = fopen(at(name), "wb");
    CHECK(f != NULL);
    if (f) fwrite(bytes, 1, n, f), fclose(f);
}

static void write_string(const char *name, const char *text) { write_bytes(name, text, strlen(text)); }

/* model/ holds the models; outside/ beside it a triangle's buffer, an MTL and a texture. */
static void make_folders(void)
{
    static int made;
    if (made++) return;
    mkdir(at("model"), 0700), mkdir(at("model/sub"), 0700), mkdir(at("outside"), 0700);
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    write_bytes("outside/tri.bin", tri, sizeof tri);
    write_bytes("model/sub/tri.bin", tri, sizeof tri);
    write_string("outside/grey.mtl", "newmtl grey\nKd 0.5 0.5 0.5\n");
    const uint8_t px[4] = {10, 20, 30, 255};
    err_buf err = {{0}};
    CHECK_INT(image_write_u8(at("outside/tex.png"), 1, 1, 4, px, &err), 0);
    CHECK_INT(image_write_u8(at("model/sub/tex.png"), 1, 1, 4, px, &err), 0);
    CHECK_INT(symlink("../outside/tri.bin", at("model/link.bin")), 0);
}

/* model/NAME: a glTF triangle whose buffer and base-colour image are the given URIs. */
static const char *gltf(const char *name, const char *buffer_uri, const char *image_uri)
{
    char text[2048], file[256];
    snprintf(text, sizeof text,
             "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
             "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":0}]}],"
             "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
             "\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"%s\"}],"
             "\"buffers\":[{\"uri\":\"%s\",\"byteLength\":36}],"
             "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
             "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
             "\"min\":[0,0,0],\"max\":[1,1,0]}]}",
             image_uri, buffer_uri);
    snprintf(file, sizeof file, "model/%s", name);
    write_string(file, text);
    return at(file);
}

/* model/NAME: an OBJ triangle with the material library and map given. */
static const char *obj(const char *name, const char *mtllib, const char *map)
{
    char text[2048], mtl[512], file[256], mtl_file[256];
    snprintf(mtl_file, sizeof mtl_file, "model/%s.mtl", name);
    snprintf(mtl, sizeof mtl, "newmtl m\nKd 0.5 0.5 0.5\nmap_Kd %s\n", map);
    write_string(mtl_file, mtl);
    snprintf(text, sizeof text, "mtllib %s\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\n",
             mtllib ? mtllib : "");
    if (!mtllib) snprintf(text, sizeof text, "mtllib %s.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                             "usemtl m\nf 1/1 2/2 3/3\n", name);
    snprintf(file, sizeof file, "model/%s", name);
    write_string(file, text);
    return at(file);
}

static int import(const char *path, const char *root, err_buf *err)
{
    scene *s = scene_new();
    mesh *m = NULL;
    model_import_options o = {.root = root};
    int rc = model_import(s, path, &o, &m, NULL, err);
    if (!rc) CHECK_INT(m->nt, 1);
    mesh_free(m);
    scene_free(s);
    return rc;
}

static void refused(const char *path, const char *ref, const char *why)
{
    err_buf err = {{0}};
    CHECK_INT(import(path, NULL, &err), -1);
    fprintf(stderr, "%s\n", err.msg);
    CHECK_INT(err.status, ERR_INPUT);
    char want[1400];
    snprintf(want, sizeof want, "%s: the model refers to the file '%s', which %s", path, ref, why);
    CHECK_STR_CONTAINS(err.msg, want);
}

static void accepted(const char *path, const char *root)
{
    err_buf err = {{0}};
    int rc = import(path, root, &err);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    CHECK_INT(rc, 0);
}

TEST(gltf_buffers_and_images_stay_in_the_folder)
{
    make_folders();
    accepted(gltf("inside.gltf", "sub/tri.bin", "sub/tex.png"), NULL);
    accepted(gltf("dots.gltf", "sub/../sub/tri.bin", "./sub/tex.png"), NULL);
    refused(gltf("up.gltf", "../outside/tri.bin", "sub/tex.png"), "../outside/tri.bin", "climbs out of the model's folder");
    refused(gltf("passwd.gltf", "../../../../../../../../etc/passwd", "sub/tex.png"),
            "../../../../../../../../etc/passwd", "climbs out of the model's folder");
    refused(gltf("image_up.gltf", "sub/tri.bin", "../outside/tex.png"), "../outside/tex.png",
            "climbs out of the model's folder");
    char uri[1300];
    snprintf(uri, sizeof uri, "%s", at("outside/tri.bin"));
    refused(gltf("absolute.gltf", uri, "sub/tex.png"), uri, "is an absolute path; a model's files must lie in ");
    snprintf(uri, sizeof uri, "file://%s", at("outside/tex.png"));
    refused(gltf("absolute_image.gltf", "sub/tri.bin", uri), uri, "is an absolute path");
    refused(gltf("link.gltf", "link.bin", "sub/tex.png"), "link.bin", "leads out of the model's folder through a symbolic link");
    /* a root that holds both folders lets the same model read outside/ */
    accepted(at("model/up.gltf"), work_dir());
}

TEST(obj_material_libraries_and_maps_stay_in_the_folder)
{
    make_folders();
    accepted(obj("inside.obj", NULL, "sub/tex.png"), NULL);
    refused(obj("lib_up.obj", "../outside/grey.mtl", "sub/tex.png"), "../outside/grey.mtl", "climbs out of the model's folder");
    refused(obj("map_up.obj", NULL, "../outside/tex.png"), "../outside/tex.png", "climbs out of the model's folder");
    char abs_tex[1300];
    snprintf(abs_tex, sizeof abs_tex, "%s", at("outside/tex.png"));
    refused(obj("map_abs.obj", NULL, abs_tex), abs_tex, "is an absolute path");
    refused(obj("map_back.obj", NULL, "..\\outside\\tex.png"), "..\\outside\\tex.png", "climbs out of the model's folder");
    refused(obj("map_drive.obj", NULL, "C:\\textures\\tex.png"), "C:\\textures\\tex.png", "is an absolute path");
    /* after a library that is missing, Assimp guesses absolute places for it (refused, not the
     * model's); a library the model names after it is judged as any other */
    refused(obj("up_after_missing.obj", "missing.mtl\nmtllib ../outside/grey.mtl", "sub/tex.png"),
            "../outside/grey.mtl", "climbs out of the model's folder");
    char abs_lib[1400];
    snprintf(abs_lib, sizeof abs_lib, "missing.mtl\nmtllib %s", at("outside/grey.mtl"));
    refused(obj("abs_after_missing.obj", abs_lib, "sub/tex.png"), at("outside/grey.mtl"), "is an absolute path");
    accepted(at("model/map_up.obj"), work_dir());
}

TEST(model_root_must_hold_the_model)
{
    make_folders();
    err_buf err = {{0}};
    CHECK_INT(import(at("model/inside.gltf"), at("outside"), &err), -1);
    CHECK_STR_CONTAINS(err.msg, "the model does not lie in its model_root");
    err_clear(&err);
    CHECK_INT(import(at("model/inside.gltf"), at("nowhere"), &err), -1);
    CHECK_STR_CONTAINS(err.msg, "model_root");
}

TEST_LIST(TEST_CASE(gltf_buffers_and_images_stay_in_the_folder),
          TEST_CASE(obj_material_libraries_and_maps_stay_in_the_folder), TEST_CASE(model_root_must_hold_the_model))
