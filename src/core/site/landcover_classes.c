/* landcover_classes.c — the map's codes at the nodes turned into the scene's classes: the codes
 * counted, the legend chosen (auto: the map's own class names when it carries them, else NLCD
 * 2011 when every code is NLCD's and the map lies in North America, else CORINE when every code
 * is a CLC grid code, else none), each code named and given a kind by the legend and the
 * scene's classes, the codes no one names reported with their node counts, and one summary
 * line. */
#include "site/landcover_codes.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TABLE_SIZE (2u * LAND_COVER_MAX_CLASSES) /* open addressing, at most half full */

typedef struct code_slot {
    int32_t code;
    int used;
    uint64_t nodes;
    uint16_t cls;       /* the class index, or LAND_COVER_NONE for a no-data code */
} code_slot;

static code_slot *slot_of(code_slot *t, int32_t code)
{
    uint32_t h = ((uint32_t)code * 2654435761u) % TABLE_SIZE;
    while (t[h].used && t[h].code != code) h = (h + 1) % TABLE_SIZE;
    return &t[h];
}

/* Counts the nodes of each code into t; *distinct codes. -1 with err set past the limit. */
static int count_codes(const int32_t *code, size_t n, code_slot *t, uint32_t *distinct, err_buf *err)
{
    *distinct = 0;
    for (size_t k = 0; k < n; k++) {
        if (code[k] == LANDCOVER_NO_CODE) continue;
        code_slot *s = slot_of(t, code[k]);
        if (!s->used) {
            if (++*distinct > LAND_COVER_MAX_CLASSES)
                return err_set(err, "it has more than %u distinct codes on the site; a land-cover map is "
                               "classified (one code per class), not a continuous raster", LAND_COVER_MAX_CLASSES);
            *s = (code_slot){.code = code[k], .used = 1};
        }
        s->nodes++;
    }
    return 0;
}

