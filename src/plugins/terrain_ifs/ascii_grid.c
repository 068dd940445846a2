/* ascii_grid.c — one streaming pass over an ESRI ASCII grid: header, then the value count. */
#include "ascii_grid.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "sylva/plugin.h"

#define WORD_MAX 64 /* longer words are not numbers a grid holds */

typedef struct word_reader {
    FILE *f;
    char buf[1 << 16];
    size_t len, pos;
    uint64_t line;      /* 1-based line of the last word read */
    uint64_t column;    /* 1-based column (byte) where the last word read starts */
    uint64_t at_column; /* the column of the next byte */
} word_reader;

/* The next whitespace-separated word into w (cut at WORD_MAX - 1 bytes; *long_word set); 0 at
 * the end of the file. */
static int next_word(word_reader *r, char w[WORD_MAX], int *long_word)
{
    size_t n = 0;
    int in_word = 0;
    *long_word = 0;
    for (;;) {
        if (r->pos == r->len) {
            r->len = fread(r->buf, 1, sizeof r->buf, r->f);
            r->pos = 0;
            if (r->len == 0) break;
        }
        char c = r->buf[r->pos];
        int space = c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
        if (space && in_word) break;
        r->pos++;
        r->at_column++;
        if (c == '\n') r->line++, r->at_column = 1;
        if (space) continue;
        if (!in_word) r->column = r->at_column - 1;
        in_word = 1;
        if (n < WORD_MAX - 1) w[n++] = c;
        else *long_word = 1;
    }
    w[n] = '\0';
    return in_word;
}

static int is_number(const char *w)
{
    char *end;
    errno = 0;
    (void)strtod(w, &end);
    return end != w && *end == '\0';
}

/* A header keyword: a word starting with a letter that is not a number ("nan" and "inf" are). */
static int is_keyword(const char *w)
{
    return ((w[0] >= 'a' && w[0] <= 'z') || (w[0] >= 'A' && w[0] <= 'Z')) && !is_number(w);
}

/* A non-finite value stands for a cell without height only when NODATA_value is that value. */
static int is_nodata(double v, int has_nodata, double nodata)
{
    return has_nodata && ((isnan(v) && isnan(nodata)) || v == nodata);
}

int ifs_ascii_grid_check(const char *path, const char *what, plugin_err *err)
{
    FILE *f = fopen(path, "rb");
    if (!f) return SYLVA_OK; /* the reader reports it */
    word_reader *r = malloc(sizeof *r); /* owned here: the read buffer */
    if (!r) {
        fclose(f);
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory checking the %s '%s'", what, path);
    }
    r->f = f, r->len = r->pos = 0, r->line = 1, r->column = 1, r->at_column = 1;
    char w[WORD_MAX];
    int long_word, rc = SYLVA_OK;
    uint64_t cols = 0, rows = 0;
    int has_nodata = 0;
    double nodata = 0;
    if (!next_word(r, w, &long_word) || strcasecmp(w, "ncols")) goto done; /* not a grid */
    /* header: "key value" pairs while the word starts with a letter */
    int have_key = 1;
    for (;;) {
        if (have_key) {
            char key[WORD_MAX];
            memcpy(key, w, sizeof key);
            if (!next_word(r, w, &long_word) || !is_number(w)) {
                rc = plugin_fail(err, SYLVA_ERR_IO, "the %s '%s' is an ESRI ASCII grid whose header "
                              "line %llu has no number after its keyword", what, path,
                              (unsigned long long)r->line);
                goto done;
            }
            double v = strtod(w, NULL);
            if (!strcasecmp(key, "ncols")) cols = v >= 1 && v <= 1e9 ? (uint64_t)v : 0;
            if (!strcasecmp(key, "nrows")) rows = v >= 1 && v <= 1e9 ? (uint64_t)v : 0;
            if (!strcasecmp(key, "nodata_value")) has_nodata = 1, nodata = v;
            if ((!strcasecmp(key, "cellsize") || !strcasecmp(key, "dx") || !strcasecmp(key, "dy")) &&
                !(v > 0 && isfinite(v))) {
                rc = plugin_fail(err, SYLVA_ERR_IO, "%s:%llu:%llu: the %s is an ESRI ASCII grid whose %s is %g; "
                              "the size of a cell must be a positive number of the grid's units",
                              path, (unsigned long long)r->line, (unsigned long long)r->column, what, key, v);
                goto done;
            }
        }
        if (!next_word(r, w, &long_word)) break;
        have_key = is_keyword(w);
        if (have_key) continue;
        break;
    }
    if (!cols || !rows) {
        rc = plugin_fail(err, SYLVA_ERR_IO, "the %s '%s' is an ESRI ASCII grid without a valid ncols "
                      "and nrows (whole numbers from 1) in its header", what, path);
        goto done;
    }
    uint64_t want = cols * rows, got = 0;
    int more = w[0] != '\0' && !have_key;
    while (more) {
        if (long_word || !is_number(w)) {
            rc = plugin_fail(err, SYLVA_ERR_IO, "the %s '%s' is an ESRI ASCII grid whose value %llu "
                          "(row %llu, column %llu, on line %llu) is not a number", what, path,
                          (unsigned long long)got + 1, (unsigned long long)(got / cols) + 1,
                          (unsigned long long)(got % cols) + 1, (unsigned long long)r->line);
            goto done;
        }
        double v = strtod(w, NULL);
        if (!isfinite(v) && !is_nodata(v, has_nodata, nodata)) {
            rc = plugin_fail(err, SYLVA_ERR_IO, "%s:%llu:%llu: the %s is an ESRI ASCII grid whose value %llu (row "
                          "%llu, column %llu) is not a finite number (NaN or infinity); give every height as "
                          "a number, or mark cells without one by the grid's NODATA_value%s",
                          path, (unsigned long long)r->line, (unsigned long long)r->column, what,
                          (unsigned long long)got + 1, (unsigned long long)(got / cols) + 1,
                          (unsigned long long)(got % cols) + 1,
                          has_nodata ? "" : " (the header declares none)");
            goto done;
        }
        if (++got > want) break;
        more = next_word(r, w, &long_word);
    }
    if (got != want)
        rc = plugin_fail(err, SYLVA_ERR_IO, "the %s '%s' is an ESRI ASCII grid of %llu x %llu values "
                      "but holds %s%llu: it is %s; give the whole grid", what, path,
                      (unsigned long long)cols, (unsigned long long)rows,
                      got > want ? "more than " : "", (unsigned long long)(got > want ? want : got),
                      got > want ? "longer than its header says" : "truncated");
done:
    fclose(f);
    free(r);
    return rc;
}
