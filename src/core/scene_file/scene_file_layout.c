/* scene_file_layout.c — a layout: a CSV file of placements (one object per row) that an
 * objects entry with `layout:` names. The first line names the columns: `id`, `easting` and
 * `northing` (map coordinates: local = map - site origin) or `x` and `y` (local metres), and
 * optionally `heading` (degrees clockwise from north) and `height_above_ground` (metres).
 * Blank lines and lines starting with '#' are skipped; a field may be wrapped in double quotes.
 * Every problem is reported at file:line:column of the CSV. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "scene_file/scene_file_loader.h"
#include "util/csv_fields.h"
#include "util/file_check.h"

#define LAYOUT_MAX_BYTES (64u << 20)
#define LAYOUT_MAX_ROWS 1000000u
#define LAYOUT_MAX_FIELDS 32u

enum { COL_ID, COL_EASTING, COL_NORTHING, COL_X, COL_Y, COL_HEADING, COL_HEIGHT, COL_COUNT };
static const char *const column_names[COL_COUNT] = {"id", "easting", "northing", "x", "y", "heading",
                                                    "height_above_ground"};

/* The file, whole, NUL-terminated, in the arena; NULL with L->err set. */
static char *read_whole(loader *L, const char *path, const char *shown, size_t *len)
{
    int fd = file_open_regular(path, shown, L->err);
    if (fd < 0) return NULL;
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        close(fd);
        err_set(L->err, "%s: cannot open: %s", shown, strerror(errno));
        return NULL;
    }
    char *buf = NULL;
    if (fseek(f, 0, SEEK_END) == 0) {
        long size = ftell(f);
        if (size < 0 || (unsigned long)size > LAYOUT_MAX_BYTES) {
            err_set(L->err, "%s: the layout is larger than %u MiB; split it into several layouts", shown,
                    LAYOUT_MAX_BYTES >> 20);
        } else if (fseek(f, 0, SEEK_SET) == 0 && (buf = arena_alloc(L->a, (size_t)size + 1))) {
            *len = fread(buf, 1, (size_t)size, f);
            if (ferror(f)) err_set(L->err, "%s: cannot read: %s", shown, strerror(errno)), buf = NULL;
            else buf[*len] = 0;
        } else if (!L->err->msg[0]) {
            sf_out_of_memory(L);
        }
    } else {
        err_set(L->err, "%s: cannot read: %s", shown, strerror(errno));
    }
    fclose(f);
    return buf;
}

static int read_number(loader *L, const char *shown, uint32_t line, uint32_t column, const char *name,
                       const char *text, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (!*text || *end || !isfinite(v))
        return sf_located(L->err, shown, line, column, "'%s' must be a finite number, got '%s'", name, text);
    *out = v;
    return 0;
}

/* Maps the header's names to columns; *where[c] is the field index of column c or -1. */
static int read_header(loader *L, const char *shown, uint32_t line, char **field, const uint32_t *column,
                       uint32_t n, int where[COL_COUNT])
{
    for (int c = 0; c < COL_COUNT; c++) where[c] = -1;
    for (uint32_t i = 0; i < n; i++) {
        int c = 0;
        while (c < COL_COUNT && strcasecmp(field[i], column_names[c])) c++;
        if (c == COL_COUNT)
            return sf_located(L->err, shown, line, column[i],
                              "unknown column '%s'; the columns are id, easting and northing (or x and y), "
                              "heading, height_above_ground", field[i]);
        if (where[c] >= 0)
            return sf_located(L->err, shown, line, column[i], "column '%s' appears twice", column_names[c]);
        where[c] = (int)i;
    }
    int map = where[COL_EASTING] >= 0 || where[COL_NORTHING] >= 0, local = where[COL_X] >= 0 || where[COL_Y] >= 0;
    if (where[COL_ID] < 0 || map == local || (map && (where[COL_EASTING] < 0 || where[COL_NORTHING] < 0)) ||
        (local && (where[COL_X] < 0 || where[COL_Y] < 0)))
        return sf_located(L->err, shown, line, 1,
                          "the first line must name the columns: id, then easting and northing (map "
                          "coordinates) or x and y (local metres), optionally heading and "
                          "height_above_ground");
    return 0;
}

