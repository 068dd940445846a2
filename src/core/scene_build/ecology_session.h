/* ecology_session.h — a scene's ecology plugin driven year by year through its optional
 * "sylva.ecology.v1" interface (include/sylva/plugin.h), for `sylva simulate` and
 * `sylva factors`. The plugin is opened through plugin_call, which writes the ecology request
 * for scene_build too, so a run stepped here to the scene's year holds the plants
 * `sylva render` places. Failures read as every plugin failure does (plugin_call.h).
 *
 * Ownership: a session owns the plugin call (state, host, species array) and the run; it
 * borrows the scene_file and the scene (built with build_options.no_ecology), which must
 * outlive it. ecology_session_free accepts NULL.
 */
#ifndef SYLVA_ECOLOGY_SESSION_H
#define SYLVA_ECOLOGY_SESSION_H

#include "plugin/plugin_host.h"
#include "scene_build/build_options.h"
#include "scene_build/plugin_call.h"

typedef struct ecology_session {
    const scene_file *sf;               /* borrowed */
    plugin_call call;                   /* owned: the plugin, its state and host */
    const sylva_ecology_ext_v1 *ext;    /* the plugin's */
    const sylva_ecology_ext_v2 *ext2;   /* the plugin's, or NULL when it offers only v1 */
    const sylva_ecology_ext_v3 *ext3;   /* the plugin's, or NULL when it offers no v3 */
    sylva_ecology_run *run;             /* owned */
} ecology_session;

/* Starts the scene's ecology at year 0. Fails (NULL, err set) when the scene has no ecology, the
 * plugin is missing or offers no "sylva.ecology.v1" interface, or create/run_new fail. */
ecology_session *ecology_session_open(const scene_file *sf, scene *s, const plugin_registry *reg,
                                      const build_options *opt, err_buf *err);
void ecology_session_free(ecology_session *e);

uint32_t ecology_session_year(const ecology_session *e);
uint32_t ecology_session_years_wanted(const ecology_session *e);

/* Each returns 0, or -1 with err holding the plugin's sentence after the session's context. */
int ecology_session_step(ecology_session *e, uint32_t years, err_buf *err);
int ecology_session_save(ecology_session *e, const char *path, err_buf *err);
int ecology_session_load(ecology_session *e, const char *path, err_buf *err);

/* Living plants: all (which = SYLVA_ECOLOGY_ALL_SPECIES) or of species `which`. */
uint32_t ecology_session_count(const ecology_session *e, uint32_t which);

/* Copies every living plant into a malloc'ed array (*out, *n; the caller frees *out). */
int ecology_session_plants(ecology_session *e, sylva_ecology_plant_record **out, uint32_t *n, err_buf *err);

/* Factor maps: their number and each one (values owned by the run). */
/* Adds the run's plants to the session's host (e->call.host.plants) as the plugin's generate()
 * would place them; *placed gets how many. Fails (err set) for a plugin without
 * "sylva.ecology.v2". */
int ecology_session_place(ecology_session *e, uint32_t *placed, err_buf *err);

/* The fate of plants set out by hand, grown `years` years among themselves by the run's rules
 * (sylva_ecology_ext_v3.planted_fate): died[i] the year plant i died in, 0 when it stands.
 * Fails (err set) for a plugin without "sylva.ecology.v3". */
int ecology_session_planted_fate(ecology_session *e, const sylva_ecology_planted *plants, uint32_t n,
                                 uint32_t years, uint64_t seed, uint32_t *died, err_buf *err);

uint32_t ecology_session_factor_count(const ecology_session *e);
int ecology_session_factor(ecology_session *e, uint32_t i, sylva_ecology_factor_map *out, err_buf *err);

#endif
