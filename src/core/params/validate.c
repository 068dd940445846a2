/* validate.c — one reader per sylva_ptype, a key loop that rejects strangers, and defaults.
 *
 * Messages name the parameter as the file spells it ('spp', 'color'[1], 'grid'[2][0]) and end
 * in "got <what the file says>", so the reader sees both sides. Defaults are copied into the
 * arena so validated parameters never point into a schema's default arrays.
 */
#include "params/validate.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "util/edit_distance.h"
#include "util/file_check.h"

#define LABEL_MAX 160

static int out_of_memory(const param_scope *s, err_buf *err)
{
    return err_nomem(err, "%s: out of memory while reading '%s'", s->file, s->where);
}

const char *param_nearest_name(const char *name, const char *const *candidates, size_t n)
{
    const char *best = NULL;
    size_t best_d = edit_distance_near_limit(name) + 1;
    for (size_t k = 0; k < n; k++) {
        if (!candidates[k]) continue;
        size_t d = edit_distance(name, candidates[k]);
        if (d < best_d && d < strlen(candidates[k])) best = candidates[k], best_d = d;
    }
    return best;
}

/* A bound as people write it: whole numbers in full (9007199254740992, not 9.007e+15). */
static const char *bound_text(double v, char *buf, size_t size)
{
    if (floor(v) == v && fabs(v) < 1e18) snprintf(buf, size, "%.0f", v);
    else snprintf(buf, size, "%.15g", v);
    return buf;
}

void param_range_phrase(const sylva_param_spec *spec, char *buf, size_t size)
{
    char lo_text[40], hi_text[40];
    bound_text(spec->min, lo_text, sizeof lo_text);
    bound_text(spec->max, hi_text, sizeof hi_text);
    int lo = (spec->flags & SYLVA_PARAM_HAS_MIN) != 0,
        hi = (spec->flags & SYLVA_PARAM_HAS_MAX) != 0;
    int lo_x = (spec->flags & SYLVA_PARAM_MIN_EXCLUSIVE) != 0;
    int hi_x = (spec->flags & SYLVA_PARAM_MAX_EXCLUSIVE) != 0;
    if (lo && hi)
        snprintf(buf, size, " in %c%s, %s%c", lo_x ? '(' : '[', lo_text, hi_text, hi_x ? ')' : ']');
    else if (lo)
        snprintf(buf, size, " %s %s", lo_x ? ">" : ">=", lo_text);
    else if (hi)
        snprintf(buf, size, " %s %s", hi_x ? "<" : "<=", hi_text);
    else if (size)
        buf[0] = '\0';
}

static int in_range(const sylva_param_spec *spec, double v)
{
    if (spec->flags & SYLVA_PARAM_HAS_MIN) {
        if (spec->flags & SYLVA_PARAM_MIN_EXCLUSIVE ? !(v > spec->min) : !(v >= spec->min))
            return 0;
    }
    if (spec->flags & SYLVA_PARAM_HAS_MAX) {
        if (spec->flags & SYLVA_PARAM_MAX_EXCLUSIVE ? !(v < spec->max) : !(v <= spec->max))
            return 0;
    }
    return 1;
}

/* What the file holds at n, for "got ..." (scalars quoted, long text cut). */
static void got_phrase(const ynode *n, char *buf, size_t size)
{
    if (!n || ynode_is_null(n)) snprintf(buf, size, "nothing");
    else if (n->kind == YNODE_SEQUENCE) snprintf(buf, size, "a sequence");
    else if (n->kind == YNODE_MAPPING) snprintf(buf, size, "a mapping");
    else if (n->quoted)
        snprintf(buf, size, "the quoted string \"%.60s%s\"", n->text,
                 n->text_len > 60 ? "..." : "");
    else snprintf(buf, size, "'%.60s%s'", n->text, n->text_len > 60 ? "..." : "");
}

/* Plain decimal or scientific notation: [+-]? (d+ .? d* | . d+) ([eE] [+-]? d+)? */
static int numeric_text(const char *t, int *integer_form)
{
    const char *p = t;
    int digits = 0;
    *integer_form = 1;
    if (*p == '+' || *p == '-') p++;
    while (*p >= '0' && *p <= '9') p++, digits++;
    if (*p == '.') {
        *integer_form = 0;
        p++;
        while (*p >= '0' && *p <= '9') p++, digits++;
    }
    if (!digits) return 0;
    if (*p == 'e' || *p == 'E') {
        *integer_form = 0;
        p++;
        if (*p == '+' || *p == '-') p++;
        if (!(*p >= '0' && *p <= '9')) return 0;
        while (*p >= '0' && *p <= '9') p++;
    }
    return *p == '\0';
}

