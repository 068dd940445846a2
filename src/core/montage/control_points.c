/* control_points.c — reading a control-point file, CSV or ImGRAFT's text (control_points.h). The
 * file is read whole (up to CONTROL_POINTS_MAX_BYTES) into the set's arena and split in place. */
#include "montage/control_points.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "util/arena.h"
#include "util/csv_fields.h"
#include "util/file_check.h"

#define CONTROL_POINTS_MAX_BYTES (16u << 20)
#define CSV_MAX_FIELDS 16u

enum { COL_ID, COL_U, COL_V, COL_EASTING, COL_NORTHING, COL_HEIGHT, COL_X, COL_Y, COL_Z, COL_COUNT };
static const char *const column_names[COL_COUNT] = {"id", "u", "v", "easting", "northing", "height", "x", "y", "z"};

typedef struct reader {
    const char *shown;
    err_buf *err;
    control_points *cp;
} reader;

static int located(reader *R, uint32_t line, uint32_t column, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static int located(reader *R, uint32_t line, uint32_t column, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    err_vat(R->err, ERR_INPUT, R->shown, line, column, fmt, ap);
    va_end(ap);
    return -1;
}

/* The file, whole and NUL-terminated, in a; NULL with err set. */
static char *read_whole(reader *R, const char *path, arena *a, size_t *len)
{
    int fd = file_open_regular(path, R->shown, R->err);
    if (fd < 0) return NULL;
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        close(fd);
        err_fail(R->err, ERR_INPUT, "%s: cannot open: %s", R->shown, strerror(errno));
        return NULL;
    }
    char *buf = NULL;
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (size < 0 || fseek(f, 0, SEEK_SET) != 0) {
        err_fail(R->err, ERR_INPUT, "%s: cannot read: %s", R->shown, strerror(errno));
    } else if ((unsigned long)size > CONTROL_POINTS_MAX_BYTES) {
        err_fail(R->err, ERR_LIMIT, "%s: the control-point file is larger than %u MiB", R->shown,
                 CONTROL_POINTS_MAX_BYTES >> 20);
    } else if (!(buf = arena_alloc(a, (size_t)size + 1))) {
        err_nomem(R->err, "%s: out of memory reading the control points", R->shown);
    } else {
        *len = fread(buf, 1, (size_t)size, f);
        if (ferror(f)) err_fail(R->err, ERR_INPUT, "%s: cannot read: %s", R->shown, strerror(errno)), buf = NULL;
        else buf[*len] = 0;
    }
    fclose(f);
    return buf;
}

/* Length of the decimal number at s ([sign] digits [. digits] [e [sign] digits], at least one
 * digit before the exponent); 0 when s does not start with one. */
static size_t number_length(const char *s, int signed_ok)
{
    size_t i = 0, digits = 0;
    if (signed_ok && (s[i] == '+' || s[i] == '-')) i++;
    while (s[i] >= '0' && s[i] <= '9') i++, digits++;
    if (s[i] == '.') {
        i++;
        while (s[i] >= '0' && s[i] <= '9') i++, digits++;
    }
    if (!digits) return 0;
    if (s[i] == 'e' || s[i] == 'E') {
        size_t j = i + 1;
        if (s[j] == '+' || s[j] == '-') j++;
        if (s[j] >= '0' && s[j] <= '9') {
            while (s[j] >= '0' && s[j] <= '9') j++;
            i = j;
        }
    }
    return i;
}

static double number_at(const char *s, size_t n)
{
    char buf[64];
    if (n >= sizeof buf) return NAN;
    memcpy(buf, s, n);
    buf[n] = 0;
    return strtod(buf, NULL);
}

/* text as a number, or (sums) as numbers joined by + and -: 0, or -1 with the error at column. */
static int read_number(reader *R, uint32_t line, uint32_t column, const char *name, const char *text, int sums,
                       double *out)
{
    size_t i = 0, n = number_length(text, 1);
    double v = n ? number_at(text, n) : NAN;
    i = n;
    while (n && sums && (text[i] == '+' || text[i] == '-')) {
        int minus = text[i] == '-';
        size_t m = number_length(text + i + 1, 0);
        if (!m) { n = 0; break; }
        double t = number_at(text + i + 1, m);
        v = minus ? v - t : v + t;
        i += 1 + m;
    }
    if (!n || text[i] || !isfinite(v))
        return located(R, line, column, "'%s' must be a finite number%s, got '%s'", name,
                       sums ? " (or numbers joined by + and -, as 1951+9)" : "", text);
    *out = v;
    return 0;
}

