/* test_alloc_faults.c — runs one `sylva` command again and again with the Nth allocation made by
 * sylva's code failing (fault_alloc.h), each run in a child process:
 *
 *   test_alloc_faults OUT_DIR [--sticky] [--max-runs K] [--only N] [--expect TEXT] -- COMMAND ARGS...
 *
 * COMMAND ARGS are the command line after `sylva`; the word @OUT in them stands for OUT_DIR.
 * A first run without failures must succeed and counts the allocations, A. Then for N = 1 .. A
 * (every N when A <= K, else K values spread evenly from 1 to A, the first 64 always included)
 * the run with allocation N failing (with --sticky: N and all later ones, as when memory has run
 * out) must
 *   - not crash (no signal, no sanitizer report: those end the child abnormally),
 *   - either succeed (the allocation was optional) or exit with status 4, the README's status
 *     for running out of memory, with a message on stderr that says the memory ran out,
 *   - free every block it allocated (the live count returns to what it was before the command),
 *   - leave no temporary file in OUT_DIR.
 * With --expect TEXT, at least one failing run's stderr must contain TEXT (e.g. a plugin's own
 * out-of-memory sentence, showing that its allocations are among those failed).
 * Prints one line per failing N and a summary; exit 0 when every run passed. --only N runs
 * allocation N alone (with FAULT_ALLOC_TRACE=1 in the environment its call stack is printed). */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/commands.h"
#include "fault_alloc.h"

#define MAX_ARGS 64
#define EXIT_OUT_OF_MEMORY 4 /* README: out of memory or internal error */
#define ALWAYS_TESTED 64 /* the first allocations (argument and scene-file handling) all */

typedef struct {
    int rc;           /* the command's exit status */
    uint64_t count;   /* allocations attempted */
    uint64_t failed;  /* allocations failed */
    long long leaked; /* live blocks after the command minus before */
} run_report;

static int dispatch(int argc, char **argv)
{
    const sylva_command *c = sylva_command_find(argv[0]);
    if (c) return c->run(argc, argv);
    fprintf(stderr, "test_alloc_faults: unknown command '%s'\n", argv[0]);
    return 99;
}

/* Removes every file in dir; returns how many were temporary files (".tmp-" in the name). */
static int clear_dir(const char *dir)
{
    int temps = 0;
    DIR *d = opendir(dir);
    if (!d) return 0;
    struct dirent *e;
    char path[4096];
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.' && (!e->d_name[1] || (e->d_name[1] == '.' && !e->d_name[2]))) continue;
        if (strstr(e->d_name, ".tmp-")) temps++;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        unlink(path);
    }
    closedir(d);
    return temps;
}

/* Runs the command in a child with allocation n failing (0: none). Returns 0 and fills *r when
 * the child ended normally, else -1 with a description in why. The child's stderr goes to
 * err_path. */
static int run_child(int argc, char **argv, uint64_t n, int sticky, const char *err_path, run_report *r,
                     char *why, size_t why_n)
{
    int fd[2];
    if (pipe(fd)) {
        snprintf(why, why_n, "pipe: %s", strerror(errno));
        return -1;
    }
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid < 0) {
        snprintf(why, why_n, "fork: %s", strerror(errno));
        return -1;
    }
    if (pid == 0) {
        close(fd[0]);
        int err = open(err_path, O_WRONLY | O_CREAT | O_TRUNC, 0644), null = open("/dev/null", O_WRONLY);
        if (err < 0 || null < 0) _exit(98);
        dup2(err, 2);
        dup2(null, 1);
        size_t before = fault_alloc_live();
        fault_alloc_arm(n, sticky);
        int rc = dispatch(argc, argv);
        fflush(stdout);
        fflush(stderr);
        run_report rep = {rc, fault_alloc_count(), fault_alloc_failed(), (long long)fault_alloc_live() - (long long)before};
        ssize_t w = write(fd[1], &rep, sizeof rep);
        _exit(w == (ssize_t)sizeof rep ? 0 : 97);
    }
    close(fd[1]);
    ssize_t got = read(fd[0], r, sizeof *r);
    close(fd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFSIGNALED(status)) {
        snprintf(why, why_n, "killed by signal %d (%s)", WTERMSIG(status), strsignal(WTERMSIG(status)));
        return -1;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || got != (ssize_t)sizeof *r) {
        snprintf(why, why_n, "ended abnormally (exit status %d; a sanitizer report is in %s)",
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1, err_path);
        return -1;
    }
    return 0;
}

/* 1 when the file at path contains text. */
static int file_contains(const char *path, const char *text)
{
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    char buf[8192];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    return strstr(buf, text) != NULL;
}

static void print_file(const char *path, int max_lines)
{
    FILE *f = fopen(path, "r");
    if (!f) return;
    char line[1024];
    for (int i = 0; i < max_lines && fgets(line, sizeof line, f); i++) printf("    | %s", line);
    fclose(f);
}

