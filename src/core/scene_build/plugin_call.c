/* plugin_call.c — opening a plugin for one part of a scene, its requests, and its failures in
 * one format (plugin_call.h). */
#include "scene_build/plugin_call.h"

#include "scene_build/ecology_habitat.h"
#include "scene_build/scene_landcover.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/rng.h"

/* The seed of a tree plugin's random streams for one species (by name) and variant. */
static uint64_t species_seed(const scene_file *sf, const char *name, uint32_t variant)
{
    return rng_combine(rng_combine(sf->image.seed, rng_hash_str(name)), variant);
}

int plugin_call_failed(plugin_call *c, const char *op, int rc, err_buf *err)
{
    const err_buf *why = &c->plugin_err;
    char text[ERR_MSG_MAX];
    if (c->host.error_set && why->msg[0]) snprintf(text, sizeof text, "%s", err_sentence(why));
    else snprintf(text, sizeof text, "returned status %d without saying why", rc);
    int nomem = rc == SYLVA_ERR_NOMEM || c->host.out_of_memory || why->status == ERR_NOMEM;
    err_status status = nomem ? ERR_NOMEM : ERR_PLUGIN;
    if (err_has_place(why))
        err_at(err, status, why->file, why->line, why->column, "%s: %s failed: %s (%s)", c->context, op, text,
               c->plugin->file);
    else
        err_at(err, status, c->sf->path, c->line, c->column, "%s: %s failed: %s (%s)", c->context, op, text,
               c->plugin->file);
    /* The next call starts with no sentence. */
    err_clear(&c->plugin_err);
    c->host.error_set = 0, c->host.out_of_memory = 0;
    return -1;
}

int plugin_call_refuse(plugin_call *c, const char *op, err_status status, err_buf *err, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    err_vset(&c->plugin_err, fmt, ap);
    va_end(ap);
    c->plugin_err.status = status;
    c->host.error_set = 1;
    return plugin_call_failed(c, op, SYLVA_ERR_INTERNAL, err);
}

/* Starts c for the plugin of the scene file's block at line:column, named in messages by the
 * context (printf-style). */
static void call_begin(plugin_call *c, const scene_file *sf, uint32_t line, uint32_t column, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
static void call_begin(plugin_call *c, const scene_file *sf, uint32_t line, uint32_t column, const char *fmt, ...)
{
    memset(c, 0, sizeof *c);
    c->sf = sf, c->line = line, c->column = column;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->context, sizeof c->context, fmt, ap);
    va_end(ap);
}

/* The seed of the plugin for one part of the scene ("terrain", "ecology"). */
static uint64_t part_seed(const scene_file *sf, const char *part)
{
    return rng_combine(sf->image.seed, rng_hash_str(part));
}

/* Finds the plugin, sets up its host and runs create(). c->sf, c->line, c->column and
 * c->context are set. */
static int call_open(plugin_call *c, scene *s, const plugin_registry *reg, const char *name, sylva_kind kind,
                     const sylva_params *params, uint64_t seed, const plugin_call_output *out, err_buf *err)
{
    err_buf lookup = {{0}};
    c->plugin = reg ? plugin_registry_find(reg, name, kind, &lookup) : NULL;
    if (!c->plugin) {
        if (lookup.status == ERR_NOMEM) return err_nomem(err, "%s", lookup.msg);
        return err_at(err, ERR_INPUT, c->sf->path, c->line, c->column, "%s",
                      reg ? lookup.msg : "no plugins were loaded");
    }
    host_init(&c->host, s, c->sf->dir, seed, c->context, &c->plugin_err);
    c->host.verbose = out ? out->verbose : 0, c->host.quiet = out ? out->quiet : 0, c->host.kind = kind;
    c->host.warnings_only = out ? out->warnings_only : 0;
    c->host.threads = out ? out->threads : 0;
    c->times = out ? out->times : NULL;
    c->host.n_species = kind == SYLVA_KIND_ECOLOGY ? c->sf->n_species : 0;
    int rc = c->plugin->desc->create(host_api_table(), &c->host, params, &c->state);
    if (rc) {
        c->state = NULL;
        plugin_call_failed(c, "create", rc, err);
        plugin_call_close(c);
        return -1;
    }
    return 0;
}

