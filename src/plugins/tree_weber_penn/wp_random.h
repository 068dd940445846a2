/* wp_random.h — the random numbers of a Weber–Penn tree as Arbaro 1.9 draws them: Java's
 * java.util.Random (a 48-bit linear congruential generator; its seed scrambling, next(bits),
 * nextDouble, nextLong, nextInt) reproduced bit for bit, and Arbaro's wrapper around it
 * (uniform(low, high), and a state saved by drawing a long and reseeding with it). Holds no
 * global state: each stream is a value the caller owns. */
#ifndef WP_RANDOM_H
#define WP_RANDOM_H

#include <stdint.h>

typedef struct wp_random {
    uint64_t seed; /* the 48-bit state */
} wp_random;

/* java.util.Random(seed) and setSeed(seed): the seed scrambled with 0x5DEECE66D. */
void wp_random_seed(wp_random *r, int64_t seed);

/* next(bits): the top `bits` (1 to 32) of the stepped state, as Java's signed int. */
int32_t wp_random_next(wp_random *r, int bits);

/* nextDouble(): 53 random bits in [0, 1). */
double wp_random_double(wp_random *r);

/* nextLong(): two next(32) joined as Java joins them (the low half sign-extended). */
int64_t wp_random_long(wp_random *r);

/* nextInt(): next(32). */
int32_t wp_random_int(wp_random *r);

/* nextInt(bound), bound > 0: uniform in [0, bound) with Java's rejection of the biased tail. */
int32_t wp_random_int_below(wp_random *r, int32_t bound);

/* Arbaro's uniform(low, high): low + nextDouble() * (high - low). */
double wp_random_uniform(wp_random *r, double low, double high);

/* Arbaro's getState(): draws a long, reseeds the stream with it and returns it. */
int64_t wp_random_save(wp_random *r);

/* Arbaro's setState(state): reseeds with a state wp_random_save returned. */
void wp_random_restore(wp_random *r, int64_t state);

#endif
