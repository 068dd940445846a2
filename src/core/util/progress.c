/* progress.c — drawing progress on stderr. */
#include "util/progress.h"

#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

double progress_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

void progress_format_seconds(char *buf, size_t n, double s)
{
    if (s < 0 || s != s) s = 0;
    if (s < 60) snprintf(buf, n, "%.1fs", s);
    else if (s < 3600) snprintf(buf, n, "%dm%02ds", (int)(s / 60), (int)s % 60);
    else snprintf(buf, n, "%dh%02dm", (int)(s / 3600), (int)(s / 60) % 60);
}

void progress_begin(progress *p, const char *label, uint64_t total, int quiet)
{
    memset(p, 0, sizeof *p);
    snprintf(p->label, sizeof p->label, "%s", label);
    p->total = total;
    p->start = progress_now();
    p->tty = isatty(STDERR_FILENO);
    p->quiet = quiet;
    p->last_decile = -1;
    pthread_mutex_init(&p->lock, NULL);
}

/* Called with the lock held. */
static void draw(progress *p, int final)
{
    if (p->quiet) return;
    double now = progress_now(), el = now - p->start;
    double frac = p->total ? (double)p->done / (double)p->total : 1.0;
    if (frac > 1) frac = 1;
    char eta[32], elapsed[32];
    progress_format_seconds(elapsed, sizeof elapsed, el);
    progress_format_seconds(eta, sizeof eta, frac > 0 ? el / frac - el : 0);
    if (p->tty) {
        if (!final && now - p->last_draw < 0.1) return;
        p->last_draw = now;
        char bar[31];
        int fill = (int)(frac * 30);
        for (int i = 0; i < 30; i++) bar[i] = i < fill ? '#' : '.';
        bar[30] = '\0';
        if (final) fprintf(stderr, "\r%s [%s] 100%%  done in %s\033[K\n", p->label, bar, elapsed);
        else fprintf(stderr, "\r%s [%s] %3d%%  ETA %s\033[K", p->label, bar, (int)(frac * 100), eta);
    } else {
        int decile = (int)(frac * 10);
        if (final) {
            fprintf(stderr, "%s: done in %s\n", p->label, elapsed);
        } else if (decile > p->last_decile) {
            p->last_decile = decile;
            fprintf(stderr, "%s: %d%% (ETA %s)\n", p->label, decile * 10, eta);
        }
    }
    fflush(stderr);
}

void progress_advance(progress *p, uint64_t n)
{
    pthread_mutex_lock(&p->lock);
    p->done += n;
    draw(p, 0);
    pthread_mutex_unlock(&p->lock);
}

void progress_set(progress *p, uint64_t done, uint64_t total)
{
    pthread_mutex_lock(&p->lock);
    p->done = done;
    p->total = total;
    draw(p, 0);
    pthread_mutex_unlock(&p->lock);
}

double progress_eta(progress *p)
{
    pthread_mutex_lock(&p->lock);
    double el = progress_now() - p->start, frac = p->total ? (double)p->done / (double)p->total : 1.0;
    pthread_mutex_unlock(&p->lock);
    return frac > 0 && frac < 1 ? el / frac - el : 0;
}

void progress_end(progress *p)
{
    pthread_mutex_lock(&p->lock);
    p->done = p->total;
    draw(p, 1);
    pthread_mutex_unlock(&p->lock);
    pthread_mutex_destroy(&p->lock);
}
