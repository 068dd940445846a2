/* wp_species_read.c — Arbaro's and Helios' species files read into wp_params through the
 * parameter table (wp_params.h): the format told by the root element, each value parsed, checked
 * against its row's range and stored, every refusal at its place in the file. */
#include "wp_species_read.h"

#include <errno.h>
#include <stdarg.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wp_xml.h"

/* What a reading needs: the file's name for messages, the list and the error. */
typedef struct reading {
    const char *file;
    wp_species_list *list;
    plugin_err *err;
} reading;

/* The rows x levels a species may give once each. */
#define SEEN_SIZE (128 * WP_LEVELS)

/* A place in the file. */
typedef struct place {
    int line, col;
} place;

static int refuse(const reading *r, place at, const char *fmt, ...) SYLVA_PRINTF(3, 4);

static int refuse(const reading *r, place at, const char *fmt, ...)
{
    char what[PLUGIN_ERR_MAX - 128];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return plugin_fail(r->err, SYLVA_ERR_PARAM, "%s:%d:%d: %s", r->file, at.line, at.col, what);
}

/* "[lo, hi]" with infinite ends open, integers without decimals. */
static void format_range(const wp_param_def *d, char *out, size_t n)
{
    char lo[32], hi[32];
    if (isinf(d->min)) snprintf(lo, sizeof lo, "(-inf");
    else snprintf(lo, sizeof lo, "[%.10g", d->min);
    if (isinf(d->max)) snprintf(hi, sizeof hi, "inf)");
    else snprintf(hi, sizeof hi, "%.10g]", d->max);
    snprintf(out, n, "%s, %s", lo, hi);
}

/* The value `text` (of length n) parsed as row d's type into *v: 0, or 1 when it is no number. */
static int parse_number(const wp_param_def *d, const char *text, size_t n, double *v)
{
    char tmp[64], *end;
    if (n == 0 || n >= sizeof tmp) return 1;
    memcpy(tmp, text, n);
    tmp[n] = '\0';
    errno = 0;
    if (d->type == WP_INT) {
        long l = strtol(tmp, &end, 10);
        *v = (double)l;
        return *end || errno || l < INT_MIN || l > INT_MAX;
    }
    *v = strtod(tmp, &end);
    return *end || !isfinite(*v);
}

/* Refuses value v of row d (named `name`, at `at`; `where` says more, e.g. the level) when it
 * is out of the row's range. */
static int check_range(const reading *r, const wp_param_def *d, const char *name, const char *where, double v,
                       place at)
{
    if (v >= d->min && v <= d->max) return 0;
    char range[80];
    format_range(d, range, sizeof range);
    return refuse(r, at, "'%s' must be %s in %s%s, got %.10g", name, d->type == WP_INT ? "an integer" : "a number",
                  range, where, v);
}

/* Stores the value `text` (n bytes, found at `at`) of row d for `level` into p, or refuses it
 * naming `name` as the file spells it; its range is checked when `checked`. */
static int store_value(const reading *r, const wp_param_def *d, const char *name, int level, const char *text,
                       size_t n, place at, wp_params *p, int checked)
{
    void *slot = wp_param_slot(d, p, level < 0 ? 0 : level);
    if (d->type == WP_TEXT) {
        if (n >= d->text_size)
            return refuse(r, at, "'%s' is longer than %zu bytes; give a shorter name", name, d->text_size - 1);
        memcpy(slot, text, n);
        ((char *)slot)[n] = '\0';
        return 0;
    }
    double v;
    if (parse_number(d, text, n, &v)) {
        char range[80];
        format_range(d, range, sizeof range);
        return refuse(r, at, "'%s' must be %s in %s, got '%.*s'", name, d->type == WP_INT ? "an integer" : "a number",
                      range, (int)(n > 40 ? 40 : n), text);
    }
    int rc = checked ? check_range(r, d, name, "", v, at) : 0;
    if (rc) return rc;
    if (d->type == WP_INT) *(int *)slot = (int)v;
    else *(double *)slot = v;
    return 0;
}