static int special_number_text(const char *t)
{
    static const char *const words[] = {".inf", "+.inf", "-.inf", ".Inf", "+.Inf", "-.Inf",
                                        ".INF", "+.INF", "-.INF", ".nan", ".NaN", ".NAN",
                                        "inf", "-inf", "nan", "infinity", "-infinity"};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (!strcmp(t, words[i])) return 1;
    return 0;
}

/* Reads a number at n. want_int: integral of magnitude <= 2^53. range: spec whose range applies
 * (its flags and bounds), or NULL. label: "'spp'", "'color'[1]". */
static int read_number(const param_scope *scope, const ynode *n, const char *label,
                       const sylva_param_spec *range, int want_int, double *out, err_buf *err)
{
    const char *kind = want_int ? "an integer" : "a number";
    char got[128], span[96] = "";
    got_phrase(n, got, sizeof got);
    if (range) param_range_phrase(range, span, sizeof span);
    if (n->kind != YNODE_SCALAR || ynode_is_null(n))
        return err_set(err, "%s:%u:%u: %s: expected %s, got %s", scope->file, n->line, n->column,
                       label, kind, got);
    if (n->quoted)
        return err_set(err,
                       "%s:%u:%u: %s: expected %s, got %s (numbers are written without quotes)",
                       scope->file, n->line, n->column, label, kind, got);
    int integer_form;
    if (!numeric_text(n->text, &integer_form)) {
        if (special_number_text(n->text))
            return err_set(err, "%s:%u:%u: %s: expected a finite number, got %s", scope->file,
                           n->line, n->column, label, got);
        return err_set(err, "%s:%u:%u: %s: expected %s, got %s", scope->file, n->line, n->column,
                       label, kind, got);
    }
    double v;
    int too_large = 0;
    if (want_int && integer_form) {
        errno = 0;
        long long iv = strtoll(n->text, NULL, 10);
        too_large = errno == ERANGE || llabs(iv) > (long long)PARAM_INT_LIMIT;
        v = (double)iv;
    } else {
        v = strtod(n->text, NULL);
        too_large = isinf(v) || (want_int && fabs(v) > PARAM_INT_LIMIT);
    }
    if (too_large) {
        if (span[0])
            return err_set(err, "%s:%u:%u: %s must be %s%s, got %s", scope->file, n->line,
                           n->column, label, want_int ? "an integer" : "a number", span, n->text);
        if (want_int)
            return err_set(err,
                           "%s:%u:%u: %s must be an integer of magnitude at most %.0f, got %s",
                           scope->file, n->line, n->column, label, PARAM_INT_LIMIT, n->text);
        return err_set(err, "%s:%u:%u: %s: the number %s is too large to represent", scope->file,
                       n->line, n->column, label, n->text);
    }
    if (want_int && floor(v) != v)
        return err_set(err, "%s:%u:%u: %s must be an integer%s, got %s", scope->file, n->line,
                       n->column, label, span, n->text);
    if (range && !in_range(range, v)) {
        if (want_int)
            return err_set(err, "%s:%u:%u: %s must be an integer%s, got %s", scope->file, n->line,
                           n->column, label, span, n->text);
        return err_set(err, "%s:%u:%u: %s must be%s, got %s", scope->file, n->line, n->column,
                       label, span, n->text);
    }
    *out = v == 0.0 ? 0.0 : v; /* no negative zero */
    return 0;
}

static void len_phrase(uint32_t min_len, uint32_t max_len, const char *what, char *buf, size_t size)
{
    if (max_len && min_len == max_len) snprintf(buf, size, "a list of %u %s", min_len, what);
    else if (max_len) snprintf(buf, size, "a list of %u to %u %s", min_len, max_len, what);
    else if (min_len) snprintf(buf, size, "a list of at least %u %s", min_len, what);
    else snprintf(buf, size, "a list of %s", what);
}

