/* plugin_call.h — the one way the core calls a plugin: find it in the registry by name and kind,
 * set up the sylva_host it works through, create() it with its validated parameters, make its
 * requests, destroy() it, and report any failure in one format:
 *
 *   FILE:LINE:COLUMN: CONTEXT: OP failed: SENTENCE (PLUGIN FILE)
 *
 * placed at the parameter the plugin named (api->param_error) or else at the plugin's block in
 * the scene file, with status ERR_NOMEM when the plugin or the host ran out of memory and
 * ERR_PLUGIN otherwise. The request of each kind is written here once — the terrain's, a tree
 * variant's (age and seed) and the ecology's — so every command that grows a scene's trees or
 * forest (render, export-pov, simulate, factors, tree-stats) asks the plugins the same.
 *
 * Ownership: a plugin_call owns the plugin's state, its host and (ecology) the species array,
 * all released by plugin_call_close; it borrows the registry's plugin, the scene file and the
 * scene, which must outlive it. The host points into the plugin_call, so a plugin_call stays
 * where it was opened until it is closed.
 */
#ifndef SYLVA_PLUGIN_CALL_H
#define SYLVA_PLUGIN_CALL_H

#include "plugin/plugin_host.h"
#include "scene_build/host.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "scene_file/scene_file.h"
#include "util/phase_times.h"

typedef struct plugin_call {
    const loaded_plugin *plugin;   /* the registry's */
    void *state;                   /* from create(); owned */
    sylva_host host;               /* the plugin's side of the calls */
    int renders_as_is;             /* terrain: the surveyed ground the last call gave is also the
                                      ground to render (sylva_terrain_out.renders_as_is) */
    err_buf plugin_err;            /* where the plugin's sentences land */
    char context[200];             /* "tree plugin 'x' for species 'y'", for messages */
    const scene_file *sf;          /* borrowed */
    uint32_t line, column;         /* the plugin's block in sf->path */
    const species_spec *species;   /* tree: borrowed from sf */
    sylva_species_info *species_info; /* ecology: owned array of sf->n_species */
    sylva_ecology_request ecology; /* ecology: the request for generate() and the run */
    uint8_t **habitat;             /* ecology: owned rows of the request's habitat (ecology_habitat.h),
                                      sf->n_species of them, or NULL */
    phase_times *times;            /* borrowed, may be NULL: where the calls' wall times add up */
    double cover_shares[SYLVA_COVER_KINDS]; /* terrain: the land cover near the site origin */
    int has_cover_shares;          /* terrain: 1 when cover_shares holds them */
} plugin_call;

/* How the plugin runs: verbose prints its DEBUG logs, quiet hides progress, warnings_only (the
 * commands' -q) hides its INFO logs (not its warnings), threads bounds its worker threads
 * (api->threads; 0: one per processor), and times (may be NULL) collects the wall time of the
 * terrain's and the ecology's generate(). */
typedef struct plugin_call_output {
    int verbose, quiet, warnings_only;
    unsigned threads;
    phase_times *times;
} plugin_call_output;

/* Each opens the plugin the scene file names for that part of the scene (the terrain, species
 * sp, the ecology) on scene s, and runs its create(). Returns 0, or -1 with err set (the
 * plugin missing or of another kind, create() failing, the ecology without a terrain) and c
 * closed. reg may be NULL ("no plugins were loaded"). */
int plugin_call_open_terrain(plugin_call *c, const scene_file *sf, scene *s, const plugin_registry *reg,
                             const plugin_call_output *out, err_buf *err);
int plugin_call_open_tree(plugin_call *c, const scene_file *sf, const species_spec *sp, scene *s,
                          const plugin_registry *reg, const plugin_call_output *out, err_buf *err);
int plugin_call_open_ecology(plugin_call *c, const scene_file *sf, scene *s, const plugin_registry *reg,
                             const plugin_call_output *out, err_buf *err);
/* Destroys the plugin's state and releases the host; accepts a zeroed or closed c. */
void plugin_call_close(plugin_call *c);

/* The terrain: generate() into the scene's heightfield, checked (made with heightfield_new,
 * positive spacing, finite heights). surveyed: the ground as surveyed into scene.surveyed (the
 * request's `surveyed`; only for a plugin that plugin_call_knows_surveyed), else the ground to
 * render into scene.terrain, refined around the camera, or around the development when
 * at_development (build_options.detail_at_development). Returns 0, or -1 with err set. */
int plugin_call_terrain(plugin_call *c, int surveyed, int at_development, err_buf *err);

/* 1 when the open terrain plugin was built for ABI 1.5 or later, so that it tells the ground
 * as surveyed from the ground to render. */
int plugin_call_knows_surveyed(const plugin_call *c);

/* One age variant of a tree species. */
typedef struct tree_variant {
    uint32_t index, count; /* variant index of count */
    double age;            /* normalised age in (0, 1]; 0 asks for (index + 1) / count */
    double height;         /* set by plugin_call_tree: the model's height in metres */
} tree_variant;

/* Makes variant v into m (an empty mesh the caller owns), seeded for the species and variant
 * index; sets v->age when it was 0 and v->height (from the mesh's bounds when the plugin gave
 * none). Returns 0, or -1 with err set. */
int plugin_call_tree(plugin_call *c, tree_variant *v, mesh *m, err_buf *err);

/* 1 when c's plugin lets generate() run for several requests at once on its state
 * (SYLVA_PLUGIN_CONCURRENT_GENERATE). */
int plugin_call_concurrent(const plugin_call *c);

/* A second caller of c's plugin state for a concurrent generate(): w gets c's plugin, state and
 * request settings with a host and failure sentence of its own. c must stay open while w is in
 * use; plugin_call_unshare(w) releases w's host (never the state, which c owns). */
void plugin_call_share(const plugin_call *c, plugin_call *w);
void plugin_call_unshare(plugin_call *w);

/* The ecology: generate(); its plants are then c->host.plants (c->host.n_plants), owned by the
 * host until plugin_call_close. Returns 0, or -1 with err set. */
int plugin_call_ecology(plugin_call *c, err_buf *err);

/* Reports that the plugin's operation op returned status rc (a sylva_status), with the
 * sentence the plugin left, in the format above. Returns -1. */
int plugin_call_failed(plugin_call *c, const char *op, int rc, err_buf *err);
/* Reports that what op gave cannot be used (fmt says why), in the same format; status is
 * ERR_PLUGIN, or ERR_NOMEM when the host ran out of memory taking it. Returns -1. */
int plugin_call_refuse(plugin_call *c, const char *op, err_status status, err_buf *err, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

#endif