/* Refuses the unknown name `name` at `at`, suggesting the nearest known one. */
static int refuse_unknown(const reading *r, const char *name, int arbaro, place at)
{
    char near[WP_NAME_MAX + 2];
    wp_param_nearest(name, arbaro, near, sizeof near);
    if (near[0]) return refuse(r, at, "unknown parameter '%.64s'; did you mean '%s'?", name, near);
    return refuse(r, at, "unknown parameter '%.64s'; the parameters are those of docs/models/tree_weber_penn.md",
                  name);
}

/* A new species named `name` at the list's end (defaults set), or NULL with err set. */
static wp_params *add_species(const reading *r, const char *name, place at)
{
    wp_species_list *l = r->list;
    if (wp_species_find(l, name)) return refuse(r, at, "species '%.64s' given twice; name each once", name), NULL;
    if (l->count == WP_MAX_SPECIES)
        return plugin_fail(r->err, SYLVA_ERR_LIMIT, "%s:%d:%d: more than %d species; split the file", r->file, at.line,
                           at.col, WP_MAX_SPECIES), NULL;
    wp_params *grown = realloc(l->items, (l->count + 1) * sizeof *grown); /* owned by the list */
    if (!grown) return plugin_fail(r->err, SYLVA_ERR_NOMEM, "%s: out of memory", r->file), NULL;
    l->items = grown;
    wp_params *p = &grown[l->count++];
    wp_params_defaults(p);
    if (strlen(name) >= sizeof p->species)
        return refuse(r, at, "species name longer than %d bytes; give a shorter name", WP_NAME_MAX - 1), NULL;
    snprintf(p->species, sizeof p->species, "%s", name);
    return p;
}

/* Refuses non-blank text of n (an element that holds only elements). */
static int only_elements(const reading *r, const wp_xml_node *n)
{
    for (const char *s = n->text; *s; s++)
        if (!strchr(" \t\r\n", *s))
            return refuse(r, (place){ n->text_line, n->text_col }, "text inside <%s>; it holds only elements", n->name);
    return 0;
}

/* The attribute `name` of n, or NULL with err set. */
static const wp_xml_attr *required_attr(const reading *r, const wp_xml_node *n, const char *name)
{
    const wp_xml_attr *a = wp_xml_attr_find(n, name);
    if (!a) refuse(r, (place){ n->line, n->col }, "<%s> needs a %s=\"...\" attribute", n->name, name);
    return a;
}

/* Refuses any attribute of n other than a and b (either may be NULL). */
static int only_attrs(const reading *r, const wp_xml_node *n, const char *a, const char *b)
{
    for (const wp_xml_attr *at = n->attrs; at; at = at->next)
        if ((!a || strcmp(at->name, a)) && (!b || strcmp(at->name, b)))
            return refuse(r, (place){ at->line, at->col }, "<%s> has no attribute '%.64s'; its attributes are: %s%s%s",
                          n->name, at->name, a ? a : "none", b ? ", " : "", b ? b : "");
    return 0;
}

/* Marks row d (level `level`) as given in `seen`; refuses a second time. */
static int mark_seen(const reading *r, unsigned char *seen, const wp_param_def *d, int level, const char *name,
                     place at)
{
    size_t i = (size_t)(d - wp_param_table) * WP_LEVELS + (size_t)(level < 0 ? 0 : level);
    if (i >= SEEN_SIZE) return plugin_fail(r->err, SYLVA_ERR_INTERNAL, "wp_param_table outgrew SEEN_SIZE");
    if (seen[i]) return refuse(r, at, "'%s' given twice for this species; give it once", name);
    seen[i] = 1;
    return 0;
}

