/* terrain_ifs.c — the terrain_ifs plugin: a DTM (raster file, inline grid or seeded coarse
 * grid) refined by 3-D fractal interpolation with an IFS (MODELS.md §1), handed to the host as
 * a heightfield with ground-cover materials and a water level.
 *
 * create() reads and checks the parameters, loads the DTM and keeps what generate() needs;
 * generate() builds the maps, computes the heights by random iteration or deterministic
 * evaluation, classifies the ground and fills the host's heightfield. Every random number comes
 * from host streams ("terrain_ifs.dtm", "terrain_ifs.chaos" chain c); the plugin keeps no
 * global state and writes nothing to stdout. What this file allocates goes through the host's
 * allocator (ABI 1.1), so the host's limits and fault tests reach it; per-cell fields are read in
 * place, since the parameters stay valid until destroy().
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dtm.h"
#include "dtm_file.h"
#include "dtm_generate.h"
#include "humidity_map.h"
#include "raster_gdal.h"
#include "plugin_threads.h"
#include "lod_levels.h"
#include "ifs_chaos.h"
#include "ifs_detail.h"
#include "ifs_eval.h"
#include "ifs_ground.h"
#include "ifs_maps.h"
#include "surface_classes.h"
#include "sylva/plugin.h"
#include "ifs_schema.h"
#include "plugin_params.h"

/* The refinement's detail is called out when its RMS passes this factor times what the DTM's
 * own roughness continues to, plus this many metres. */
#define TERRAIN_IFS_DETAIL_WARN_FACTOR 2.0
#define TERRAIN_IFS_DETAIL_WARN_METRES 0.25

/* What create() keeps for generate(). Owned by the plugin until terrain_ifs_destroy, which frees
 * it with the host's mem_free it keeps (destroy receives no table). */
typedef struct terrain_ifs_state {
    void (*mem_free)(void *);    /* the host's: frees the state and humidity */
    ifs_dtm *dtm;                /* owned; heights after z_scale and z_offset */
    const double *alpha_field;   /* the parameter's values, (N-1)(M-1), or NULL */
    const double *probability_field; /* likewise, or NULL */
    ifs_mode mode;
    double alpha;                /* the global alpha: given, or chosen by choose_alpha */
    int alpha_chosen;            /* 1 once alpha is known (choose_alpha runs once) */
    ifs_roughness roughness;     /* the DTM's own, measured by choose_alpha */
    int random;                  /* 1: random iteration, 0: deterministic evaluation */
    uint64_t iterations;
    int has_start;
    double start_u, start_v, start_z;
    uint32_t depth;              /* 0: automatic */
    uint32_t nx_out, ny_out;     /* the output grid: with levels of detail, the DTM's nodes */
    int lod;                     /* 1: levels of detail around the eye (refine_levels) */
    uint32_t refine;             /* the finest level's nodes per DTM cell */
    double lod_radius;           /* the finest window's half-width, DTM cells */
    uint32_t threads;
    double centre[2];
    int classes;                 /* 1: ground-cover classes, 0: the scene's material */
    int has_water;               /* 1: a water surface at water_z */
    double water_z;              /* metres, heightfield heights */
    ifs_surface_rules rules;
    double zmin, zmax;           /* the DTM's height range, metres */
    float *humidity;             /* owned (host allocator): humidity at each output node, or NULL */
    float albedo[IFS_SURFACE_CLASSES][3];
    float water_albedo[3];
    ifs_ground ground;           /* the biome and what it put in rules and albedo (ifs_ground.h) */
    double latitude;             /* the site's (ABI 1.6 request), NaN without one */
    ifs_cover_shares cover;      /* the land cover near the site (ABI 1.6 request) */
    int has_cover;               /* 1: cover holds the request's shares */
    char source[512];            /* what the DTM is, for the log */
    const sylva_params *params;  /* create()'s, valid until destroy (the host's promise) */
    int georeferenced;           /* 1: the DTM file's node (0, 0) is at node0 in its CRS */
    double node0[2];             /* map coordinates of DTM node (0, 0) (after a warp: the site's) */
    double z_shift;              /* metres taken off every DTM height (the site origin's height) */
} terrain_ifs_state;

static void state_free(terrain_ifs_state *s)
{
    if (!s) return;
    ifs_dtm_free(s->dtm);
    s->mem_free(s->humidity);
    s->mem_free(s);
}

static int is_whole(double v) { return v == floor(v) && isfinite(v); }

/* Parameters that only one DTM source or one setting reads. */
static const char *const file_only[] = {"band", "crop", "step", "units"};
static const char *const classes_only[] = {"biome", "snow_line", "scree_line", "snow_altitude",
                                           "scree_altitude", "scree_slope", "rock_slope",
                                           "humidity_map", "humidity_band", "humidity_range",
                                           "dry_humidity", "grass_albedo",
                                           "dry_grass_albedo", "scree_albedo", "rock_albedo",
                                           "snow_albedo", "water_albedo"};

static int is_set(plugin_params *r, const char *name) { return plugin_param_given(r, name); }

/* The output grid for an nx x ny DTM: output_nodes, or (N - 1) refine + 1 along each axis. */
static void output_size(plugin_params *r, uint32_t nx, uint32_t ny, uint64_t *nxo, uint64_t *nyo)
{
    const sylva_value *out = plugin_param(r, "output_nodes");
    uint64_t refine = (uint64_t)plugin_param_int(r, "refine");
    *nxo = out->is_set ? (uint64_t)out->list[0] : (nx - 1) * refine + 1;
    *nyo = out->is_set ? (uint64_t)out->list[1] : (ny - 1) * refine + 1;
}

/* Whether the terrain is refined in levels of detail around the eye (lod_levels.h) rather than
 * uniformly: with refine >= 2, when detail_radius is given, or when the uniform grid would pass
 * TERRAIN_IFS_UNIFORM_NODES (then the finest window is TERRAIN_IFS_LOD_CELLS output cells
 * across its half-width). output_nodes always refines uniformly. */
static void lod_plan(plugin_params *params, const ifs_dtm *d, int *lod, uint32_t *refine,
                     double *radius_cells)
{
    uint64_t r = (uint64_t)plugin_param_int(params, "refine");
    double radius = plugin_param_real(params, "detail_radius");
    uint64_t uniform = ((d->nx - 1) * r + 1) * ((d->ny - 1) * r + 1);
    *refine = (uint32_t)r;
    *lod = !plugin_param_given(params, "output_nodes") && r >= 2 &&
           (radius > 0 || uniform > TERRAIN_IFS_UNIFORM_NODES);
    double spacing = d->dx < d->dy ? d->dx : d->dy;
    *radius_cells = radius > 0 && spacing > 0 ? radius / spacing : (double)TERRAIN_IFS_LOD_CELLS / r;
}

