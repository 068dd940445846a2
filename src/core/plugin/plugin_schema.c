/* plugin_schema.c — checking and printing parameter schemas (sylva_param_spec tables).
 *
 * plugin_schema_check() is what lets the scene loader trust a schema: after it passes, every
 * name is well-formed and unique, every type known, every field the type does not use left
 * empty, every range non-empty and every default valid for its own schema. The first problem
 * found is reported; tables and nesting have limits so a corrupt table cannot run away.
 * plugin_schema_print() renders the same table for people, so help cannot drift from code.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "plugin/plugin_host.h"

#define SCHEMA_MAX_PARAMS 256  /* entries in one table */
#define SCHEMA_MAX_DEPTH 8     /* GROUP / GROUP_LIST nesting */
#define SCHEMA_MAX_CHOICES 256 /* ENUM choices */
#define SCHEMA_PATH_MAX 512    /* "outer[].inner.name" */

/* What each type reads from a spec. */
typedef struct ptype_traits {
    const char *name;
    unsigned range : 1;    /* HAS_MIN/HAS_MAX apply (to the value or each element) */
    unsigned number : 1;   /* the default lives in def */
    unsigned text : 1;     /* the default lives in def_str */
    unsigned list : 1;     /* the default lives in def_list/def_len */
    unsigned lengths : 1;  /* min_len/max_len apply */
    unsigned group : 1;    /* group/n_group describe the members */
    const char *element;   /* what min_len/max_len count */
} ptype_traits;

static const ptype_traits ptype_table[] = {
    [SYLVA_P_BOOL] = {"bool", 0, 1, 0, 0, 0, 0, NULL},
    [SYLVA_P_INT] = {"int", 1, 1, 0, 0, 0, 0, NULL},
    [SYLVA_P_REAL] = {"real", 1, 1, 0, 0, 0, 0, NULL},
    [SYLVA_P_STRING] = {"string", 0, 0, 1, 0, 0, 0, NULL},
    [SYLVA_P_ENUM] = {"enum", 0, 0, 1, 0, 0, 0, NULL},
    [SYLVA_P_PATH] = {"path", 0, 0, 1, 0, 0, 0, NULL},
    [SYLVA_P_VEC3] = {"vec3", 1, 0, 0, 1, 0, 0, NULL},
    [SYLVA_P_LIST] = {"list", 1, 0, 0, 1, 1, 0, "elements"},
    [SYLVA_P_POLYLINE] = {"polyline", 1, 0, 0, 1, 1, 0, "points"},
    [SYLVA_P_GRID] = {"grid", 1, 0, 0, 0, 0, 0, NULL},
    [SYLVA_P_GROUP] = {"group", 0, 0, 0, 0, 0, 1, NULL},
    [SYLVA_P_GROUP_LIST] = {"group list", 0, 0, 0, 0, 1, 1, "items"},
};

static const ptype_traits *ptype_traits_of(sylva_ptype t)
{
    if ((int)t < SYLVA_P_BOOL || (int)t > SYLVA_P_GROUP_LIST) return NULL;
    return &ptype_table[t];
}

const char *plugin_param_type_name(sylva_ptype type)
{
    const ptype_traits *tr = ptype_traits_of(type);
    return tr ? tr->name : "unknown";
}

/* --------------------------------------------------------------------------------------------
 * Ranges
 */

int plugin_value_in_range(const sylva_param_spec *p, double v)
{
    if (isnan(v)) return 0;
    if (p->flags & SYLVA_PARAM_HAS_MIN) {
        if ((p->flags & SYLVA_PARAM_MIN_EXCLUSIVE) ? !(v > p->min) : !(v >= p->min)) return 0;
    }
    if (p->flags & SYLVA_PARAM_HAS_MAX) {
        if ((p->flags & SYLVA_PARAM_MAX_EXCLUSIVE) ? !(v < p->max) : !(v <= p->max)) return 0;
    }
    return 1;
}

const char *plugin_number_format(char buf[32], double v)
{
    if (v == floor(v) && fabs(v) < 1e17) snprintf(buf, 32, "%.0f", v);
    else snprintf(buf, 32, "%.10g", v);
    return buf;
}

