/* branch_law.c — 002 eq. 6, counting branches in a derived string, choosing a level. */
#include "branch_law.h"

#include <math.h>
#include <stdlib.h>

#include "lsys_symbols.h"

double branch_law_count(double n1, double h1, double h2, double d) { return n1 * pow(h1 / h2, -d / 2.0); }

int branch_count(const unsigned char *s, size_t n, uint64_t *count, plugin_err *err)
{
    *count = 0;
    /* A stack of one flag per open bracket: "this block drew wood itself"; drew[0] is the main
     * axis. Wood inside a nested block belongs to that block, not to its parent. */
    size_t cap = 256, depth = 0;
    uint8_t *drew = calloc(cap, 1); /* owned here */
    if (!drew) return plugin_fail(err, LSYS_ERR_NOMEM, "out of memory counting the branches");
    uint64_t found = 0;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = s[i];
        if (c == '(') {
            size_t g = lsys_arg_group(s + i, n - i, NULL);
            if (g) i += g - 1;
        } else if (c == 'F' || c == 'Z') {
            drew[depth] = 1;
        } else if (c == '[') {
            if (depth + 1 == cap) {
                uint8_t *g = realloc(drew, cap * 2);
                if (!g) {
                    free(drew);
                    return plugin_fail(err, LSYS_ERR_NOMEM, "out of memory counting the branches of %zu nested "
                                     "'[' blocks", depth + 1);
                }
                drew = g, cap *= 2;
            }
            drew[++depth] = 0;
        } else if (c == ']' && depth) {
            found += drew[depth--];
        }
    }
    for (; depth; depth--) found += drew[depth];
    found += drew[0];
    free(drew);
    *count = found;
    return LSYS_OK;
}

uint32_t branch_law_level(const uint64_t *branches, uint32_t levels, double target)
{
    uint32_t best = levels ? levels - 1 : 0;
    double best_d = INFINITY;
    double lt = log(target > 0 ? target : 1.0);
    for (uint32_t r = 0; r < levels; r++) {
        double d = branches[r] ? fabs(log((double)branches[r]) - lt) : INFINITY;
        if (d <= best_d) best = r, best_d = d; /* ascending r: a tie goes to the higher level */
    }
    return best;
}
