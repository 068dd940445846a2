/* fuzz_model_import.c — libFuzzer target for model import through Assimp
 * (model/model_import.h): the input's first byte chooses the format (its value modulo 5: OBJ,
 * STL, PLY, glTF, GLB), the rest is written to model.<ext> in a scratch folder of its own and
 * imported into a new scene, with a triangle limit of 2^20 so that a small file instancing a
 * mesh many times is refused rather than built. Importing must end in a mesh that indexes only
 * its own vertices, all finite, or an error sentence: a crash, a sanitizer report, a leak, a
 * hang or runaway memory is a finding. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "model/model_import.h"
#include "scene/scene.h"
#include "fuzz_file.h"

#define TARGET "fuzz_model_import"
#define N_FORMATS 5

static const char *const extensions[N_FORMATS] = {"obj", "stl", "ply", "gltf", "glb"};
static const char *model_path[N_FORMATS]; /* in the scratch folder (work_dir.h owns it) */

/* The model at path imported into a new scene, as every input is: model_import's status, and
 * the mesh into *m (the caller's) when it is 0. */
static int import(const char *path, mesh **m, err_buf *err)
{
    scene *s = scene_new(); /* owned here: the model's materials and textures go into it */
    if (!s) fuzz_finding(TARGET, "out of memory for a scene");
    model_import_options opt = {.max_triangles = 1u << 20};
    int rc = model_import(s, path, &opt, m, NULL, err);
    scene_free(s);
    return rc;
}

/* A run whose model module cannot be opened (a build whose sanitizers leave a symbol of the
 * module unresolved) would refuse every input with a sentence and find nothing: a valid triangle
 * must import before the run starts. */
static void check_a_model_imports(void)
{
    static const char triangle[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    char path[1200];
    fuzz_write_file(TARGET, fuzz_scratch_path("triangle.obj", path, sizeof path), (const uint8_t *)triangle,
                    sizeof triangle - 1);
    err_buf err = {{0}};
    mesh *m = NULL; /* owned here */
    int failed = import(path, &m, &err) || m->nt != 1;
    mesh_free(m);
    if (failed) {
        fprintf(stderr, "%s: a one-triangle OBJ does not import, so no input would reach the model reader: %s\n",
                TARGET, err.msg[0] ? err.msg : "no mesh of one triangle");
        exit(1);
    }
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static char paths[N_FORMATS][1200];
    for (int f = 0; f < N_FORMATS; f++) {
        char name[16];
        snprintf(name, sizeof name, "model.%s", extensions[f]);
        model_path[f] = fuzz_scratch_path(name, paths[f], sizeof paths[f]);
    }
    check_a_model_imports();
    return 0;
}

static void check_mesh(const mesh *m)
{
    for (uint64_t i = 0; i < 3 * (uint64_t)m->nt; i++)
        if (m->tri[i] >= m->nv) fuzz_finding(TARGET, "a triangle indexes past the mesh's vertices");
    for (uint64_t i = 0; i < 3 * (uint64_t)m->nv; i++)
        if (!isfinite(m->pos[i]) || !isfinite(m->nrm[i])) fuzz_finding(TARGET, "a vertex or normal is not finite");
    for (uint64_t i = 0; i < 2 * (uint64_t)m->nv; i++)
        if (!isfinite(m->uv[i])) fuzz_finding(TARGET, "a texture coordinate is not finite");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    const char *path = model_path[data[0] % N_FORMATS];
    fuzz_write_file(TARGET, path, data + 1, size - 1);
    err_buf err = {{0}};
    mesh *m = NULL; /* owned here */
    if (import(path, &m, &err)) {
        if (!err.msg[0]) fuzz_finding(TARGET, "importing failed without a message");
    } else {
        check_mesh(m);
    }
    mesh_free(m);
    return 0;
}
