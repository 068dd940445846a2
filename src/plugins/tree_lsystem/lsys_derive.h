/* lsys_derive.h — derivation: every symbol of the string is rewritten in parallel by its rule,
 * `steps` times, starting from the axiom (a D0L-system). Symbols without a rule stay as they
 * are; an argument group "(number)" is copied unchanged and stays after whatever its symbol
 * became, as Lparser does with its text (so a rule `R=(10)` turns `+R` into `+(10)`).
 *
 * Guards: the derived string may not exceed `max_bytes`, and the bytes written over all steps
 * may not exceed LSYS_WORK_FACTOR times that; each step's size is computed before anything is
 * allocated, so the limit is reported, never an out-of-memory failure.
 *
 * Ownership: *out is malloc'ed and owned by the caller (free()).
 */
#ifndef LSYS_DERIVE_H
#define LSYS_DERIVE_H

#include <stddef.h>
#include <stdint.h>

#include "lsys_status.h"
#include "lsys_system.h"

#define LSYS_WORK_FACTOR 16

/* Called after each level (0 = the axiom) with that level's string, e.g. to count branches;
 * a non-zero return stops the derivation with that status. */
typedef int (*lsys_level_fn)(void *ctx, uint32_t level, const unsigned char *s, size_t n);

/* Derives `steps` levels of `sys`. Returns LSYS_OK with *out / *out_len, or LSYS_ERR_LIMIT
 * naming the step and the limit, or LSYS_ERR_NOMEM. on_level may be NULL. */
int lsys_derive(const lsys_system *sys, uint32_t steps, uint64_t max_bytes, lsys_level_fn on_level,
                void *level_ctx, unsigned char **out, size_t *out_len, plugin_err *err);

#endif
