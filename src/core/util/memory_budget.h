/* memory_budget.h — the memory one run may plan for, so that work which cannot fit is refused
 * with a sentence before anything is allocated, instead of ending in an out-of-memory kill.
 *
 * The budget is the machine's physical memory (sysconf), or the environment variable
 * SYLVA_MEMORY_LIMIT when it is set (bytes, or a number with K, M or G: "512M"), for a run
 * that must leave room for others. Estimates are compared with the budget, not with what is
 * free at the moment, so the same scene gets the same answer on the same machine. */
#ifndef SYLVA_MEMORY_BUDGET_H
#define SYLVA_MEMORY_BUDGET_H

#include <stdint.h>

#include "util/err.h"

/* 0 when SYLVA_MEMORY_LIMIT is unset or a valid size; otherwise -1 with err (ERR_USAGE) quoting
 * it and naming the valid forms. Run once before any work, so a mistyped limit is never
 * silently ignored. */
int memory_limit_check(err_buf *err);

/* The budget in bytes (never 0). */
uint64_t memory_budget(void);

/* 0 when need bytes fit the budget; otherwise -1 with err set to "WHAT needs about N GiB of
 * memory, more than the M GiB this machine has" (or "... SYLVA_MEMORY_LIMIT allows"). */
int memory_check(uint64_t need, const char *what, err_buf *err);

#endif
