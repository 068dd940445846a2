/* test_lsys_corpus.c — every L-parser file of the shared corpus (../shared/data/lparser/, 120
 * real .ls files in two dialects) either builds a mesh through the whole pipeline (scene file,
 * host, plugin, two age variants) or fails with a sentence naming the file: no crash, no hang,
 * no runaway memory. Each file runs in a child process under a CPU-time limit and (outside
 * AddressSanitizer builds, whose shadow memory needs the address space) an address-space limit.
 * Strict mode must build at least 95 % of the files; lenient mode builds the rest. Skips,
 * saying why, when the corpus is absent. */
#include "harness.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "lsys_derive.h"
#include "lsys_system.h"
#include "lsys_turtle.h"
#include "plugin/plugin_host.h"
#include "scene/scene.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

#if defined(__SANITIZE_ADDRESS__)
#define UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UNDER_ASAN 1
#endif
#endif
#ifndef UNDER_ASAN
#define UNDER_ASAN 0
#endif

#define CPU_LIMIT_S 60                     /* per file */
#define MEMORY_LIMIT ((rlim_t)2 << 30)     /* address space per file (not under ASan) */
#define RSS_LIMIT_KB (1024L * 1024L)       /* peak resident memory per file: 1 GiB */

typedef struct corpus {
    char **paths;
    uint32_t n, cap;
} corpus;

static int path_cmp(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static void find_ls(corpus *c, const char *dir, int depth)
{
    DIR *d = opendir(dir);
    if (!d) return;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.') continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        size_t l = strlen(e->d_name);
        if (l > 3 && !strcmp(e->d_name + l - 3, ".ls")) {
            if (c->n == c->cap) {
                c->cap = c->cap ? 2 * c->cap : 128;
                c->paths = realloc(c->paths, c->cap * sizeof *c->paths);
            }
            c->paths[c->n++] = strdup(path);
        } else if (depth < 2) {
            find_ls(c, path, depth + 1);
        }
    }
    closedir(d);
    qsort(c->paths, c->n, sizeof *c->paths, path_cmp);
}

typedef struct outcome {
    int built;            /* 1: a mesh was built */
    int clean;            /* 1: the child ended by itself (built, or failed with a sentence) */
    char message[1024];   /* the child's report */
    double seconds;
    long max_rss_kb;
} outcome;

/* The child: loads a scene with one species from `path` and builds it; reports through fd. */
static void child_build(const char *path, int lenient, int fd)
{
    struct rlimit cpu = {CPU_LIMIT_S, CPU_LIMIT_S};
    setrlimit(RLIMIT_CPU, &cpu);
    if (!UNDER_ASAN) {
        struct rlimit as = {MEMORY_LIMIT, MEMORY_LIMIT};
        setrlimit(RLIMIT_AS, &as);
    }
    char scene_path[64];
    snprintf(scene_path, sizeof scene_path, "/tmp/sylva_corpus_%d.yaml", (int)getpid());
    FILE *f = fopen(scene_path, "w");
    if (!f) _exit(5);
    fprintf(f,
            "camera: {position: [0, -20, 5]}\n"
            "species:\n"
            "  t: {plugin: tree_lsystem, variants: 2, height: 5, lenient: %s, file: '%s'}\n",
            lenient ? "true" : "false", path);
    fclose(f);
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open_path(TREE_LSYSTEM_PLUGIN_DIR, &err);
    scene_file *sf = reg ? scene_file_load(scene_path, reg, &err) : NULL;
    scene *s = sf ? scene_build(sf, reg, &(build_options){.quiet = 1}, &err) : NULL;
    unlink(scene_path);
    char msg[1100];
    int code;
    if (s) {
        uint64_t tri = 0;
        for (uint32_t p = 0; p < s->n_prototypes; p++) tri += s->prototypes[p].mesh->nt;
        snprintf(msg, sizeof msg, "built %u variants, %llu triangles", s->n_prototypes, (unsigned long long)tri);
        code = tri ? 0 : 4;
    } else {
        snprintf(msg, sizeof msg, "%s", err.msg);
        code = 3;
    }
    ssize_t w = write(fd, msg, strlen(msg));
    (void)w;
    scene_free(s);
    scene_file_free(sf);
    plugin_registry_free(reg);
    _exit(code);
}

