/* povray_run.c — POV-Ray as a child process (posix_spawn: the caller may have threads), its
 * timing from the log it writes. */
#define _GNU_SOURCE /* memmem, posix_spawn_file_actions_addchdir_np */
#include "crosscheck/povray_run.h"

#include <errno.h>
#include <fcntl.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include "util/progress.h"

extern char **environ;

void povray_antialias_options(uint32_t spp, char *out, size_t n)
{
    uint32_t grid = 1;
    while ((grid + 1) * (grid + 1) <= spp) grid++;
    if (grid > 1) snprintf(out, n, "+A0.0 +AM1 +R%u -J", grid);
    else snprintf(out, n, "-A");
}

/* The log's whole text (NUL-terminated, caller frees), or NULL. */
static char *read_log(const char *folder, const char *log)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/%s", folder, log);
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *text = NULL;
    size_t len = 0, cap = 0;
    char chunk[8192];
    size_t got;
    while ((got = fread(chunk, 1, sizeof chunk, f)) > 0) {
        if (len + got + 1 > cap) {
            size_t c = cap ? cap * 2 : 65536;
            while (c < len + got + 1) c *= 2;
            char *t = realloc(text, c);
            if (!t) break;
            text = t, cap = c;
        }
        memcpy(text + len, chunk, got);
        len += got;
    }
    fclose(f);
    if (text) text[len] = '\0';
    return text;
}

/* POV-Ray's statistics read "  Parse Time:  0 hours  0 minutes  0 seconds (0.005 seconds)". */
static double logged_seconds(const char *log, const char *label)
{
    const char *p = log ? strstr(log, label) : NULL;
    if (!p) return -1.0;
    const char *open = strchr(p, '(');
    const char *eol = strchr(p, '\n');
    if (!open || (eol && open > eol)) return -1.0;
    char *end;
    double v = strtod(open + 1, &end);
    return end == open + 1 ? -1.0 : v;
}

/* ... followed by "  using 2 thread(s) with 0.061 CPU-seconds total" */
static double logged_cpu_seconds(const char *log, const char *label)
{
    const char *p = log ? strstr(log, label) : NULL;
    const char *with = p ? strstr(p, " with ") : NULL;
    const char *cpu = with ? strstr(with, "CPU-seconds") : NULL;
    if (!cpu || cpu - with > 40) return -1.0;
    char *end;
    double v = strtod(with + 6, &end);
    return end == with + 6 ? -1.0 : v;
}

/* Copies up to n bytes of the log's lines that report errors into out. */
static void error_lines(const char *log, char *out, size_t n)
{
    size_t k = 0;
    out[0] = '\0';
    for (const char *line = log; line && *line && k + 4 < n;) {
        const char *eol = line + strcspn(line, "\r\n");
        size_t len = (size_t)(eol - line);
        if (memmem(line, len, "rror", 4)) {
            if (k) out[k++] = ' ';
            size_t c = len < n - k - 1 ? len : n - k - 1;
            memcpy(out + k, line, c);
            k += c;
            out[k] = '\0';
        }
        line = *eol ? eol + 1 : NULL;
    }
}

