/* tree_lsystem_bench.c — throughput of the tree_lsystem plugin on the paper's full tree (001
 * Fig. 9: tropism, random turns, elongation, leaves) grown to about 10^7 symbols.
 *
 * Prints, with the machine's details:
 *  1. derivation alone: bytes and symbols of the string, seconds;
 *  2. one turtle pass alone (bounds, counts): symbols/s;
 *  3. the plugin's generate() through the host, end to end (derivation, the bounds pass, the
 *     building pass with tubes, leaves, materials and the silhouette, appended to a host mesh):
 *     seconds, symbols/s, triangles;
 *  4. the process's peak resident memory;
 * and the headline, the real mesh build (3) per 10^7 symbols, against the goals of ≤ 2 s per
 * 10^7 symbols on one core and ≤ 1 GiB of memory. Usage: bench_tree_lsystem [RECURSION] (default 21: 1.16e7 symbols). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "lsys_derive.h"
#include "lsys_system.h"
#include "lsys_turtle.h"
#include "plugin/plugin_host.h"
#include "scene_build/host.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "scene_file/scene_file.h"

static const char fig9[] = "13\n30\n20\nCCA\n"
                           "A=$t(.2)C[&BL[|zL]][>(120)&BL[|zL]]<(120)&BL[|zL]\n"
                           "B=$t(.2)CCA\n"
                           "C=!(0.95)~(5)FL[|zL]\n"
                           "F=c(9)'(1.15)F'(0.87)\n"
                           "L=[-c(3){+(30)f(2)-120f(2)-120f(2)}]\n@\n";

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void machine(void)
{
    char model[256] = "unknown CPU";
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f))
            if (!strncmp(line, "model name", 10)) {
                char *c = strchr(line, ':');
                if (c) snprintf(model, sizeof model, "%s", c + 2);
                model[strcspn(model, "\n")] = '\0';
                break;
            }
        fclose(f);
    }
    printf("machine: %s, %ld cores online; one thread used\n", model, sysconf(_SC_NPROCESSORS_ONLN));
}

static double lcg(void *ctx)
{
    uint64_t *s = ctx;
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

int main(int argc, char **argv)
{
    int recursion = argc > 1 ? atoi(argv[1]) : 21;
    if (recursion < 1 || recursion > 40) {
        fprintf(stderr, "usage: bench_tree_lsystem [RECURSION 1..40]\n");
        return 1;
    }
    machine();
    lsys_system *sys = NULL;
    plugin_err e = {0};
    if (lsys_read(fig9, sizeof fig9 - 1, "fig9", NULL, &sys, &e)) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    /* 1. derivation */
    double t0 = now();
    unsigned char *str = NULL;
    size_t n = 0;
    if (lsys_derive(sys, (uint32_t)recursion, 1u << 30, NULL, NULL, &str, &n, &e)) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    double t_derive = now() - t0;
    /* 2. one turtle pass */
    uint64_t rng = 1;
    lsys_turtle_config cfg = {.angle_deg = 30, .thickness = 20, .base_length = 1, .colour = 2,
                              .max_segments = 100000000, .max_polygons = 100000000, .max_polygon_vertices = 4096,
                              .max_depth = 65536, .tube_corners = 8, .random = lcg, .random_ctx = &rng};
    lsys_turtle_stats st;
    t0 = now();
    if (lsys_interpret(str, n, &cfg, NULL, 0, &st, &e)) {
        fprintf(stderr, "%s\n", e.msg);
        return 1;
    }
    double t_turtle = now() - t0;
    free(str);
    lsys_system_free(sys);
    printf("001 Fig. 9 at recursion %d: %zu bytes, %.3g symbols, %llu segments, %llu leaves\n", recursion, n,
           (double)st.symbols, (unsigned long long)st.segments, (unsigned long long)st.polygons);
    printf("derivation:        %.3f s  (%.3g symbols/s)\n", t_derive, st.symbols / t_derive);
    printf("turtle pass:       %.3f s  (%.3g symbols/s)\n", t_turtle, st.symbols / t_turtle);
    printf("derive + interpret %.3f s for %.3g symbols  (%.2f s per 1e7; the goal is the whole build below)\n",
           t_derive + t_turtle, (double)st.symbols, (t_derive + t_turtle) * 1e7 / st.symbols);

    /* 3. the plugin's generate() through the host */
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open_path(TREE_LSYSTEM_PLUGIN_DIR, &err);
    char path[] = "/tmp/sylva_lsys_bench_XXXXXX.yaml";
    int fd = mkstemps(path, 5);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!reg || !f) {
        fprintf(stderr, "bench_tree_lsystem: cannot set up the plugin run: %s\n", err.msg);
        return 1;
    }
    fprintf(f, "camera: {position: [0, -20, 5]}\nspecies:\n  fig9:\n    plugin: tree_lsystem\n    variants: 1\n"
               "    recursion: %d\n    base_length: 1\n    max_segments: 100000000\n    max_polygons: 100000000\n"
               "    source: |\n",
            recursion);
    for (const char *p = fig9; *p;) {
        const char *e2 = strchr(p, '\n');
        fprintf(f, "      %.*s\n", (int)(e2 - p), p);
        p = e2 + 1;
    }
    fclose(f);
    scene_file *sf = scene_file_load(path, reg, &err);
    unlink(path);
    const loaded_plugin *lp = sf ? plugin_registry_find(reg, "tree_lsystem", SYLVA_KIND_TREE, &err) : NULL;
    if (!lp) {
        fprintf(stderr, "bench_tree_lsystem: %s\n", err.msg);
        return 1;
    }
    scene *sc = scene_new();
    sylva_host h;
    host_init(&h, sc, sf->dir, 1, "bench", &err);
    h.kind = SYLVA_KIND_TREE, h.quiet = 1;
    void *state = NULL;
    mesh *m = mesh_new();
    sylva_tree_request req = {.size = sizeof req, .age = 1.0, .n_variants = 1, .seed = 1};
    sylva_tree_out out = {.size = sizeof out, .mesh = m};
    t0 = now();
    int rc = lp->desc->create(host_api_table(), &h, sf->species[0].params, &state);
    if (!rc) rc = lp->desc->generate(state, host_api_table(), &h, &req, &out);
    double t_gen = now() - t0;
    if (rc) {
        fprintf(stderr, "bench_tree_lsystem: %s\n", err.msg);
        return 1;
    }
    printf("plugin generate(): %.3f s  (%.3g symbols/s end to end), %u triangles, %u vertices, height %.2f m\n", t_gen,
           st.symbols / t_gen, m->nt, m->nv, out.height);
    printf("headline: the real mesh build (create + generate) %.2f s per 1e7 symbols (goal <= 2 s)\n",
           t_gen * 1e7 / st.symbols);
    lp->desc->destroy(state);
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("peak memory:       %.1f MiB  (goal <= 1024 MiB; includes the host's mesh)\n", ru.ru_maxrss / 1024.0);
    mesh_free(m);
    host_release(&h);
    scene_free(sc);
    scene_file_free(sf);
    plugin_registry_free(reg);
    return 0;
}