/* What the memory check needs beside the DTM's size. */
/* The worker threads of a run: the scene's own count, else the run's (--threads), else one per
 * processor; at most PLUGIN_MAX_THREADS. */
static uint32_t run_threads(plugin_params *r)
{
    uint32_t threads = (uint32_t)plugin_param_int(r, "threads");
    if (!threads) threads = SYLVA_API_HAS(r->api, threads) ? r->api->threads(r->host) : plugin_threads_online();
    return threads < PLUGIN_MAX_THREADS ? threads : PLUGIN_MAX_THREADS;
}

typedef struct memory_ask {
    plugin_params *params;       /* the plugin's block, through the host of the call */
    const char *source;          /* the DTM, for the sentence */
} memory_ask;

/* The plugin's own bytes for an nx x ny DTM and its output grid, and the output grid itself (the
 * host adds its own cost per heightfield node), against the host's memory budget (ABI 1.2). The
 * plugin holds the DTM (IFS_DTM_BYTES_PER_NODE a node; the maps are computed from it, not
 * stored), one class byte per output node while classifying, 4 bytes of humidity per output node
 * with a humidity map, and for the random iteration 16 bytes per output node and worker. */
static int memory_fits(void *ctx, uint32_t nx, uint32_t ny, plugin_err *err)
{
    const memory_ask *m = ctx;
    const sylva_host_api *api = m->params->api;
    if (!SYLVA_API_HAS(api, memory_check)) return SYLVA_OK;
    uint64_t nxo, nyo;
    output_size(m->params, nx, ny, &nxo, &nyo);
    int lod;
    uint32_t refine;
    double radius;
    ifs_dtm shape = {.nx = nx, .ny = ny};
    lod_plan(m->params, &shape, &lod, &refine, &radius);
    if (lod) { /* the DTM's nodes, and each level at most (2 radius refine + 1)^2 nodes */
        uint64_t side = (uint64_t)(2 * radius * refine + 2), levels = 0;
        for (uint32_t r = refine; r > 1; r = r % 2 ? 1 : r / 2) levels++;
        nxo = nx, nyo = (uint64_t)ny + levels * side * side / nx + 1;
    }
    if (nxo > 65536 || nyo > 65536) return SYLVA_OK; /* refused with its own sentence later */
    uint64_t out = nxo * nyo, per_out = 1;
    if (plugin_param_str(m->params, "humidity_map")) per_out += 4;
    if (plugin_param_int(m->params, "method") == 0) per_out += 16 * (uint64_t)run_threads(m->params);
    if (m->params->status) return m->params->status; /* the host has the sentence */
    char what[600];
    snprintf(what, sizeof what, "terrain_ifs: the %u x %u node DTM %s refined to %llu x %llu "
             "nodes", nx, ny, m->source, (unsigned long long)nxo, (unsigned long long)nyo);
    if (api->memory_check(m->params->host, (uint64_t)nx * ny * IFS_DTM_BYTES_PER_NODE + out * per_out,
                             out, what) == SYLVA_OK)
        return SYLVA_OK;
    /* the host's sentence is set; the plugin's error carries the status only */
    err->msg[0] = '\0';
    return SYLVA_ERR_LIMIT;
}

/* Loads the DTM from the one source the scene names. */
static int load_dtm(plugin_params *r, terrain_ifs_state *s, const char *target_wkt)
{
    const sylva_host_api *api = r->api;
    sylva_host *host = r->host;
    const sylva_params *params = r->block;
    const sylva_value *dtm = plugin_param(r, "dtm"), *heights = plugin_param(r, "heights");
    const sylva_value *cell = plugin_param(r, "cell_size");
    if (r->status) return r->status; /* the host has the sentence */
    double cs[2] = {0, 0};
    if (cell->len) cs[0] = cell->list[0], cs[1] = cell->list[cell->len > 1 ? 1 : 0];
    plugin_err err = {0};
    int rc;
    if (dtm->s) {
        const sylva_value *crop = plugin_param(r, "crop");
        const sylva_value *range = plugin_param(r, "height_range");
        ifs_dtm_file_options o = {.band = (uint32_t)plugin_param_int(r, "band"),
                                  .has_crop = crop->len == 4,
                                  .step = (uint32_t)plugin_param_int(r, "step"),
                                  .units = (ifs_units)plugin_param_int(r, "units"),
                                  .cell_size = {cs[0], cs[1]},
                                  .height_range = {range->list[0], range->list[1]}};
        char quoted[520];
        snprintf(quoted, sizeof quoted, "'%s'", dtm->s);
        memory_ask ask = {r, quoted};
        o.check_size = memory_fits, o.check_ctx = &ask, o.target_wkt = target_wkt;
        if (r->status) return r->status; /* the host has the sentence */
        if (!(range->list[0] < range->list[1]))
            return api->param_error(host, params, "height_range", "height_range [%g, %g] is "
                                    "empty; give [low, high] with low < high", range->list[0],
                                    range->list[1]);
        if (crop->len != 0 && crop->len != 4)
            return api->param_error(host, params, "crop", "crop has %u numbers; give 4, [first "
                                    "column, first row, columns, rows], or leave it out", crop->len);
        for (uint32_t k = 0; k < crop->len; k++) {
            if (!is_whole(crop->list[k]) || crop->list[k] > 4294967295.0)
                return api->param_error(host, params, "crop", "crop[%u] is %g; the window is "
                                        "given in whole pixels", k, crop->list[k]);
            o.crop[k] = (uint32_t)crop->list[k];
        }
        ifs_dtm_file_info info;
        if ((rc = ifs_dtm_read_file(dtm->s, &o, &s->dtm, &info, &err))) {
            if (err.msg[0]) api->param_error(host, params, "dtm", "%s", err.msg);
            return rc;
        }
        snprintf(s->source, sizeof s->source, "%s (%s %s%s; %u x %u pixels from column %u, row %u; "
                 "step %u)", dtm->s, info.driver, info.type_name, info.warped ? ", warped into the "
                 "site's coordinate system" : "", info.window[2], info.window[3], info.window[0],
                 info.window[1], o.step);
        s->georeferenced = !info.degrees && !o.cell_size[0];
        s->node0[0] = info.node0_x, s->node0[1] = info.node0_y;
        if (info.nodata_filled)
            api->log(host, SYLVA_LOG_INFO, "%s: %llu nodata node%s filled from their neighbours",
                     dtm->s, (unsigned long long)info.nodata_filled,
                     info.nodata_filled == 1 ? "" : "s");
        if (info.degrees)
            api->log(host, SYLVA_LOG_INFO, "%s: degrees converted to metres at latitude %.5f "
                     "(%.3f x %.3f m between nodes)%s", dtm->s, info.centre_lat, s->dtm->dx,
                     s->dtm->dy, info.units_guessed ? "; the file has no coordinate system, set "
                     "units: metres if it is not in degrees" : "");
        return SYLVA_OK;
    }
    double dx = cs[0] > 0 ? cs[0] : TERRAIN_IFS_DEFAULT_CELL;
    double dy = cs[1] > 0 ? cs[1] : TERRAIN_IFS_DEFAULT_CELL;
    if (heights->is_set) {
        if ((rc = ifs_dtm_from_rows(heights->list, heights->cols, heights->rows, dx, dy, &s->dtm,
                                    &err))) {
            api->param_error(host, params, "heights", "%s", err.msg);
            return rc;
        }
        snprintf(s->source, sizeof s->source, "inline heights");
        return SYLVA_OK;
    }
    plugin_params g = plugin_params_in(r, plugin_param(r, "generated")->group);
    const sylva_value *nodes = plugin_param(&g, "nodes");
    ifs_dtm_generator gen = {.dx = dx, .dy = dy, .relief = plugin_param_real(&g, "relief"),
                             .smoothness = plugin_param_real(&g, "smoothness")};
    if (r->status) return r->status; /* the host has the sentence */
    for (uint32_t k = 0; k < 2; k++)
        if (!is_whole(nodes->list[k]))
            return api->param_error(host, params, "generated", "generated.nodes[%u] is %g; node "
                                    "counts are whole numbers", k, nodes->list[k]);
    gen.nx = (uint32_t)nodes->list[0], gen.ny = (uint32_t)nodes->list[1];
    sylva_rng rng;
    api->rng_init(host, &rng, "terrain_ifs.dtm", 0);
    if ((rc = ifs_dtm_generate(&gen, api->rng_u64, &rng, &s->dtm, &err))) {
        api->param_error(host, params, "generated", "%s", err.msg);
        return rc;
    }
    snprintf(s->source, sizeof s->source, "generated %u x %u DTM", gen.nx, gen.ny);
    return SYLVA_OK;
}