static control_point *add_point(reader *R, uint32_t line)
{
    control_points *cp = R->cp;
    control_point *p = &cp->points[cp->n];
    *p = (control_point){.line = line};
    char number[16];
    snprintf(number, sizeof number, "%u", cp->n + 1);
    if (!(p->id = arena_strdup(cp->arena, number))) return NULL;
    cp->n++;
    return p;
}

/* One line of ImGRAFT's text: X Y Z U V, whitespace-separated (the comment already cut off). */
static int read_imgraft_line(reader *R, char *text, uint32_t line)
{
    static const char *const names[5] = {"X", "Y", "Z", "U", "V"};
    char *field[5];
    uint32_t column[5], nf = 0;
    for (char *p = text;;) {
        while (*p == ' ' || *p == '\t' || *p == '\r') p++;
        if (!*p) break;
        if (nf == 5)
            return located(R, line, (uint32_t)(p - text) + 1,
                           "more than 5 columns; a line holds X Y Z (map metres) and U V (pixels)");
        field[nf] = p, column[nf] = (uint32_t)(p - text) + 1, nf++;
        while (*p && *p != ' ' && *p != '\t' && *p != '\r') p++;
        if (*p) *p++ = 0;
    }
    if (nf < 5)
        return located(R, line, 1, "%u columns; a line holds 5: X Y Z (map metres) and U V (pixels)", nf);
    if (strchr(text, ','))
        return located(R, line, 1, "a comma in a whitespace-separated line; a CSV file starts with a header");
    control_point *p = add_point(R, line);
    if (!p) return err_nomem(R->err, "%s: out of memory reading the control points", R->shown);
    for (int c = 0; c < 3; c++)
        if (read_number(R, line, column[c], names[c], field[c], 0, &p->world[c])) return -1;
    for (int c = 0; c < 2; c++) {
        if (read_number(R, line, column[3 + c], names[3 + c], field[3 + c], 1, &p->pixel[c])) return -1;
        p->pixel[c] -= 0.5; /* ImGRAFT's first pixel is centred at 1 */
    }
    p->column = column[3];
    return 0;
}

static int read_csv_header(reader *R, uint32_t line, char **field, const uint32_t *column, uint32_t n,
                           int where[COL_COUNT])
{
    for (int c = 0; c < COL_COUNT; c++) where[c] = -1;
    for (uint32_t i = 0; i < n; i++) {
        int c = 0;
        while (c < COL_COUNT && strcasecmp(field[i], column_names[c])) c++;
        if (c == COL_COUNT)
            return located(R, line, column[i],
                           "unknown column '%s'; the columns are u, v and easting, northing, height (map "
                           "coordinates) or x, y, z (local metres), optionally id",
                           field[i]);
        if (where[c] >= 0) return located(R, line, column[i], "column '%s' appears twice", column_names[c]);
        where[c] = (int)i;
    }
    int map = where[COL_EASTING] >= 0 && where[COL_NORTHING] >= 0 && where[COL_HEIGHT] >= 0;
    int local = where[COL_X] >= 0 && where[COL_Y] >= 0 && where[COL_Z] >= 0;
    int any_map = where[COL_EASTING] >= 0 || where[COL_NORTHING] >= 0 || where[COL_HEIGHT] >= 0;
    int any_local = where[COL_X] >= 0 || where[COL_Y] >= 0 || where[COL_Z] >= 0;
    if (where[COL_U] < 0 || where[COL_V] < 0 || !(map ? !any_local : local && !any_map))
        return located(R, line, 1,
                       "the first line must name the columns: u and v (the pixel), then easting, "
                       "northing and height (map coordinates) or x, y and z (local metres), optionally id");
    R->cp->map = map;
    return 0;
}

static int read_csv_row(reader *R, uint32_t line, char **field, const uint32_t *column, uint32_t nf,
                        const int where[COL_COUNT], uint32_t expected)
{
    if (nf != expected)
        return located(R, line, 1, "%u fields, but the first line names %u columns", nf, expected);
    control_point *p = add_point(R, line);
    if (!p) return err_nomem(R->err, "%s: out of memory reading the control points", R->shown);
    if (where[COL_ID] >= 0) {
        const char *id = field[where[COL_ID]];
        if (!*id) return located(R, line, column[where[COL_ID]], "'id' is empty; name the point");
        if (!(p->id = arena_strdup(R->cp->arena, id)))
            return err_nomem(R->err, "%s: out of memory reading the control points", R->shown);
    }
    int first = R->cp->map ? COL_EASTING : COL_X;
    for (int c = 0; c < 3; c++) {
        int k = where[first + c];
        if (read_number(R, line, column[k], column_names[first + c], field[k], 0, &p->world[c])) return -1;
    }
    for (int c = 0; c < 2; c++) {
        int k = where[COL_U + c];
        if (read_number(R, line, column[k], column_names[COL_U + c], field[k], 0, &p->pixel[c])) return -1;
    }
    p->column = column[where[COL_U]];
    return 0;
}

