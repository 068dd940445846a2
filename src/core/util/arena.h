/* arena.h — a bump allocator for data that lives and dies together (a loaded scene file).
 * Blocks are malloc'ed as needed and released all at once by arena_free. Allocation failure
 * returns NULL; callers report it. */
#ifndef SYLVA_ARENA_H
#define SYLVA_ARENA_H

#include <stddef.h>

typedef struct arena arena;

arena *arena_new(void);                 /* NULL when out of memory; free with arena_free */
void arena_free(arena *a);              /* accepts NULL */
void *arena_alloc(arena *a, size_t n);  /* zeroed, 16-byte aligned; NULL on failure */
char *arena_strdup(arena *a, const char *s);
char *arena_strndup(arena *a, const char *s, size_t n);

#endif