int plugin_call_concurrent(const plugin_call *c)
{
    return c->plugin && (c->plugin->desc->flags & SYLVA_PLUGIN_CONCURRENT_GENERATE);
}

void plugin_call_share(const plugin_call *c, plugin_call *w)
{
    *w = *c;
    err_clear(&w->plugin_err);
    w->species_info = NULL; /* c's */
    w->habitat = NULL;      /* c's */
    const sylva_host *h = &c->host;
    host_init(&w->host, h->scene, h->scene_dir, h->seed, w->context, &w->plugin_err);
    w->host.verbose = h->verbose, w->host.quiet = h->quiet, w->host.kind = h->kind, w->host.threads = h->threads;
    w->host.warnings_only = h->warnings_only;
    w->host.concurrent = 1;
}

void plugin_call_unshare(plugin_call *w)
{
    host_release(&w->host);
    memset(w, 0, sizeof *w);
}

void plugin_call_close(plugin_call *c)
{
    if (c->plugin && c->state) c->plugin->desc->destroy(c->state);
    if (c->plugin) host_release(&c->host);
    free(c->species_info);
    ecology_habitat_free(c->habitat, c->sf ? c->sf->n_species : 0);
    memset(c, 0, sizeof *c);
}

int plugin_call_open_terrain(plugin_call *c, const scene_file *sf, scene *s, const plugin_registry *reg,
                             const plugin_call_output *out, err_buf *err)
{
    const terrain_spec *t = &sf->terrain;
    call_begin(c, sf, t->line, t->column, "terrain plugin '%s'", t->plugin);
    c->has_cover_shares = scene_landcover_shares(sf, c->cover_shares);
    return call_open(c, s, reg, t->plugin, SYLVA_KIND_TERRAIN, t->params, part_seed(sf, "terrain"), out, err);
}

int plugin_call_open_tree(plugin_call *c, const scene_file *sf, const species_spec *sp, scene *s,
                          const plugin_registry *reg, const plugin_call_output *out, err_buf *err)
{
    call_begin(c, sf, sp->line, sp->column, "tree plugin '%s' for species '%s'", sp->plugin, sp->name);
    c->species = sp;
    return call_open(c, s, reg, sp->plugin, SYLVA_KIND_TREE, sp->params, species_seed(sf, sp->name, 0), out, err);
}

/* The ecology request's species: name, the species' block under the ecology's species section,
 * and the full-grown model's height (its oldest variant). */
static sylva_species_info *ecology_species(const scene *s, const scene_file *sf, err_buf *err)
{
    sylva_species_info *info = calloc(sf->n_species ? sf->n_species : 1, sizeof *info);
    if (!info) {
        err_nomem(err, "out of memory for %u species", sf->n_species);
        return NULL;
    }
    for (uint32_t i = 0; i < sf->n_species && i < s->n_species; i++) {
        const species *sp = &s->species[i];
        double h = sp->n_variants ? s->prototypes[sp->first_prototype + sp->n_variants - 1].height : 0;
        info[i] = (sylva_species_info){.size = sizeof *info, .name = sp->name, .ecology = sf->species[i].ecology,
                                       .model_height = h};
    }
    return info;
}

/* The site origin's latitude for a plugin's request (ABI 1.6): NaN without a site. */
static double site_latitude(const scene_file *sf)
{
    return sf->site.crs_wkt ? sf->site.latitude_deg : NAN;
}

int plugin_call_open_ecology(plugin_call *c, const scene_file *sf, scene *s, const plugin_registry *reg,
                             const plugin_call_output *out, err_buf *err)
{
    const ecology_spec *es = &sf->ecology;
    call_begin(c, sf, es->line, es->column, "ecology plugin '%s'", es->plugin);
    if (!s->surveyed) return err_at(err, ERR_INPUT, sf->path, es->line, es->column, "the ecology needs a terrain");
    if (!(c->species_info = ecology_species(s, sf, err))) return -1;
    uint64_t seed = part_seed(sf, "ecology");
    err_clear(err);
    c->habitat = ecology_habitat_new(s, sf, err);
    if (!c->habitat && err->status) return -1;
    c->ecology = (sylva_ecology_request){.size = sizeof c->ecology, .seed = seed, .terrain = s->surveyed,
                                         .species = c->species_info, .n_species = sf->n_species,
                                         .site_latitude = site_latitude(sf),
                                         .habitat = (const uint8_t *const *)c->habitat};
    if (call_open(c, s, reg, es->plugin, SYLVA_KIND_ECOLOGY, es->params, seed, out, err)) {
        plugin_call_close(c);
        return -1;
    }
    return 0;
}

