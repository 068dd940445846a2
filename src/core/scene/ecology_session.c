/* ecology_session.c — create(), the "sylva.ecology.v1" run and its calls, with the plugin's
 * failures turned into located sentences. */
#include "scene/ecology_session.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The plugin's sentence (or a stand-in when it gave none) after the session's context. */
static int session_failed(ecology_session *e, const char *op, int rc, err_buf *err)
{
    const char *why = e->host.error_set ? e->plugin_err.msg : "";
    if (!*why) err_set(err, "%s (%s): %s returned status %d without saying why", e->context, e->plugin->file, op, rc);
    else err_set(err, "%s (%s): %s failed: %s", e->context, e->plugin->file, op, why);
    e->host.error_set = 0;
    e->plugin_err.msg[0] = '\0';
    return -1;
}

ecology_session *ecology_session_open(const scene_file *sf, scene *s, const plugin_registry *reg,
                                      const build_options *opt, err_buf *err)
{
    const ecology_spec *es = &sf->ecology;
    if (!es->plugin) {
        err_set(err, "%s: the scene has no 'ecology:' section; add one (ecology: {plugin: ecology}) to grow plants",
                sf->path);
        return NULL;
    }
    if (!s->terrain) {
        err_set(err, "%s:%u:%u: the ecology needs a terrain", sf->path, es->line, es->column);
        return NULL;
    }
    err_buf lookup = {{0}};
    const loaded_plugin *lp = reg ? plugin_registry_find(reg, es->plugin, SYLVA_KIND_ECOLOGY, &lookup) : NULL;
    if (!lp) {
        err_set(err, "%s:%u:%u: %s", sf->path, es->line, es->column, reg ? lookup.msg : "no plugins were loaded");
        return NULL;
    }
    const sylva_ecology_ext_v1 *ext = lp->desc->extension ? lp->desc->extension(SYLVA_ECOLOGY_EXT_V1) : NULL;
    if (!ext || ext->size < sizeof *ext) {
        err_set(err, "%s:%u:%u: ecology plugin '%s' (%s) cannot be run year by year: it offers no '%s' interface; "
                "render the scene instead", sf->path, es->line, es->column, es->plugin, lp->file, SYLVA_ECOLOGY_EXT_V1);
        return NULL;
    }
    ecology_session *e = calloc(1, sizeof *e);
    if (!e) {
        err_set(err, "out of memory");
        return NULL;
    }
    e->sf = sf, e->scene = s, e->plugin = lp, e->ext = ext;
    snprintf(e->context, sizeof e->context, "ecology plugin '%s'", es->plugin);
    host_init(&e->host, s, sf->dir, scene_ecology_seed(sf), e->context, &e->plugin_err);
    e->host.verbose = opt ? opt->verbose : 0;
    e->host.quiet = 1; /* the command reports progress per year itself */
    e->host.n_species = sf->n_species, e->host.kind = SYLVA_KIND_ECOLOGY;
    if (!(e->species = scene_ecology_species(s, sf, err))) goto fail;
    const sylva_host_api *api = host_api_table();
    int rc = lp->desc->create(api, &e->host, es->params, &e->state);
    if (rc) {
        session_failed(e, "create", rc, err);
        e->state = NULL;
        goto fail;
    }
    sylva_ecology_request req = {.size = sizeof req, .seed = e->host.seed, .terrain = s->terrain,
                                 .species = e->species, .n_species = sf->n_species};
    rc = ext->run_new(e->state, api, &e->host, &req, &e->run);
    if (rc) {
        session_failed(e, "run_new", rc, err);
        e->run = NULL;
        goto fail;
    }
    return e;
fail:
    ecology_session_free(e);
    return NULL;
}

void ecology_session_free(ecology_session *e)
{
    if (!e) return;
    if (e->run) e->ext->run_free(e->run);
    if (e->state) e->plugin->desc->destroy(e->state);
    host_release(&e->host);
    free(e->species);
    free(e);
}

uint32_t ecology_session_year(const ecology_session *e) { return e->ext->year(e->run); }
uint32_t ecology_session_years_wanted(const ecology_session *e) { return e->ext->years_wanted(e->run); }

int ecology_session_step(ecology_session *e, uint32_t years, err_buf *err)
{
    int rc = e->ext->step(e->run, host_api_table(), &e->host, years);
    return rc ? session_failed(e, "step", rc, err) : 0;
}

int ecology_session_save(ecology_session *e, const char *path, err_buf *err)
{
    int rc = e->ext->save(e->run, host_api_table(), &e->host, path);
    return rc ? session_failed(e, "save", rc, err) : 0;
}

int ecology_session_load(ecology_session *e, const char *path, err_buf *err)
{
    int rc = e->ext->load(e->run, host_api_table(), &e->host, path);
    return rc ? session_failed(e, "load", rc, err) : 0;
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
    if (!p) return err_set(err, "out of memory for %u plants", count);
    int rc = e->ext->plants(e->run, host_api_table(), &e->host, 0, count, p);
    if (rc) {
        free(p);
        return session_failed(e, "plants", rc, err);
    }
    for (uint32_t i = 0; i < count; i++)
        if (p[i].species >= e->sf->n_species) {
            uint32_t bad = p[i].species;
            free(p);
            return err_set(err, "%s (%s): plant %u names species %u; the scene has %u", e->context, e->plugin->file, i,
                           bad, e->sf->n_species);
        }
    *out = p, *n = count;
    return 0;
}

uint32_t ecology_session_factor_count(const ecology_session *e) { return e->ext->factor_count(e->run); }

int ecology_session_factor(const ecology_session *e, uint32_t i, sylva_ecology_factor_map *out, err_buf *err)
{
    memset(out, 0, sizeof *out);
    int rc = e->ext->factor(e->run, i, out);
    if (rc || !out->values || !out->nx || !out->ny || !out->name)
        return err_set(err, "%s (%s): factor map %u is missing or empty", e->context, e->plugin->file, i);
    return 0;
}