int povray_render(const povray_job *job, povray_result *res, err_buf *err)
{
    memset(res, 0, sizeof *res);
    res->parse_seconds = res->bounding_seconds = res->trace_seconds = -1.0;
    const char *exe = job->executable ? job->executable : getenv("SYLVA_POVRAY");
    if (!exe || !*exe) exe = "povray";

    char in[4200], out[4200], w[32], h[32], aa[64], threads[32];
    /* POV-Ray splits option values at spaces unless they are quoted */
    if (strchr(job->scene, '"') || strchr(job->output, '"'))
        return err_set(err, "POV-Ray cannot be given file names with quotes ('%s', '%s')", job->scene, job->output);
    snprintf(in, sizeof in, "+I\"%s\"", job->scene);
    snprintf(out, sizeof out, "+O\"%s\"", job->output);
    snprintf(w, sizeof w, "+W%u", job->width);
    snprintf(h, sizeof h, "+H%u", job->height);
    snprintf(threads, sizeof threads, "+WT%u", job->threads);
    povray_antialias_options(job->spp, aa, sizeof aa);
    char *argv[24];
    int argc = 0;
    argv[argc++] = (char *)exe;
    argv[argc++] = in;
    argv[argc++] = out;
    argv[argc++] = "+FE";
    argv[argc++] = w;
    argv[argc++] = h;
    for (char *tok = strtok(aa, " "); tok && argc < 16; tok = strtok(NULL, " ")) argv[argc++] = tok;
    argv[argc++] = "+UA";
    argv[argc++] = "Declare=Sylva_sky_transmit=1";
    if (job->no_air) {
        argv[argc++] = "Declare=Sylva_no_air=1";
        argv[argc++] = "Declare=Sylva_coverage_only=1";
    }
    argv[argc++] = "-D";
    argv[argc++] = "-P";
    if (job->threads) argv[argc++] = threads;
    argv[argc] = NULL;

    posix_spawn_file_actions_t fa;
    if (posix_spawn_file_actions_init(&fa)) return err_nomem(err, "out of memory starting POV-Ray");
    int rc = posix_spawn_file_actions_addchdir_np(&fa, job->folder);
    if (!rc) rc = posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    if (!rc) rc = posix_spawn_file_actions_addopen(&fa, 1, job->log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (!rc) rc = posix_spawn_file_actions_adddup2(&fa, 1, 2);
    if (rc) {
        posix_spawn_file_actions_destroy(&fa);
        return err_set(err, "cannot prepare to start POV-Ray: %s", strerror(rc));
    }
    double t0 = progress_now();
    pid_t pid;
    rc = posix_spawnp(&pid, exe, &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc) {
        if (rc == ENOENT)
            return err_set(err, "POV-Ray was not found as '%s'; install POV-Ray 3.7 (package povray) or set "
                           "SYLVA_POVRAY to its path", exe);
        return err_set(err, "cannot start POV-Ray ('%s' in %s): %s", exe, job->folder, strerror(rc));
    }
    int status = 0;
    struct rusage usage = {0};
    while (wait4(pid, &status, 0, &usage) < 0) {
        if (errno != EINTR) return err_set(err, "lost track of POV-Ray (pid %ld): %s", (long)pid, strerror(errno));
    }
    res->wall_seconds = progress_now() - t0;
    char *log = read_log(job->folder, job->log);
    res->parse_seconds = logged_seconds(log, "Parse Time:");
    res->bounding_seconds = logged_seconds(log, "Bounding Time:");
    res->trace_seconds = logged_seconds(log, "Trace Time:");
    res->parse_cpu_seconds = logged_cpu_seconds(log, "Parse Time:");
    res->trace_cpu_seconds = logged_cpu_seconds(log, "Trace Time:");
    res->cpu_seconds = (double)usage.ru_utime.tv_sec + 1e-6 * usage.ru_utime.tv_usec +
                       (double)usage.ru_stime.tv_sec + 1e-6 * usage.ru_stime.tv_usec;
    if (WIFSIGNALED(status)) {
        free(log);
        res->exit_status = 128 + WTERMSIG(status);
        return err_set(err, "POV-Ray was killed by signal %d (log: %s/%s)", WTERMSIG(status), job->folder, job->log);
    }
    res->exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (res->exit_status != 0) {
        char lines[1200];
        error_lines(log, lines, sizeof lines);
        free(log);
        if (res->exit_status == 127)
            return err_set(err, "POV-Ray could not be started as '%s' (exit status 127); install POV-Ray 3.7 "
                           "or set SYLVA_POVRAY to its path", exe);
        return err_set(err, "POV-Ray failed on %s/%s with exit status %d%s%s (log: %s/%s)", job->folder, job->scene,
                       res->exit_status, lines[0] ? ": " : "", lines, job->folder, job->log);
    }
    free(log);
    return 0;
}
