/* memory_budget.c — physical memory or SYLVA_MEMORY_LIMIT, and the refusal sentence. */
#include "util/memory_budget.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

/* SYLVA_MEMORY_LIMIT in bytes, or 0 when unset or not a positive size. */
static uint64_t limit_from_environment(void)
{
    const char *s = getenv("SYLVA_MEMORY_LIMIT");
    if (!s || !*s) return 0;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || !(v > 0)) return 0;
    double unit = 1;
    if (*end == 'K' || *end == 'k') unit = 1024.0, end++;
    else if (*end == 'M' || *end == 'm') unit = 1024.0 * 1024.0, end++;
    else if (*end == 'G' || *end == 'g') unit = 1024.0 * 1024.0 * 1024.0, end++;
    if (*end || v * unit >= 1.8e19) return 0;
    return (uint64_t)(v * unit);
}

uint64_t memory_budget(void)
{
    uint64_t limit = limit_from_environment();
    if (limit) return limit;
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0) return (uint64_t)pages * (uint64_t)page;
    return (uint64_t)1 << 32; /* unknown: plan for 4 GiB */
}

/* "1.5 GiB" or "340 MiB" */
static void format_size(uint64_t bytes, char *out, size_t n)
{
    const double mib = 1024.0 * 1024.0, gib = 1024.0 * mib;
    if ((double)bytes >= gib) snprintf(out, n, "%.1f GiB", (double)bytes / gib);
    else snprintf(out, n, "%.0f MiB", (double)bytes / mib);
}

int memory_check(uint64_t need, const char *what, err_buf *err)
{
    uint64_t budget = memory_budget();
    if (need <= budget) return 0;
    char need_s[32], budget_s[32];
    format_size(need, need_s, sizeof need_s);
    format_size(budget, budget_s, sizeof budget_s);
    if (limit_from_environment())
        return err_set(err, "%s needs about %s of memory, more than the %s SYLVA_MEMORY_LIMIT "
                       "allows", what, need_s, budget_s);
    return err_set(err, "%s needs about %s of memory, more than the %s this machine has", what,
                   need_s, budget_s);
}