/* A per-cell field of the parameters, after checking it matches the DTM's cells. */
static int cell_field(plugin_params *r, const char *name, const ifs_dtm *d, const double **out)
{
    const sylva_value *v = plugin_param(r, name);
    *out = NULL;
    if (r->status || !v->is_set) return r->status;
    if (v->rows != d->ny - 1 || v->cols != d->nx - 1)
        return plugin_params_error(r, name, "%s has %u rows of %u values; the DTM has %u rows of %u "
                                   "cells (one value per cell, rows from south to north)",
                                   name, v->rows, v->cols, d->ny - 1, d->nx - 1);
    *out = v->list; /* valid until destroy(): the host's promise */
    return SYLVA_OK;
}

/* The relations between parameters that the schema cannot express. */
static int check_relations(plugin_params *r)
{
    int has_file = plugin_param_str(r, "dtm") != NULL, has_heights = is_set(r, "heights");
    if (has_file && has_heights)
        return plugin_params_error(r, "heights", "give dtm or heights, not both");
    if ((has_file || has_heights) && is_set(r, "generated"))
        return plugin_params_error(r, "generated", "generated makes a DTM when neither "
                                   "dtm nor heights is given; remove it or them");
    for (size_t k = 0; !has_file && k < sizeof file_only / sizeof file_only[0]; k++)
        if (is_set(r, file_only[k]))
            return plugin_params_error(r, file_only[k], "%s applies to a dtm file; this "
                                       "terrain has none", file_only[k]);
    if (is_set(r, "alpha") && is_set(r, "alpha_field"))
        return plugin_params_error(r, "alpha_field", "give alpha or alpha_field, not both");
    if (is_set(r, "detail") && (is_set(r, "alpha") || is_set(r, "alpha_field")))
        return plugin_params_error(r, "detail", "give detail (metres) or alpha, not both: "
                                   "detail chooses alpha");
    if (is_set(r, "refine") && is_set(r, "output_nodes"))
        return plugin_params_error(r, "output_nodes", "give refine or output_nodes, not "
                                   "both");
    int random = plugin_param_int(r, "method") == 0;
    if (!random && (is_set(r, "iterations") || is_set(r, "start")))
        return plugin_params_error(r, is_set(r, "iterations") ? "iterations" : "start",
                                   "iterations and start belong to method: random; this terrain is "
                                   "evaluated deterministically (the default): add method: random, "
                                   "or remove %s", is_set(r, "iterations") ? "iterations" : "start");
    if (plugin_param_int(r, "surface") == 1)
        for (size_t k = 0; k < sizeof classes_only / sizeof classes_only[0]; k++)
            if (is_set(r, classes_only[k]))
                return plugin_params_error(r, classes_only[k], "%s belongs to surface: "
                                           "classes; with surface: scene the scene's terrain "
                                           "material covers the ground", classes_only[k]);
    const sylva_value *cell = plugin_param(r, "cell_size");
    if (cell->is_set && cell->len == 0)
        return plugin_params_error(r, "cell_size", "cell_size is empty; give [dx, dy] or "
                                   "[d] in metres, or leave it out");
    const sylva_value *out = plugin_param(r, "output_nodes");
    if (out->is_set && (out->len != 2 || !is_whole(out->list[0]) || !is_whole(out->list[1])))
        return plugin_params_error(r, "output_nodes", "output_nodes must be two whole "
                                   "numbers [nx, ny]");
    const sylva_value *start = plugin_param(r, "start");
    if (start->is_set && start->len != 3)
        return plugin_params_error(r, "start", "start has %u numbers; give [x, y, z] in "
                                   "metres, or leave it out for the DTM's origin", start->len);
    if (plugin_param_real(r, "scree_slope") > plugin_param_real(r, "rock_slope"))
        return plugin_params_error(r, "scree_slope", "scree_slope %g exceeds rock_slope "
                                   "%g; scree lies on gentler slopes than rock",
                                   plugin_param_real(r, "scree_slope"),
                                   plugin_param_real(r, "rock_slope"));
    static const char *const older[3][2] = {{"snow_altitude", "snow_line"},
                                             {"scree_altitude", "scree_line"},
                                             {"water_altitude", "water_level"}};
    for (int k = 0; k < 3; k++)
        if (is_set(r, older[k][0]) && is_set(r, older[k][1]))
            return plugin_params_error(r, older[k][1], "give %s (metres) or %s (a fraction "
                                       "of the DTM's height range), not both", older[k][0],
                                       older[k][1]);
    if (is_set(r, "scree_line") && is_set(r, "snow_line") &&
        plugin_param_real(r, "scree_line") > plugin_param_real(r, "snow_line"))
        return plugin_params_error(r, "scree_line", "scree_line %g is above snow_line %g; "
                                   "scree lies below the snow", plugin_param_real(r, "scree_line"),
                                   plugin_param_real(r, "snow_line"));
    if (!is_set(r, "scree_line") && !is_set(r, "snow_line") && is_set(r, "scree_altitude") &&
        is_set(r, "snow_altitude") &&
        plugin_param_real(r, "scree_altitude") > plugin_param_real(r, "snow_altitude"))
        return plugin_params_error(r, "scree_altitude", "scree_altitude %g m is above "
                                   "snow_altitude %g m; scree lies below the snow",
                                   plugin_param_real(r, "scree_altitude"),
                                   plugin_param_real(r, "snow_altitude"));
    return SYLVA_OK;
}

