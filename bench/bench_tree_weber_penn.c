/* bench_tree_weber_penn.c — how long tree_weber_penn takes to build one model (one core:
 * generate() is single-threaded) and how large the models are, at ages 0.25, 0.5 and 1: the
 * aspen of tests/scenes/tree_weber_penn_aspen.yaml, and with --arbaro DIR every species file of
 * Arbaro's trees/ folder (e.g. ../shared/data/weber-penn/arbaro). Per model: stem levels,
 * triangles, vertices, height, and generate()'s time (best and median of the runs).
 * Usage: bench_tree_weber_penn [--runs N] [--arbaro DIR]
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/progress.h"
#include "wp_age.h"
#include "wp_fixture.h"

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Builds the opened species at each age `runs` times and prints one row per age. */
static int bench_species(wp_fixture *fx, const char *label, int runs)
{
    static const double ages[] = {0.25, 0.5, 1.0};
    double *times = calloc((size_t)runs, sizeof *times); /* owned here */
    if (!times) return -1;
    int rc = wp_fixture_create(fx);
    for (size_t a = 0; a < sizeof ages / sizeof ages[0] && !rc; a++) {
        uint32_t nt = 0, nv = 0;
        double height = 0;
        for (int r = 0; r < runs && !rc; r++) {
            mesh *m = NULL;
            double t0 = progress_now();
            rc = wp_fixture_generate(fx, ages[a], 0, 1, &m, &height);
            times[r] = progress_now() - t0;
            if (m) nt = m->nt, nv = m->nv;
            mesh_free(m);
        }
        if (rc) break;
        qsort(times, (size_t)runs, sizeof *times, cmp_double);
        printf("%-22s %5.2f %6d %10u %10u %8.3f %9.1f %9.1f\n", label, ages[a],
               wp_age_levels(fx->cfg.species.levels, ages[a]), nt, nv, height, 1e3 * times[0], 1e3 * times[runs / 2]);
    }
    if (rc) fprintf(stderr, "bench: %s: %s\n", label, fx->err.msg);
    free(times);
    return rc;
}

int main(int argc, char **argv)
{
    int runs = 5;
    const char *arbaro = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--runs") && i + 1 < argc) runs = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--arbaro") && i + 1 < argc) arbaro = argv[++i];
        else return fprintf(stderr, "usage: bench_tree_weber_penn [--runs N] [--arbaro DIR]\n"), 1;
    }
    if (runs < 1) runs = 1;
    printf("%-22s %5s %6s %10s %10s %8s %9s %9s\n", "species", "age", "levels", "triangles", "vertices", "height",
           "best ms", "median ms");
    wp_fixture fx;
    int rc = wp_fixture_open_species(&fx, SYLVA_SOURCE_DIR "/tests/scenes/tree_weber_penn_aspen.yaml", "aspen");
    rc = rc ? (fprintf(stderr, "bench: %s\n", fx.err.msg), rc) : bench_species(&fx, "aspen (inline)", runs);
    wp_fixture_close(&fx);
    DIR *d = arbaro ? opendir(arbaro) : NULL;
    if (arbaro && !d) return fprintf(stderr, "bench: cannot open %s\n", arbaro), 1;
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        if (n < 5 || strcmp(e->d_name + n - 4, ".xml")) continue;
        char yaml[4400];
        snprintf(yaml, sizeof yaml, "file: %s/%s\n", arbaro, e->d_name);
        int r = wp_fixture_open(&fx, yaml, ".");
        r = r ? (fprintf(stderr, "bench: %s\n", fx.err.msg), r) : bench_species(&fx, e->d_name, runs);
        rc |= r;
        wp_fixture_close(&fx);
    }
    if (d) closedir(d);
    return rc ? 1 : 0;
}
