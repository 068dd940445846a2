/* lsys_derive.c — parallel rewriting of the derived string with size guards. Two passes per
 * step: the first sums the next string's size, the second writes it. */
#include "lsys_derive.h"

#include <stdlib.h>
#include <string.h>

#include "lsys_symbols.h"

/* Size of the next level, or UINT64_MAX past `limit`. */
static uint64_t next_size(const lsys_system *sys, const unsigned char *s, size_t n, uint64_t limit)
{
    uint64_t total = 0;
    for (size_t i = 0; i < n;) {
        unsigned char c = s[i];
        if (c == '(') {
            size_t g = lsys_arg_group(s + i, n - i, NULL);
            if (g) {
                total += g, i += g;
                continue;
            }
        }
        total += sys->rules[c].defined ? sys->rules[c].length : 1;
        i++;
        if (total > limit) return UINT64_MAX;
    }
    return total;
}

static void rewrite(const lsys_system *sys, const unsigned char *s, size_t n, unsigned char *dst)
{
    for (size_t i = 0; i < n;) {
        unsigned char c = s[i];
        if (c == '(') {
            size_t g = lsys_arg_group(s + i, n - i, NULL);
            if (g) {
                memcpy(dst, s + i, g);
                dst += g, i += g;
                continue;
            }
        }
        const lsys_rule *r = &sys->rules[c];
        if (r->defined) {
            if (r->length == 1) *dst++ = r->successor[0];
            else if (r->length) memcpy(dst, r->successor, r->length), dst += r->length;
        } else {
            *dst++ = c;
        }
        i++;
    }
}

int lsys_derive(const lsys_system *sys, uint32_t steps, uint64_t max_bytes, lsys_level_fn on_level,
                void *level_ctx, unsigned char **out, size_t *out_len, plugin_err *err)
{
    *out = NULL, *out_len = 0;
    if (sys->axiom_length > max_bytes)
        return plugin_fail(err, LSYS_ERR_LIMIT, "%s: the axiom has %u bytes, more than the limit max_string = %llu",
                         sys->name, sys->axiom_length, (unsigned long long)max_bytes);
    size_t cap_cur = sys->axiom_length ? sys->axiom_length : 1;
    unsigned char *cur = malloc(cap_cur), *next = NULL; /* both owned here */
    size_t n = sys->axiom_length, cap_next = 0;
    if (!cur) return plugin_fail(err, LSYS_ERR_NOMEM, "%s: out of memory for the axiom", sys->name);
    if (n) memcpy(cur, sys->axiom, n);
    uint64_t work = 0, work_limit = max_bytes * LSYS_WORK_FACTOR;
    int rc = on_level ? on_level(level_ctx, 0, cur, n) : LSYS_OK;
    for (uint32_t step = 1; step <= steps && !rc; step++) {
        uint64_t m = next_size(sys, cur, n, max_bytes);
        if (m == UINT64_MAX) {
            rc = plugin_fail(err, LSYS_ERR_LIMIT,
                           "%s: derivation step %u of %u would make the string longer than the limit "
                           "max_string = %llu bytes (step %u has %zu); lower the recursion level or raise max_string",
                           sys->name, step, steps, (unsigned long long)max_bytes, step - 1, n);
            break;
        }
        work += m;
        if (work > work_limit) {
            rc = plugin_fail(err, LSYS_ERR_LIMIT,
                           "%s: derivation step %u of %u: the steps together would write more than %d times "
                           "max_string = %llu bytes; lower the recursion level or raise max_string",
                           sys->name, step, steps, LSYS_WORK_FACTOR, (unsigned long long)max_bytes);
            break;
        }
        if (m > cap_next || !next) {
            size_t cap = m ? (size_t)m : 1;
            unsigned char *grown = realloc(next, cap);
            if (!grown) {
                rc = plugin_fail(err, LSYS_ERR_NOMEM, "%s: out of memory for derivation step %u (%llu bytes)",
                               sys->name, step, (unsigned long long)m);
                break;
            }
            next = grown, cap_next = cap;
        }
        rewrite(sys, cur, n, next);
        unsigned char *t = cur;
        size_t tc = cap_cur;
        cur = next, cap_cur = cap_next, n = (size_t)m;
        next = t, cap_next = tc;
        if (on_level) rc = on_level(level_ctx, step, cur, n);
    }
    free(next);
    if (rc) {
        free(cur);
        return rc;
    }
    *out = cur, *out_len = n;
    return LSYS_OK;
}
