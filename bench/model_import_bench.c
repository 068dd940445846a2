/* model_import_bench.c — the speed of model_import on a large model against Assimp alone.
 *
 * Writes a wavy height grid (default 708 x 708 cells, two triangles each: 1,002,528
 * triangles) as a binary STL (50 MB, no shared vertices) or a binary little-endian PLY (17 MB,
 * shared vertices, walked whole by ply_check before Assimp reads it) to a fresh folder under
 * $TMPDIR (or /tmp), then times, best of K runs (default 3) each:
 *   - Assimp alone: aiImportFile with no post-processing (the baseline);
 *   - model_import: the whole import into a sylva mesh (Assimp's reading with triangulation,
 *     type sorting and validation, the copy with transforms, normals, materials).
 * Prints the machine, both times, the ratio model_import / Assimp alone, the mesh's bytes per
 * triangle, and the goal (<= 2 s). The folder is removed at the end.
 * Usage: model_import_bench [--cells N] [--runs K] [--ply] */
#include <assimp/cimport.h>
#include <assimp/scene.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench_machine.h"
#include "render/render.h"
#include "model/model_import.h"
#include "scene/scene.h"
#include "util/progress.h"

static void print_machine(void)
{
    char model[256];
    bench_cpu_model(model, sizeof model);
    printf("machine: %s, %u cores\n", model, render_default_threads());
}

static float height(uint32_t i, uint32_t j) { return (float)(3.0 * sin(i * 0.05) * cos(j * 0.07)); }

/* One facet: zero normal (the reader makes them), three corners, no attribute. */
static void facet(FILE *f, const float a[3], const float b[3], const float c[3])
{
    float rec[12] = {0, 0, 0, a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]};
    uint16_t attr = 0;
    fwrite(rec, sizeof rec, 1, f);
    fwrite(&attr, 2, 1, f);
}

static int write_grid_stl(const char *path, uint32_t cells)
{
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    char header[80] = "sylva model_import_bench grid";
    uint32_t n = cells * cells * 2;
    fwrite(header, sizeof header, 1, f);
    fwrite(&n, 4, 1, f);
    for (uint32_t j = 0; j < cells; j++)
        for (uint32_t i = 0; i < cells; i++) {
            float p00[3] = {(float)i, (float)j, height(i, j)}, p10[3] = {(float)i + 1, (float)j, height(i + 1, j)};
            float p01[3] = {(float)i, (float)j + 1, height(i, j + 1)};
            float p11[3] = {(float)i + 1, (float)j + 1, height(i + 1, j + 1)};
            facet(f, p00, p10, p11);
            facet(f, p00, p11, p01);
        }
    return fclose(f) == 0 ? 0 : -1;
}

static int write_grid_ply(const char *path, uint32_t cells)
{
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    uint32_t side = cells + 1;
    fprintf(f, "ply\nformat binary_little_endian 1.0\ncomment sylva model_import_bench grid\n"
               "element vertex %u\nproperty float x\nproperty float y\nproperty float z\n"
               "element face %u\nproperty list uchar int vertex_indices\nend_header\n",
            side * side, cells * cells * 2);
    for (uint32_t j = 0; j < side; j++)
        for (uint32_t i = 0; i < side; i++) {
            float p[3] = {(float)i, (float)j, height(i, j)};
            fwrite(p, sizeof p, 1, f);
        }
    for (uint32_t j = 0; j < cells; j++)
        for (uint32_t i = 0; i < cells; i++) {
            uint8_t three = 3;
            int32_t a = (int32_t)(j * side + i), b = a + 1, c = a + (int32_t)side + 1, d = a + (int32_t)side;
            int32_t t0[3] = {a, b, c}, t1[3] = {a, c, d};
            fwrite(&three, 1, 1, f), fwrite(t0, sizeof t0, 1, f);
            fwrite(&three, 1, 1, f), fwrite(t1, sizeof t1, 1, f);
        }
    return fclose(f) == 0 ? 0 : -1;
}

int main(int argc, char **argv)
{
    uint32_t cells = 708, runs = 3;
    int ply = 0;
    for (int a = 1; a < argc; a++) {
        if (!strcmp(argv[a], "--cells") && a + 1 < argc) cells = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--runs") && a + 1 < argc) runs = (uint32_t)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--ply")) ply = 1;
        else {
            fprintf(stderr, "usage: model_import_bench [--cells N] [--runs K] [--ply]\n");
            return 2;
        }
    }
    if (cells < 1 || cells > 3000 || runs < 1) {
        fprintf(stderr, "model_import_bench: --cells 1..3000 and --runs >= 1 are valid\n");
        return 2;
    }
    print_machine();
    const char *tmpdir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    char dir[1024], path[1100];
    snprintf(dir, sizeof dir, "%s/sylva-model-bench-XXXXXX", tmpdir);
    if (!mkdtemp(dir)) {
        perror("model_import_bench: mkdtemp");
        return 4;
    }
    snprintf(path, sizeof path, "%s/grid.%s", dir, ply ? "ply" : "stl");
    int rc = 4;
    double t0 = progress_now();
    if (ply ? write_grid_ply(path, cells) : write_grid_stl(path, cells)) {
        fprintf(stderr, "model_import_bench: cannot write %s\n", path);
        goto done;
    }
    printf("model: binary %s, %u triangles, written in %.2f s\n", ply ? "PLY" : "STL", cells * cells * 2,
           progress_now() - t0);

    double best_raw = INFINITY, best_import = INFINITY;
    uint32_t nt = 0, nv = 0;
    for (uint32_t r = 0; r < runs; r++) {
        t0 = progress_now();
        const struct aiScene *ai = aiImportFile(path, 0);
        double t_raw = progress_now() - t0;
        if (!ai) {
            fprintf(stderr, "model_import_bench: Assimp: %s\n", aiGetErrorString());
            goto done;
        }
        aiReleaseImport(ai);
        scene *s = scene_new();
        mesh *m = NULL;
        err_buf err = {{0}};
        t0 = progress_now();
        int failed = !s || model_import(s, path, NULL, &m, NULL, &err);
        double t_import = progress_now() - t0;
        if (failed) {
            fprintf(stderr, "model_import_bench: %s\n", err.msg);
            scene_free(s);
            goto done;
        }
        nt = m->nt, nv = m->nv;
        mesh_free(m);
        scene_free(s);
        printf("run %u: Assimp alone %.3f s, model_import %.3f s\n", r + 1, t_raw, t_import);
        if (t_raw < best_raw) best_raw = t_raw;
        if (t_import < best_import) best_import = t_import;
    }
    printf("best of %u: Assimp alone %.3f s, model_import %.3f s, ratio %.2f\n", runs, best_raw,
           best_import, best_import / best_raw);
    printf("mesh: %u triangles, %u vertices, %.1f bytes per triangle (32 per vertex, 16 per "
           "triangle)\n", nt, nv, (32.0 * nv + 16.0 * nt) / nt);
    printf("goal: model_import of >= 1 M triangles <= 2 s: %s\n",
           nt >= 1000000 ? (best_import <= 2.0 ? "met" : "NOT met") : "not measured (fewer triangles)");
    rc = 0;
done:
    remove(path);
    rmdir(dir);
    return rc;
}
