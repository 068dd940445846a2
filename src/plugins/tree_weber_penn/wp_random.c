/* wp_random.c — java.util.Random's generator and Arbaro's use of it (wp_random.h). The state
 * is kept in an unsigned 64-bit word so that the multiplication wraps as Java's long does;
 * only the low 48 bits are kept after each step. */
#include "wp_random.h"

#define JAVA_MULTIPLIER 0x5DEECE66DULL
#define JAVA_ADDEND 0xBULL
#define JAVA_MASK ((1ULL << 48) - 1)

void wp_random_seed(wp_random *r, int64_t seed)
{
    r->seed = ((uint64_t)seed ^ JAVA_MULTIPLIER) & JAVA_MASK;
}

int32_t wp_random_next(wp_random *r, int bits)
{
    r->seed = (r->seed * JAVA_MULTIPLIER + JAVA_ADDEND) & JAVA_MASK;
    /* Java's (int)(seed >>> (48 - bits)): the low 32 bits, read as signed */
    return (int32_t)(uint32_t)(r->seed >> (48 - bits));
}

double wp_random_double(wp_random *r)
{
    int64_t high = wp_random_next(r, 26);
    int64_t low = wp_random_next(r, 27);
    return (double)((high << 27) + low) * 0x1.0p-53;
}

int64_t wp_random_long(wp_random *r)
{
    int64_t high = wp_random_next(r, 32);
    int64_t low = wp_random_next(r, 32);
    return (int64_t)(((uint64_t)high << 32) + (uint64_t)low);
}

int32_t wp_random_int(wp_random *r)
{
    return wp_random_next(r, 32);
}

int32_t wp_random_int_below(wp_random *r, int32_t bound)
{
    int32_t x = wp_random_next(r, 31);
    int32_t m = bound - 1;
    if ((bound & m) == 0) return (int32_t)(((int64_t)bound * x) >> 31);
    /* Java's loop `u - (r = u % bound) + m < 0` tests for int overflow: done here in 64 bits */
    for (int32_t u = x;; u = wp_random_next(r, 31)) {
        x = u % bound;
        if ((int64_t)u - x + m <= INT32_MAX) return x;
    }
}

double wp_random_uniform(wp_random *r, double low, double high)
{
    return low + wp_random_double(r) * (high - low);
}

int64_t wp_random_save(wp_random *r)
{
    int64_t state = wp_random_long(r);
    wp_random_seed(r, state);
    return state;
}

void wp_random_restore(wp_random *r, int64_t state)
{
    wp_random_seed(r, state);
}
