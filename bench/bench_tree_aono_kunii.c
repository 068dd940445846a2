/* bench_tree_aono_kunii.c — how long tree_aono_kunii takes to build a tree (one core: the
 * plugin is single-threaded), and how large the trees are.
 *
 *  1. a 12-level stochastic tree (two or three children, even odds), bare and with leaves:
 *     segments, triangles, build time (create + generate; best and median of the runs), against
 *     the goal of 0.2 s for the bare tree;
 *  2. the figure scenes (scenes/aono_fig18 ... fig24.yaml) and the broadleaf species
 *     (scenes/species/aono_broadleaf.yaml): segments, triangles, build time.
 * Usage: bench_tree_aono_kunii [--runs N]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/utsname.h>

#include "aono_fixture.h"
#include "util/progress.h"

typedef struct tree_figures {
    uint32_t segments, triangles;
    double height;       /* metres */
    double best, median; /* seconds */
} tree_figures;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Opens the tree (from inline YAML, or species `name` of the file `path`), builds it `runs`
 * times, and counts its segments and triangles. Returns 0, or -1 after printing the reason. */
static int measure(const char *yaml, const char *path, const char *name, int runs, tree_figures *out)
{
    double *times = calloc((size_t)runs, sizeof *times); /* owned here */
    if (!times) return -1;
    int rc = 0;
    for (int r = 0; r < runs && !rc; r++) {
        aono_fixture fx;
        double t0 = progress_now();
        rc = path ? aono_fixture_open_species(&fx, path, name, 1) : aono_fixture_open(&fx, yaml, 1);
        mesh *m = NULL;
        if (!rc) rc = aono_fixture_generate(&fx, 1.0, &m, &out->height);
        times[r] = progress_now() - t0;
        if (!rc && r == 0) {
            aono_config cfg;
            aono_skeleton s = {0};
            rc = aono_fixture_config(&fx, &cfg);
            if (!rc) rc = aono_grow(&cfg, cfg.levels, &fx.env, &s, &fx.fail);
            if (!rc) out->segments = s.n, out->triangles = m->nt;
            aono_skeleton_release(&s);
            aono_config_release(&cfg);
        }
        if (rc) fprintf(stderr, "bench: %s: %s\n", path ? path : "inline tree", fx.err.msg);
        mesh_free(m);
        aono_fixture_close(&fx);
    }
    if (!rc) {
        qsort(times, (size_t)runs, sizeof *times, cmp_double);
        out->best = times[0];
        out->median = times[runs / 2];
    }
    free(times);
    return rc ? -1 : 0;
}

static void print_machine(void)
{
    char model[256] = "unknown CPU";
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f))
            if (!strncmp(line, "model name", 10) && strchr(line, ':')) {
                snprintf(model, sizeof model, "%s", strchr(line, ':') + 2);
                model[strcspn(model, "\n")] = 0;
                break;
            }
        fclose(f);
    }
    struct utsname u;
    if (uname(&u)) strcpy(u.sysname, "?"), strcpy(u.release, "?");
    printf("machine: %s; %s %s; compiler %s\n", model, u.sysname, u.release, __VERSION__);
}

int main(int argc, char **argv)
{
    int runs = 5;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--runs") && i + 1 < argc) runs = atoi(argv[++i]);
        else {
            fprintf(stderr, "usage: bench_tree_aono_kunii [--runs N]\n");
            return 1;
        }
    }
    if (runs < 1) runs = 1;
    print_machine();
    printf("one core (the plugin is single-threaded); build = create + generate; %d runs each\n\n", runs);

    static const char stochastic[] = "levels: 12\npattern: stochastic\nternary_probability: 0.5\n"
                                     "fi: [35, 40, 10]\nsf: 6\nri: [0.78, 0.72, 0.85]\n";
    char leafy[512];
    snprintf(leafy, sizeof leafy, "%sleaf_count: 6\n", stochastic);
    tree_figures bare, leaves;
    if (measure(stochastic, NULL, NULL, runs, &bare) || measure(leafy, NULL, NULL, runs, &leaves)) return 2;
    printf("12-level stochastic tree (p(three children) = 0.5)\n");
    printf("  %-10s %9s %10s %10s %10s\n", "", "segments", "triangles", "best s", "median s");
    printf("  %-10s %9u %10u %10.4f %10.4f\n", "bare", bare.segments, bare.triangles, bare.best, bare.median);
    printf("  %-10s %9u %10u %10.4f %10.4f\n", "6 leaves", leaves.segments, leaves.triangles, leaves.best,
           leaves.median);
    printf("  goal 0.2 s for the bare tree: median %.4f s is %.2f of it (%s)\n\n", bare.median, bare.median / 0.2,
           bare.median <= 0.2 ? "met" : "missed");

    static const char *const figures[][2] = {
        {"scenes/aono_fig18.yaml", "fig18"}, {"scenes/aono_fig19.yaml", "fig19"}, {"scenes/aono_fig21.yaml", "fig21"},
        {"scenes/aono_fig22.yaml", "fig22"}, {"scenes/aono_fig23.yaml", "fig23"},
        {"scenes/aono_fig24.yaml", "fig24"}, {"scenes/species/aono_broadleaf.yaml", "aono_broadleaf"},
    };
    printf("%-44s %9s %10s %8s %10s %10s\n", "scene species", "segments", "triangles", "height m", "best s",
           "median s");
    for (size_t k = 0; k < sizeof figures / sizeof figures[0]; k++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", SYLVA_SOURCE_DIR, figures[k][0]);
        tree_figures t;
        if (measure(NULL, path, figures[k][1], runs, &t)) return 2;
        char label[128];
        snprintf(label, sizeof label, "%s %s", figures[k][0], figures[k][1]);
        printf("%-44s %9u %10u %8.2f %10.4f %10.4f\n", label, t.segments, t.triangles, t.height, t.best, t.median);
    }
    return 0;
}