static void read_albedo(plugin_params *r, const char *name, float out[3])
{
    const double *v = plugin_param(r, name)->list;
    for (int k = 0; k < 3; k++) out[k] = (float)v[k];
}

/* Everything the plugin derives from its DTM: loads it (in target_wkt when given, else in the
 * file's own coordinate system), checks the fields that depend on its size, and sizes the
 * output, the ground-cover rules and the humidity. */
static int terrain_setup(plugin_params *r, terrain_ifs_state *s, const char *target_wkt)
{
    const sylva_host_api *api = r->api;
    sylva_host *host = r->host;
    int rc;
    if ((rc = load_dtm(r, s, target_wkt))) goto fail;
    ifs_dtm *d = s->dtm;
    double zs = plugin_param_real(r, "z_scale"), zo = plugin_param_real(r, "z_offset");
    if ((rc = r->status)) goto fail; /* the host has the sentence */
    for (size_t k = 0; k < (size_t)d->nx * d->ny; k++) d->z[k] = d->z[k] * zs + zo;
    if ((rc = cell_field(r, "alpha_field", d, &s->alpha_field))) goto fail;
    if ((rc = cell_field(r, "probability_field", d, &s->probability_field)))
        goto fail;

    const sylva_value *out = plugin_param(r, "output_nodes");
    uint64_t nxo, nyo;
    output_size(r, d->nx, d->ny, &nxo, &nyo);
    lod_plan(r, d, &s->lod, &s->refine, &s->lod_radius);
    if (s->lod) nxo = d->nx, nyo = d->ny; /* the DTM's nodes, and the levels in generate() */
    if (nxo > 65536 || nyo > 65536 || nxo * nyo > TERRAIN_IFS_MAX_OUTPUT_NODES) {
        rc = plugin_params_error(r, out->is_set ? "output_nodes" : "refine",
                                 "the output grid would have %llu x %llu nodes; at most %u nodes "
                                 "(16384 x 16384) and 65536 along a side are made: lower %s",
                                 (unsigned long long)nxo, (unsigned long long)nyo,
                                 TERRAIN_IFS_MAX_OUTPUT_NODES, out->is_set ? "output_nodes" : "refine");
        goto fail;
    }
    if (!plugin_param_str(r, "dtm")) {
        plugin_err err = {0};
        memory_ask ask = {r, s->source};
        if ((rc = memory_fits(&ask, d->nx, d->ny, &err))) goto fail;
    }
    s->nx_out = (uint32_t)nxo, s->ny_out = (uint32_t)nyo;

    const double *centre = plugin_param(r, "centre")->list;
    s->centre[0] = centre[0], s->centre[1] = centre[1];
    s->mode = plugin_param_int(r, "mode") == 1 ? IFS_MODE_AFFINE : IFS_MODE_BILINEAR;
    s->alpha = plugin_param_real(r, "alpha");
    s->random = plugin_param_int(r, "method") == 0;
    s->iterations = (uint64_t)plugin_param_int(r, "iterations");
    s->depth = (uint32_t)plugin_param_int(r, "depth");
    s->threads = run_threads(r);

    /* The starting point: the DTM origin (U, V) = (0, 0) at its height, or the scene's point. */
    const sylva_value *start = plugin_param(r, "start");
    s->start_z = d->z[0];
    if (start->is_set) {
        double w = (d->nx - 1) * d->dx, h = (d->ny - 1) * d->dy;
        double u = (start->list[0] - (s->centre[0] - 0.5 * w)) / w;
        double v = (start->list[1] - (s->centre[1] - 0.5 * h)) / h;
        if (!(u >= 0 && u <= 1 && v >= 0 && v <= 1)) {
            rc = plugin_params_error(r, "start", "start (%g, %g) lies outside the DTM, "
                                     "which covers x in [%g, %g] and y in [%g, %g]", start->list[0],
                                     start->list[1], s->centre[0] - 0.5 * w, s->centre[0] + 0.5 * w,
                                     s->centre[1] - 0.5 * h, s->centre[1] + 0.5 * h);
            goto fail;
        }
        s->has_start = 1, s->start_u = u, s->start_v = v, s->start_z = start->list[2];
    }

    s->classes = plugin_param_int(r, "surface") == 0;
    /* Altitudes in metres; the older fractions of the DTM's height range when given. */
    double zmin, zmax;
    ifs_dtm_range(d, &zmin, &zmax);
    s->zmin = zmin, s->zmax = zmax;
    ifs_ground_resolve(r, s->latitude, s->has_cover ? &s->cover : NULL, zmin, zmax, &s->ground);
    if (s->ground.biome_auto && isfinite(s->latitude) && !s->has_cover && r->api)
        r->api->log(r->host, SYLVA_LOG_WARN, "biome '%s' picked from the site's latitude (%.2f) alone; "
                    "the same latitude holds deserts, scrub, prairie and humid woods: give the terrain's "
                    "biome: (temperate, mediterranean, semi_arid, prairie, boreal or alpine)",
                    ifs_biome_preset_of(s->ground.biome)->name, s->latitude);
    s->rules = s->ground.rules;
    memcpy(s->albedo, s->ground.albedo, sizeof s->albedo);
    s->has_water = is_set(r, "water_altitude") || plugin_param_real(r, "water_level") > 0;
    s->water_z = is_set(r, "water_level")
                     ? zmin + plugin_param_real(r, "water_level") * (zmax - zmin)
                     : plugin_param_real(r, "water_altitude");
    read_albedo(r, "water_albedo", s->water_albedo);
    const char *hum = plugin_param_str(r, "humidity_map");
    const sylva_value *hrange = plugin_param(r, "humidity_range");
    if (!hum && (is_set(r, "humidity_band") || hrange->is_set)) {
        rc = plugin_params_error(r, hrange->is_set ? "humidity_range" : "humidity_band",
                                 "humidity_band and humidity_range describe a humidity_map; this "
                                 "terrain has none");
        goto fail;
    }
    if (hrange->is_set && (hrange->len != 2 || hrange->list[0] == hrange->list[1])) {
        rc = plugin_params_error(r, "humidity_range", "humidity_range must be two "
                                 "different numbers [raw value of humidity 0, of humidity 1]");
        goto fail;
    }
    if ((rc = r->status)) goto fail;
    if (hum) {
        plugin_err err = {0};
        ifs_humidity_source src = {.path = hum,
                                   .band = (uint32_t)plugin_param_int(r, "humidity_band"),
                                   .has_range = hrange->is_set};
        if (hrange->is_set) src.range[0] = hrange->list[0], src.range[1] = hrange->list[1];
        s->humidity = api->mem_alloc((size_t)s->nx_out * s->ny_out * sizeof *s->humidity);
        if (!s->humidity) {
            api->error(host, "terrain_ifs: out of memory for the humidity of %u x %u nodes",
                       s->nx_out, s->ny_out);
            rc = SYLVA_ERR_NOMEM;
            goto fail;
        }
        if ((rc = ifs_humidity_read(&src, s->nx_out, s->ny_out, s->humidity, &err))) {
            plugin_params_error(r, "humidity_map", "%s", err.msg);
            goto fail;
        }
    }
    return SYLVA_OK;
fail:
    return rc;
}

