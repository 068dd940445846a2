/* tree_survey_csv.c — a survey as a CSV: the first line names the columns, each later line is a
 * tree at the x and y columns the request names (in the request's CRS, or the site's), with its
 * attributes by column name. Blank lines and lines starting with '#' are skipped; each tree is
 * named by its line for messages. Read line by line (util/csv_fields.h), never more than
 * SURVEY_CSV_MAX_TREES trees. */
#include "site/tree_survey.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "util/csv_fields.h"
#include "util/file_check.h"

#define SURVEY_CSV_MAX_TREES 10000000u
#define SURVEY_CSV_MAX_COLUMNS 256u

/* Columns of the names the request reads: x, y, then the attributes; -1 when not read. */
typedef struct csv_columns {
    int x, y, value[SURVEY_N_VALUES];
} csv_columns;

static int column_of(char **field, uint32_t n, const char *name)
{
    for (uint32_t i = 0; name && i < n; i++)
        if (!strcmp(field[i], name)) return (int)i;
    return -1;
}

static int header_columns(const survey_request *rq, char **field, uint32_t n, csv_columns *c, survey_key *bad_key,
                          err_buf *err)
{
    static const survey_key value_key[SURVEY_N_VALUES] = {SURVEY_KEY_SPECIES, SURVEY_KEY_HEIGHT,
                                                          SURVEY_KEY_CROWN, SURVEY_KEY_AGE};
    const char *name[2 + SURVEY_N_VALUES] = {rq->x_field, rq->y_field};
    survey_key key[2 + SURVEY_N_VALUES] = {SURVEY_KEY_X, SURVEY_KEY_Y};
    int *col[2 + SURVEY_N_VALUES] = {&c->x, &c->y};
    for (int k = 0; k < SURVEY_N_VALUES; k++)
        name[2 + k] = rq->field[k], key[2 + k] = value_key[k], col[2 + k] = &c->value[k];
    for (int k = 0; k < 2 + SURVEY_N_VALUES; k++) {
        *col[k] = column_of(field, n, name[k]);
        if (*col[k] >= 0 || !name[k]) continue;
        char names[768] = "";
        for (uint32_t i = 0, used = 0; i < n && used + 1 < sizeof names; i++)
            used += (uint32_t)snprintf(names + used, sizeof names - used, "%s'%s'", i ? ", " : "", field[i]);
        *bad_key = key[k];
        return err_set(err, "'%s' has no column '%s'; its first line names %s", rq->shown, name[k], names);
    }
    return 0;
}

static int read_coordinate(const char *shown, uint32_t line, uint32_t column, const char *name, const char *text,
                           double *out, err_buf *err)
{
    char *end;
    errno = 0;
    *out = strtod(text, &end);
    if (!text[0] || *end || errno || !isfinite(*out))
        return err_set(err, "'%s' line %u column %u: %s '%s' is not a number; give the coordinate in metres (or "
                       "degrees for a geographic CRS)", shown, line, column, name, text);
    return 0;
}

static int read_row(arena *a, const survey_request *rq, const csv_columns *c, char **field, const uint32_t *column,
                    uint32_t n, uint32_t line, survey_point *p, err_buf *err)
{
    if ((uint32_t)(c->x > c->y ? c->x : c->y) >= n)
        return err_set(err, "'%s' line %u has %u fields, fewer than the first line's columns %s and %s", rq->shown,
                       line, n, rq->x_field, rq->y_field);
    if (read_coordinate(rq->shown, line, column[c->x], rq->x_field, field[c->x], &p->map[0], err) ||
        read_coordinate(rq->shown, line, column[c->y], rq->y_field, field[c->y], &p->map[1], err))
        return -1;
    char *feature = arena_alloc(a, 32);
    if (!feature) return err_nomem(err, "out of memory");
    snprintf(feature, 32, "line %u", line);
    p->feature = feature;
    for (int k = 0; k < SURVEY_N_VALUES; k++) {
        int i = c->value[k];
        p->value[k] = i >= 0 && (uint32_t)i < n && field[i][0] ? arena_strdup(a, field[i]) : NULL;
        if (i >= 0 && (uint32_t)i < n && field[i][0] && !p->value[k]) return err_nomem(err, "out of memory");
    }
    return 0;
}

/* One line: the header (when *have_header is 0) or a tree appended to out. */
static int read_line(arena *a, const survey_request *rq, char *text, uint32_t line, csv_columns *c,
                     int *have_header, survey_points *out, uint32_t *cap, survey_key *bad_key, err_buf *err)
{
    char *field[SURVEY_CSV_MAX_COLUMNS];
    uint32_t column[SURVEY_CSV_MAX_COLUMNS], open_quote = 0;
    uint32_t n = csv_split(text, field, column, SURVEY_CSV_MAX_COLUMNS, &open_quote);
    if (open_quote)
        return err_set(err, "'%s' line %u column %u: a double quote that does not close", rq->shown, line, open_quote);
    if (n > SURVEY_CSV_MAX_COLUMNS)
        return err_set(err, "'%s' line %u has %u fields; at most %u are read", rq->shown, line, n,
                       SURVEY_CSV_MAX_COLUMNS);
    if (!*have_header) {
        *have_header = 1;
        return header_columns(rq, field, n, c, bad_key, err);
    }
    if (out->n == SURVEY_CSV_MAX_TREES)
        return err_set(err, "'%s' holds more than %u trees; split the survey", rq->shown, SURVEY_CSV_MAX_TREES);
    if (out->n == *cap) {
        uint32_t grown = *cap ? *cap * 2 : 1024;
        survey_point *more = arena_alloc(a, (size_t)grown * sizeof *more); /* the old block stays in the arena */
        if (!more) return err_nomem(err, "out of memory for %u trees", grown);
        if (out->n) memcpy(more, out->points, (size_t)out->n * sizeof *more);
        out->points = more, *cap = grown;
    }
    return read_row(a, rq, c, field, column, n, line, &out->points[out->n++], err);
}

int survey_read_csv(arena *a, const survey_request *rq, survey_points *out, survey_key *bad_key, err_buf *err)
{
    int fd = file_open_regular(rq->path, rq->shown, err);
    if (fd < 0) return -1;
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        close(fd);
        return err_set(err, "'%s': cannot open: %s", rq->shown, strerror(errno));
    }
    out->is_csv = 1;
    csv_columns c;
    int have_header = 0, rc = 0;
    uint32_t line = 0, cap = 0;
    char *text = NULL; /* getline's buffer, freed below */
    size_t size = 0;
    for (ssize_t len; !rc && (len = getline(&text, &size, f)) >= 0;) {
        char *start = text + (line++ == 0 ? csv_bom_length(text) : 0);
        while (len > 0 && (text[len - 1] == '\n' || text[len - 1] == '\r')) text[--len] = 0;
        const char *s = start + strspn(start, " \t");
        if (!*s || *s == '#') continue;
        rc = read_line(a, rq, start, line, &c, &have_header, out, &cap, bad_key, err);
    }
    if (!rc && ferror(f)) rc = err_set(err, "'%s': cannot read: %s", rq->shown, strerror(errno));
    if (!rc && !have_header)
        rc = err_set(err, "'%s' is empty; its first line names the columns (%s, %s, ...)", rq->shown, rq->x_field,
                     rq->y_field);
    free(text);
    fclose(f);
    return rc;
}
