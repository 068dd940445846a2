/* host.h — the host's side of a plugin call: the sylva_host a plugin receives (scene, seed,
 * error sentence, progress, log level) and the sylva_host_api table that serves it.
 *
 * Ownership: a sylva_host borrows the scene and err_buf; paths it resolves for a plugin are
 * owned by it and freed by host_release. */
#ifndef SYLVA_HOST_H
#define SYLVA_HOST_H

#include "scene/scene.h"
#include "sylva/plugin.h"
#include "util/progress.h"

struct sylva_host {
    scene *scene;          /* borrowed: where meshes, materials and plants go */
    const char *scene_dir; /* folder that relative paths resolve against */
    uint64_t seed;         /* seed of this call's random streams */
    const char *context;   /* e.g. "terrain plugin 'terrain_ifs'", for messages */
    err_buf *err;          /* borrowed: the plugin's failure sentence goes here */
    int error_set;         /* 1 once the plugin called error()/param_error() */
    int out_of_memory;     /* 1 once a host function ran out of memory for the plugin */
    int verbose;           /* 1: print DEBUG logs */
    int quiet;             /* 1: no progress */
    int warnings_only;     /* 1 (-q): INFO logs are not printed; warnings always are */
    int progress_open;
    progress prog;
    char **paths; uint32_t n_paths; /* owned: strings returned by resolve_path */
    /* ecology: plants are collected here, then turned into instances */
    sylva_plant *plants; uint32_t n_plants, cap_plants; /* owned */
    uint32_t n_species;    /* ecology: species count for checking plant_add */
    sylva_kind kind;       /* the calling plugin's kind: heightfield_new only for terrain,
                              plant_add only for ecology; 0 (tests) allows both */
    unsigned threads;      /* the plugin's worker threads (api->threads); 0: one per processor */
    int concurrent;        /* 1: one of several hosts calling generate() at once on one plugin
                              state; material_new and texture_new refuse (create() makes them) */
    int surveyed;          /* terrain: 1 while the plugin answers for the ground as surveyed;
                              heightfield_new then makes scene->surveyed, not scene->terrain */
};

void host_init(sylva_host *h, scene *sc, const char *scene_dir, uint64_t seed, const char *context,
               err_buf *err);
void host_release(sylva_host *h); /* frees resolved paths and plants; ends open progress */

const sylva_host_api *host_api_table(void);

#endif