int main(int argc, char **argv)
{
    const char *out_dir = NULL, *expect = NULL;
    int sticky = 0, first = 0;
    uint64_t max_runs = 400, only = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--")) {
            first = i + 1;
            break;
        } else if (!strcmp(argv[i], "--sticky")) {
            sticky = 1;
        } else if (!strcmp(argv[i], "--expect") && i + 1 < argc) {
            expect = argv[++i];
        } else if (!strcmp(argv[i], "--only") && i + 1 < argc) {
            only = strtoull(argv[++i], NULL, 10);
        } else if (!strcmp(argv[i], "--max-runs") && i + 1 < argc) {
            max_runs = strtoull(argv[++i], NULL, 10);
        } else if (!out_dir) {
            out_dir = argv[i];
        }
    }
    if (!out_dir || !first || first >= argc || argc - first > MAX_ARGS || max_runs < ALWAYS_TESTED + 2) {
        fprintf(stderr, "usage: test_alloc_faults OUT_DIR [--sticky] [--max-runs K>=%d] [--only N] [--expect TEXT] -- "
                "COMMAND ARGS...\n",
                ALWAYS_TESTED + 2);
        return 2;
    }
    mkdir(out_dir, 0755); /* its parent exists (tests/faults/CMakeLists.txt makes it) */
    /* The command line, with @OUT replaced by the output folder. */
    static char words[MAX_ARGS][4096];
    char *cargv[MAX_ARGS + 1];
    int cargc = argc - first;
    for (int i = 0; i < cargc; i++) {
        const char *w = argv[first + i], *at = strstr(w, "@OUT");
        if (at)
            snprintf(words[i], sizeof words[i], "%.*s%s%s", (int)(at - w), w, out_dir, at + 4);
        else
            snprintf(words[i], sizeof words[i], "%s", w);
        cargv[i] = words[i];
    }
    cargv[cargc] = NULL;
    char err_path[4200], why[512] = "";
    snprintf(err_path, sizeof err_path, "%s.stderr", out_dir);

    run_report r = {0};
    clear_dir(out_dir);
    if (run_child(cargc, cargv, 0, 0, err_path, &r, why, sizeof why) || r.rc != 0 || r.leaked != 0) {
        printf("FAIL: the run without failures: %s (exit status %d, %lld blocks leaked)\n", why, r.rc, r.leaked);
        print_file(err_path, 6);
        return 1;
    }
    uint64_t total = r.count;
    printf("%s: %llu allocations by sylva's code in a run without failures\n", cargv[0], (unsigned long long)total);

    unsigned runs = 0, bad = 0, succeeded = 0, expected_seen = 0;
    for (uint64_t k = 0;; k++) {
        uint64_t n;
        if (total <= max_runs) {
            n = k + 1;
        } else if (k < ALWAYS_TESTED) {
            n = k + 1;
        } else {
            uint64_t rest = max_runs - ALWAYS_TESTED, j = k - ALWAYS_TESTED; /* j in [0, rest) */
            n = ALWAYS_TESTED + 1 + (j * (total - ALWAYS_TESTED - 1)) / (rest - 1);
        }
        if (only) {
            if (k) break;
            n = only;
        }
        if (n > total || (total > max_runs && k >= max_runs)) break;
        runs++;
        clear_dir(out_dir);
        memset(&r, 0, sizeof r);
        if (run_child(cargc, cargv, n, sticky, err_path, &r, why, sizeof why)) {
            printf("FAIL: allocation %llu failing: %s\n", (unsigned long long)n, why);
            print_file(err_path, 6);
            bad++;
            continue;
        }
        if (only) print_file(err_path, 40);
        int temps = clear_dir(out_dir);
        if (expect && r.rc != 0 && file_contains(err_path, expect)) expected_seen++;
        const char *problem = NULL;
        if (r.rc != 0 && r.rc != EXIT_OUT_OF_MEMORY)
            problem = "exit status other than 4 (out of memory)";
        else if (r.rc != 0 && !file_contains(err_path, "out of memory"))
            problem = "no 'out of memory' on stderr";
        if (!problem && r.leaked != 0) problem = "blocks leaked";
        if (!problem && temps) problem = "temporary files left behind";
        if (problem) {
            printf("FAIL: allocation %llu failing: %s (exit status %d, %lld blocks leaked, %d temporary files)\n",
                   (unsigned long long)n, problem, r.rc, r.leaked, temps);
            print_file(err_path, 6);
            bad++;
        } else if (r.rc == 0) {
            printf("allocation %llu failing: the command succeeded without it\n", (unsigned long long)n);
            succeeded++;
        }
    }
    clear_dir(out_dir);
    unlink(err_path);
    printf("%s: %u runs with one allocation failing%s, %u failed as they should, %u succeeded without it, %u wrong\n",
           cargv[0], runs, sticky ? " (and every later one)" : "", runs - bad - succeeded, succeeded, bad);
    if (expect) {
        printf("%s: %u failing runs said \"%s\"\n", cargv[0], expected_seen, expect);
        if (!expected_seen) bad++;
    }
    return bad ? 1 : 0;
}
