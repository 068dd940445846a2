/* tree_lsystem.c — the tree plugin `tree_lsystem`: L-systems in the L-parser language (001,
 * MODELS.md §3) grown to the age each variant asks for by the branch-number law (002,
 * MODELS.md §4). This is the plugin file, the only one that calls the host: it owns the
 * descriptor, the plugin state and the order of work; the schema (lsys_schema.c), reading,
 * derivation, the turtle, the mesh, box counting and the law are the model, which reports
 * failures in an plugin_err and takes warnings and random numbers as callbacks.
 *
 * generate() for one variant:
 *   1. the variant's height H(age) from height and height_by_age;
 *   2. its recursion level: the full level, or — with branch_law — the level whose branch count
 *      is nearest N2 = N1 (H1 / H2)^(-D/2) (002 eq. 6), N1 and D from the full-grown tree;
 *   3. derivation to that level; a first turtle pass for the bounds; a second that builds the
 *      mesh scaled to H(age) (or by unit_length metres per file unit) and rasterises the side
 *      silhouette for D_B (002 eq. 3).
 * Randomness (`~`) comes from api->rng_init(host, "tree_lsystem.jitter", 0), restarted for
 * every pass, so both passes and every run see the same turns.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "branch_law.h"
#include "lsys_derive.h"
#include "lsys_mesh.h"
#include "lsys_palette.h"
#include "lsys_schema.h"
#include "lsys_silhouette.h"
#include "lsys_system.h"
#include "lsys_texture.h"
#include "lsys_turtle.h"
#include "plugin_host.h"
#include "plugin_params.h"
#include "sylva/plugin.h"
#include "sylva/tree_stats.h"

#define MAX_NESTING 65536       /* [ ] and { } nesting */
#define START_COLOUR 2          /* Lparser's starting colour index */

typedef struct palette_override {
    int32_t index;
    float albedo[3], transmittance[3];
    int has_transmittance;
} palette_override;

/* The plugin's state for one species. Owned by the plugin until tree_destroy. */
typedef struct tree_state {
    lsys_system *sys;               /* owned */
    uint32_t recursion;
    double angle, thickness, min_thickness, base_length, height;
    double unit_length;             /* metres per file unit; 0: scale each variant to its height */
    uint32_t sides;
    int flat;                       /* prisms */
    uint64_t max_string, max_segments, max_polygons;
    uint32_t max_polygon_vertices;
    double *height_by_age;          /* owned: x y pairs */
    uint32_t n_height_by_age;
    int branch_law;
    double law_height;              /* H1 of a measured tree (0: the full-grown tree's) */
    double law_branches;            /* its N1 (with law_height) */
    double box_dimension;           /* 0: measure */
    double bark_tile;               /* metres of branch per repeat of the bark texture */
    int32_t bark_texture, leaf_texture; /* host texture ids, -1: none (the key says off) */
    palette_override *palette;      /* owned */
    uint32_t n_palette;
    int32_t *material;              /* owned: material id per key (-1: not made yet) */
    uint32_t n_material;
    /* The full-grown tree's figures for the branch-number law, made once. */
    int law_ready;
    uint64_t *level_branches;       /* owned: recursion + 1 counts */
    double law_dimension;
    int warned;                     /* structure warnings given once */
    int has_last;
    sylva_tree_stats last;
} tree_state;

static void warn_to_host(void *ctx, const char *sentence)
{
    const plugin_host_ref *h = ctx;
    h->api->log(h->host, SYLVA_LOG_WARN, "%s", sentence);
}

static int fail(const sylva_host_api *api, sylva_host *host, int lsys_status, const plugin_err *e)
{
    api->error(host, "%s", e->msg);
    switch (lsys_status) {
    case LSYS_ERR_LIMIT: return SYLVA_ERR_LIMIT;
    case LSYS_ERR_NOMEM: return SYLVA_ERR_NOMEM;
    case LSYS_ERR_IO: return SYLVA_ERR_IO;
    default: return SYLVA_ERR_PARAM;
    }
}