static int terrain_ifs_create(const sylva_host_api *api, sylva_host *host,
                              const sylva_params *params, void **state)
{
    *state = NULL;
    plugin_params r = plugin_params_open(api, host, params);
    int rc = check_relations(&r);
    if (rc || (rc = r.status)) return rc;
    if (!SYLVA_API_HAS(api, mem_alloc))
        return api->error(host, "terrain_ifs needs a host with sylva plugin ABI 1.1 or newer (for "
                          "its allocator); this host speaks %u.%u", api->abi_major, api->abi_minor);
    terrain_ifs_state *s = api->mem_calloc(1, sizeof *s); /* owned by the plugin until destroy */
    if (!s) {
        api->error(host, "terrain_ifs: out of memory for its settings");
        return SYLVA_ERR_NOMEM;
    }
    s->mem_free = api->mem_free;
    s->params = params; /* the DTM is read by generate(), once the request says in which CRS */
    *state = s;
    return SYLVA_OK;
}

/* Host progress from the model's workers (called on the plugin's calling thread only). */
typedef struct progress_sink {
    const sylva_host_api *api;
    sylva_host *host;
    const char *label;
} progress_sink;

static void report_progress(void *pctx, uint64_t done, uint64_t total)
{
    const progress_sink *p = pctx;
    p->api->progress(p->host, p->label, done, total);
}

/* The heights of window `win` of the nx x ny output lattice over the footprint: random
 * iteration or deterministic evaluation into z (win->nx * win->ny). */
static int compute_heights(const terrain_ifs_state *s, const ifs_maps *maps, uint32_t depth,
                           uint32_t nx, uint32_t ny, const ifs_window *win,
                           const sylva_host_api *api, sylva_host *host, float *z)
{
    plugin_err err = {0};
    int rc;
    if (!s->random) {
        progress_sink p = {api, host, "terrain_ifs evaluation"};
        if ((rc = ifs_eval_window(maps, nx, ny, win, depth, s->threads, z, report_progress, &p,
                                  &err))) {
            api->error(host, "%s", err.msg);
            return rc;
        }
        api->log(host, SYLVA_LOG_INFO, "deterministic evaluation f_%u at %u x %u nodes", depth,
                 win->nx, win->ny);
        return SYLVA_OK;
    }
    uint64_t chains = ifs_chaos_chain_count(s->iterations);
    sylva_rng *streams = api->mem_alloc(chains * sizeof *streams); /* owned here */
    if (!streams) {
        api->error(host, "terrain_ifs: out of memory for %llu random streams",
                   (unsigned long long)chains);
        return SYLVA_ERR_NOMEM;
    }
    for (uint64_t c = 0; c < chains; c++) api->rng_init(host, &streams[c], "terrain_ifs.chaos", c);
    progress_sink p = {api, host, "terrain_ifs random iteration"};
    ifs_chaos_job job = {.points = s->iterations, .start_u = s->start_u, .start_v = s->start_v,
                         .start_z = s->start_z, .streams = streams, .rng_u64 = api->rng_u64,
                         .nx = nx, .ny = ny, .window = *win, .depth = depth, .threads = s->threads,
                         .progress = report_progress, .pctx = &p};
    ifs_chaos_stats stats;
    rc = ifs_chaos_grid(maps, &job, z, &stats, &err);
    api->mem_free(streams);
    if (rc) {
        api->error(host, "%s", err.msg);
        return rc;
    }
    api->log(host, SYLVA_LOG_INFO, "random iteration: %llu points on %u x %u nodes (%u thread%s); "
             "%llu node%s no point reached took f_%u", (unsigned long long)s->iterations,
             win->nx, win->ny, stats.workers, stats.workers == 1 ? "" : "s",
             (unsigned long long)stats.empty_nodes, stats.empty_nodes == 1 ? "" : "s", depth);
    return SYLVA_OK;
}

/* Classes of an nx x ny grid of heights dx x dy apart into material ids (ids per class), counted
 * into counts. */
static int classify_grid(const terrain_ifs_state *s, const sylva_host_api *api, sylva_host *host,
                         const float *z, uint32_t nx, uint32_t ny, double dx, double dy,
                         const float *humidity, const int32_t ids[IFS_SURFACE_CLASSES],
                         int32_t *material, uint64_t counts[IFS_SURFACE_CLASSES])
{
    ifs_surface_rules rules = s->rules; /* altitudes are the DTM's; the heights are local */
    rules.snow_z -= s->z_shift, rules.scree_z -= s->z_shift;
    size_t n = (size_t)nx * ny;
    uint8_t *cls = api->mem_alloc(n); /* owned here */
    if (!cls) {
        api->error(host, "terrain_ifs: out of memory classifying %zu nodes", n);
        return SYLVA_ERR_NOMEM;
    }
    ifs_surface_classify(z, nx, ny, dx, dy, humidity, &rules, cls);
    for (size_t k = 0; k < n; k++) material[k] = ids[cls[k]], counts[cls[k]]++;
    api->mem_free(cls);
    return SYLVA_OK;
}

/* The humidity of level l's nodes: that of the nearest node of the output grid the humidity map
 * was sampled on (the DTM's nodes when there are levels), into a new array (host allocator). */
static float *level_humidity(const terrain_ifs_state *s, const sylva_host_api *api,
                             const sylva_terrain_level *l)
{
    float *h = api->mem_alloc((size_t)l->nx * l->ny * sizeof *h); /* owned by the caller */
    for (uint32_t j = 0; h && j < l->ny; j++)
        for (uint32_t i = 0; i < l->nx; i++) {
            uint32_t bi = l->i0 + (i + l->refine / 2) / l->refine, bj = l->j0 + (j + l->refine / 2) / l->refine;
            h[(size_t)j * l->nx + i] = s->humidity[(size_t)bj * s->nx_out + bi];
        }
    return h;
}

