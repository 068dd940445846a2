/* harness.h — the unit-test harness: CHECK macros that print got vs. expected with file and
 * line, and a main that runs the file's tests by name (all, or the names given on the command
 * line). A test file defines its tests with TEST(name) and lists them in TEST_LIST. */
#ifndef SYLVA_TEST_HARNESS_H
#define SYLVA_TEST_HARNESS_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static int harness_failures;

#define TEST(name) static void test_##name(void)
#define CHECK(cond)                                                                          \
    do {                                                                                     \
        if (!(cond)) {                                                                       \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);         \
            harness_failures++;                                                              \
        }                                                                                    \
    } while (0)
#define CHECK_NEAR(got, want, tol)                                                           \
    do {                                                                                     \
        double g_ = (double)(got), w_ = (double)(want);                                      \
        if (!(fabs(g_ - w_) <= (tol))) {                                                     \
            fprintf(stderr, "%s:%d: %s = %.9g, expected %.9g (tolerance %g)\n", __FILE__,     \
                    __LINE__, #got, g_, w_, (double)(tol));                                  \
            harness_failures++;                                                              \
        }                                                                                    \
    } while (0)
#define CHECK_INT(got, want)                                                                 \
    do {                                                                                     \
        long long g_ = (long long)(got), w_ = (long long)(want);                             \
        if (g_ != w_) {                                                                      \
            fprintf(stderr, "%s:%d: %s = %lld, expected %lld\n", __FILE__, __LINE__, #got,   \
                    g_, w_);                                                                 \
            harness_failures++;                                                              \
        }                                                                                    \
    } while (0)
#define CHECK_STR_CONTAINS(hay, needle)                                                      \
    do {                                                                                     \
        const char *h_ = (hay), *n_ = (needle);                                              \
        if (!h_ || !strstr(h_, n_)) {                                                        \
            fprintf(stderr, "%s:%d: \"%s\" does not contain \"%s\"\n", __FILE__, __LINE__,   \
                    h_ ? h_ : "(null)", n_);                                                 \
            harness_failures++;                                                              \
        }                                                                                    \
    } while (0)

/* Seconds on a monotonic clock, for checks that something ends in time. */
static inline double harness_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

typedef struct harness_case {
    const char *name;
    void (*fn)(void);
} harness_case;

#define TEST_CASE(name) {#name, test_##name}
#define TEST_LIST(...)                                                                       \
    static const harness_case harness_cases[] = {__VA_ARGS__};                               \
    int main(int argc, char **argv)                                                          \
    {                                                                                        \
        int ran = 0;                                                                         \
        for (size_t i = 0; i < sizeof harness_cases / sizeof harness_cases[0]; i++) {        \
            int want = argc < 2;                                                             \
            for (int a = 1; a < argc; a++)                                                   \
                if (!strcmp(argv[a], harness_cases[i].name)) want = 1;                       \
            if (!want) continue;                                                             \
            int before = harness_failures;                                                   \
            harness_cases[i].fn();                                                           \
            ran++;                                                                           \
            fprintf(stderr, "%s %s\n", harness_failures == before ? "ok  " : "FAIL",          \
                    harness_cases[i].name);                                                  \
        }                                                                                    \
        if (!ran) {                                                                          \
            fprintf(stderr, "no test matched\n");                                            \
            return 2;                                                                        \
        }                                                                                    \
        return harness_failures ? 1 : 0;                                                     \
    }

#endif