static void tree_destroy(void *state)
{
    tree_state *s = state;
    if (!s) return;
    lsys_system_free(s->sys);
    free(s->height_by_age);
    free(s->palette);
    free(s->material);
    free(s->level_branches);
    free(s);
}

static int read_palette(tree_state *s, plugin_params *params)
{
    const sylva_host_api *api = params->api;
    sylva_host *host = params->host;
    const sylva_value *v = plugin_param(params, "palette");
    if (params->status || !v->len) return params->status;
    s->palette = calloc(v->len, sizeof *s->palette);
    if (!s->palette) {
        api->error(host, "tree_lsystem: out of memory for the palette");
        return SYLVA_ERR_NOMEM;
    }
    for (uint32_t i = 0; i < v->len; i++) {
        plugin_params item = plugin_params_in(params, &v->items[i]);
        const sylva_params *e = item.block;
        palette_override *p = &s->palette[i];
        p->index = (int32_t)plugin_param_int(&item, "index");
        const sylva_value *a = plugin_param(&item, "albedo"), *t = plugin_param(&item, "transmittance");
        if (params->status) return params->status;
        for (int k = 0; k < 3; k++) p->albedo[k] = (float)a->list[k];
        if (t->is_set) {
            p->has_transmittance = 1;
            for (int k = 0; k < 3; k++) {
                p->transmittance[k] = (float)t->list[k];
                if (p->albedo[k] + p->transmittance[k] > 1.0f)
                    return api->param_error(host, e, "transmittance",
                                            "albedo + transmittance is %g in channel %d; a leaf cannot scatter "
                                            "more than it receives (at most 1)",
                                            p->albedo[k] + p->transmittance[k], k);
            }
        }
        for (uint32_t j = 0; j < i; j++)
            if (s->palette[j].index == p->index)
                return api->param_error(host, e, "index", "colour index %d is given twice in the palette",
                                        p->index);
    }
    s->n_palette = v->len;
    return SYLVA_OK;
}

static int read_height_by_age(tree_state *s, plugin_params *r)
{
    const sylva_host_api *api = r->api;
    sylva_host *host = r->host;
    const sylva_params *params = r->block;
    const sylva_value *v = plugin_param(r, "height_by_age");
    if (r->status) return r->status;
    s->n_height_by_age = v->len;
    s->height_by_age = malloc(2 * (size_t)v->len * sizeof *s->height_by_age);
    if (!s->height_by_age) {
        api->error(host, "tree_lsystem: out of memory");
        return SYLVA_ERR_NOMEM;
    }
    memcpy(s->height_by_age, v->list, 2 * (size_t)v->len * sizeof *s->height_by_age);
    for (uint32_t i = 0; i < v->len; i++)
        if (!(v->list[2 * i] >= 0 && v->list[2 * i] <= 1))
            return api->param_error(host, params, "height_by_age",
                                    "age %g of point %u is outside [0, 1]; ages are normalised (1 = full grown)",
                                    v->list[2 * i], i);
    return SYLVA_OK;
}

/* The species' bark texture handed to the host: its id, or a negative status (message set). */
static int32_t bark_texture(int bark, const sylva_host_api *api, sylva_host *host)
{
    const size_t texels = (size_t)LSYS_BARK_TEXTURE_SIZE * LSYS_BARK_TEXTURE_SIZE;
    float *height = malloc(texels * sizeof *height); /* owned here */
    uint8_t *rgba = malloc(texels * 4);              /* owned here */
    int32_t id = SYLVA_ERR_NOMEM;
    if (height && rgba) {
        char name[64];
        snprintf(name, sizeof name, "tree_lsystem bark %s", lsys_bark_texture_names[bark]);
        lsys_texture_bark(bark, height, rgba);
        id = api->texture_new(host, name, LSYS_BARK_TEXTURE_SIZE, LSYS_BARK_TEXTURE_SIZE, rgba);
    } else {
        api->error(host, "tree_lsystem: out of memory for the bark texture");
    }
    free(height);
    free(rgba);
    return id;
}