int plugin_call_knows_surveyed(const plugin_call *c)
{
    return c->plugin->desc->abi_minor >= 5;
}

/* Where the development stands (scene_file_development_place); NaN when the scene names none. */
static void development_centre(const scene_file *sf, double at[3])
{
    if (scene_file_development_place(sf, at)) at[0] = at[1] = NAN;
    at[2] = NAN;
}

int plugin_call_terrain(plugin_call *c, int surveyed, int at_development, err_buf *err)
{
    scene *s = c->host.scene;
    const scene_file *sf = c->sf;
    sylva_terrain_request req = {.size = sizeof req, .seed = c->host.seed, .site_crs = sf->site.crs_wkt,
                                 .site_origin = {sf->site.origin[0], sf->site.origin[1], sf->site.origin[2]},
                                 .eye = {sf->camera.position[0], sf->camera.position[1], sf->camera.position[2]},
                                 .surveyed = surveyed, .site_latitude = site_latitude(sf),
                                 .cover_shares = c->has_cover_shares ? c->cover_shares : NULL};
    if (at_development) development_centre(sf, req.eye);
    else if (!sf->has_camera) req.eye[0] = req.eye[1] = req.eye[2] = NAN; /* no eye: the footprint's centre */
    sylva_terrain_out out = {.size = sizeof out};
    c->host.surveyed = surveyed;
    phase_mark t0 = phase_start();
    int rc = c->plugin->desc->generate(c->state, host_api_table(), &c->host, &req, &out);
    phase_stop(c->times, PHASE_TERRAIN, t0);
    c->host.surveyed = 0;
    if (rc) return plugin_call_failed(c, "generate", rc, err);
    c->renders_as_is = surveyed && out.renders_as_is;
    const sylva_heightfield *hf = surveyed ? s->surveyed : s->terrain;
    if (!out.terrain || out.terrain != hf)
        return plugin_call_refuse(c, "generate", ERR_PLUGIN, err, "gave no heightfield made with heightfield_new");
    if (!(hf->dx > 0 && hf->dy > 0 && isfinite(hf->x0) && isfinite(hf->y0)))
        return plugin_call_refuse(c, "generate", ERR_PLUGIN, err,
                                  "gave a heightfield with spacing %g x %g; spacing must be positive", hf->dx, hf->dy);
    for (size_t i = 0; i < (size_t)hf->nx * hf->ny; i++)
        if (!isfinite(hf->z[i]))
            return plugin_call_refuse(c, "generate", ERR_PLUGIN, err, "gave a non-finite height at node %zu", i);
    return 0;
}

int plugin_call_tree(plugin_call *c, tree_variant *v, mesh *m, err_buf *err)
{
    if (!(v->age > 0)) v->age = (double)(v->index + 1) / v->count;
    c->host.seed = species_seed(c->sf, c->species->name, v->index);
    sylva_tree_request req = {.size = sizeof req, .age = v->age, .variant = v->index, .n_variants = v->count,
                              .lod = 0, .seed = c->host.seed};
    sylva_tree_out out = {.size = sizeof out, .mesh = m};
    int rc = c->plugin->desc->generate(c->state, host_api_table(), &c->host, &req, &out);
    if (rc) return plugin_call_failed(c, "generate", rc, err);
    if (!(out.height > 0 && isfinite(out.height))) {
        float lo[3], hi[3];
        mesh_bounds(m, lo, hi);
        out.height = hi[2] - lo[2];
    }
    v->height = out.height;
    return 0;
}

int plugin_call_ecology(plugin_call *c, err_buf *err)
{
    sylva_ecology_out out = {.size = sizeof out};
    phase_mark t0 = phase_start();
    int rc = c->plugin->desc->generate(c->state, host_api_table(), &c->host, &c->ecology, &out);
    phase_stop(c->times, PHASE_ECOLOGY, t0);
    return rc ? plugin_call_failed(c, "generate", rc, err) : 0;
}