static int expect_sequence(const param_scope *scope, const ynode *n, const char *label,
                           const char *expected, err_buf *err)
{
    if (n->kind == YNODE_SEQUENCE) return 0;
    char got[128];
    got_phrase(n, got, sizeof got);
    return err_set(err, "%s:%u:%u: %s must be %s, got %s", scope->file, n->line, n->column, label,
                   expected, got);
}

static int read_numbers(arena *a, const param_scope *scope, const ynode *n, const char *name,
                        const sylva_param_spec *spec, uint32_t min_len, uint32_t max_len,
                        const char *what, sylva_value *v, err_buf *err)
{
    char label[LABEL_MAX], expected[96];
    snprintf(label, sizeof label, "'%s'", name);
    len_phrase(min_len, max_len, what, expected, sizeof expected);
    if (expect_sequence(scope, n, label, expected, err)) return -1;
    if (n->n_items < min_len || (max_len && n->n_items > max_len))
        return err_set(err, "%s:%u:%u: %s must be %s, got %u number%s", scope->file, n->line,
                       n->column, label, expected, n->n_items, n->n_items == 1 ? "" : "s");
    double *list = arena_alloc(a, (size_t)n->n_items * sizeof *list + 1);
    if (!list) return out_of_memory(scope, err);
    for (uint32_t i = 0; i < n->n_items; i++) {
        snprintf(label, sizeof label, "'%s'[%u]", name, i);
        if (read_number(scope, n->items[i], label, spec, 0, &list[i], err)) return -1;
    }
    v->list = list, v->len = n->n_items;
    return 0;
}

static int read_polyline(arena *a, const param_scope *scope, const ynode *n,
                         const sylva_param_spec *spec, sylva_value *v, err_buf *err)
{
    char label[LABEL_MAX];
    uint32_t min_points = spec->min_len ? spec->min_len : 1;
    snprintf(label, sizeof label, "'%s'", spec->name);
    if (expect_sequence(scope, n, label, "a list of points [[x, y], ...]", err)) return -1;
    if (n->n_items < min_points)
        return err_set(err, "%s:%u:%u: %s needs at least %u point%s [x, y], got %u", scope->file,
                       n->line, n->column, label, min_points, min_points == 1 ? "" : "s",
                       n->n_items);
    if (spec->max_len && n->n_items > spec->max_len)
        return err_set(err, "%s:%u:%u: %s takes at most %u points [x, y], got %u", scope->file,
                       n->line, n->column, label, spec->max_len, n->n_items);
    double *xy = arena_alloc(a, (size_t)n->n_items * 2 * sizeof *xy);
    if (!xy) return out_of_memory(scope, err);
    for (uint32_t i = 0; i < n->n_items; i++) {
        const ynode *pt = n->items[i];
        snprintf(label, sizeof label, "'%s'[%u]", spec->name, i);
        if (expect_sequence(scope, pt, label, "a point [x, y]", err)) return -1;
        if (pt->n_items != 2)
            return err_set(err, "%s:%u:%u: %s must be a point [x, y], got %u number%s",
                           scope->file, pt->line, pt->column, label, pt->n_items,
                           pt->n_items == 1 ? "" : "s");
        snprintf(label, sizeof label, "'%s'[%u] x", spec->name, i);
        if (read_number(scope, pt->items[0], label, NULL, 0, &xy[2 * i], err)) return -1;
        snprintf(label, sizeof label, "'%s'[%u] y", spec->name, i);
        if (read_number(scope, pt->items[1], label, spec, 0, &xy[2 * i + 1], err)) return -1;
        if (i > 0 && xy[2 * i] < xy[2 * i - 2])
            return err_set(err,
                           "%s:%u:%u: '%s'[%u]: x must not decrease along the polyline, got %s "
                           "after %.15g (equal x makes a step)",
                           scope->file, pt->items[0]->line, pt->items[0]->column, spec->name, i,
                           pt->items[0]->text, xy[2 * i - 2]);
    }
    v->list = xy, v->len = n->n_items;
    return 0;
}