/* The rules the nodes were classed by, in the heightfield's heights, and the humidity at its
 * nodes, for a host that shades the ground from continuous weights (ABI 1.3). */
static int report_ground_rules(const terrain_ifs_state *s, const sylva_host_api *api, sylva_host *host,
                               sylva_heightfield *hf)
{
    if (!SYLVA_HAS_FIELD(hf, sylva_heightfield, humidity)) return SYLVA_OK;
    hf->has_ground_rules = 1;
    hf->ground = (sylva_ground_rules){.snow_z = s->rules.snow_z - s->z_shift,
                                      .scree_z = s->rules.scree_z - s->z_shift,
                                      .scree_slope = s->rules.scree_slope,
                                      .rock_slope = s->rules.rock_slope,
                                      .dry_humidity = s->rules.dry_humidity};
    for (int k = 0; k < 3; k++) {
        hf->ground.grass_albedo[k] = s->albedo[IFS_SURFACE_GRASS][k];
        hf->ground.dry_grass_albedo[k] = s->albedo[IFS_SURFACE_DRY_GRASS][k];
        hf->ground.scree_albedo[k] = s->albedo[IFS_SURFACE_SCREE][k];
        hf->ground.rock_albedo[k] = s->albedo[IFS_SURFACE_ROCK][k];
        hf->ground.snow_albedo[k] = s->albedo[IFS_SURFACE_SNOW][k];
    }
    if (SYLVA_HAS_FIELD(hf, sylva_heightfield, palette))
        hf->has_ground_palette = 1, hf->palette = s->ground.palette;
    if (!s->humidity) return SYLVA_OK;
    size_t n = (size_t)hf->nx * hf->ny;
    hf->humidity = api->mem_alloc(n * sizeof *hf->humidity);
    if (!hf->humidity) {
        api->error(host, "terrain_ifs: out of memory for the humidity of %u x %u nodes", hf->nx, hf->ny);
        return SYLVA_ERR_NOMEM;
    }
    memcpy(hf->humidity, s->humidity, n * sizeof *hf->humidity);
    return SYLVA_OK;
}

/* Ground-cover materials per node of the heightfield and of its levels, and the water material. */
static int apply_surface(const terrain_ifs_state *s, const sylva_host_api *api, sylva_host *host,
                         sylva_heightfield *hf)
{
    int32_t ids[IFS_SURFACE_CLASSES];
    uint64_t counts[IFS_SURFACE_CLASSES] = {0}, level_counts[IFS_SURFACE_CLASSES] = {0};
    for (int c = 0; c < IFS_SURFACE_CLASSES; c++) {
        char name[48];
        snprintf(name, sizeof name, "terrain_ifs %s", ifs_surface_class_name((ifs_surface_class)c));
        sylva_material_desc m = {.size = sizeof m, .name = name, .bsdf = SYLVA_BSDF_LAMBERT,
                                 .texture = -1};
        memcpy(m.albedo, s->albedo[c], sizeof m.albedo);
        if ((ids[c] = api->material_new(host, &m)) < 0) return ids[c];
    }
    int rc = classify_grid(s, api, host, hf->z, hf->nx, hf->ny, hf->dx, hf->dy, s->humidity, ids,
                           hf->material, counts);
    for (uint32_t k = 0; !rc && k < hf->n_levels; k++) {
        const sylva_terrain_level *l = &hf->levels[k];
        float *hum = s->humidity ? level_humidity(s, api, l) : NULL;
        if (s->humidity && !hum) {
            api->error(host, "terrain_ifs: out of memory for the humidity of a level of detail");
            return SYLVA_ERR_NOMEM;
        }
        rc = classify_grid(s, api, host, l->z, l->nx, l->ny, hf->dx / l->refine, hf->dy / l->refine,
                           hum, ids, l->material, level_counts);
        api->mem_free(hum);
    }
    if (rc) return rc;
    double n = (double)hf->nx * hf->ny;
    api->log(host, SYLVA_LOG_INFO, "ground: %.1f%% grass, %.1f%% dry grass, %.1f%% scree, "
             "%.1f%% rock, %.1f%% snow", 100.0 * counts[0] / n, 100.0 * counts[1] / n,
             100.0 * counts[2] / n, 100.0 * counts[3] / n, 100.0 * counts[4] / n);
    char biome[96];
    ifs_ground_describe(&s->ground, s->latitude, s->has_cover, biome, sizeof biome);
    api->log(host, SYLVA_LOG_INFO, "ground of biome %s: snow from %.0f m, scree from %.0f m and "
             "%.0f deg, rock from %.0f deg", biome, s->rules.snow_z, s->rules.scree_z,
             s->rules.scree_slope, s->rules.rock_slope);
    if ((rc = report_ground_rules(s, api, host, hf))) return rc;
    if (s->has_water) {
        sylva_material_desc w = {.size = sizeof w, .name = "terrain_ifs water",
                                 .bsdf = SYLVA_BSDF_LAMBERT, .texture = -1};
        memcpy(w.albedo, s->water_albedo, sizeof w.albedo);
        if ((hf->water_material = api->material_new(host, &w)) < 0) return hf->water_material;
    }
    return SYLVA_OK;
}

/* Levels of detail (lod_levels.h): the DTM's own heights over the whole footprint, and around
 * the eye (DTM cell units from node (0, 0); NaN: the footprint's centre) windows refined at
 * halving resolutions, each refined as the uniform grid of its resolution would be there, its
 * rim then pinned onto the coarser level around it. */