static outcome run_file(const char *path, int lenient)
{
    outcome o = {0};
    int p[2];
    if (pipe(p)) {
        snprintf(o.message, sizeof o.message, "pipe: %s", strerror(errno));
        return o;
    }
    fflush(stderr);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    pid_t pid = fork();
    if (pid == 0) {
        close(p[0]);
        child_build(path, lenient, p[1]);
    }
    close(p[1]);
    size_t got = 0;
    ssize_t r;
    while (got + 1 < sizeof o.message && (r = read(p[0], o.message + got, sizeof o.message - 1 - got)) > 0)
        got += (size_t)r;
    o.message[got] = '\0';
    close(p[0]);
    int status = 0;
    struct rusage ru;
    memset(&ru, 0, sizeof ru);
    if (pid < 0 || wait4(pid, &status, 0, &ru) < 0) {
        snprintf(o.message, sizeof o.message, "fork/wait failed: %s", strerror(errno));
        return o;
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    o.seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    o.max_rss_kb = ru.ru_maxrss;
    if (WIFSIGNALED(status)) {
        snprintf(o.message, sizeof o.message, "killed by signal %d (%s)", WTERMSIG(status),
                 WTERMSIG(status) == SIGXCPU ? "CPU-time limit: a hang" : strsignal(WTERMSIG(status)));
        return o;
    }
    int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    o.built = code == 0;
    o.clean = code == 0 || code == 3;
    return o;
}

static const char *base_name(const char *p)
{
    const char *s = strrchr(p, '/');
    return s ? s + 1 : p;
}

TEST(every_file_builds_or_fails_clearly)
{
    const char *dir = harness_shared_data("lparser");
    if (!dir) SKIP("the shared L-parser corpus (lparser/ in SYLVA_SHARED_DATA_DIR) is not there");
    corpus c = {0};
    find_ls(&c, dir, 0);
    CHECK(c.n >= 100);
    uint32_t strict_built = 0, lenient_built = 0;
    double slowest = 0;
    long biggest = 0;
    const char *slowest_file = "";
    for (uint32_t i = 0; i < c.n; i++) {
        outcome o = run_file(c.paths[i], 0);
        if (o.seconds > slowest) slowest = o.seconds, slowest_file = c.paths[i];
        if (o.max_rss_kb > biggest) biggest = o.max_rss_kb;
        CHECK(o.clean);
        CHECK(o.max_rss_kb <= RSS_LIMIT_KB);
        if (!o.clean) fprintf(stderr, "NOT CLEAN %s: %s\n", c.paths[i], o.message);
        if (o.built) {
            strict_built++, lenient_built++;
            continue;
        }
        /* A failure must say what and where: the file's name is in the sentence. */
        CHECK_STR_CONTAINS(o.message, base_name(c.paths[i]));
        fprintf(stderr, "strict: %s\n", o.message);
        outcome l = run_file(c.paths[i], 1);
        CHECK(l.clean);
        if (l.built) lenient_built++;
        else fprintf(stderr, "lenient: %s\n", l.message);
    }
    fprintf(stderr,
            "corpus: %u files; strict mode built %u (%.1f %%), lenient mode built %u (%.1f %%); slowest %.2f s (%s); "
            "largest peak memory %.1f MiB%s\n",
            c.n, strict_built, 100.0 * strict_built / c.n, lenient_built, 100.0 * lenient_built / c.n, slowest,
            base_name(slowest_file), biggest / 1024.0, UNDER_ASAN ? " (address-space limit off under ASan)" : "");
    CHECK(strict_built * 100 >= 95 * c.n);
    CHECK_INT(lenient_built, c.n);
    for (uint32_t i = 0; i < c.n; i++) free(c.paths[i]);
    free(c.paths);
}

/* K-3D's port of Lparser 4 builds abop-nested-polygon-leaves.ls at growth 2 into 6 cylinders and
 * 5 petal polygons (shared/data/lparser/reference-outputs/k3d: 63 faces = 6 x 8 + 5 x 3). */
TEST(k3d_reference_counts)
{
    const char *path = harness_shared_data("lparser/lparser4-k3d/abop-nested-polygon-leaves.ls");
    if (!path) SKIP("the shared L-parser corpus (lparser/ in SYLVA_SHARED_DATA_DIR) is not there");
    lsys_system *s = NULL;
    plugin_err e = {0};
    CHECK_INT(lsys_read_file(path, NULL, &s, &e), LSYS_OK);
    if (!s) return;
    unsigned char *str = NULL;
    size_t n = 0;
    CHECK_INT(lsys_derive(s, 2, 1u << 20, NULL, NULL, &str, &n, &e), LSYS_OK);
    lsys_turtle_config cfg = {.angle_deg = s->angle_deg, .thickness = s->thickness, .base_length = s->base_length,
                              .colour = 2, .max_segments = 1000, .max_polygons = 1000, .max_polygon_vertices = 1000,
                              .max_depth = 1000, .tube_corners = 8};
    lsys_turtle_stats st;
    CHECK_INT(lsys_interpret(str, n, &cfg, NULL, 0, &st, &e), LSYS_OK);
    CHECK_INT(st.segments, 6);
    CHECK_INT(st.polygons, 5);
    free(str);
    lsys_system_free(s);
}

TEST_LIST(TEST_CASE(every_file_builds_or_fails_clearly), TEST_CASE(k3d_reference_counts))
