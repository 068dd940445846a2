/* interleave.h — work split between parts by turns: part p of P takes items p, p + P, p + 2P, ...
 * (the renderer's tile rows and the ZTV grid's rows between MPI ranks). */
#ifndef SYLVA_INTERLEAVE_H
#define SYLVA_INTERLEAVE_H

#include <stdint.h>

/* How many of the items 0 .. n-1 part `part` of `parts` takes. */
static inline uint32_t interleave_count(uint32_t n, uint32_t part, uint32_t parts)
{
    return part < n ? (n - part + parts - 1) / parts : 0;
}

#endif
