/* fault_alloc.h — a fault-injecting allocator for tests. A test executable linked with
 * -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free,--wrap=strdup sends every
 * allocation made by sylva's own code (the core and command-line objects linked into it) through
 * here; libraries (libyaml, Embree, OpenImageIO, libc) allocate as usual. The allocator can fail
 * the Nth allocation and counts the blocks it handed out that are still live, so a test can run a
 * command once per possible failure and check that each failure is reported and leaks nothing. */
#ifndef SYLVA_TEST_FAULT_ALLOC_H
#define SYLVA_TEST_FAULT_ALLOC_H

#include <stddef.h>
#include <stdint.h>

/* Starts counting afresh: allocation number n (from 1) fails, and so does every later one when
 * sticky is set (a process out of memory stays so); n = 0 fails none. */
void fault_alloc_arm(uint64_t n, int sticky);

/* Allocations attempted since the last fault_alloc_arm, failed ones included. */
uint64_t fault_alloc_count(void);

/* Allocations that were failed since the last fault_alloc_arm. */
uint64_t fault_alloc_failed(void);

/* Blocks handed out through the wrappers and not yet freed. */
size_t fault_alloc_live(void);

#endif