static int refine_levels(const terrain_ifs_state *s, const ifs_maps *maps, uint32_t depth,
                         const double eye[2], const sylva_host_api *api, sylva_host *host,
                         sylva_heightfield *hf)
{
    if (!SYLVA_API_HAS(api, heightfield_level_new))
        return api->error(host, "terrain_ifs: levels of detail need a host with sylva plugin ABI "
                          "1.2; this host speaks %u.%u (set detail_radius to 0 and lower refine)",
                          api->abi_major, api->abi_minor);
    const ifs_dtm *d = s->dtm;
    for (size_t k = 0; k < (size_t)d->nx * d->ny; k++) hf->z[k] = (float)d->z[k];
    ifs_lod_window w[IFS_LOD_MAX_LEVELS];
    uint32_t n = ifs_lod_windows(d->nx - 1, d->ny - 1, s->refine, eye[0], eye[1], s->lod_radius, w);
    ifs_lod_window base = {0, 0, d->nx - 1, d->ny - 1, 1};
    const float *coarser = hf->z;
    const ifs_lod_window *around = &base;
    for (uint32_t k = 0; k < n; k++) {
        sylva_terrain_level *l = api->heightfield_level_new(host, hf, w[k].i0, w[k].j0, w[k].cells_x,
                                                            w[k].cells_y, w[k].refine, s->classes);
        if (!l) return SYLVA_ERR_LIMIT; /* the host has said why */
        uint32_t r = w[k].refine;
        ifs_window win = {w[k].i0 * r, w[k].j0 * r, l->nx, l->ny};
        int rc = compute_heights(s, maps, depth, (d->nx - 1) * r + 1, (d->ny - 1) * r + 1, &win, api,
                                 host, l->z);
        if (rc) return rc;
        ifs_lod_pin_rim(around, coarser, &w[k], l->z);
        coarser = l->z, around = &w[k];
        /* the level pointer is the host's until the next level: heights are final here */
    }
    api->log(host, SYLVA_LOG_INFO, "levels of detail: the DTM's %u x %u nodes, and %u window%s "
             "around (%.0f, %.0f) m refined %u to 2 times (finest half-width %.0f m)", d->nx, d->ny,
             n, n == 1 ? "" : "s", hf->x0 + eye[0] * hf->dx, hf->y0 + eye[1] * hf->dy, s->refine,
             s->lod_radius * hf->dx);
    return SYLVA_OK;
}

/* A site (ABI 1.2 request), once the DTM is read in the site's CRS (terrain_setup warps a file
 * in another one): its heights taken down by the origin's height. Sets *placed when the DTM's
 * own georeferencing places it (a file read in metres of its CRS), 0 when it keeps `centre`. */
static void site_place(terrain_ifs_state *s, plugin_params *r, const sylva_terrain_request *req,
                       int *placed)
{
    const sylva_host_api *api = r->api;
    sylva_host *host = r->host;
    const char *path = plugin_param_str(r, "dtm");
    if (!path)
        api->log(host, SYLVA_LOG_INFO, "the scene has a site; the %s has no coordinates of its own "
                 "and stands at centre", s->source);
    else if (!s->georeferenced)
        api->log(host, SYLVA_LOG_WARN, "%s: its node spacing is not its coordinate system's (cell_size "
                 "or degrees), so it stands at centre, not at its map position", path);
    *placed = path && s->georeferenced;
    double shift = req->site_origin[2] - s->z_shift;
    if (shift != 0.0) {
        for (size_t k = 0; k < (size_t)s->dtm->nx * s->dtm->ny; k++) s->dtm->z[k] -= shift;
        if (!s->has_start) s->start_z -= shift;
        s->z_shift = req->site_origin[2];
    }
}

/* Where the heightfield's node (0, 0) stands for a DTM of the given width and depth: at
 * `centre`, or (placed on a site) by the DTM's own georeferencing. */
static void place_footprint(const terrain_ifs_state *s, const sylva_terrain_request *req, int placed,
                            sylva_heightfield *hf)
{
    double width = (s->dtm->nx - 1) * s->dtm->dx, depth_m = (s->dtm->ny - 1) * s->dtm->dy;
    hf->x0 = s->centre[0] - 0.5 * width, hf->y0 = s->centre[1] - 0.5 * depth_m;
    if (placed) /* node (E, N) at local (E - origin E, N - origin N) */
        hf->x0 = s->node0[0] - req->site_origin[0], hf->y0 = s->node0[1] - req->site_origin[1];
}

/* The water surface and what lies past the footprint's edge, the same on both grounds. */
static void set_water_and_edge(const terrain_ifs_state *s, plugin_params *r, sylva_heightfield *hf)
{
    if (s->has_water) {
        hf->has_water = 1;
        hf->water_level = s->water_z - s->z_shift;
    }
    if (SYLVA_HAS_FIELD(hf, sylva_heightfield, beyond_edge))
        hf->beyond_edge = plugin_param_int(r, "beyond_edge") == 0 ? SYLVA_EDGE_FLAT : SYLVA_EDGE_VOID;
}

/* 1 when the ground to render is the DTM's own nodes (refine 1, no levels, the deterministic
 * evaluation in bilinear mode, which passes through every node): the surveyed request is then
 * answered with it, materials and all, and the host renders it as it is. */
static int renders_dtm_nodes(const terrain_ifs_state *s)
{
    return !s->lod && !s->random && s->mode == IFS_MODE_BILINEAR && s->nx_out == s->dtm->nx &&
           s->ny_out == s->dtm->ny;
}

/* The ground as surveyed (ABI 1.5 request): the DTM's own nodes and heights, as read, cropped,
 * stepped and placed, with no detail added: what the analyses read whatever the camera. */
static int surveyed_ground(const terrain_ifs_state *s, plugin_params *r, const sylva_terrain_request *req,
                           int placed, sylva_terrain_out *o)
{
    const sylva_host_api *api = r->api;
    sylva_host *host = r->host;
    const ifs_dtm *d = s->dtm;
    sylva_heightfield *hf = api->heightfield_new(host, d->nx, d->ny, 0);
    if (!hf) return SYLVA_ERR_NOMEM; /* the host has said why */
    place_footprint(s, req, placed, hf);
    hf->dx = d->dx, hf->dy = d->dy;
    for (size_t k = 0; k < (size_t)d->nx * d->ny; k++) hf->z[k] = (float)d->z[k];
    set_water_and_edge(s, r, hf);
    if (r->status) return r->status; /* the host has the sentence */
    o->terrain = hf;
    return SYLVA_OK;
}

/* The global alpha, once: as given, or the one whose detail has the RMS the `detail` key gives
 * or, by default, the DTM's own roughness continued below what its nodes resolve (ifs_detail.h). */
static int choose_alpha(terrain_ifs_state *s, plugin_params *params)
{
    const sylva_host_api *api = params->api;
    sylva_host *host = params->host;
    if (s->alpha_chosen) return SYLVA_OK;
    s->alpha_chosen = 1;
    int measured = !ifs_roughness_measure(s->dtm, &s->roughness);
    int alpha_given = is_set(params, "alpha"), given = is_set(params, "detail");
    double detail = plugin_param_real(params, "detail");
    if (params->status) return params->status; /* the host has the sentence */
    if (s->alpha_field || alpha_given) return SYLVA_OK;
    const ifs_roughness *r = &s->roughness;
    double target = given ? detail : r->target;
    plugin_err err = {0};
    int rc = ifs_alpha_for_detail(s->dtm, s->mode, s->depth, target, &s->alpha, &err);
    if (rc) {
        api->error(host, "%s", err.msg);
        return rc;
    }
    if (given)
        api->log(host, SYLVA_LOG_INFO, "detail %.3g m RMS (given): alpha %.4g", target, s->alpha);
    else if (measured)
        api->log(host, SYLVA_LOG_INFO, "detail from the DTM's own roughness: %.3g m RMS from the surface "
                 "through every 2nd node, %.3g m through every 4th (Hurst exponent %.2f), continued below "
                 "half its %.3g m cells, which its nodes do not resolve, to %.3g m RMS: alpha %.4g", r->half2,
                 r->half4, r->hurst, fmin(s->dtm->dx, s->dtm->dy), target, s->alpha);
    else
        api->log(host, SYLVA_LOG_INFO, "the DTM has fewer than 5 x 5 nodes, too few to measure its "
                 "roughness: no detail added (alpha 0; give detail or alpha for some)");
    return SYLVA_OK;
}

