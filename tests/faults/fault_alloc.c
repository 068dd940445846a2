/* fault_alloc.c — the --wrap allocation functions behind fault_alloc.h. Live blocks are kept in
 * an open-addressing set of addresses (static storage, so the bookkeeping allocates nothing);
 * a free of an address the set does not hold (a block a library allocated) is passed on as is. */
#include "fault_alloc.h"

#include <execinfo.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void *__real_malloc(size_t n);
void *__real_calloc(size_t k, size_t n);
void *__real_realloc(void *p, size_t n);
void __real_free(void *p);

#define SLOTS (1u << 20) /* a power of two, well above the live blocks of a test scene */
#define TOMB ((uintptr_t)1)

static uintptr_t slots[SLOTS]; /* 0 empty, TOMB removed, else a live address */
static size_t live;
static uint64_t attempts, failures, fail_at;
static int sticky_failure;
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;

static size_t slot_of(uintptr_t a)
{
    uint64_t h = (uint64_t)a * 0x9E3779B97F4A7C15ull;
    return (size_t)(h >> 44) & (SLOTS - 1);
}

static void set_add(void *p)
{
    uintptr_t a = (uintptr_t)p;
    for (size_t i = slot_of(a), k = 0; k < SLOTS; i = (i + 1) & (SLOTS - 1), k++)
        if (slots[i] == 0 || slots[i] == TOMB) {
            slots[i] = a;
            live++;
            return;
        }
    fprintf(stderr, "fault_alloc: more than %u live blocks\n", SLOTS);
    abort();
}

/* 1 when p was in the set (and is now removed). */
static int set_remove(void *p)
{
    uintptr_t a = (uintptr_t)p;
    for (size_t i = slot_of(a), k = 0; k < SLOTS && slots[i] != 0; i = (i + 1) & (SLOTS - 1), k++)
        if (slots[i] == a) {
            slots[i] = TOMB;
            live--;
            return 1;
        }
    return 0;
}

/* Counts one allocation attempt; 1 when it is to fail. Called with the lock held. With
 * FAULT_ALLOC_TRACE set in the environment the first failed allocation prints its call stack on
 * stderr (addresses resolve with addr2line -f -e EXECUTABLE). */
static int should_fail(void)
{
    attempts++;
    if (fail_at && (attempts == fail_at || (sticky_failure && attempts > fail_at))) {
        if (!failures++ && getenv("FAULT_ALLOC_TRACE")) {
            void *frames[32];
            backtrace_symbols_fd(frames, backtrace(frames, 32), 2);
        }
        return 1;
    }
    return 0;
}

void fault_alloc_arm(uint64_t n, int sticky)
{
    pthread_mutex_lock(&lock);
    attempts = failures = 0;
    fail_at = n;
    sticky_failure = sticky;
    pthread_mutex_unlock(&lock);
}

uint64_t fault_alloc_count(void)
{
    pthread_mutex_lock(&lock);
    uint64_t n = attempts;
    pthread_mutex_unlock(&lock);
    return n;
}

uint64_t fault_alloc_failed(void)
{
    pthread_mutex_lock(&lock);
    uint64_t n = failures;
    pthread_mutex_unlock(&lock);
    return n;
}

size_t fault_alloc_live(void)
{
    pthread_mutex_lock(&lock);
    size_t n = live;
    pthread_mutex_unlock(&lock);
    return n;
}

void *__wrap_malloc(size_t n)
{
    pthread_mutex_lock(&lock);
    void *p = should_fail() ? NULL : __real_malloc(n);
    if (p) set_add(p);
    pthread_mutex_unlock(&lock);
    return p;
}

void *__wrap_calloc(size_t k, size_t n)
{
    pthread_mutex_lock(&lock);
    void *p = should_fail() ? NULL : __real_calloc(k, n);
    if (p) set_add(p);
    pthread_mutex_unlock(&lock);
    return p;
}

void *__wrap_realloc(void *old, size_t n)
{
    pthread_mutex_lock(&lock);
    void *p = NULL;
    if (old && n == 0) { /* glibc frees the block and returns NULL */
        set_remove(old);
        __real_realloc(old, 0);
    } else if (!should_fail()) {
        p = __real_realloc(old, n);
        if (p) {
            if (old) set_remove(old);
            set_add(p);
        }
    }
    pthread_mutex_unlock(&lock);
    return p;
}

void __wrap_free(void *p)
{
    if (!p) return;
    pthread_mutex_lock(&lock);
    set_remove(p);
    __real_free(p);
    pthread_mutex_unlock(&lock);
}

char *__wrap_strdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = __wrap_malloc(n);
    if (p) memcpy(p, s, n);
    return p;
}