static int read_grid(arena *a, const param_scope *scope, const ynode *n,
                     const sylva_param_spec *spec, sylva_value *v, err_buf *err)
{
    char label[LABEL_MAX];
    snprintf(label, sizeof label, "'%s'", spec->name);
    if (expect_sequence(scope, n, label, "a list of rows [[a, b, ...], ...]", err)) return -1;
    if (n->n_items == 0)
        return err_set(err, "%s:%u:%u: %s needs at least one row of numbers, got an empty list",
                       scope->file, n->line, n->column, label);
    uint32_t rows = n->n_items, cols = 0;
    for (uint32_t r = 0; r < rows; r++) {
        const ynode *row = n->items[r];
        snprintf(label, sizeof label, "'%s'[%u]", spec->name, r);
        if (expect_sequence(scope, row, label, "a row of numbers [a, b, ...]", err)) return -1;
        if (row->n_items == 0)
            return err_set(err, "%s:%u:%u: %s is an empty row; rows need at least one number",
                           scope->file, row->line, row->column, label);
        if (r == 0) cols = row->n_items;
        else if (row->n_items != cols)
            return err_set(err,
                           "%s:%u:%u: %s has %u numbers but row 0 has %u; every row must have "
                           "the same length",
                           scope->file, row->line, row->column, label, row->n_items, cols);
    }
    double *cells = arena_alloc(a, (size_t)rows * cols * sizeof *cells);
    if (!cells) return out_of_memory(scope, err);
    for (uint32_t r = 0; r < rows; r++)
        for (uint32_t c = 0; c < cols; c++) {
            snprintf(label, sizeof label, "'%s'[%u][%u]", spec->name, r, c);
            if (read_number(scope, n->items[r]->items[c], label, spec, 0,
                            &cells[(size_t)r * cols + c], err))
                return -1;
        }
    v->list = cells, v->rows = rows, v->cols = cols, v->len = rows * cols;
    return 0;
}

static int read_text(arena *a, const param_scope *scope, const ynode *n, const char *label,
                     const char *expected, const char **out, err_buf *err)
{
    if (n->kind != YNODE_SCALAR || ynode_is_null(n)) {
        char got[128];
        got_phrase(n, got, sizeof got);
        return err_set(err, "%s:%u:%u: %s must be %s, got %s", scope->file, n->line, n->column,
                       label, expected, got);
    }
    *out = arena_strdup(a, n->text);
    return *out ? 0 : out_of_memory(scope, err);
}

static int read_bool(const param_scope *scope, const ynode *n, const char *label, int64_t *out,
                     err_buf *err)
{
    static const char *const yes[] = {"true", "True", "TRUE", "yes", "Yes", "YES"};
    static const char *const no[] = {"false", "False", "FALSE", "no", "No", "NO"};
    if (n->kind == YNODE_SCALAR && !n->quoted) {
        for (size_t i = 0; i < sizeof yes / sizeof yes[0]; i++) {
            if (!strcmp(n->text, yes[i]) || !strcmp(n->text, no[i])) {
                *out = !strcmp(n->text, yes[i]);
                return 0;
            }
        }
    }
    char got[128];
    got_phrase(n, got, sizeof got);
    return err_set(err, "%s:%u:%u: %s must be true or false, got %s", scope->file, n->line,
                   n->column, label, got);
}

static int read_enum(arena *a, const param_scope *scope, const ynode *n,
                     const sylva_param_spec *spec, const char *label, sylva_value *v, err_buf *err)
{
    size_t n_choices = 0;
    while (spec->choices && spec->choices[n_choices]) n_choices++;
    if (n->kind == YNODE_SCALAR && !ynode_is_null(n)) {
        for (size_t k = 0; k < n_choices; k++)
            if (!strcmp(n->text, spec->choices[k])) {
                v->i = (int64_t)k;
                v->s = arena_strdup(a, spec->choices[k]);
                return v->s ? 0 : out_of_memory(scope, err);
            }
    }
    char list[1024] = "", got[128];
    size_t used = 0;
    for (size_t k = 0; k < n_choices && used < sizeof list; k++)
        used += (size_t)snprintf(list + used, sizeof list - used, "%s%s", k ? ", " : "",
                                 spec->choices[k]);
    got_phrase(n, got, sizeof got);
    const char *near =
        n->kind == YNODE_SCALAR ? param_nearest_name(n->text, spec->choices, n_choices) : NULL;
    if (near)
        return err_set(err, "%s:%u:%u: %s must be one of %s; got %s (did you mean '%s'?)",
                       scope->file, n->line, n->column, label, list, got, near);
    return err_set(err, "%s:%u:%u: %s must be one of %s; got %s", scope->file, n->line,
                   n->column, label, list, got);
}