static int by_code(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

/* The distinct codes, ascending (malloc'ed), or NULL when out of memory. */
static int64_t *sorted_codes(const code_slot *t, uint32_t distinct)
{
    int64_t *codes = malloc((distinct + 1) * sizeof *codes);
    if (!codes) return NULL;
    for (uint32_t h = 0, n = 0; h < TABLE_SIZE; h++)
        if (t[h].used) codes[n++] = t[h].code;
    qsort(codes, distinct, sizeof *codes, by_code);
    return codes;
}

static int in_north_america(const landcover_codes *c)
{
    const double *p = c->centre_lonlat;
    return c->has_centre && p[0] >= -170.0 && p[0] <= -50.0 && p[1] >= 14.0 && p[1] <= 84.0;
}

/* The legend `auto` stands for, and why, in `why`. */
static landcover_legend choose_legend(const landcover_codes *c, const int64_t *codes, uint32_t n, char *why,
                                      size_t size)
{
    if (c->n_names) return snprintf(why, size, "auto: the map names its classes"), LEGEND_NAMES;
    if (landcover_legend_fits(LEGEND_NLCD2011, codes, n) && in_north_america(c))
        return snprintf(why, size, "auto: NLCD codes, in North America"), LEGEND_NLCD2011;
    if (landcover_legend_fits(LEGEND_CORINE, codes, n))
        return snprintf(why, size, "auto: CORINE grid codes"), LEGEND_CORINE;
    snprintf(why, size, "auto: no shipped legend holds every code");
    return LEGEND_NONE;
}

/* What one code is: the legend's class, then the scene's classes over it. */
typedef struct code_class {
    const char *name;   /* NULL: "code N" */
    land_kind kind;
    int no_data, known;
} code_class;

static code_class resolve(const landcover_source *src, landcover_legend l, const landcover_codes *c, int64_t code)
{
    code_class r = {NULL, LAND_UNKNOWN, 0, 0};
    const legend_class *lc = landcover_legend_class(l, code);
    if (lc) r = (code_class){lc->name, lc->kind, lc->no_data, 1};
    const char *name = l == LEGEND_NAMES ? landcover_codes_name(c, code) : NULL;
    if (name) r.name = name, r.kind = landcover_kind_of_name(name, &r.no_data), r.known = 1;
    for (uint32_t i = 0; i < src->n_classes; i++) {
        const landcover_class_spec *s = &src->classes[i];
        if (s->code != code) continue;
        if (s->name) r.name = s->name;
        if (s->kind >= 0) r.kind = (land_kind)s->kind;
        r.no_data = 0, r.known = 1;
    }
    return r;
}

/* Appends a class to lc; -1 with err set when out of memory. */
static int add_class(land_cover *lc, int64_t code, const code_class *r, uint64_t nodes, err_buf *err)
{
    char fallback[40];
    snprintf(fallback, sizeof fallback, "code %lld", (long long)code);
    land_class *cls = &lc->classes[lc->n_classes];
    *cls = (land_class){code, strdup(r->name ? r->name : fallback), r->kind, nodes};
    if (!cls->name) return err_nomem(err, "out of memory naming the land-cover classes");
    lc->n_classes++;
    return 0;
}

/* "1,234,567" */
static const char *grouped(uint64_t v, char buf[32])
{
    char digits[24];
    int n = snprintf(digits, sizeof digits, "%llu", (unsigned long long)v), o = 0;
    for (int i = 0; i < n; i++) {
        if (i && (n - i) % 3 == 0) buf[o++] = ',';
        buf[o++] = digits[i];
    }
    buf[o] = '\0';
    return buf;
}

/* The codes no one names, with their nodes, as one warning. */
static void warn_unknown(FILE *log, const land_cover *lc, const code_class *rs, const char *source)
{
    char list[1024] = "", num[32];
    size_t used = 0;
    uint32_t n = 0;
    for (uint32_t i = 0; i < lc->n_classes; i++) {
        if (rs[i].known) continue;
        n++;
        if (used < sizeof list)
            used += (size_t)snprintf(list + used, sizeof list - used, "%s%lld (%s nodes)", n > 1 ? ", " : "",
                                     (long long)lc->classes[i].code, grouped(lc->classes[i].nodes, num));
    }
    if (n && log)
        fprintf(log, "sylva: warning: landcover: the legend %s has no class for %s %s of '%s'; %s kept as "
                "kind unknown (name %s under landcover: classes:)\n", lc->legend, n > 1 ? "codes" : "code", list,
                source, n > 1 ? "they are" : "it is", n > 1 ? "them" : "it");
}

/* The share of each broad kind among the classed nodes, largest first, into buf. */
static void kind_shares(const land_cover *lc, char *buf, size_t size)
{
    uint64_t by_kind[LAND_KIND_COUNT] = {0}, total = 0;
    for (uint32_t i = 0; i < lc->n_classes; i++) {
        by_kind[land_kind_broad(lc->classes[i].kind)] += lc->classes[i].nodes;
        total += lc->classes[i].nodes;
    }
    size_t used = 0;
    buf[0] = '\0';
    for (int listed = 0; total && used < size; listed++) {
        int best = -1;
        for (int k = 0; k < LAND_KIND_COUNT; k++)
            if (by_kind[k] && (best < 0 || by_kind[k] > by_kind[best])) best = k;
        if (best < 0) break;
        used += (size_t)snprintf(buf + used, size - used, "%s%s %.1f %%", listed ? ", " : "", land_kind_names[best],
                                 100.0 * (double)by_kind[best] / (double)total);
        by_kind[best] = 0;
    }
}

static void print_summary(FILE *log, const land_cover *lc, const char *why, size_t nodes)
{
    if (!log) return;
    char shares[1024], a[32], b[32];
    kind_shares(lc, shares, sizeof shares);
    fprintf(log, "sylva: landcover: %s, legend %s (%s), %u class%s, %s nodes on the site grid (%s with no data)%s%s\n",
            lc->source, lc->legend, why, lc->n_classes, lc->n_classes == 1 ? "" : "es", grouped(nodes, a),
            grouped(lc->no_data, b),
            shares[0] ? "; " : "", shares);
}

/* Fills lc's classes from the counted codes and marks each code's class in the table. */
static int make_classes(const landcover_source *src, landcover_legend l, const landcover_codes *c, code_slot *t,
                        const int64_t *codes, uint32_t distinct, land_cover *lc, code_class *rs, err_buf *err)
{
    for (uint32_t i = 0; i < distinct; i++) {
        code_slot *s = slot_of(t, (int32_t)codes[i]);
        code_class r = resolve(src, l, c, codes[i]);
        s->cls = LAND_COVER_NONE;
        if (r.no_data) {
            lc->no_data += s->nodes;
            continue;
        }
        rs[lc->n_classes] = r;
        s->cls = (uint16_t)lc->n_classes;
        if (add_class(lc, codes[i], &r, s->nodes, err)) return -1;
    }
    return 0;
}

/* The land cover's frame, names and arrays; NULL when out of memory. */
static land_cover *land_cover_for(const landcover_source *src, const landcover_grid *g, landcover_legend l,
                                  uint32_t distinct)
{
    land_cover *lc = calloc(1, sizeof *lc);
    if (!lc) return NULL;
    *lc = (land_cover){.nx = g->nx, .ny = g->ny, .x0 = g->x0, .y0 = g->y0, .dx = g->dx, .dy = g->dy};
    const char *slash = strrchr(src->path, '/');
    lc->source = strdup(slash ? slash + 1 : src->path);
    lc->legend = strdup(landcover_legend_name(l));
    lc->classes = calloc(distinct + 1, sizeof *lc->classes);
    lc->node_class = malloc((size_t)g->nx * g->ny * sizeof *lc->node_class);
    if (lc->source && lc->legend && lc->classes && lc->node_class) return lc;
    land_cover_free(lc);
    return NULL;
}

static land_cover *classify_counted(const landcover_source *src, const landcover_grid *g, landcover_codes *c,
                                    code_slot *t, const int64_t *codes, uint32_t distinct, FILE *warnings,
                                    FILE *summary, err_buf *err)
{
    char why[96] = "given";
    landcover_legend l = src->legend == LEGEND_AUTO ? choose_legend(c, codes, distinct, why, sizeof why) : src->legend;
    land_cover *lc = land_cover_for(src, g, l, distinct);
    code_class *rs = calloc(distinct + 1, sizeof *rs);
    if (!lc || !rs) {
        free(rs), land_cover_free(lc);
        err_nomem(err, "out of memory for the land cover's classes");
        return NULL;
    }
    if (make_classes(src, l, c, t, codes, distinct, lc, rs, err)) {
        free(rs), land_cover_free(lc);
        return NULL;
    }
    size_t n = (size_t)g->nx * g->ny;
    for (size_t k = 0; k < n; k++) {
        lc->node_class[k] = c->code[k] == LANDCOVER_NO_CODE ? LAND_COVER_NONE : slot_of(t, c->code[k])->cls;
        lc->no_data += c->code[k] == LANDCOVER_NO_CODE;
    }
    warn_unknown(warnings, lc, rs, src->path);
    print_summary(summary, lc, why, n);
    free(rs);
    return lc;
}

land_cover *landcover_classify(const landcover_source *src, const landcover_grid *g, landcover_codes *c,
                               FILE *warnings, FILE *summary, err_buf *err)
{
    code_slot *t = calloc(TABLE_SIZE, sizeof *t); /* freed below */
    uint32_t distinct = 0;
    int64_t *codes = NULL;
    land_cover *lc = NULL;
    if (!t) err_nomem(err, "out of memory counting the land-cover codes");
    else if (!count_codes(c->code, (size_t)g->nx * g->ny, t, &distinct, err)) {
        if (!(codes = sorted_codes(t, distinct))) err_nomem(err, "out of memory counting the land-cover codes");
        else lc = classify_counted(src, g, c, t, codes, distinct, warnings, summary, err);
    }
    free(codes);
    free(t);
    return lc;
}