static int terrain_ifs_generate(void *state, const sylva_host_api *api, sylva_host *host,
                                const void *request, void *out)
{
    terrain_ifs_state *s = state;
    const sylva_terrain_request *req = request;
    sylva_terrain_out *o = out;
    if (o->size < offsetof(sylva_terrain_out, terrain) + sizeof o->terrain) {
        api->error(host, "terrain_ifs: the host's terrain output is too small (%u bytes)", o->size);
        return SYLVA_ERR_INTERNAL;
    }
    int placed = 0, rc;
    plugin_params r = plugin_params_open(api, host, s->params);
    const int site = req && SYLVA_HAS_FIELD(req, sylva_terrain_request, eye) && req->site_crs;
    s->latitude = req && SYLVA_HAS_FIELD(req, sylva_terrain_request, site_latitude) ? req->site_latitude : NAN;
    s->has_cover = req && SYLVA_HAS_FIELD(req, sylva_terrain_request, cover_shares) && req->cover_shares;
    if (s->has_cover) s->cover = ifs_cover_shares_of(req->cover_shares);
    if (!s->dtm && (rc = terrain_setup(&r, s, site ? req->site_crs : NULL))) return rc;
    if (site) site_place(s, &r, req, &placed);
    if (r.status) return r.status; /* the host has the sentence */
    int surveyed = req && SYLVA_HAS_FIELD(req, sylva_terrain_request, surveyed) && req->surveyed;
    if (surveyed && !renders_dtm_nodes(s)) return surveyed_ground(s, &r, req, placed, o);
    if (surveyed && SYLVA_HAS_FIELD(o, sylva_terrain_out, renders_as_is)) o->renders_as_is = 1;
    if ((rc = choose_alpha(s, &r))) return rc;
    plugin_err err = {0};
    ifs_maps *maps = NULL;
    ifs_maps_params mp = {.mode = s->mode, .alpha = s->alpha, .alpha_field = s->alpha_field,
                          .probability = s->probability_field};
    rc = ifs_maps_build(s->dtm, &mp, &maps, &err);
    if (rc) {
        api->error(host, "%s", err.msg);
        return rc;
    }
    sylva_heightfield *hf = api->heightfield_new(host, s->nx_out, s->ny_out, s->classes);
    if (!hf) { /* the host has said why */
        ifs_maps_free(maps);
        return SYLVA_ERR_NOMEM;
    }
    place_footprint(s, req, placed, hf);
    hf->dx = (s->dtm->nx - 1) * s->dtm->dx / (s->nx_out - 1);
    hf->dy = (s->dtm->ny - 1) * s->dtm->dy / (s->ny_out - 1);
    /* with levels of detail: the depth of the uniform refinement the finest level stands for */
    uint32_t depth = s->depth ? s->depth
                     : s->lod ? ifs_eval_auto_depth(maps, (s->dtm->nx - 1) * s->refine + 1,
                                                    (s->dtm->ny - 1) * s->refine + 1)
                              : ifs_eval_auto_depth(maps, s->nx_out, s->ny_out);
    double rms, top;
    ifs_detail_measure(maps, depth, &rms, &top);
    api->log(host, SYLVA_LOG_INFO, "%s: %u x %u nodes %.3g x %.3g m apart, heights %.1f to %.1f m; "
             "%s maps, alpha %s %.4g: the refinement adds %.3g m RMS of detail to the DTM's surface, "
             "at most %.3g m", s->source, s->dtm->nx, s->dtm->ny, s->dtm->dx, s->dtm->dy, s->zmin, s->zmax,
             s->mode == IFS_MODE_AFFINE ? "affine" : "bilinear", s->alpha_field ? "per cell, largest |alpha|"
             : "global", maps->alpha_max, rms, top);
    double own = s->roughness.target;
    if (rms > TERRAIN_IFS_DETAIL_WARN_FACTOR * own + TERRAIN_IFS_DETAIL_WARN_METRES)
        api->log(host, SYLVA_LOG_WARN, "%s adds %.3g m RMS of relief (at most %.3g m) within the DTM's "
                 "%.3g m cells, %.1f times the %.3g m its own roughness continues to: the render shows "
                 "relief the DTM does not have (the analyses read the DTM as surveyed); leave alpha out "
                 "to continue the DTM's roughness, or give detail in metres",
                 s->alpha_field ? "alpha_field" : is_set(&r, "detail") ? "detail" : "alpha", rms, top,
                 fmin(s->dtm->dx, s->dtm->dy), own > 0 ? rms / own : INFINITY, own);
    if (s->lod) {
        double eye[2] = {NAN, NAN};
        if (req && SYLVA_HAS_FIELD(req, sylva_terrain_request, eye))
            eye[0] = (req->eye[0] - hf->x0) / hf->dx, eye[1] = (req->eye[1] - hf->y0) / hf->dy;
        rc = refine_levels(s, maps, depth, eye, api, host, hf);
    } else {
        ifs_window whole = {0, 0, s->nx_out, s->ny_out};
        rc = compute_heights(s, maps, depth, s->nx_out, s->ny_out, &whole, api, host, hf->z);
    }
    ifs_maps_free(maps);
    if (rc) return rc;
    set_water_and_edge(s, &r, hf);
    if (r.status) return r.status; /* the host has the sentence */
    if (s->classes && (rc = apply_surface(s, api, host, hf))) return rc;
    o->terrain = hf;
    return SYLVA_OK;
}

static void terrain_ifs_destroy(void *state) { state_free(state); }

static const sylva_plugin terrain_ifs = {
    .size = sizeof(sylva_plugin),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .param_spec_size = sizeof(sylva_param_spec),
    .kind = SYLVA_KIND_TERRAIN,
    .name = "terrain_ifs",
    .summary = "A DTM refined by 3-D fractal interpolation with an IFS (Petric 1994), with "
               "ground cover and water.",
    .version = "1.0",
    .params = terrain_ifs_params,
    .n_params = TERRAIN_IFS_N_PARAMS,
    .create = terrain_ifs_create,
    .generate = terrain_ifs_generate,
    .destroy = terrain_ifs_destroy,
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &terrain_ifs : NULL;
}