const char *param_resolve_path(arena *a, const char *dir, const char *rel)
{
    if (rel[0] == '/') return arena_strdup(a, rel);
    while (rel[0] == '.' && rel[1] == '/') {
        rel += 2;
        while (*rel == '/') rel++;
    }
    size_t ld = strlen(dir), lr = strlen(rel);
    while (ld > 1 && dir[ld - 1] == '/') ld--;
    char *p = arena_alloc(a, ld + 1 + lr + 1);
    if (!p) return NULL;
    memcpy(p, dir, ld);
    if (!lr) return p;
    if (!(ld == 1 && dir[0] == '/')) p[ld++] = '/';
    memcpy(p + ld, rel, lr);
    return p;
}

/* A PATH value names a file to read: a GDAL virtual path, URL or connection string only when the
 * command line allowed it (kept as written), otherwise a path resolved against the scene's
 * folder that, when it exists, must be a regular file (a FIFO or device would hang a reader). */
static int read_input_path(arena *a, const param_scope *scope, const ynode *n, const char *label,
                           const char *rel, const char **out, err_buf *err)
{
    if (file_is_gdal_virtual(rel)) {
        if (!file_gdal_virtual_allowed())
            return err_set(err, "%s:%u:%u: %s: '%s' is a GDAL virtual path, URL or connection "
                           "string, which may reach the network; name a local file, or run with "
                           "--allow-gdal-virtual to let GDAL open it", scope->file, n->line,
                           n->column, label, rel);
        if (!(*out = arena_strdup(a, rel))) return out_of_memory(scope, err);
        return 0;
    }
    if (!(*out = param_resolve_path(a, scope->dir, rel))) return out_of_memory(scope, err);
    struct stat st;
    err_buf why;
    if (stat(*out, &st) == 0 && file_check_regular(*out, rel, &why))
        return err_set(err, "%s:%u:%u: %s: %s; name a file", scope->file, n->line, n->column,
                       label, why.msg);
    return 0;
}

static int read_group_list(arena *a, const ynode *n, const sylva_param_spec *spec,
                           const param_scope *scope, sylva_value *v, err_buf *err)
{
    char label[LABEL_MAX], expected[96];
    snprintf(label, sizeof label, "'%s'", spec->name);
    len_phrase(spec->min_len, spec->max_len, "mappings", expected, sizeof expected);
    if (expect_sequence(scope, n, label, expected, err)) return -1;
    if (n->n_items < spec->min_len || (spec->max_len && n->n_items > spec->max_len))
        return err_set(err, "%s:%u:%u: %s must be %s, got %u item%s", scope->file, n->line,
                       n->column, label, expected, n->n_items, n->n_items == 1 ? "" : "s");
    sylva_params *items = arena_alloc(a, (size_t)n->n_items * sizeof *items + 1);
    if (!items) return out_of_memory(scope, err);
    for (uint32_t i = 0; i < n->n_items; i++) {
        const ynode *item = n->items[i];
        size_t size = strlen(scope->where) + strlen(spec->name) + 16;
        char *where = arena_alloc(a, size);
        if (!where) return out_of_memory(scope, err);
        snprintf(where, size, "%s.%s[%u]", scope->where, spec->name, i);
        if (item->kind != YNODE_MAPPING) {
            char got[128];
            got_phrase(item, got, sizeof got);
            return err_set(err, "%s:%u:%u: '%s' must be a mapping (key: value), got %s",
                           scope->file, item->line, item->column, where, got);
        }
        param_scope inner = {scope->file, scope->dir, where, NULL, 0, item->line, item->column};
        const sylva_params *p;
        if (params_validate(a, item, spec->group, spec->n_group, &inner, &p, err)) return -1;
        items[i] = *p;
    }
    v->items = items, v->len = n->n_items;
    return 0;
}

static const char *member_where(arena *a, const param_scope *scope, const char *name)
{
    size_t size = strlen(scope->where) + strlen(name) + 2;
    char *w = arena_alloc(a, size);
    if (w) snprintf(w, size, "%s.%s", scope->where, name);
    return w;
}