int sf_read_layout(loader *L, const char *path, const char *shown, layout_row **rows_out, uint32_t *n_out)
{
    size_t len = 0;
    char *text = read_whole(L, path, shown, &len);
    if (!text) return -1;
    if (memchr(text, 0, len))
        return sf_located(L->err, shown, 1, 1, "the layout holds a NUL byte; it must be a text CSV file");
    uint32_t cap = 0;
    for (size_t i = 0; i < len; i++) cap += text[i] == '\n';
    layout_row *rows = arena_alloc(L->a, ((size_t)cap + 1) * sizeof *rows);
    if (!rows) return sf_out_of_memory(L);
    int where[COL_COUNT], have_header = 0;
    uint32_t n = 0, line = 0;
    char *field[LAYOUT_MAX_FIELDS];
    uint32_t column[LAYOUT_MAX_FIELDS];
    for (char *p = text + csv_bom_length(text); p && *p;) {
        char *nl = strchr(p, '\n');
        if (nl) *nl = 0;
        char *cur = p;
        p = nl ? nl + 1 : NULL;
        line++;
        const char *q = cur;
        while (*q == ' ' || *q == '\t' || *q == '\r') q++;
        if (!*q || *q == '#') continue;
        uint32_t open_quote;
        uint32_t nf = csv_split(cur, field, column, LAYOUT_MAX_FIELDS, &open_quote);
        if (open_quote)
            return sf_located(L->err, shown, line, open_quote, "this field opens a double quote that is not "
                              "closed; close it before the next comma or the end of the line (a field cannot "
                              "hold a comma)");
        if (nf > LAYOUT_MAX_FIELDS)
            return sf_located(L->err, shown, line, 1, "%u fields; a layout line has at most %u", nf,
                              LAYOUT_MAX_FIELDS);
        if (!have_header) {
            if (read_header(L, shown, line, field, column, nf, where)) return -1;
            have_header = 1;
            continue;
        }
        if (n >= LAYOUT_MAX_ROWS)
            return sf_located(L->err, shown, line, 1, "more than %u placements in one layout", LAYOUT_MAX_ROWS);
        int expected = 0;
        for (int c = 0; c < COL_COUNT; c++) expected += where[c] >= 0;
        if (nf != (uint32_t)expected)
            return sf_located(L->err, shown, line, 1, "%u fields, but the first line names %d columns", nf,
                              expected);
        layout_row *r = &rows[n];
        *r = (layout_row){.line = line};
        const char *id = field[where[COL_ID]];
        if (!*id) return sf_located(L->err, shown, line, column[where[COL_ID]], "'id' is empty; name the placement");
        if (!(r->id = arena_strdup(L->a, id))) return sf_out_of_memory(L);
        int map = where[COL_EASTING] >= 0;
        int cx = map ? COL_EASTING : COL_X, cy = map ? COL_NORTHING : COL_Y;
        if (read_number(L, shown, line, column[where[cx]], column_names[cx], field[where[cx]], &r->xy[0]) ||
            read_number(L, shown, line, column[where[cy]], column_names[cy], field[where[cy]], &r->xy[1]))
            return -1;
        if (map) r->xy[0] -= L->sf->site.origin[0], r->xy[1] -= L->sf->site.origin[1];
        if (where[COL_HEADING] >= 0 && *field[where[COL_HEADING]]) {
            if (read_number(L, shown, line, column[where[COL_HEADING]], "heading", field[where[COL_HEADING]],
                            &r->heading_deg))
                return -1;
            if (fabs(r->heading_deg) > 360)
                return sf_located(L->err, shown, line, column[where[COL_HEADING]],
                                  "'heading' must be in [-360, 360] degrees, got %g", r->heading_deg);
            r->has_heading = 1;
        }
        if (where[COL_HEIGHT] >= 0 && *field[where[COL_HEIGHT]]) {
            if (read_number(L, shown, line, column[where[COL_HEIGHT]], "height_above_ground",
                            field[where[COL_HEIGHT]], &r->height_above_ground))
                return -1;
            r->has_height = 1;
        }
        n++;
    }
    if (!have_header)
        return sf_located(L->err, shown, 1, 1, "the layout is empty; its first line names the columns (id, "
                          "easting, northing, ...)");
    *rows_out = rows, *n_out = n;
    return 0;
}
