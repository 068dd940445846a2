/* ecology_session.c — the scene's ecology plugin opened through plugin_call, its
 * "sylva.ecology.v1" run, and the run's calls. */
#include "scene_build/ecology_session.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

ecology_session *ecology_session_open(const scene_file *sf, scene *s, const plugin_registry *reg,
                                      const build_options *opt, err_buf *err)
{
    if (!sf->ecology.plugin) {
        err_fail(err, ERR_INPUT,
                 "%s: the scene has no 'ecology:' section; add one (ecology: {plugin: ecology}) to grow plants",
                 sf->path);
        return NULL;
    }
    ecology_session *e = calloc(1, sizeof *e);
    if (!e) {
        err_nomem(err, "out of memory");
        return NULL;
    }
    e->sf = sf;
    /* The command reports progress per year itself. */
    plugin_call_output out = {.verbose = opt ? opt->verbose : 0, .quiet = 1,
                              .warnings_only = opt ? opt->quiet : 0, .threads = opt ? opt->threads : 0,
                              .times = opt ? opt->times : NULL};
    if (plugin_call_open_ecology(&e->call, sf, s, reg, &out, err)) {
        free(e);
        return NULL;
    }
    const loaded_plugin *lp = e->call.plugin;
    e->ext = lp->desc->extension ? lp->desc->extension(SYLVA_ECOLOGY_EXT_V1) : NULL;
    if (!e->ext || e->ext->size < sizeof *e->ext) {
        err_at(err, ERR_INPUT, sf->path, sf->ecology.line, sf->ecology.column,
               "ecology plugin '%s' (%s) cannot be run year by year: it offers no '%s' interface; render the scene "
               "instead", sf->ecology.plugin, lp->file, SYLVA_ECOLOGY_EXT_V1);
        ecology_session_free(e);
        return NULL;
    }
    const sylva_ecology_ext_v2 *v2 = lp->desc->extension(SYLVA_ECOLOGY_EXT_V2);
    e->ext2 = v2 && v2->v1.size >= sizeof *v2 ? v2 : NULL;
    const sylva_ecology_ext_v3 *v3 = lp->desc->extension(SYLVA_ECOLOGY_EXT_V3);
    e->ext3 = v3 && v3->v2.v1.size >= sizeof *v3 ? v3 : NULL;
    int rc = e->ext->run_new(e->call.state, host_api_table(), &e->call.host, &e->call.ecology, &e->run);
    if (rc) {
        e->run = NULL;
        plugin_call_failed(&e->call, "run_new", rc, err);
        ecology_session_free(e);
        return NULL;
    }
    return e;
}

void ecology_session_free(ecology_session *e)
{
    if (!e) return;
    if (e->run) e->ext->run_free(e->run);
    plugin_call_close(&e->call);
    free(e);
}

uint32_t ecology_session_year(const ecology_session *e) { return e->ext->year(e->run); }
uint32_t ecology_session_years_wanted(const ecology_session *e) { return e->ext->years_wanted(e->run); }

int ecology_session_step(ecology_session *e, uint32_t years, err_buf *err)
{
    phase_mark t0 = phase_start();
    int rc = e->ext->step(e->run, host_api_table(), &e->call.host, years);
    phase_stop(e->call.times, PHASE_ECOLOGY, t0);
    return rc ? plugin_call_failed(&e->call, "step", rc, err) : 0;
}

int ecology_session_save(ecology_session *e, const char *path, err_buf *err)
{
    int rc = e->ext->save(e->run, host_api_table(), &e->call.host, path);
    if (!rc) return 0;
    plugin_call_failed(&e->call, "save", rc, err);
    if (rc == SYLVA_ERR_IO && err) err->status = ERR_OUTPUT; /* the state file was not written */
    return -1;
}

int ecology_session_load(ecology_session *e, const char *path, err_buf *err)
{
    phase_mark t0 = phase_start();
    int rc = e->ext->load(e->run, host_api_table(), &e->call.host, path);
    phase_stop(e->call.times, PHASE_ECOLOGY, t0);
    return rc ? plugin_call_failed(&e->call, "load", rc, err) : 0;
}

/* The refusal of a call the plugin's interfaces lack: at the scene's ecology section. */
static int lacks_interface(const ecology_session *e, const char *what, const char *id, const char *instead,
                           err_buf *err)
{
    return err_at(err, ERR_INPUT, e->sf->path, e->sf->ecology.line, e->sf->ecology.column,
                  "ecology plugin '%s' (%s) cannot %s: it offers no '%s' interface; %s", e->sf->ecology.plugin,
                  e->call.plugin->file, what, id, instead);
}

int ecology_session_place(ecology_session *e, uint32_t *placed, err_buf *err)
{
    *placed = 0;
    if (!e->ext2)
        return lacks_interface(e, "place a saved run's plants", SYLVA_ECOLOGY_EXT_V2,
                               "give the plants as a list, or let the ecology run", err);
    phase_mark t0 = phase_start();
    int rc = e->ext2->place(e->run, host_api_table(), &e->call.host, placed);
    phase_stop(e->call.times, PHASE_ECOLOGY, t0);
    return rc ? plugin_call_failed(&e->call, "place", rc, err) : 0;
}

int ecology_session_planted_fate(ecology_session *e, const sylva_ecology_planted *plants, uint32_t n,
                                 uint32_t years, uint64_t seed, uint32_t *died, err_buf *err)
{
    if (!e->ext3)
        return lacks_interface(e, "grow planted plants", SYLVA_ECOLOGY_EXT_V3,
                               "set 'ecology: false' in the planting plan", err);
    phase_mark t0 = phase_start();
    int rc = e->ext3->planted_fate(e->run, host_api_table(), &e->call.host, plants, n, years, seed, died);
    phase_stop(e->call.times, PHASE_ECOLOGY, t0);
    return rc ? plugin_call_failed(&e->call, "planted_fate", rc, err) : 0;
}

uint32_t ecology_session_count(const ecology_session *e, uint32_t which)
{
    return e->ext->plant_count(e->run, which);
}

int ecology_session_plants(ecology_session *e, sylva_ecology_plant_record **out, uint32_t *n, err_buf *err)
{
    *out = NULL, *n = 0;
    uint32_t count = e->ext->plant_count(e->run, SYLVA_ECOLOGY_ALL_SPECIES);
    sylva_ecology_plant_record *p = malloc((count ? count : 1) * sizeof *p);
    if (!p) return err_nomem(err, "out of memory for %u plants", count);
    int rc = e->ext->plants(e->run, host_api_table(), &e->call.host, 0, count, p);
    if (rc) {
        free(p);
        return plugin_call_failed(&e->call, "plants", rc, err);
    }
    for (uint32_t i = 0; i < count; i++)
        if (p[i].species >= e->sf->n_species) {
            uint32_t bad = p[i].species;
            free(p);
            return plugin_call_refuse(&e->call, "plants", ERR_PLUGIN, err, "plant %u names species %u; the scene has %u",
                                      i, bad, e->sf->n_species);
        }
    *out = p, *n = count;
    return 0;
}

uint32_t ecology_session_factor_count(const ecology_session *e) { return e->ext->factor_count(e->run); }

int ecology_session_factor(ecology_session *e, uint32_t i, sylva_ecology_factor_map *out, err_buf *err)
{
    memset(out, 0, sizeof *out);
    int rc = e->ext->factor(e->run, i, out);
    if (rc || !out->values || !out->nx || !out->ny || !out->name)
        return plugin_call_refuse(&e->call, "factor", ERR_PLUGIN, err, "factor map %u is missing or empty", i);
    return 0;
}
