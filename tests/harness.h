/* harness.h — the unit-test harness: CHECK macros that print got vs. expected with file and
 * line, and a main that runs the file's tests by name (all, or the names given on the command
 * line). A test file defines its tests with TEST(name) and lists them in TEST_LIST. A test that
 * cannot run here ends with SKIP("why"); when every test that ran was skipped, the process exits
 * 77, which ctest reports as skipped (cmake/SylvaTest.cmake). */
#ifndef SYLVA_TEST_HARNESS_H
#define SYLVA_TEST_HARNESS_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/stat.h>

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

static int harness_skipped; /* set by SKIP in the running test */

/* Ends the running test as skipped, printing "skipped: " and the printf-style reason. */
#define SKIP(...)                                                                            \
    do {                                                                                     \
        fprintf(stderr, "skipped: ");                                                        \
        fprintf(stderr, __VA_ARGS__);                                                        \
        fputc('\n', stderr);                                                                 \
        harness_skipped = 1;                                                                 \
        return;                                                                              \
    } while (0)

/* The text file at path read into buf (cap bytes, NUL-terminated, cut to cap - 1): 1, or 0 when
 * it cannot be opened (buf then ""). */
static inline int harness_read_text(const char *path, char *buf, size_t cap)
{
    FILE *f = fopen(path, "rb");
    buf[0] = '\0';
    if (!f) return 0;
    size_t n = fread(buf, 1, cap - 1, f);
    fclose(f);
    buf[n] = '\0';
    return 1;
}

/* The folder SUB of the shared data (DEMs, L-parser corpus beside the clone), whose root ctest
 * passes in SYLVA_SHARED_DATA_DIR to tests registered NEEDS_SHARED_DATA; NULL when it is not
 * there. The string lives until the next call. */
static inline const char *harness_shared_data(const char *sub)
{
    static char path[4096];
    const char *root = getenv("SYLVA_SHARED_DATA_DIR");
    if (!root || !*root) return NULL;
    snprintf(path, sizeof path, "%s/%s", root, sub);
    struct stat st;
    return stat(path, &st) == 0 ? path : NULL;
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
        int ran = 0, skipped = 0;                                                            \
        for (size_t i = 0; i < sizeof harness_cases / sizeof harness_cases[0]; i++) {        \
            int want = argc < 2;                                                             \
            for (int a = 1; a < argc; a++)                                                   \
                if (!strcmp(argv[a], harness_cases[i].name)) want = 1;                       \
            if (!want) continue;                                                             \
            int before = harness_failures;                                                   \
            harness_skipped = 0;                                                             \
            harness_cases[i].fn();                                                           \
            ran++;                                                                           \
            skipped += harness_skipped && harness_failures == before;                        \
            fprintf(stderr, "%s %s\n",                                                       \
                    harness_failures != before ? "FAIL" : harness_skipped ? "skip" : "ok  ",  \
                    harness_cases[i].name);                                                  \
        }                                                                                    \
        if (!ran) {                                                                          \
            fprintf(stderr, "no test matched\n");                                            \
            return 2;                                                                        \
        }                                                                                    \
        return harness_failures ? 1 : skipped == ran ? 77 : 0;                               \
    }

#endif