/* One Arbaro <param name=... value=.../> into p. */
static int arbaro_param(const reading *r, const wp_xml_node *n, wp_params *p, unsigned char *seen)
{
    if (strcmp(n->name, "param") != 0)
        return refuse(r, (place){ n->line, n->col }, "<%s> inside <species>; only <param name=... value=.../>", n->name);
    int rc = only_attrs(r, n, "name", "value");
    if (!rc) rc = only_elements(r, n);
    if (!rc && n->children) rc = refuse(r, (place){ n->children->line, n->children->col }, "<param> holds nothing");
    const wp_xml_attr *name = rc ? NULL : required_attr(r, n, "name");
    const wp_xml_attr *value = name ? required_attr(r, n, "value") : NULL;
    if (!value) return rc ? rc : r->err->status;
    int level;
    const wp_param_def *d = wp_param_find_arbaro(name->value, &level);
    place at_name = { name->value_line, name->value_col }, at_value = { value->value_line, value->value_col };
    if (!d) return refuse_unknown(r, name->value, 1, at_name);
    if ((rc = mark_seen(r, seen, d, level, name->value, at_name))) return rc;
    return store_value(r, d, name->value, level, value->value, strlen(value->value), at_value, p, 1);
}

/* The naming attribute `attr` of a species element n, which must be <elem attr=...> with no
 * other attribute, inside <parent>; NULL with err set otherwise. */
static const wp_xml_attr *species_name(const reading *r, const wp_xml_node *n, const char *elem, const char *attr,
                                       const char *parent)
{
    if (strcmp(n->name, elem) != 0) {
        refuse(r, (place){ n->line, n->col }, "<%s> inside <%s>; only <%s %s=...>", n->name, parent, elem, attr);
        return NULL;
    }
    return only_attrs(r, n, attr, NULL) ? NULL : required_attr(r, n, attr);
}

/* One Arbaro <species name=...> into the list. */
static int arbaro_species(const reading *r, const wp_xml_node *n)
{
    const wp_xml_attr *name = species_name(r, n, "species", "name", "arbaro");
    if (!name) return r->err->status;
    int rc;
    wp_params *p = add_species(r, name->value, (place){ name->value_line, name->value_col });
    if (!p) return r->err->status;
    if ((rc = only_elements(r, n))) return rc;
    unsigned char seen[SEEN_SIZE] = { 0 };
    seen[(size_t)(wp_param_find("Species") - wp_param_table) * WP_LEVELS] = 1; /* given by name=... */
    for (const wp_xml_node *c = n->children; c && !rc; c = c->next) rc = arbaro_param(r, c, p, seen);
    return rc;
}

/* Helios' fields that are its own (files of its renderer) and not Weber-Penn parameters. */
static const char *const helios_own[] = { "LeafFile", "WoodFile", "WoodColor", "LeafAngleDist" };

/* Notes the Helios-only field `name` in the list's `ignored`, once. */
static void note_ignored(wp_species_list *l, const char *name)
{
    size_t n = strlen(l->ignored), k = strlen(name);
    for (const char *s = strstr(l->ignored, name); s; s = strstr(s + 1, name))
        if ((s == l->ignored || s[-1] == ',') && (s[k] == ',' || s[k] == '\0')) return;
    if (n + k + 2 < sizeof l->ignored) snprintf(l->ignored + n, sizeof l->ignored - n, "%s%s", n ? "," : "", name);
}

static int is_helios_own(const char *name)
{
    for (size_t i = 0; i < sizeof helios_own / sizeof helios_own[0]; i++)
        if (strcmp(name, helios_own[i]) == 0) return 1;
    return 0;
}

/* The place of text[k] when text[first] (the first non-blank) is at `start`. */
static place place_in_text(const char *text, size_t first, size_t k, place start)
{
    for (size_t i = first; i < k; i++) {
        if (text[i] == '\n') start.line++, start.col = 1;
        else start.col++;
    }
    return start;
}

