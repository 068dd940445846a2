/* bench_mpi_scene.c — why every rank of an MPI job builds the scene itself (docs/mpi.md): the
 * time each rank takes to load and build a scene, against the bytes of the built scene graph
 * that rank 0 would have to send the others instead, and the time MPI_Bcast takes to send that
 * many bytes here. The broadcast's figure is a lower bound for that design: it leaves out
 * writing the graph into a buffer and reading it back, and the other ranks would wait for rank
 * 0's build first. Neither design avoids the Embree BVH build on every rank (Embree 3 cannot
 * write a BVH out), so it is not counted.
 *
 * usage: mpirun -np N bench_mpi_scene [SCENE]   (default: scenes/default.yaml)
 */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_machine.h"
#include "cli/cli_scene.h"
#include "util/progress.h"

static uint64_t mesh_bytes(const mesh *m)
{
    return m ? (uint64_t)m->nv * (3 + 3 + 2) * sizeof(float) + (uint64_t)m->nt * (3 * sizeof(uint32_t) + sizeof(int32_t))
             : 0;
}

/* The bytes of the scene graph's arrays (meshes, placements, textures, terrain): what a
 * broadcast of it carries at the least. */
static uint64_t scene_bytes(const scene *s)
{
    uint64_t b = 0;
    for (uint32_t p = 0; p < s->n_prototypes; p++) b += mesh_bytes(s->prototypes[p].mesh);
    for (uint32_t o = 0; o < s->n_objects; o++) b += mesh_bytes(s->objects[o].mesh) + sizeof(object);
    for (uint32_t m = 0; m < s->n_models; m++) b += mesh_bytes(s->models[m].mesh);
    b += (uint64_t)s->n_instances * sizeof(instance);
    for (uint32_t t = 0; t < s->n_textures; t++) b += (uint64_t)s->textures[t].width * s->textures[t].height * 4;
    const sylva_heightfield *h = s->terrain;
    if (h) {
        b += (uint64_t)h->nx * h->ny * (sizeof(float) + (h->material ? sizeof(int32_t) : 0));
        for (uint32_t l = 0; l < h->n_levels; l++)
            b += (uint64_t)h->levels[l].nx * h->levels[l].ny * (sizeof(float) + (h->levels[l].material ? 4 : 0));
    }
    return b;
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank, ranks;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    const char *path = argc > 1 ? argv[1] : SYLVA_SOURCE_DIR "/scenes/default.yaml";
    build_options bo = {.quiet = 1};
    cli_scene cs;
    MPI_Barrier(MPI_COMM_WORLD);
    double t0 = progress_now();
    int rc = cli_scene_open(&cs, "bench_mpi_scene", path, NULL, &bo);
    double build = progress_now() - t0, slowest = 0;
    int failed = 0;
    MPI_Allreduce(&rc, &failed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (failed) {
        cli_scene_close(&cs);
        MPI_Finalize();
        return 1;
    }
    MPI_Reduce(&build, &slowest, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    uint64_t bytes = rank == 0 ? scene_bytes(cs.scene) : 0;
    MPI_Bcast(&bytes, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    char *buf = malloc(bytes ? bytes : 1); /* owned: the broadcast's bytes */
    if (buf) memset(buf, rank, bytes);
    /* every rank broadcasts, or none does: a rank without its buffer would leave the others waiting */
    int held = buf != NULL, all_held = 0;
    MPI_Allreduce(&held, &all_held, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (!all_held) {
        if (rank == 0) fprintf(stderr, "bench_mpi_scene: a rank could not hold %llu bytes\n", (unsigned long long)bytes);
        free(buf);
        cli_scene_close(&cs);
        MPI_Finalize();
        return 1;
    }
    double best = 1e30;
    for (int round = 0; round < 3; round++) {
        MPI_Barrier(MPI_COMM_WORLD);
        double t1 = progress_now();
        for (uint64_t at = 0; at < bytes; at += 1u << 30)
            MPI_Bcast(buf + at, (int)(bytes - at < (1u << 30) ? bytes - at : 1u << 30), MPI_BYTE, 0, MPI_COMM_WORLD);
        MPI_Barrier(MPI_COMM_WORLD);
        double t = progress_now() - t1;
        if (t < best) best = t;
    }
    if (rank == 0) {
        char cpu[128];
        bench_cpu_model(cpu, sizeof cpu);
        const scene *s = cs.scene;
        printf("machine: %s, %d ranks\nscene: %s: %u prototypes, %u instances, %u objects\n", cpu, ranks, path,
               s->n_prototypes, s->n_instances, s->n_objects);
        printf("build on every rank at once: %.2f s (the slowest rank; %.2f s on rank 0)\n", slowest, build);
        printf("scene graph to broadcast: %.1f MiB; MPI_Bcast to %d ranks: %.3f s (%.2f GiB/s), best of 3\n",
               bytes / 1048576.0, ranks - 1, best, bytes / 1073741824.0 / (best > 0 ? best : 1e-9));
        printf("broadcast design: %.2f s build on rank 0 + %.3f s transfer + serialisation; ratio of the "
               "transfer alone to the build: %.3f\n", build, best, best / (build > 0 ? build : 1e-9));
    }
    free(buf);
    cli_scene_close(&cs);
    MPI_Finalize();
    return 0;
}