/* The species' leaf texture handed to the host: its id, or a negative status (message set). */
static int32_t leaf_texture(int leaf, const sylva_host_api *api, sylva_host *host)
{
    uint8_t *rgba = malloc((size_t)LSYS_LEAF_TEXTURE_SIZE * LSYS_LEAF_TEXTURE_SIZE * 4); /* owned here */
    int32_t id = SYLVA_ERR_NOMEM;
    if (rgba && !lsys_texture_leaf(leaf, rgba)) {
        char name[64];
        snprintf(name, sizeof name, "tree_lsystem leaf %s", lsys_leaf_texture_names[leaf]);
        id = api->texture_new(host, name, LSYS_LEAF_TEXTURE_SIZE, LSYS_LEAF_TEXTURE_SIZE, rgba);
    } else {
        api->error(host, "tree_lsystem: out of memory for the leaf texture");
    }
    free(rgba);
    return id;
}

/* The species' textures (the bark and leaf keys), made once. */
static int make_textures(tree_state *s, plugin_params *r)
{
    const sylva_host_api *api = r->api;
    sylva_host *host = r->host;
    int bark = (int)plugin_param_int(r, "bark"), leaf = (int)plugin_param_int(r, "leaf");
    if (r->status) return r->status;
    s->bark_texture = s->leaf_texture = -1;
    if (bark != LSYS_BARK_TEXTURE_OFF && (s->bark_texture = bark_texture(bark, api, host)) < 0) return s->bark_texture;
    if (leaf != LSYS_LEAF_TEXTURE_OFF && (s->leaf_texture = leaf_texture(leaf, api, host)) < 0) return s->leaf_texture;
    return SYLVA_OK;
}

/* H(age) / height: the polyline, flat beyond its ends; at a step the later point wins. */
static double height_fraction(const tree_state *s, double age)
{
    const double *p = s->height_by_age;
    uint32_t n = s->n_height_by_age;
    if (age <= p[0]) return p[1];
    for (uint32_t i = 1; i < n; i++) {
        double x0 = p[2 * i - 2], x1 = p[2 * i];
        if (age < x1) return p[2 * i - 1] + (age - x0) / (x1 - x0) * (p[2 * i + 1] - p[2 * i - 1]);
    }
    return p[2 * n - 1];
}