/* The next blank-separated token of text from *pos: its start and length (0 at the end). */
static size_t next_token(const char *text, size_t *pos, size_t *start)
{
    while (text[*pos] && strchr(" \t\r\n", text[*pos])) (*pos)++;
    *start = *pos;
    while (text[*pos] && !strchr(" \t\r\n", text[*pos])) (*pos)++;
    return *pos - *start;
}

/* One Helios tree being read: the rows given, and where each per-level value is, for the range
 * checks made once Levels is known. */
typedef struct helios_tree_state {
    wp_params *p;
    unsigned char seen[SEEN_SIZE];
    place at[SEEN_SIZE]; /* row * WP_LEVELS + level */
} helios_tree_state;

/* The blank-separated values of a Helios field: one for a general row (its range checked), one
 * per level for a per-level row (their places kept for helios_check_levels). */
static int helios_values(const reading *r, const wp_xml_node *n, const wp_param_def *d, helios_tree_state *t)
{
    size_t pos = 0, start, first = strspn(n->text, " \t\r\n"), len, row = (size_t)(d - wp_param_table);
    int want = d->per_level ? WP_LEVELS : 1, got = 0, rc = 0;
    const char *each = want > 1 ? "s, one per level 0 to 3" : "";
    place at0 = { n->text_line, n->text_col };
    if (d->type == WP_TEXT) {
        len = strlen(n->text + first);
        while (len && strchr(" \t\r\n", n->text[first + len - 1])) len--;
        return store_value(r, d, n->name, -1, n->text + first, len, at0, t->p, 1);
    }
    while (!rc && (len = next_token(n->text, &pos, &start)) > 0) {
        place at = place_in_text(n->text, first, start, at0);
        if (got == want) return refuse(r, at, "<%s> takes %d value%s; remove the extra ones", n->name, want, each);
        if (d->per_level) t->at[row * WP_LEVELS + (size_t)got] = at;
        rc = store_value(r, d, n->name, d->per_level ? got : -1, n->text + start, len, at, t->p, !d->per_level);
        got++;
    }
    if (!rc && got < want) rc = refuse(r, at0, "<%s> takes %d value%s, got %d", n->name, want, each, got);
    return rc;
}

/* The per-level values given for t's tree, range-checked at the levels Arbaro reads for its
 * Levels (Helios fills the levels a tree does not grow with zeros). */
static int helios_check_levels(const reading *r, const helios_tree_state *t)
{
    for (size_t row = 0; row < wp_param_count; row++) {
        const wp_param_def *d = &wp_param_table[row];
        if (!d->per_level || !t->seen[row * WP_LEVELS]) continue;
        for (int l = 0; l < WP_LEVELS; l++) {
            if (!wp_param_used(d, t->p->levels, l)) continue;
            const void *slot = wp_param_slot(d, t->p, l);
            double v = d->type == WP_INT ? *(const int *)slot : *(const double *)slot;
            char where[64];
            snprintf(where, sizeof where, " at level %d", l);
            int rc = check_range(r, d, d->name, where, v, t->at[row * WP_LEVELS + (size_t)l]);
            if (rc) return rc;
        }
    }
    return 0;
}

/* One Helios field element into t's tree. */
static int helios_field(const reading *r, const wp_xml_node *n, helios_tree_state *t)
{
    place at = { n->line, n->col };
    int rc = only_attrs(r, n, NULL, NULL);
    if (!rc && n->children) rc = refuse(r, (place){ n->children->line, n->children->col }, "<%s> holds only text", n->name);
    if (rc) return rc;
    if (is_helios_own(n->name)) return note_ignored(r->list, n->name), 0;
    const char *name = strcmp(n->name, "BaseSplits") == 0 ? "0BaseSplits" : n->name;
    const wp_param_def *d = wp_param_find(name);
    if (!d || strcmp(name, "Species") == 0) return refuse_unknown(r, n->name, 0, at);
    if ((rc = mark_seen(r, t->seen, d, -1, n->name, at))) return rc;
    return helios_values(r, n, d, t);
}

