/* bench_machine.h — the machine line every benchmark prints: the CPU model from
 * /proc/cpuinfo ("unknown" elsewhere). Header-only, for the benchmark executables. */
#ifndef SYLVA_BENCH_MACHINE_H
#define SYLVA_BENCH_MACHINE_H

#include <stdio.h>
#include <string.h>

/* Writes the CPU model name into out (cap bytes). */
static inline void bench_cpu_model(char *out, size_t cap)
{
    snprintf(out, cap, "unknown");
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f) return;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        const char *colon = strchr(line, ':');
        if (strncmp(line, "model name", 10) || !colon) continue;
        snprintf(out, cap, "%s", colon + 2);
        out[strcspn(out, "\n")] = '\0';
        break;
    }
    fclose(f);
}

#endif