static int tree_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params, void **state)
{
    *state = NULL;
    plugin_params r = plugin_params_open(api, host, params);
    const sylva_value *vsource = plugin_param(&r, "source"), *vfile = plugin_param(&r, "file");
    int lenient = (int)plugin_param_int(&r, "lenient");
    if (r.status) return r.status; /* the host has the sentence */
    const char *source = vsource->s, *file = vfile->s;
    int has_source = vsource->is_set && source, has_file = vfile->is_set && file;
    if (has_source == has_file)
        return api->param_error(host, params, has_source ? "file" : "source",
                                "give the L-system either inline as source or as a file path, %s",
                                has_source ? "not both" : "one of them is required");
    tree_state *s = calloc(1, sizeof *s); /* owned by the plugin until tree_destroy */
    if (!s) {
        api->error(host, "tree_lsystem: out of memory for its state");
        return SYLVA_ERR_NOMEM;
    }
    plugin_host_ref ref = {api, host};
    lsys_read_options ro = {.lenient = lenient, .warn = warn_to_host, .warn_ctx = &ref};
    plugin_err e = {0};
    int rc = has_file ? lsys_read_file(file, &ro, &s->sys, &e)
                      : lsys_read(source, strlen(source), "source", &ro, &s->sys, &e);
    if (rc) {
        tree_destroy(s);
        api->param_error(host, params, has_source ? "source" : "file", "%s", e.msg);
        return rc == LSYS_ERR_IO ? SYLVA_ERR_IO : rc == LSYS_ERR_NOMEM ? SYLVA_ERR_NOMEM
               : rc == LSYS_ERR_LIMIT ? SYLVA_ERR_LIMIT : SYLVA_ERR_PARAM;
    }
    const lsys_system *sys = s->sys;
    const sylva_value *v;
    s->recursion = (v = plugin_param(&r, "recursion"))->is_set ? (uint32_t)v->i : sys->recursion;
    s->angle = (v = plugin_param(&r, "angle"))->is_set ? v->r : sys->angle_deg;
    s->thickness = (v = plugin_param(&r, "thickness"))->is_set ? v->r : sys->thickness;
    s->min_thickness = (v = plugin_param(&r, "min_thickness"))->is_set ? v->r : sys->min_thickness;
    double base_length = plugin_param_real(&r, "base_length");
    s->base_length = base_length > 0 ? base_length : sys->base_length;
    s->height = plugin_param_real(&r, "height");
    s->unit_length = plugin_param_real(&r, "unit_length");
    int64_t shape = plugin_param_int(&r, "segment_shape");
    s->flat = shape == 1 || (shape == 0 && sys->shape == 0);
    s->sides = s->flat ? 4 : (uint32_t)plugin_param_int(&r, "sides");
    s->max_string = (uint64_t)plugin_param_int(&r, "max_string");
    s->max_segments = (uint64_t)plugin_param_int(&r, "max_segments");
    s->max_polygons = (uint64_t)plugin_param_int(&r, "max_polygons");
    if (sys->poly_limit && sys->poly_limit < s->max_polygons) s->max_polygons = sys->poly_limit;
    s->max_polygon_vertices = (uint32_t)plugin_param_int(&r, "max_polygon_vertices");
    s->branch_law = (int)plugin_param_int(&r, "branch_law");
    s->box_dimension = plugin_param_real(&r, "box_dimension");
    s->law_height = plugin_param_real(&r, "law_height");
    s->law_branches = (double)plugin_param_int(&r, "law_branches");
    s->bark_tile = plugin_param_real(&r, "bark_tile_length");
    if (r.status) {
        tree_destroy(s);
        return r.status;
    }
    if ((s->law_height > 0) != (s->law_branches > 0)) {
        const char *given = s->law_height > 0 ? "law_height" : "law_branches";
        tree_destroy(s);
        return api->param_error(host, params, given,
                                "the branch-number law's measured tree needs both law_height and law_branches "
                                "(H1 and N1 of 002 eq. 6); give the other one too, or neither to start from the "
                                "full-grown tree");
    }
    if ((rc = read_palette(s, &r)) || (rc = read_height_by_age(s, &r)) || (rc = make_textures(s, &r))) {
        tree_destroy(s);
        return rc;
    }
    *state = s;
    return SYLVA_OK;
}

/* ---- one turtle pass ---------------------------------------------------------------------- */

typedef struct jitter {
    const sylva_host_api *api;
    sylva_rng rng;
} jitter;

static double jitter_next(void *ctx)
{
    jitter *j = ctx;
    return j->api->rng_uniform(&j->rng);
}

static lsys_turtle_config turtle_config(const tree_state *s, jitter *j)
{
    return (lsys_turtle_config){.angle_deg = s->angle, .thickness = s->thickness, .min_thickness = s->min_thickness,
                                .base_length = s->base_length, .colour = START_COLOUR,
                                .max_segments = s->max_segments, .max_polygons = s->max_polygons,
                                .max_polygon_vertices = s->max_polygon_vertices, .max_depth = MAX_NESTING,
                                .tube_corners = s->flat ? 4 : 8,
                                .random = jitter_next, .random_ctx = j};
}

static int interpret(const tree_state *s, const sylva_host_api *api, sylva_host *host, const unsigned char *str,
                     size_t n, const lsys_sink *sinks, int n_sinks, lsys_turtle_stats *st, plugin_err *e)
{
    jitter j = {.api = api};
    api->rng_init(host, &j.rng, "tree_lsystem.jitter", 0);
    lsys_turtle_config cfg = turtle_config(s, &j);
    return lsys_interpret(str, n, &cfg, sinks, n_sinks, st, e);
}

/* The silhouette raster over the model's side view (x–z), from the bounds. */
static int silhouette_init(box_raster *r, const lsys_turtle_stats *st)
{
    return box_silhouette_init(r, st->lo[0], st->lo[2], st->hi[0] - st->lo[0], st->hi[2] - st->lo[2]);
}

/* ---- the branch-number law's figures of the full-grown tree ---------------------------------- */

