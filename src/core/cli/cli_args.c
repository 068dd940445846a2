/* cli_args.c — number and size parsing for the command line, the scene argument and a scene
 * file's stem. */
#include "cli/cli_args.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


int cli_parse_u64(const char *cmd, const char *opt, const char *s, uint64_t lo, uint64_t hi, uint64_t *out)
{
    char *end;
    errno = 0;
    unsigned long long v = s && *s != '-' ? strtoull(s, &end, 10) : 0;
    if (!s || *s == '-' || !*s || *end || errno || v < lo || v > hi) {
        fprintf(stderr, "sylva %s: %s expects a whole number from %" PRIu64 " to %" PRIu64 ", got '%s'\n", cmd, opt,
                lo, hi, s ? s : "");
        return -1;
    }
    *out = v;
    return 0;
}

/* One side of WIDTHxHEIGHT: decimal digits only, read without wrapping. Sets *end past them. */
static int parse_side(const char *s, const char **end, uint64_t *v)
{
    *v = 0;
    const char *c = s;
    for (; *c >= '0' && *c <= '9'; c++)
        if (*v <= UINT64_MAX / 100) *v = *v * 10 + (uint64_t)(*c - '0'); /* past 1e17 it only grows */
    *end = c;
    return c == s ? -1 : 0;
}

int cli_parse_size(const char *cmd, const char *opt, const char *s, uint32_t *w, uint32_t *h)
{
    uint64_t a = 0, b = 0;
    const char *c = s;
    int bad = !s || parse_side(c, &c, &a) || *c != 'x' || parse_side(c + 1, &c, &b) || *c;
    if (bad || a < 1 || b < 1 || a > CLI_SIZE_MAX || b > CLI_SIZE_MAX) {
        fprintf(stderr, "sylva %s: %s expects WIDTHxHEIGHT with each side a whole number from 1 to %u, got '%s'\n",
                cmd, opt, CLI_SIZE_MAX, s ? s : "");
        return -1;
    }
    *w = (uint32_t)a, *h = (uint32_t)b;
    return 0;
}

int cli_scene_argument(const char *cmd, const char *arg, const char **scene_path)
{
    if (arg[0] == '-') {
        fprintf(stderr, "sylva %s: unknown option '%s' (see sylva %s --help)\n", cmd, arg, cmd);
        return -1;
    }
    if (*scene_path) {
        fprintf(stderr, "sylva %s: one scene file only; '%s' is extra\n", cmd, arg);
        return -1;
    }
    *scene_path = arg;
    return 0;
}

int cli_scene_stem(const char *scene_path, const char *prefix, const char *suffix, char *out, size_t n)
{
    const char *slash = strrchr(scene_path, '/');
    const char *name = slash ? slash + 1 : scene_path;
    const char *dot = strrchr(name, '.');
    size_t l = dot && dot != name ? (size_t)(dot - name) : strlen(name);
    return (size_t)snprintf(out, n, "%s%.*s%s", prefix, (int)l, name, suffix) >= n ? -1 : 0;
}