/* 1 when the line is blank or only a comment (# or %). */
static int skipped(const char *s)
{
    while (*s == ' ' || *s == '\t' || *s == '\r') s++;
    return !*s || *s == '#' || *s == '%';
}

static int read_lines(reader *R, char *text, size_t len)
{
    if (memchr(text, 0, len))
        return located(R, 1, 1, "the file holds a NUL byte; control points are a text file (CSV or ImGRAFT's)");
    uint32_t cap = 1;
    for (size_t i = 0; i < len; i++) cap += text[i] == '\n';
    if (!(R->cp->points = arena_alloc(R->cp->arena, (size_t)cap * sizeof *R->cp->points)))
        return err_nomem(R->err, "%s: out of memory reading the control points", R->shown);
    int format = 0; /* 0: not known yet, 1: CSV (header read), 2: ImGRAFT */
    int where[COL_COUNT];
    uint32_t expected = 0, line = 0;
    char *field[CSV_MAX_FIELDS];
    uint32_t column[CSV_MAX_FIELDS];
    for (char *p = text + csv_bom_length(text); p && *p;) {
        char *cur = p, *nl = strchr(p, '\n');
        if (nl) *nl = 0;
        p = nl ? nl + 1 : NULL;
        line++;
        if (skipped(cur)) continue;
        if (R->cp->n >= CONTROL_POINTS_MAX)
            return located(R, line, 1, "more than %u control points", CONTROL_POINTS_MAX);
        if (!format) { /* a comma before any '%' comment makes it CSV */
            const char *comment = strchr(cur, '%');
            format = memchr(cur, ',', comment ? (size_t)(comment - cur) : strlen(cur)) ? 1 : 2;
        }
        if (format == 2) {
            char *comment = strchr(cur, '%');
            if (comment) *comment = 0;
            if (read_imgraft_line(R, cur, line)) return -1;
            continue;
        }
        uint32_t open_quote;
        uint32_t nf = csv_split(cur, field, column, CSV_MAX_FIELDS, &open_quote);
        if (open_quote)
            return located(R, line, open_quote, "this field opens a double quote that is not closed; close it "
                           "before the next comma or the end of the line (a field cannot hold a comma)");
        if (nf > CSV_MAX_FIELDS) return located(R, line, 1, "%u fields; a line has at most %u", nf, CSV_MAX_FIELDS);
        if (!expected) {
            if (read_csv_header(R, line, field, column, nf, where)) return -1;
            expected = nf;
        } else if (read_csv_row(R, line, field, column, nf, where, expected)) {
            return -1;
        }
    }
    if (R->cp->n == 0)
        return located(R, line ? line : 1, 1,
                       "no control points; give a CSV (header u,v,easting,northing,height or u,v,x,y,z, "
                       "then one point per line) or ImGRAFT's lines X Y Z U V");
    R->cp->map = format == 2 ? 1 : R->cp->map;
    R->cp->pixel_shift = format == 2 ? 0.5 : 0.0;
    return 0;
}

control_points *control_points_read(const char *path, const char *shown, err_buf *err)
{
    control_points *cp = calloc(1, sizeof *cp);
    if (!cp || !(cp->arena = arena_new())) {
        free(cp);
        err_nomem(err, "out of memory reading the control points");
        return NULL;
    }
    reader R = {.shown = shown ? shown : path, .err = err, .cp = cp};
    size_t len = 0;
    char *text = read_whole(&R, path, cp->arena, &len);
    if (!text || read_lines(&R, text, len)) {
        control_points_free(cp);
        return NULL;
    }
    return cp;
}

int control_points_check_image(const control_points *cp, const char *shown, const char *photo, uint32_t width,
                               uint32_t height, err_buf *err)
{
    for (uint32_t i = 0; i < cp->n; i++) {
        const control_point *p = &cp->points[i];
        if (p->pixel[0] >= 0 && p->pixel[0] <= width && p->pixel[1] >= 0 && p->pixel[1] <= height) continue;
        const double s = cp->pixel_shift;
        return err_at(err, ERR_INPUT, shown, p->line, p->column,
                      "control point '%s' is at pixel (%g, %g), outside the photograph %s of %u x %u pixels "
                      "(u from %g to %g, v from %g to %g); give the points picked on this photograph",
                      p->id, p->pixel[0] + s, p->pixel[1] + s, photo, width, height, s, width + s, s, height + s);
    }
    return 0;
}

void control_points_free(control_points *cp)
{
    if (!cp) return;
    arena_free(cp->arena);
    free(cp);
}