int param_value_read(arena *a, const ynode *node, const sylva_param_spec *spec,
                     const param_scope *scope, sylva_value *v, err_buf *err)
{
    char label[LABEL_MAX];
    snprintf(label, sizeof label, "'%s'", spec->name);
    memset(v, 0, sizeof *v);
    v->line = node->line, v->column = node->column;
    double x = 0.0;
    int rc = 0;
    switch (spec->type) {
    case SYLVA_P_BOOL:
        rc = read_bool(scope, node, label, &v->i, err);
        v->r = (double)v->i;
        break;
    case SYLVA_P_INT:
        rc = read_number(scope, node, label, spec, 1, &x, err);
        v->i = (int64_t)x, v->r = x;
        break;
    case SYLVA_P_REAL:
        rc = read_number(scope, node, label, spec, 0, &v->r, err);
        break;
    case SYLVA_P_STRING:
        rc = read_text(a, scope, node, label, "a string", &v->s, err);
        break;
    case SYLVA_P_ENUM:
        rc = read_enum(a, scope, node, spec, label, v, err);
        break;
    case SYLVA_P_PATH: {
        const char *rel;
        rc = read_text(a, scope, node, label, "a file path", &rel, err);
        if (!rc && !rel[0])
            rc = err_set(err, "%s:%u:%u: %s must be a file path, got an empty string",
                         scope->file, node->line, node->column, label);
        if (!rc) rc = read_input_path(a, scope, node, label, rel, &v->s, err);
        break;
    }
    case SYLVA_P_VEC3:
        rc = read_numbers(a, scope, node, spec->name, spec, 3, 3, "numbers [x, y, z]", v, err);
        break;
    case SYLVA_P_LIST:
        rc = read_numbers(a, scope, node, spec->name, spec, spec->min_len, spec->max_len,
                          "numbers", v, err);
        break;
    case SYLVA_P_POLYLINE:
        rc = read_polyline(a, scope, node, spec, v, err);
        break;
    case SYLVA_P_GRID:
        rc = read_grid(a, scope, node, spec, v, err);
        break;
    case SYLVA_P_GROUP: {
        param_scope inner = {scope->file, scope->dir, member_where(a, scope, spec->name), NULL, 0,
                             node->line, node->column};
        if (!inner.where) return out_of_memory(scope, err);
        rc = params_validate(a, node, spec->group, spec->n_group, &inner, &v->group, err);
        break;
    }
    case SYLVA_P_GROUP_LIST:
        rc = read_group_list(a, node, spec, scope, v, err);
        break;
    default:
        rc = err_set(err, "%s:%u:%u: %s has a parameter type (%d) this host does not know",
                     scope->file, node->line, node->column, label, (int)spec->type);
    }
    if (rc) return -1;
    v->is_set = 1;
    return 0;
}

int param_value_default(arena *a, const sylva_param_spec *spec, const param_scope *scope,
                        sylva_value *v, err_buf *err)
{
    memset(v, 0, sizeof *v);
    switch (spec->type) {
    case SYLVA_P_BOOL:
        v->i = spec->def != 0.0, v->r = (double)v->i;
        break;
    case SYLVA_P_INT:
        v->i = (int64_t)spec->def, v->r = (double)v->i;
        break;
    case SYLVA_P_REAL:
        v->r = spec->def;
        break;
    case SYLVA_P_STRING:
        if (spec->def_str && !(v->s = arena_strdup(a, spec->def_str)))
            return out_of_memory(scope, err);
        break;
    case SYLVA_P_ENUM: {
        const char *name = spec->def_str ? spec->def_str : spec->choices ? spec->choices[0] : NULL;
        for (int64_t k = 0; spec->choices && name && spec->choices[k]; k++)
            if (!strcmp(spec->choices[k], name)) v->i = k;
        if (name && !(v->s = arena_strdup(a, name))) return out_of_memory(scope, err);
        break;
    }
    case SYLVA_P_PATH:
        if (spec->def_str && !(v->s = param_resolve_path(a, scope->dir, spec->def_str)))
            return out_of_memory(scope, err);
        break;
    case SYLVA_P_VEC3:
    case SYLVA_P_LIST:
    case SYLVA_P_POLYLINE: {
        /* A VEC3 is always three numbers (zeros when the schema gives none). */
        uint32_t len = spec->type == SYLVA_P_VEC3 ? 3 : spec->def_list ? spec->def_len : 0;
        size_t count = (size_t)len * (spec->type == SYLVA_P_POLYLINE ? 2 : 1);
        size_t given =
            spec->def_list ? (size_t)spec->def_len * (spec->type == SYLVA_P_POLYLINE ? 2 : 1) : 0;
        if (!count) break;
        double *list = arena_alloc(a, count * sizeof *list);
        if (!list) return out_of_memory(scope, err);
        for (size_t k = 0; k < count && k < given; k++) list[k] = spec->def_list[k];
        v->list = list, v->len = len;
        break;
    }
    case SYLVA_P_GROUP: {
        param_scope inner = {scope->file, scope->dir, member_where(a, scope, spec->name), NULL, 0,
                             scope->line, scope->column};
        if (!inner.where) return out_of_memory(scope, err);
        if (params_validate(a, NULL, spec->group, spec->n_group, &inner, &v->group, err)) return -1;
        break;
    }
    default: /* GRID and GROUP_LIST default to empty */
        break;
    }
    return 0;
}