typedef struct level_counts {
    uint64_t *branches; /* recursion + 1 counts */
    plugin_err *err;
} level_counts;

static int count_level(void *ctx, uint32_t level, const unsigned char *s, size_t n)
{
    level_counts *c = ctx;
    return branch_count(s, n, &c->branches[level], c->err);
}

static int prepare_law(tree_state *s, const sylva_host_api *api, sylva_host *host)
{
    if (s->law_ready) return SYLVA_OK;
    if (!s->level_branches) s->level_branches = calloc((size_t)s->recursion + 1, sizeof *s->level_branches);
    if (!s->level_branches) {
        api->error(host, "tree_lsystem: out of memory");
        return SYLVA_ERR_NOMEM;
    }
    plugin_err e = {0};
    unsigned char *str = NULL; /* owned here */
    size_t n = 0;
    level_counts counts = {s->level_branches, &e};
    int rc = lsys_derive(s->sys, s->recursion, s->max_string, count_level, &counts, &str, &n, &e);
    if (rc) return fail(api, host, rc, &e);
    s->law_dimension = s->box_dimension;
    if (!(s->law_dimension > 0)) {
        lsys_turtle_stats st;
        rc = interpret(s, api, host, str, n, NULL, 0, &st, &e);
        box_raster r = {0};
        if (!rc && st.segments && !silhouette_init(&r, &st)) {
            lsys_sink sink = lsys_silhouette_sink(&r);
            rc = interpret(s, api, host, str, n, &sink, 1, &st, &e);
            if (!rc) s->law_dimension = box_silhouette_dimension(&r);
        }
        box_raster_free(&r);
    }
    free(str);
    if (rc) return fail(api, host, rc, &e);
    s->law_ready = 1;
    return SYLVA_OK;
}

/* ---- materials and the mesh ------------------------------------------------------------------ */

static void colour_of(const tree_state *s, int32_t index, float albedo[3], float trans[3])
{
    for (uint32_t i = 0; i < s->n_palette; i++)
        if (s->palette[i].index == index) {
            memcpy(albedo, s->palette[i].albedo, 3 * sizeof *albedo);
            if (s->palette[i].has_transmittance) memcpy(trans, s->palette[i].transmittance, 3 * sizeof *trans);
            else lsys_leaf_transmittance(albedo, trans);
            return;
        }
    if (index >= 0 && index < LSYS_MAX_FILE_COLOURS && s->sys->colour_given[index]) {
        for (int k = 0; k < 3; k++) {
            float a = lsys_srgb_to_linear(s->sys->colour_srgb[index][k]);
            albedo[k] = a < LSYS_ALBEDO_CAP ? a : LSYS_ALBEDO_CAP;
        }
    } else {
        lsys_palette_default(index, albedo);
    }
    lsys_leaf_transmittance(albedo, trans);
}

typedef struct mesh_out {
    tree_state *s;
    const sylva_host_api *api;
    sylva_host *host;
    sylva_mesh *mesh;
    int32_t *mat;      /* owned by the caller of the build: one id per triangle of a chunk */
    int status;        /* the failing call's status */
} mesh_out;

static int32_t material_for(mesh_out *o, int32_t key)
{
    tree_state *s = o->s;
    if ((uint32_t)key >= s->n_material) {
        uint32_t n = (uint32_t)key + 64;
        int32_t *g = realloc(s->material, n * sizeof *g);
        if (!g) {
            o->api->error(o->host, "tree_lsystem: out of memory for materials");
            o->status = SYLVA_ERR_NOMEM;
            return -1;
        }
        for (uint32_t i = s->n_material; i < n; i++) g[i] = -1;
        s->material = g, s->n_material = n;
    }
    if (s->material[key] >= 0) return s->material[key];
    int32_t colour = key / 2;
    int leaf = key % 2;
    char name[64];
    snprintf(name, sizeof name, "tree_lsystem colour %d %s", colour, leaf ? "leaf" : "wood");
    /* The texture multiplies the colour's albedo; a leaf polygon is its own outline, so its
     * texture is opaque and no alpha mask applies. */
    sylva_material_desc d = {.size = sizeof d, .name = name, .bsdf = leaf ? SYLVA_BSDF_LEAF : SYLVA_BSDF_LAMBERT,
                             .texture = leaf ? s->leaf_texture : s->bark_texture};
    float trans[3];
    colour_of(s, colour, d.albedo, trans);
    if (leaf) memcpy(d.transmittance, trans, sizeof trans);
    int32_t id = o->api->material_new(o->host, &d);
    if (id < 0) {
        o->status = id;
        return -1;
    }
    s->material[key] = id;
    return id;
}

