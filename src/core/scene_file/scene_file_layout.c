/* scene_file_layout.c — a layout: a CSV file of placements (one object per row of an objects
 * entry with `layout:`, or one viewpoint per row of a study's points file). The first line names
 * the columns: `id` (or `name`), `easting` and `northing` (map coordinates: local = map - site
 * origin), `longitude` and `latitude` (degrees, WGS 84, placed on the site's map) or `x` and `y`
 * (local metres), and optionally `heading` (degrees clockwise from north) and
 * `height_above_ground` (metres). Blank lines and lines starting with '#' are skipped; a field
 * may be wrapped in double quotes. Every problem is reported at file:line:column of the CSV. */
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

enum { COL_ID, COL_EASTING, COL_NORTHING, COL_LONGITUDE, COL_LATITUDE, COL_X, COL_Y, COL_HEADING, COL_HEIGHT,
       COL_COUNT };
static const char *const column_names[COL_COUNT] = {"id", "easting", "northing", "longitude", "latitude", "x", "y",
                                                    "heading", "height_above_ground"};
/* The pairs of columns that give a position, and what each pair is. */
static const int position_columns[3][2] = {{COL_EASTING, COL_NORTHING}, {COL_LONGITUDE, COL_LATITUDE}, {COL_X, COL_Y}};
#define LAYOUT_COLUMNS "id (or name), then easting and northing (map coordinates), longitude and latitude " \
                       "(degrees) or x and y (local metres), optionally heading and height_above_ground"

char *sf_read_text_file(loader *L, const char *path, const char *shown, size_t *len)
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

/* Maps the header's names to columns; *where[c] is the field index of column c or -1, and
 * *pair the pair of position_columns the file gives. */
static int read_header(loader *L, const char *shown, uint32_t line, char **field, const uint32_t *column,
                       uint32_t n, int where[COL_COUNT], int *pair)
{
    for (int c = 0; c < COL_COUNT; c++) where[c] = -1;
    for (uint32_t i = 0; i < n; i++) {
        const char *name = strcasecmp(field[i], "name") ? field[i] : "id";
        int c = 0;
        while (c < COL_COUNT && strcasecmp(name, column_names[c])) c++;
        if (c == COL_COUNT)
            return sf_located(L->err, shown, line, column[i], "unknown column '%s'; the columns are " LAYOUT_COLUMNS,
                              field[i]);
        if (where[c] >= 0)
            return sf_located(L->err, shown, line, column[i], "column '%s' appears twice%s", column_names[c],
                              c == COL_ID ? " (name is another name of id)" : "");
        where[c] = (int)i;
    }
    int pairs = 0, whole = 0;
    for (int k = 0; k < 3; k++) {
        int a = where[position_columns[k][0]] >= 0, b = where[position_columns[k][1]] >= 0;
        pairs += a || b, whole += a && b;
        if (a || b) *pair = k;
    }
    if (where[COL_ID] < 0 || pairs != 1 || whole != 1)
        return sf_located(L->err, shown, line, 1, "the first line must name the columns: " LAYOUT_COLUMNS);
    if (*pair == 1 && !L->site)
        return sf_located(L->err, shown, line, column[where[COL_LONGITUDE]],
                          "longitude and latitude are placed on the site's map, and the scene has no site: "
                          "section; add one, or give x and y in local metres");
    return 0;
}

/* The row's position in local metres from the pair of columns the file gives. */
static int read_position(loader *L, const char *shown, uint32_t line, char **field, const uint32_t *column,
                         const int where[COL_COUNT], int pair, double xy[2])
{
    int cx = position_columns[pair][0], cy = position_columns[pair][1];
    if (read_number(L, shown, line, column[where[cx]], column_names[cx], field[where[cx]], &xy[0]) ||
        read_number(L, shown, line, column[where[cy]], column_names[cy], field[where[cy]], &xy[1]))
        return -1;
    if (pair == 2) return 0;
    if (pair == 1) {
        if (fabs(xy[0]) > 180 || fabs(xy[1]) > 90)
            return sf_located(L->err, shown, line, column[where[fabs(xy[0]) > 180 ? cx : cy]],
                              "longitude %g, latitude %g lies off the globe; longitude is in [-180, 180] and "
                              "latitude in [-90, 90] degrees", xy[0], xy[1]);
        double map[2];
        if (site_frame_from_lonlat(L->site, xy[0], xy[1], map, L->err)) {
            err_prefix(L->err, "longitude %g, latitude %g: ", xy[0], xy[1]);
            return err_locate(L->err, shown, line, column[where[cx]]);
        }
        xy[0] = map[0], xy[1] = map[1];
    }
    xy[0] -= L->sf->site.origin[0], xy[1] -= L->sf->site.origin[1];
    return 0;
}

int sf_read_layout(loader *L, const char *path, const char *shown, layout_row **rows_out, uint32_t *n_out)
{
    size_t len = 0;
    char *text = sf_read_text_file(L, path, shown, &len);
    if (!text) return -1;
    if (memchr(text, 0, len))
        return sf_located(L->err, shown, 1, 1, "the layout holds a NUL byte; it must be a text CSV file");
    uint32_t cap = 0;
    for (size_t i = 0; i < len; i++) cap += text[i] == '\n';
    layout_row *rows = arena_alloc(L->a, ((size_t)cap + 1) * sizeof *rows);
    if (!rows) return sf_out_of_memory(L);
    int where[COL_COUNT], have_header = 0, pair = 0;
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
            if (read_header(L, shown, line, field, column, nf, where, &pair)) return -1;
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
        if (read_position(L, shown, line, field, column, where, pair, r->xy)) return -1;
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
