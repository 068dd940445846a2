/* wp_pool.c — blocks of records that stay in place (wp_pool.h). */
#include "wp_pool.h"

#include <stdlib.h>
#include <string.h>

void wp_pool_init(wp_pool *p, size_t size)
{
    memset(p, 0, sizeof *p);
    p->size = size;
}

void *wp_pool_push(wp_pool *p)
{
    size_t b = p->count / WP_POOL_BLOCK;
    if (b == p->n_blocks) {
        if (p->n_blocks == p->cap_blocks) {
            size_t cap = p->cap_blocks ? 2 * p->cap_blocks : 16;
            void **grown = realloc(p->block, cap * sizeof *grown); /* owned by p */
            if (!grown) return NULL;
            p->block = grown;
            p->cap_blocks = cap;
        }
        p->block[b] = malloc(WP_POOL_BLOCK * p->size); /* owned by p */
        if (!p->block[b]) return NULL;
        p->n_blocks++;
    }
    void *rec = wp_pool_at(p, p->count++);
    memset(rec, 0, p->size);
    return rec;
}

void wp_pool_truncate(wp_pool *p, size_t n)
{
    if (n < p->count) p->count = n;
}

void wp_pool_free(wp_pool *p)
{
    for (size_t i = 0; i < p->n_blocks; i++) free(p->block[i]);
    free(p->block);
    size_t size = p->size;
    memset(p, 0, sizeof *p);
    p->size = size;
}