static int flush_to_host(void *ctx, const float *pos, const float *nrm, const float *uv, uint32_t nv,
                         const uint32_t *tri,
                         const int32_t *key, uint32_t nt)
{
    mesh_out *o = ctx;
    for (uint32_t i = 0; i < nt; i++)
        if ((o->mat[i] = material_for(o, key[i])) < 0) return -1;
    int rc = o->api->mesh_append(o->host, o->mesh, pos, nrm, uv, nv, tri, o->mat, nt);
    if (rc) {
        o->status = rc;
        return -1;
    }
    return 0;
}

static void warn_structure(tree_state *s, const sylva_host_api *api, sylva_host *host, const lsys_turtle_stats *st)
{
    if (s->warned || !(st->stray_pops || st->stray_polygon_ends || st->open_at_end)) return;
    s->warned = 1;
    api->log(host, SYLVA_LOG_WARN,
             "%s: the string is unbalanced: %llu ']' without '[' and %llu '}' without '{' were ignored, %llu "
             "'[' or '{' were still open at the end",
             s->sys->name, (unsigned long long)st->stray_pops, (unsigned long long)st->stray_polygon_ends,
             (unsigned long long)st->open_at_end);
}

/* ---- generate -------------------------------------------------------------------------------- */

static int tree_generate(void *state, const sylva_host_api *api, sylva_host *host, const void *request, void *out)
{
    tree_state *s = state;
    const sylva_tree_request *req = request;
    sylva_tree_out *o = out;
    if (!req || req->size < offsetof(sylva_tree_request, seed) + sizeof req->seed || !o ||
        o->size < offsetof(sylva_tree_out, height) + sizeof o->height)
        return api->error(host, "tree_lsystem: the tree request or output is smaller than this plugin reads");
    double age = req->age > 0 && req->age <= 1 ? req->age : 1.0;
    double frac = height_fraction(s, age), h2 = s->height * frac;
    if (!(frac > 0))
        return api->error(host, "tree_lsystem: height_by_age gives height 0 at age %g; every variant's age needs a "
                          "positive height fraction", age);
    sylva_tree_stats stats = {.size = sizeof stats, .age = age};
    uint32_t level = s->recursion;
    int rc;
    /* Eq. 6 from the full-grown tree to each younger one, or (law_height, law_branches given)
     * from a measured tree to every variant, the full-grown one too: the paper's direction. */
    int measured = s->law_height > 0;
    if (s->branch_law && (frac < 1.0 || measured)) {
        if ((rc = prepare_law(s, api, host))) return rc;
        double n1 = measured ? s->law_branches : (double)s->level_branches[s->recursion];
        double h1 = measured ? s->law_height : s->height;
        if (n1 > 0 && s->law_dimension > 0) {
            stats.law_dimension = s->law_dimension;
            stats.target_branches = branch_law_count(n1, h1, h2, s->law_dimension);
            level = branch_law_level(s->level_branches, s->recursion + 1, stats.target_branches);
        }
    }
    plugin_err e = {0};
    unsigned char *str = NULL; /* owned here */
    size_t n = 0;
    if ((rc = lsys_derive(s->sys, level, s->max_string, NULL, NULL, &str, &n, &e))) return fail(api, host, rc, &e);
    lsys_turtle_stats st;
    if ((rc = interpret(s, api, host, str, n, NULL, 0, &st, &e))) {
        free(str);
        return fail(api, host, rc, &e);
    }
    if (!st.has_bounds) {
        free(str);
        return api->error(host, "%s: at recursion level %u the L-system draws nothing (no F, Z or polygon)",
                          s->sys->name, level);
    }
    double ext[3] = {st.hi[0] - st.lo[0], st.hi[1] - st.lo[1], st.hi[2] - st.lo[2]};
    double widest = fmax(ext[0], fmax(ext[1], ext[2]));
    double size = ext[2] > 1e-6 * widest ? ext[2] : widest;
    double scale = s->unit_length > 0 ? s->unit_length : h2 / size;
    if (!(size > 0) || !isfinite(scale) || !isfinite(widest * scale) || widest * scale > 1e7) {
        free(str);
        return api->error(host, "%s: the model at recursion level %u spans %g by %g by %g file units, which cannot "
                          "be scaled to a height of %g m",
                          s->sys->name, level, ext[0], ext[1], ext[2], h2);
    }
    mesh_out mo = {.s = s, .api = api, .host = host, .mesh = o->mesh};
    mo.mat = malloc(LSYS_MESH_CHUNK_TRIANGLES * sizeof *mo.mat);
    lsys_mesh_config mc = {.sides = s->sides, .flat = s->flat, .scale = scale, .bark_tile = s->bark_tile,
                           .max_polygon_vertices = s->max_polygon_vertices, .flush = flush_to_host, .flush_ctx = &mo};
    lsys_mesh *mesh = mo.mat ? lsys_mesh_new(&mc, &e) : NULL; /* owned here */
    if (!mesh) {
        free(mo.mat);
        free(str);
        api->error(host, "tree_lsystem: out of memory for the mesh builder");
        return SYLVA_ERR_NOMEM;
    }
    box_raster r = {0};
    int have_raster = st.segments && !silhouette_init(&r, &st);
    lsys_sink sinks[2] = {lsys_mesh_sink(mesh), lsys_silhouette_sink(&r)};
    rc = interpret(s, api, host, str, n, sinks, have_raster ? 2 : 1, &st, &e);
    if (!rc) rc = lsys_mesh_finish(mesh);
    uint64_t triangles = lsys_mesh_triangles(mesh);
    uint64_t branches = 0;
    if (!rc) rc = branch_count(str, n, &branches, &e);
    lsys_mesh_free(mesh);
    free(mo.mat);
    free(str);
    if (rc) {
        box_raster_free(&r);
        if (rc == LSYS_ERR_SINK) return mo.status ? mo.status : SYLVA_ERR_INTERNAL;
        return fail(api, host, rc, &e);
    }
    stats.box_dimension = have_raster ? box_silhouette_dimension(&r) : 0.0;
    box_raster_free(&r);
    warn_structure(s, api, host, &st);
    o->height = size * scale;
    stats.recursion = level;
    stats.symbols = st.symbols;
    stats.segments = st.segments;
    stats.leaves = st.polygons;
    stats.triangles = triangles;
    stats.branches = branches;
    for (int k = 0; k < 3; k++) stats.bbox_min[k] = st.lo[k] * scale, stats.bbox_max[k] = st.hi[k] * scale;
    stats.height = o->height;
    s->last = stats;
    s->has_last = 1;
    return SYLVA_OK;
}

/* ---- statistics interface ------------------------------------------------------------------ */

static int tree_last_stats(void *state, sylva_tree_stats *out)
{
    const tree_state *s = state;
    return s ? plugin_tree_stats_copy(&s->last, s->has_last, out) : SYLVA_ERR_PARAM;
}

static const sylva_tree_stats_v1 stats_interface = {.size = sizeof stats_interface, .last_stats = tree_last_stats};

static const void *tree_extension(const char *id)
{
    return id && !strcmp(id, SYLVA_TREE_STATS_V1) ? &stats_interface : NULL;
}

static const sylva_plugin tree_lsystem = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TREE,
    .name = "tree_lsystem",
    .summary = "Trees from L-systems in the L-parser language, grown by the branch-number law.",
    .version = "1.0",
    .params = lsys_schema,
    .n_params = LSYS_SCHEMA_COUNT,
    .create = tree_create,
    .generate = tree_generate,
    .destroy = tree_destroy,
    .extension = tree_extension,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index) { return index == 0 ? &tree_lsystem : NULL; }