/* One Helios <WeberPennTree label=...> into the list. */
static int helios_tree(const reading *r, const wp_xml_node *n)
{
    const wp_xml_attr *label = species_name(r, n, "WeberPennTree", "label", "helios");
    if (!label) return r->err->status;
    place at = { label->value_line, label->value_col };
    if (!label->value[0]) return refuse(r, at, "empty label; name the tree, e.g. label=\"Almond\"");
    helios_tree_state *t = calloc(1, sizeof *t); /* owned here */
    if (!t) return plugin_fail(r->err, SYLVA_ERR_NOMEM, "%s: out of memory", r->file);
    t->p = add_species(r, label->value, at);
    int rc = t->p ? only_elements(r, n) : r->err->status;
    for (const wp_xml_node *c = n->children; c && !rc; c = c->next) rc = helios_field(r, c, t);
    if (!rc) rc = helios_check_levels(r, t);
    /* Helios grows one trunk and never reads nBranches at level 0 (0 in most of its species, 40
     * in its olive); Arbaro reads 0Branches as the number of trunks. */
    if (!rc) t->p->level[0].branches = 1;
    free(t);
    return rc;
}

/* The root's species, by its format. */
static int read_root(const reading *r, const wp_xml_node *root)
{
    int arbaro = strcmp(root->name, "arbaro") == 0;
    if (!arbaro && strcmp(root->name, "helios") != 0)
        return refuse(r, (place){ root->line, root->col }, "root element <%s>; a species file starts <arbaro> or <helios>",
                      root->name);
    int rc = only_attrs(r, root, NULL, NULL);
    if (!rc) rc = only_elements(r, root);
    for (const wp_xml_node *c = root->children; c && !rc; c = c->next) rc = arbaro ? arbaro_species(r, c) : helios_tree(r, c);
    if (!rc && r->list->count == 0)
        rc = refuse(r, (place){ root->line, root->col }, "no species in <%s>; give at least one %s", root->name,
                    arbaro ? "<species name=...>" : "<WeberPennTree label=...>");
    return rc;
}

int wp_species_read_buffer(const char *file, const char *buf, size_t len, wp_species_list *out, plugin_err *err)
{
    memset(out, 0, sizeof *out);
    wp_xml_node *root = NULL;
    int rc = wp_xml_parse(file, buf, len, &root, err);
    if (rc) return rc;
    reading r = { file, out, err };
    rc = read_root(&r, root);
    wp_xml_free(root);
    if (rc) wp_species_list_free(out);
    return rc;
}

int wp_species_read_file(const char *path, wp_species_list *out, plugin_err *err)
{
    memset(out, 0, sizeof *out);
    FILE *f = fopen(path, "rb");
    if (!f) return plugin_fail(err, SYLVA_ERR_IO, "%s: cannot open the species file: %s", path, strerror(errno));
    char *buf = malloc(WP_XML_MAX_BYTES + 1); /* owned here */
    size_t n = buf ? fread(buf, 1, WP_XML_MAX_BYTES + 1, f) : 0;
    int bad = buf ? ferror(f) : 0;
    fclose(f);
    int rc;
    if (!buf) rc = plugin_fail(err, SYLVA_ERR_NOMEM, "%s: out of memory", path);
    else if (bad) rc = plugin_fail(err, SYLVA_ERR_IO, "%s: cannot read the species file", path);
    else rc = wp_species_read_buffer(path, buf, n, out, err);
    free(buf);
    return rc;
}

void wp_species_list_free(wp_species_list *list)
{
    free(list->items);
    memset(list, 0, sizeof *list);
}

const wp_params *wp_species_find(const wp_species_list *list, const char *name)
{
    for (size_t i = 0; i < list->count; i++)
        if (strcmp(list->items[i].species, name) == 0) return &list->items[i];
    return NULL;
}
