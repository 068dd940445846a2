/* wp_pool.h — a growing array of fixed-size records that never move once made (kept in blocks
 * of 4096), so that a stem being grown can hold a pointer to its own record while its children
 * are appended; records are found by their index and dropped from the end (a pruning test's
 * trial stems and segments). */
#ifndef WP_POOL_H
#define WP_POOL_H

#include <stddef.h>

#define WP_POOL_BLOCK 4096

typedef struct wp_pool {
    size_t size;     /* bytes per record */
    size_t count;    /* records in use */
    void **block;    /* owned; n_blocks blocks of WP_POOL_BLOCK records, each owned */
    size_t n_blocks, cap_blocks;
} wp_pool;

/* An empty pool of records of `size` bytes. */
void wp_pool_init(wp_pool *p, size_t size);

/* A new zeroed record at index p->count (then count + 1), or NULL when memory is short. */
void *wp_pool_push(wp_pool *p);

/* The record at index i < count. */
static inline void *wp_pool_at(const wp_pool *p, size_t i)
{
    return (char *)p->block[i / WP_POOL_BLOCK] + (i % WP_POOL_BLOCK) * p->size;
}

/* Drops the records from index n on (n <= count); their memory is kept for reuse. */
void wp_pool_truncate(wp_pool *p, size_t n);

/* Frees every block and empties the pool. */
void wp_pool_free(wp_pool *p);

#endif
