/* bench_tree_vessel.c — build time, size and memory of the vessel-model trees on one core.
 *
 * For each preset (and the spruce at every level of detail) it times Algorithm 2 (the branch
 * structure) and the mesh (cones, leaves) built by the model library, then the copy of that
 * mesh into a host mesh as mesh_append does; best of several runs, one thread, in CPU time of
 * that thread (the load average is printed beside it: page faults still count). It prints the
 * triangle and vertex counts, the bytes the structure and the mesh take, and the process's peak
 * resident memory, and the spruce's full build (S = 6000, rho_l = 30) against its goal of
 * 0.1 s. Usage:
 *   bench_tree_vessel [--runs N]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "scene/mesh.h"
#include "vessel_mesh.h"
#include "vessel_presets.h"
#include "vessel_structure.h"

#define GOAL_SECONDS 0.1

/* CPU time of this thread: what one core spends, unaffected by other processes' turns. */
static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

typedef struct figures {
    double grow_s, mesh_s, host_s; /* best of the runs */
    uint32_t segments, vessels, nv, nt, bark, leaf;
    size_t structure_bytes, mesh_bytes;
    double height;
} figures;

/* Builds p at lod `runs` times; 0, or -1 after printing the failure. */
static int measure(const vessel_params *p, uint32_t lod, int runs, figures *f)
{
    memset(f, 0, sizeof *f);
    f->grow_s = f->mesh_s = f->host_s = 1e30;
    for (int r = 0; r < runs; r++) {
        vessel_tree t = {0};
        vessel_mesh m = {0};
        plugin_err err = {0};
        vessel_growth g = {.age = 1.0, .lod = lod};
        double t0 = now();
        if (vessel_tree_grow(p, &g, &t, &err)) goto fail;
        double t1 = now();
        if (vessel_mesh_build(&t, p, 0, 1, &m, &err)) goto fail;
        double t2 = now();
        mesh *host = mesh_new();
        err_buf herr;
        if (!host || mesh_append(host, m.pos, m.nrm, m.uv, m.nv, m.tri, m.mat, -1, m.nt, &herr)) {
            fprintf(stderr, "bench_tree_vessel: host mesh: %s\n", host ? herr.msg : "out of memory");
            mesh_free(host);
            vessel_mesh_release(&m), vessel_tree_release(&t);
            return -1;
        }
        double t3 = now();
        mesh_free(host);
        if (t1 - t0 < f->grow_s) f->grow_s = t1 - t0;
        if (t2 - t1 < f->mesh_s) f->mesh_s = t2 - t1;
        if (t3 - t2 < f->host_s) f->host_s = t3 - t2;
        f->segments = t.n, f->vessels = t.vessels, f->nv = m.nv, f->nt = m.nt;
        f->bark = m.bark_triangles, f->leaf = m.leaf_triangles, f->height = m.top;
        f->structure_bytes = (size_t)t.n * sizeof(vessel_branch);
        f->mesh_bytes = (size_t)m.nv * 8 * sizeof(float) + (size_t)m.nt * 4 * sizeof(uint32_t);
        vessel_mesh_release(&m);
        vessel_tree_release(&t);
        continue;
    fail:
        fprintf(stderr, "bench_tree_vessel: %s\n", err.msg);
        vessel_mesh_release(&m), vessel_tree_release(&t);
        return -1;
    }
    return 0;
}

static void print_machine(void)
{
    char model[256] = "unknown";
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f))
            if (!strncmp(line, "model name", 10)) {
                char *colon = strchr(line, ':');
                if (colon) snprintf(model, sizeof model, "%s", colon + 2);
                model[strcspn(model, "\n")] = 0;
                break;
            }
        fclose(f);
    }
    double load = 0;
    f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &load) != 1) load = 0;
        fclose(f);
    }
    printf("machine: %s; compiler: %s; one thread; load average %.2f\n", model, __VERSION__, load);
}

int main(int argc, char **argv)
{
    int runs = 5;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--runs") && i + 1 < argc) runs = atoi(argv[++i]);
        else {
            fprintf(stderr, "usage: bench_tree_vessel [--runs N]\n");
            return 1;
        }
    }
    if (runs < 1) runs = 1;
    print_machine();
    printf("best of %d runs; thread CPU times in milliseconds\n\n", runs);
    printf("%-15s %6s %6s %9s %9s %9s %9s %7s %7s %7s %7s %8s %8s\n", "preset", "S", "height",
           "segments", "bark_tri", "leaf_tri", "vertices", "grow", "mesh", "total", "host", "struct",
           "mesh");
    printf("%-15s %6s %6s %9s %9s %9s %9s %7s %7s %7s %7s %8s %8s\n", "", "", "m", "", "", "", "",
           "ms", "ms", "ms", "copy ms", "MiB", "MiB");
    figures spruce = {0};
    for (int k = 0; k < VESSEL_PRESETS; k++) {
        vessel_params p;
        vessel_preset_get((vessel_preset)k, &p);
        figures f;
        if (measure(&p, 0, runs, &f)) return 4;
        if (k == VESSEL_PRESET_SPRUCE) spruce = f;
        printf("%-15s %6u %6.1f %9u %9u %9u %9u %7.2f %7.2f %7.2f %7.2f %8.2f %8.2f\n",
               vessel_preset_names[k], f.vessels, f.height, f.segments, f.bark, f.leaf, f.nv,
               1e3 * f.grow_s, 1e3 * f.mesh_s, 1e3 * (f.grow_s + f.mesh_s), 1e3 * f.host_s,
               f.structure_bytes / 1048576.0, f.mesh_bytes / 1048576.0);
    }

    printf("\nspruce by level of detail (3.27-3.29)\n%-5s %9s %9s %9s %7s\n", "lod", "segments",
           "triangles", "vertices", "ms");
    vessel_params p;
    vessel_preset_get(VESSEL_PRESET_SPRUCE, &p);
    for (uint32_t lod = 0; lod <= 10; lod++) {
        figures f;
        if (measure(&p, lod, runs, &f)) return 4;
        printf("%-5u %9u %9u %9u %7.2f\n", lod, f.segments, f.nt, f.nv, 1e3 * (f.grow_s + f.mesh_s));
    }

    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    double total = spruce.grow_s + spruce.mesh_s;
    printf("\nspruce full mesh (S = %u, rho_l = %u): %u triangles, %.1f ms model + %.1f ms host copy "
           "= %.1f ms; goal %.0f ms: %.2f of the goal\n",
           p.vessels, p.leaf_density, spruce.nt, 1e3 * total, 1e3 * spruce.host_s,
           1e3 * (total + spruce.host_s), 1e3 * GOAL_SECONDS, (total + spruce.host_s) / GOAL_SECONDS);
    printf("spruce memory: structure %.2f MiB, mesh %.2f MiB; process peak resident %.1f MiB\n",
           spruce.structure_bytes / 1048576.0, spruce.mesh_bytes / 1048576.0, ru.ru_maxrss / 1024.0);
    return 0;
}
