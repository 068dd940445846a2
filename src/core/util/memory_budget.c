/* memory_budget.c — physical memory or SYLVA_MEMORY_LIMIT, and the refusal sentence. */
#include "util/memory_budget.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define LIMIT_FORMS "a byte count (2147483648) or a number with K, M or G (512M, 8G, 1.5G)"

/* text as a memory size in bytes: 0 with *bytes set, or -1 when it is not a positive size of
 * one of LIMIT_FORMS that fits in 64 bits. */
static int parse_limit(const char *text, uint64_t *bytes)
{
    char *end;
    errno = 0;
    double v = text[0] >= '0' && text[0] <= '9' ? strtod(text, &end) : 0;
    if (!(text[0] >= '0' && text[0] <= '9') || errno || !(v > 0)) return -1;
    double unit = 1;
    if (*end == 'K' || *end == 'k') unit = 1024.0, end++;
    else if (*end == 'M' || *end == 'm') unit = 1024.0 * 1024.0, end++;
    else if (*end == 'G' || *end == 'g') unit = 1024.0 * 1024.0 * 1024.0, end++;
    if (*end || v * unit >= 1.8e19 || v * unit < 1) return -1;
    *bytes = (uint64_t)(v * unit);
    return 0;
}

/* SYLVA_MEMORY_LIMIT in bytes, or 0 when unset or not a valid size (which
 * memory_limit_check refuses before any work). */
static uint64_t limit_from_environment(void)
{
    const char *s = getenv("SYLVA_MEMORY_LIMIT");
    uint64_t bytes = 0;
    return s && !parse_limit(s, &bytes) ? bytes : 0;
}

int memory_limit_check(err_buf *err)
{
    const char *s = getenv("SYLVA_MEMORY_LIMIT");
    uint64_t bytes;
    if (!s || !parse_limit(s, &bytes)) return 0;
    if (!*s)
        return err_fail(err, ERR_USAGE, "SYLVA_MEMORY_LIMIT is set but empty; give %s, or unset it to plan for "
                        "the machine's memory", LIMIT_FORMS);
    return err_fail(err, ERR_USAGE, "SYLVA_MEMORY_LIMIT is '%.64s%s', which is not a memory size; give %s, or "
                    "unset it to plan for the machine's memory", s, strlen(s) > 64 ? "..." : "", LIMIT_FORMS);
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