static int is_host_key(const param_scope *scope, const char *key)
{
    for (uint32_t k = 0; k < scope->n_host_keys; k++)
        if (scope->host_keys[k] && !strcmp(scope->host_keys[k], key)) return 1;
    return 0;
}

static int unknown_key(const param_scope *scope, const ynode_pair *pair,
                       const sylva_param_spec *spec, uint32_t n, err_buf *err)
{
    const char *names[256];
    size_t count = 0;
    for (uint32_t k = 0; k < n && count < 256; k++) names[count++] = spec[k].name;
    for (uint32_t k = 0; k < scope->n_host_keys && count < 256; k++)
        names[count++] = scope->host_keys[k];
    const char *near = param_nearest_name(pair->key, names, count);
    if (near)
        return err_set(err, "%s:%u:%u: unknown key '%s' in '%s'; did you mean '%s'?", scope->file,
                       pair->key_line, pair->key_column, pair->key, scope->where, near);
    if (!count)
        return err_set(err, "%s:%u:%u: unknown key '%s' in '%s', which takes no keys",
                       scope->file, pair->key_line, pair->key_column, pair->key, scope->where);
    char list[1200] = "";
    size_t used = 0;
    for (size_t k = 0; k < count && used < sizeof list; k++)
        used += (size_t)snprintf(list + used, sizeof list - used, "%s%s", k ? ", " : "", names[k]);
    return err_set(err, "%s:%u:%u: unknown key '%s' in '%s'; valid keys are %s", scope->file,
                   pair->key_line, pair->key_column, pair->key, scope->where, list);
}

int params_validate(arena *a, const ynode *map, const sylva_param_spec *spec, uint32_t n,
                    const param_scope *scope, const sylva_params **out, err_buf *err)
{
    if (map && ynode_is_null(map)) map = NULL;
    if (map && map->kind != YNODE_MAPPING) {
        char got[128];
        got_phrase(map, got, sizeof got);
        return err_set(err, "%s:%u:%u: '%s' must be a mapping (key: value), got %s", scope->file,
                       map->line, map->column, scope->where, got);
    }
    sylva_params *p = arena_alloc(a, sizeof *p);
    sylva_value *values = arena_alloc(a, (size_t)n * sizeof *values + 1);
    const char *file = arena_strdup(a, scope->file);
    if (!p || !values || !file) return out_of_memory(scope, err);
    p->spec = spec, p->n = n, p->values = values, p->file = file;
    p->line = map ? map->line : scope->line;
    p->column = map ? map->column : scope->column;

    for (uint32_t i = 0; map && i < map->n_pairs; i++) {
        const ynode_pair *pair = &map->pairs[i];
        uint32_t k = 0;
        while (k < n && strcmp(spec[k].name, pair->key)) k++;
        if (k == n) {
            if (is_host_key(scope, pair->key)) continue;
            return unknown_key(scope, pair, spec, n, err);
        }
        if (param_value_read(a, pair->value, &spec[k], scope, &values[k], err)) return -1;
    }
    for (uint32_t k = 0; k < n; k++) {
        if (values[k].is_set) continue;
        if (spec[k].flags & SYLVA_PARAM_REQUIRED)
            return err_set(err, "%s:%u:%u: missing required key '%s' in '%s'", scope->file,
                           p->line, p->column, spec[k].name, scope->where);
        param_scope at = *scope;
        at.line = p->line, at.column = p->column;
        if (param_value_default(a, &spec[k], &at, &values[k], err)) return -1;
    }
    *out = p;
    return 0;
}
