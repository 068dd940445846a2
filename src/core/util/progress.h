/* progress.h — progress reports on stderr: a bar with percentage and ETA when stderr is a
 * terminal, otherwise a plain line at every 10 %. Thread-safe: workers call progress_advance;
 * the print is serialised. A progress value belongs to one stage; no global state. */
#ifndef SYLVA_PROGRESS_H
#define SYLVA_PROGRESS_H

#include <pthread.h>
#include <stddef.h>
#include <stdint.h>

typedef struct progress {
    char label[64];
    uint64_t total, done;
    double start;         /* seconds (monotonic) */
    int tty;              /* 1: redraw a bar with \r */
    int quiet;            /* 1: print nothing */
    int last_decile;      /* plain mode: last 10 % step printed */
    double last_draw;     /* tty mode: time of the last redraw */
    pthread_mutex_t lock;
} progress;

void progress_begin(progress *p, const char *label, uint64_t total, int quiet);
void progress_advance(progress *p, uint64_t n);
/* Sets the absolute count (for plugins reporting done/total). */
void progress_set(progress *p, uint64_t done, uint64_t total);
/* Seconds left at the pace so far (0 before any progress is made). */
double progress_eta(progress *p);
/* Writes seconds as a duration ("4.2s", "3m07s", "1h02m") into buf. */
void progress_format_seconds(char *buf, size_t n, double seconds);
/* Prints the final line with the elapsed time. */
void progress_end(progress *p);

double progress_now(void); /* monotonic seconds */

#endif