/* "[0, 1]", "(0, 1000]", ">= 2", "< 90" — without unit; "" when unbounded. */
static void format_range(char *buf, size_t cap, const sylva_param_spec *p)
{
    int lo = (p->flags & SYLVA_PARAM_HAS_MIN) != 0, hi = (p->flags & SYLVA_PARAM_HAS_MAX) != 0;
    int lo_ex = (p->flags & SYLVA_PARAM_MIN_EXCLUSIVE) != 0;
    int hi_ex = (p->flags & SYLVA_PARAM_MAX_EXCLUSIVE) != 0;
    char a[32], b[32];
    if (lo && hi)
        snprintf(buf, cap, "%c%s, %s%c", lo_ex ? '(' : '[', plugin_number_format(a, p->min),
                 plugin_number_format(b, p->max), hi_ex ? ')' : ']');
    else if (lo)
        snprintf(buf, cap, "%s %s", lo_ex ? ">" : ">=", plugin_number_format(a, p->min));
    else if (hi)
        snprintf(buf, cap, "%s %s", hi_ex ? "<" : "<=", plugin_number_format(b, p->max));
    else if (cap)
        buf[0] = '\0';
}

/* --------------------------------------------------------------------------------------------
 * Checking
 */

/* Sets err to "parameter 'path': <reason>" and returns -1. */
static int SYLVA_PRINTF(3, 4) spec_fail(err_buf *err, const char *path, const char *fmt, ...)
{
    char reason[ERR_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(reason, sizeof reason, fmt, ap);
    va_end(ap);
    return err_set(err, "parameter '%s': %s", path, reason);
}

static int check_table(const sylva_param_spec *spec, uint32_t n, const char *prefix, int depth,
                       err_buf *err);

/* Where an entry sits, for entries whose name cannot be used: "entry 3" or "entry 3 of 'a.b'". */
static void entry_place(char *buf, size_t cap, const char *prefix, uint32_t k)
{
    size_t plen = strlen(prefix);
    if (plen == 0) {
        snprintf(buf, cap, "entry %u", k);
        return;
    }
    /* prefix ends in "." or "[]."; drop that to name the group */
    size_t cut = plen - 1;
    if (cut >= 2 && prefix[cut - 1] == ']' && prefix[cut - 2] == '[') cut -= 2;
    snprintf(buf, cap, "entry %u of group '%.*s'", k, (int)cut, prefix);
}

static int check_number_default(const sylva_param_spec *p, const char *path, err_buf *err)
{
    char range[128], a[32];
    format_range(range, sizeof range, p);
    const char *unit = p->unit ? p->unit : "";
    const char *sp = p->unit ? " " : "";
    if (!isfinite(p->def))
        return spec_fail(err, path, "the default is not a finite number; give one in def");
    if (p->type == SYLVA_P_BOOL && p->def != 0.0 && p->def != 1.0)
        return spec_fail(err, path, "a bool's default must be 0 (false) or 1 (true), not %g",
                         p->def);
    if (p->type == SYLVA_P_INT && (p->def != floor(p->def) || fabs(p->def) > 9007199254740992.0))
        return spec_fail(err, path, "an int's default must be a whole number (at most 2^53 in "
                         "magnitude), not %.17g", p->def);
    if (!plugin_value_in_range(p, p->def))
        return spec_fail(err, path, "the default %s%s%s is outside the range %s%s%s",
                         plugin_number_format(a, p->def), sp, unit, range, sp, unit);
    return 0;
}

static int check_enum(const sylva_param_spec *p, const char *path, err_buf *err)
{
    if (!p->choices || !p->choices[0])
        return spec_fail(err, path, "an enum needs at least one choice in its NULL-terminated "
                         "choices array");
    uint32_t n = 0;
    for (; p->choices[n]; n++) {
        if (n == SCHEMA_MAX_CHOICES)
            return spec_fail(err, path, "more than %d choices; is the choices array "
                             "NULL-terminated?", SCHEMA_MAX_CHOICES);
        if (!p->choices[n][0]) return spec_fail(err, path, "choice %u is an empty string", n);
        for (uint32_t k = 0; k < n; k++)
            if (!strcmp(p->choices[k], p->choices[n]))
                return spec_fail(err, path, "the choice \"%s\" appears twice; choices must be "
                                 "unique", p->choices[n]);
    }
    if (p->flags & SYLVA_PARAM_REQUIRED) return 0;
    if (!p->def_str)
        return spec_fail(err, path, "an optional enum needs a default: set def_str to one of "
                         "its choices (or mark it SYLVA_PARAM_REQUIRED)");
    for (uint32_t k = 0; k < n; k++)
        if (!strcmp(p->choices[k], p->def_str)) return 0;
    return spec_fail(err, path, "the default \"%s\" is not one of the choices", p->def_str);
}

static int check_list_default(const sylva_param_spec *p, const char *path, const ptype_traits *tr,
                              err_buf *err)
{
    if (p->type == SYLVA_P_VEC3 && p->def_list && p->def_len != 3)
        return spec_fail(err, path, "a vec3 default has 3 elements, not %u", p->def_len);
    if (tr->lengths) {
        if (p->def_len < p->min_len)
            return spec_fail(err, path, "the default has %u %s, fewer than min_len %u; give a "
                             "longer default or mark it SYLVA_PARAM_REQUIRED", p->def_len,
                             tr->element, p->min_len);
        if (p->max_len && p->def_len > p->max_len)
            return spec_fail(err, path, "the default has %u %s, more than max_len %u",
                             p->def_len, tr->element, p->max_len);
    }
    char range[128];
    format_range(range, sizeof range, p);
    if (p->type == SYLVA_P_POLYLINE) {
        for (uint32_t k = 0; k < p->def_len; k++) {
            double x = p->def_list[2 * k], y = p->def_list[2 * k + 1];
            if (!isfinite(x) || !isfinite(y))
                return spec_fail(err, path, "default point %u is not finite", k);
            if (k > 0 && x < p->def_list[2 * k - 2])
                return spec_fail(err, path, "default point %u has x %g, less than the previous "
                                 "point's %g; x must not decrease", k, x, p->def_list[2 * k - 2]);
            if (!plugin_value_in_range(p, y))
                return spec_fail(err, path, "default point %u has y %g, outside the range %s", k,
                                 y, range);
        }
        return 0;
    }
    for (uint32_t k = 0; k < p->def_len; k++) {
        double v = p->def_list[k];
        if (!isfinite(v)) return spec_fail(err, path, "default element %u is not finite", k);
        if (!plugin_value_in_range(p, v))
            return spec_fail(err, path, "default element %u is %g, outside the range %s", k, v,
                             range);
    }
    return 0;
}

/* Fields a type does not read must stay empty: a value there is a default or range that the
 * host would silently ignore. */
static int check_unused_fields(const sylva_param_spec *p, const char *path, const ptype_traits *tr,
                               err_buf *err)
{
    const char *t = tr->name;
    if (!tr->range && (p->flags & (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX)))
        return spec_fail(err, path, "type %s takes no range; clear SYLVA_PARAM_HAS_MIN/HAS_MAX", t);
    if (!tr->number && p->def != 0.0)
        return spec_fail(err, path, "type %s does not read def (%g); %s", t, p->def,
                         tr->text ? "give the default in def_str"
                         : tr->list ? "give the default in def_list/def_len"
                                    : "leave it 0");
    if (!tr->text && p->def_str)
        return spec_fail(err, path, "type %s does not read def_str; leave it NULL", t);
    if (!tr->list && (p->def_list || p->def_len))
        return spec_fail(err, path, "type %s does not read def_list/def_len; leave them empty", t);
    if (tr->list && !p->def_list && p->def_len)
        return spec_fail(err, path, "def_len is %u but def_list is NULL", p->def_len);
    if (tr->list && p->def_list && !p->def_len)
        return spec_fail(err, path, "def_list is set but def_len is 0; use def_list NULL for "
                         "an empty default");
    if (!tr->lengths && (p->min_len || p->max_len))
        return spec_fail(err, path, "type %s takes no min_len/max_len; only list, polyline and "
                         "group list do", t);
    if (p->type != SYLVA_P_ENUM && p->choices)
        return spec_fail(err, path, "type %s takes no choices; only enum does", t);
    if (!tr->group && (p->group || p->n_group))
        return spec_fail(err, path, "type %s takes no group; only group and group list do", t);
    return 0;
}

static int check_spec(const sylva_param_spec *p, const char *path, int depth, err_buf *err)
{
    const ptype_traits *tr = ptype_traits_of(p->type);
    if (!tr)
        return spec_fail(err, path, "unknown type %d; types run from SYLVA_P_BOOL (%d) to "
                         "SYLVA_P_GROUP_LIST (%d)", (int)p->type, SYLVA_P_BOOL,
                         SYLVA_P_GROUP_LIST);
    if (!p->help || !p->help[0])
        return spec_fail(err, path, "no help sentence; every parameter says in one sentence "
                         "what it sets");
    const uint32_t known = SYLVA_PARAM_REQUIRED | SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX |
                           SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_MAX_EXCLUSIVE;
    if (p->flags & ~known)
        return spec_fail(err, path, "unknown flag bits 0x%x; known flags are REQUIRED, HAS_MIN, "
                         "HAS_MAX, MIN_EXCLUSIVE and MAX_EXCLUSIVE", p->flags & ~known);
    if ((p->flags & SYLVA_PARAM_MIN_EXCLUSIVE) && !(p->flags & SYLVA_PARAM_HAS_MIN))
        return spec_fail(err, path, "SYLVA_PARAM_MIN_EXCLUSIVE without SYLVA_PARAM_HAS_MIN");
    if ((p->flags & SYLVA_PARAM_MAX_EXCLUSIVE) && !(p->flags & SYLVA_PARAM_HAS_MAX))
        return spec_fail(err, path, "SYLVA_PARAM_MAX_EXCLUSIVE without SYLVA_PARAM_HAS_MAX");
    if (check_unused_fields(p, path, tr, err)) return -1;

    int lo = (p->flags & SYLVA_PARAM_HAS_MIN) != 0, hi = (p->flags & SYLVA_PARAM_HAS_MAX) != 0;
    if (lo && isnan(p->min)) return spec_fail(err, path, "min is not a number");
    if (hi && isnan(p->max)) return spec_fail(err, path, "max is not a number");
    if (lo && hi) {
        int open = (p->flags & (SYLVA_PARAM_MIN_EXCLUSIVE | SYLVA_PARAM_MAX_EXCLUSIVE)) != 0;
        if (p->min > p->max || (open && p->min == p->max))
            return spec_fail(err, path, "the range is empty: min %g, max %g; min must be below "
                             "max", p->min, p->max);
    }
    if (tr->lengths && p->max_len && p->min_len > p->max_len)
        return spec_fail(err, path, "min_len %u is above max_len %u (max_len 0 means no bound)",
                         p->min_len, p->max_len);

    if (p->type == SYLVA_P_ENUM && check_enum(p, path, err)) return -1;
    if (tr->group) {
        if (!p->group || p->n_group == 0)
            return spec_fail(err, path, "type %s needs members: group and n_group describe them",
                             tr->name);
        if (depth + 1 >= SCHEMA_MAX_DEPTH)
            return spec_fail(err, path, "groups nest deeper than %d levels", SCHEMA_MAX_DEPTH);
        char inner[SCHEMA_PATH_MAX];
        snprintf(inner, sizeof inner, "%s%s", path,
                 p->type == SYLVA_P_GROUP_LIST ? "[]." : ".");
        if (check_table(p->group, p->n_group, inner, depth + 1, err)) return -1;
    }

    if (p->flags & SYLVA_PARAM_REQUIRED) return 0; /* defaults are never used */
    if (tr->number) return check_number_default(p, path, err);
    if (tr->list) return check_list_default(p, path, tr, err);
    if (p->type == SYLVA_P_GROUP_LIST && p->min_len > 0)
        return spec_fail(err, path, "the default is an empty list but min_len is %u; mark it "
                         "SYLVA_PARAM_REQUIRED", p->min_len);
    return 0;
}

static int check_table(const sylva_param_spec *spec, uint32_t n, const char *prefix, int depth,
                       err_buf *err)
{
    char place[SCHEMA_PATH_MAX];
    if (n && !spec) {
        entry_place(place, sizeof place, prefix, 0);
        return err_set(err, "the table of %u parameters is NULL (at %s)", n, place);
    }
    if (n > SCHEMA_MAX_PARAMS)
        return err_set(err, "%u parameters in one table%s%s; the limit is %d", n,
                       prefix[0] ? " under " : "", prefix, SCHEMA_MAX_PARAMS);
    for (uint32_t k = 0; k < n; k++) {
        const sylva_param_spec *p = &spec[k];
        if (!p->name) {
            entry_place(place, sizeof place, prefix, k);
            return err_set(err, "parameter at %s has no name (NULL); names are [a-z][a-z0-9_]*",
                           place);
        }
        if (!plugin_name_is_valid(p->name)) {
            entry_place(place, sizeof place, prefix, k);
            return err_set(err, "parameter name \"%.*s\" (%s) is not a valid name: a lowercase "
                           "letter, then lowercase letters, digits or '_', at most %d bytes",
                           PLUGIN_NAME_MAX + 1, p->name, place, PLUGIN_NAME_MAX);
        }
        char path[SCHEMA_PATH_MAX];
        snprintf(path, sizeof path, "%s%s", prefix, p->name);
        for (uint32_t j = 0; j < k; j++)
            if (spec[j].name && !strcmp(spec[j].name, p->name))
                return spec_fail(err, path, "the name appears twice (entries %u and %u); names "
                                 "must be unique in their table", j, k);
        if (check_spec(p, path, depth, err)) return -1;
    }
    return 0;
}

int plugin_schema_check(const sylva_param_spec *spec, uint32_t n, err_buf *err)
{
    return check_table(spec, n, "", 0, err);
}

/* --------------------------------------------------------------------------------------------
 * Printing
 */

/* Appends to a fixed buffer; once full, the text ends in "..." instead of overflowing. */
typedef struct text_buf {
    char *s;
    size_t cap, len;
} text_buf;

static void SYLVA_PRINTF(2, 3) text_add(text_buf *t, const char *fmt, ...)
{
    if (t->len + 1 >= t->cap) return;
    va_list ap;
    va_start(ap, fmt);
    int w = vsnprintf(t->s + t->len, t->cap - t->len, fmt, ap);
    va_end(ap);
    if (w < 0) return;
    if ((size_t)w >= t->cap - t->len) {
        t->len = t->cap - 1;
        if (t->cap >= 4) memcpy(t->s + t->cap - 4, "...", 4);
    } else {
        t->len += (size_t)w;
    }
}

static void format_default(char *buf, size_t cap, const sylva_param_spec *p)
{
    text_buf t = {buf, cap, 0};
    buf[0] = '\0';
    const char *unit = p->unit ? p->unit : "";
    const char *sp = p->unit ? " " : "";
    char a[32], b[32];
    if (p->flags & SYLVA_PARAM_REQUIRED) {
        text_add(&t, "required");
        return;
    }
    switch (p->type) {
    case SYLVA_P_BOOL: text_add(&t, "default %s", p->def != 0.0 ? "true" : "false"); break;
    case SYLVA_P_INT:
    case SYLVA_P_REAL: text_add(&t, "default %s%s%s", plugin_number_format(a, p->def), sp, unit); break;
    case SYLVA_P_STRING:
    case SYLVA_P_PATH:
        if (p->def_str) text_add(&t, "default \"%s\"", p->def_str);
        else text_add(&t, "default none");
        break;
    case SYLVA_P_ENUM: text_add(&t, "default %s", p->def_str ? p->def_str : "none"); break;
    case SYLVA_P_VEC3:
    case SYLVA_P_LIST:
        if (!p->def_list) {
            text_add(&t, p->type == SYLVA_P_VEC3 ? "default none" : "default []");
            break;
        }
        text_add(&t, "default [");
        for (uint32_t k = 0; k < p->def_len; k++)
            text_add(&t, "%s%s", k ? ", " : "", plugin_number_format(a, p->def_list[k]));
        text_add(&t, "]%s%s", sp, unit);
        break;
    case SYLVA_P_POLYLINE:
        text_add(&t, "default [");
        for (uint32_t k = 0; p->def_list && k < p->def_len; k++)
            text_add(&t, "%s[%s, %s]", k ? ", " : "", plugin_number_format(a, p->def_list[2 * k]),
                     plugin_number_format(b, p->def_list[2 * k + 1]));
        text_add(&t, "]");
        break;
    case SYLVA_P_GRID: text_add(&t, "default none"); break;
    case SYLVA_P_GROUP: break; /* its members carry the defaults */
    case SYLVA_P_GROUP_LIST: text_add(&t, "default []"); break;
    }
}

/* The range column: value range with unit, enum choices, length bounds. */
static void format_constraints(char *buf, size_t cap, const sylva_param_spec *p)
{
    text_buf t = {buf, cap, 0};
    buf[0] = '\0';
    const ptype_traits *tr = ptype_traits_of(p->type);
    if (!tr) return;
    if (p->type == SYLVA_P_ENUM && p->choices) {
        text_add(&t, "one of:");
        for (uint32_t k = 0; p->choices[k] && k < SCHEMA_MAX_CHOICES; k++)
            text_add(&t, "%s %s", k ? "," : "", p->choices[k]);
    }
    char range[128];
    format_range(range, sizeof range, p);
    if (tr->range && range[0]) {
        text_add(&t, "%s%s", p->type == SYLVA_P_POLYLINE ? "y " : "", range);
        if (p->unit) text_add(&t, " %s", p->unit);
    } else if (tr->range && p->unit) {
        text_add(&t, "in %s", p->unit);
    }
    if (tr->lengths && (p->min_len || p->max_len)) {
        if (t.len) text_add(&t, ", ");
        if (p->min_len && p->max_len)
            text_add(&t, "%u..%u %s", p->min_len, p->max_len, tr->element);
        else if (p->min_len) text_add(&t, "at least %u %s", p->min_len, tr->element);
        else text_add(&t, "at most %u %s", p->max_len, tr->element);
    }
}

static void print_table(FILE *out, const sylva_param_spec *spec, uint32_t n, int indent, int depth)
{
    if (!spec || depth >= SCHEMA_MAX_DEPTH) return;
    if (n > SCHEMA_MAX_PARAMS) n = SCHEMA_MAX_PARAMS;
    size_t wname = 0, wtype = 0, wdef = 0, wcons = 0;
    char def[256], cons[256];
    for (uint32_t k = 0; k < n; k++) {
        const sylva_param_spec *p = &spec[k];
        size_t l = p->name ? strlen(p->name) : 0;
        if (l > wname) wname = l;
        l = strlen(plugin_param_type_name(p->type));
        if (l > wtype) wtype = l;
        format_default(def, sizeof def, p);
        if (strlen(def) > wdef) wdef = strlen(def);
        format_constraints(cons, sizeof cons, p);
        if (strlen(cons) > wcons) wcons = strlen(cons);
    }
    for (uint32_t k = 0; k < n; k++) {
        const sylva_param_spec *p = &spec[k];
        format_default(def, sizeof def, p);
        format_constraints(cons, sizeof cons, p);
        fprintf(out, "%*s%-*s  %-*s  %-*s  ", indent, "", (int)wname, p->name ? p->name : "",
                (int)wtype, plugin_param_type_name(p->type), (int)wdef, def);
        if (wcons) fprintf(out, "%-*s  ", (int)wcons, cons);
        fprintf(out, "%s\n", p->help ? p->help : "");
        if ((p->type == SYLVA_P_GROUP || p->type == SYLVA_P_GROUP_LIST) && p->group)
            print_table(out, p->group, p->n_group, indent + 4, depth + 1);
    }
}

void plugin_schema_print(FILE *out, const sylva_param_spec *spec, uint32_t n, int indent)
{
    print_table(out, spec, n, indent < 0 ? 0 : indent, 0);
}
