/* eco_sim.c — starting a run (terrain factors, species, growth area, random streams), one year
 * of Algorithm 9, and releasing it. */
#include "eco_sim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eco_growth.h"

const char *const eco_stream_purposes[ECO_N_STREAMS] = {
    "ecology.near",           "ecology.parent",          "ecology.side",
    "ecology.anywhere",       "ecology.position_i",      "ecology.position_j",
    "ecology.death_dominance", "ecology.death_altitude", "ecology.death_humidity",
    "ecology.death_sunniness", "ecology.death_windiness", "ecology.death_slope",
    "ecology.death_age",      "ecology.rotation",        "ecology.establish"};

static uint64_t fnv1a(uint64_t h, const void *data, size_t n)
{
    const unsigned char *b = data;
    for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 0x100000001b3ull;
    return h;
}

#define FNV_START 0xcbf29ce484222325ull

void eco_sim_free(eco_sim *s)
{
    if (!s) return;
    eco_terrain_free(&s->terrain);
    for (uint32_t i = 0; s->pop && i < s->n_species; i++) free(s->pop[i].plants);
    for (uint32_t i = 0; s->names && i < s->n_species; i++) free(s->names[i]);
    free(s->species), free(s->request_index), free(s->names), free(s->model_height), free(s->p_r);
    free(s->pop), free(s->seeds), free(s->carry), free(s->rng);
    free(s->growable), free(s->growable_list), free(s->establish), free(s->band_list);
    for (uint32_t j = 0; s->habitat && j < s->n_species; j++) free(s->habitat[j]);
    free(s->habitat);
    free(s->cell_start), free(s->patch_r_max), free(s->cell);
    free(s);
}

uint32_t eco_sim_count(const eco_sim *s)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->n_species; i++) n += s->pop[i].n;
    return n;
}

/* Which of the request's species take part: `only` names them (commas or spaces between), or
 * NULL/empty for all. Fills pick (n_species entries of 0/1). */
static int pick_species(const sylva_params *params, const char *only, const sylva_ecology_request *req,
                        uint8_t *pick, plugin_err *err)
{
    int any = 0;
    for (const char *c = only; c && *c; c++) any |= *c != ',' && *c != ' ';
    if (!any) {
        memset(pick, 1, req->n_species);
        return SYLVA_OK;
    }
    memset(pick, 0, req->n_species);
    const char *c = only;
    while (*c) {
        while (*c == ',' || *c == ' ') c++;
        if (!*c) break;
        size_t len = strcspn(c, ", ");
        uint32_t found = req->n_species;
        for (uint32_t i = 0; i < req->n_species; i++)
            if (req->species[i].name && strlen(req->species[i].name) == len && !strncmp(req->species[i].name, c, len))
                found = i;
        if (found == req->n_species) {
            char list[512] = "";
            for (uint32_t i = 0; i < req->n_species; i++)
                snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", i ? ", " : "",
                         req->species[i].name ? req->species[i].name : "?");
            return plugin_fail_param(err, params, "species", "unknown species '%.*s'; the scene's species are %s",
                                     (int)len, c, req->n_species ? list : "none");
        }
        if (pick[found])
            return plugin_fail_param(err, params, "species", "species '%.*s' is named twice; name each once",
                                     (int)len, c);
        pick[found] = 1;
        c += len;
    }
    return SYLVA_OK;
}

/* The growth area: the rectangle and the mask, widened by the edge band, minus water. */
static int growth_area(eco_sim *s, const eco_random *rnd, const sylva_params *params, plugin_err *err)
{
    const eco_terrain *t = &s->terrain;
    const eco_config *c = &s->config;
    size_t n = (size_t)t->ni * t->nk;
    if (c->area[0] >= 0) {
        const int64_t *a = c->area;
        if (a[2] < a[0] || a[3] < a[1])
            return plugin_fail_param(err, params, "growth_area",
                                     "growth_area [%lld, %lld, %lld, %lld] is empty; give [i0, k0, i1, k1] with "
                                     "i0 <= i1 and k0 <= k1", (long long)a[0], (long long)a[1], (long long)a[2],
                                     (long long)a[3]);
        if (a[2] >= t->ni || a[3] >= t->nk)
            return plugin_fail_param(err, params, "growth_area",
                                     "growth_area [%lld, %lld, %lld, %lld] reaches outside the terrain's %u x %u "
                                     "patches; patch indices run from 0 to %u along x and 0 to %u along y",
                                     (long long)a[0], (long long)a[1], (long long)a[2], (long long)a[3], t->ni, t->nk,
                                     t->ni - 1, t->nk - 1);
    }
    s->growable = malloc(n);
    s->growable_list = malloc(n * sizeof *s->growable_list);
    if (!s->growable || !s->growable_list)
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the growth area");
    s->n_growable = 0;
    for (uint32_t k = 0; k < t->nk; k++)
        for (uint32_t i = 0; i < t->ni; i++) {
            size_t p = i + (size_t)k * t->ni;
            int ok = 1;
            if (c->area[0] >= 0) ok = ok && i >= c->area[0] && i <= c->area[2] && k >= c->area[1] && k <= c->area[3];
            if (c->mask) {
                uint32_t col = (uint32_t)((i + 0.5) / t->ni * c->mask_cols);
                uint32_t row = (uint32_t)((k + 0.5) / t->nk * c->mask_rows);
                if (col >= c->mask_cols) col = c->mask_cols - 1;
                if (row >= c->mask_rows) row = c->mask_rows - 1;
                ok = ok && c->mask[(size_t)row * c->mask_cols + col] != 0;
            }
            s->growable[p] = (uint8_t)ok;
        }
    /* the edge band: an area or mask that leaves patches out fades into them */
    int bounded = 0;
    for (size_t p = 0; p < n && !bounded; p++) bounded = !s->growable[p];
    if (bounded && c->edge_fade > 0) {
        sylva_rng r;
        rnd->stream(rnd->ctx, &r, "ecology.edge_noise", 0);
        s->establish = eco_edge_establishment(t, s->growable, c->edge_fade,
                                              (uint64_t)(rnd->uniform(&r) * 9007199254740992.0));
    } else if ((s->establish = malloc(n * sizeof *s->establish))) {
        for (size_t p = 0; p < n; p++) s->establish[p] = s->growable[p];
    }
    if (!s->establish) return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the growth area's edge");
    /* the area's patches take the seedlings from anywhere as before; the band's get their own
     * share of that seed rain (eco_reproduce.c) */
    s->band_list = malloc(n * sizeof *s->band_list);
    if (!s->band_list) return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the growth area's edge");
    s->n_band = 0;
    for (size_t p = 0; p < n; p++) {
        s->growable[p] = !t->water[p] && s->establish[p] > 0;
        if (!s->growable[p]) continue;
        if (s->establish[p] >= 1.0f) s->growable_list[s->n_growable++] = (uint32_t)p;
        else s->band_list[s->n_band++] = (uint32_t)p;
    }
    if (!s->n_growable)
        return plugin_fail_param(err, params,
                                 c->area[0] >= 0 ? "growth_area"
                                 : c->mask       ? "growth_mask"
                                                 : "water_altitude",
                                 "no patch of the terrain is left where plants may grow (every patch is water or "
                                 "outside the growth area); widen the growth area or lower the water");
    return SYLVA_OK;
}

static uint64_t sim_fingerprint(const eco_sim *s)
{
    const eco_terrain *t = &s->terrain;
    size_t n = (size_t)t->ni * t->nk;
    uint64_t h = FNV_START;
    h = fnv1a(h, &t->ni, sizeof t->ni);
    h = fnv1a(h, &t->nk, sizeof t->nk);
    h = fnv1a(h, t->cz, n * sizeof *t->cz);
    for (int f = 0; f < ECO_N_FACTORS; f++) h = fnv1a(h, t->factor[f], n * sizeof(float));
    h = fnv1a(h, s->growable, n);
    h = fnv1a(h, s->establish, n * sizeof *s->establish);
    h = fnv1a(h, &s->n_species, sizeof s->n_species);
    for (uint32_t i = 0; i < s->n_species; i++) {
        h = fnv1a(h, s->names[i], strlen(s->names[i]) + 1);
        h = fnv1a(h, &s->species[i], sizeof s->species[i]);
        h = fnv1a(h, &s->model_height[i], sizeof s->model_height[i]);
        if (s->habitat && s->habitat[i]) h = fnv1a(h, s->habitat[i], n); /* a run without keeps its print */
    }
    return h;
}

int eco_sim_new(const eco_random *rnd, plugin_params *reader, const eco_config *cfg, const char *only,
                const sylva_ecology_request *req, eco_sim **out, plugin_err *err)
{
    const sylva_params *params = reader->block;
    *out = NULL;
    if (!req->terrain) return plugin_fail(err, SYLVA_ERR_PARAM, "the ecology request carries no terrain");
    eco_sim *s = calloc(1, sizeof *s);
    uint8_t *pick = calloc(req->n_species ? req->n_species : 1, 1);
    if (!s || !pick) {
        free(s), free(pick);
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory starting the ecology");
    }
    s->config = *cfg;
    int rc = pick_species(params, only, req, pick, err);
    if (rc) goto fail;
    for (uint32_t i = 0; i < req->n_species; i++) s->n_species += pick[i];
    uint32_t ns = s->n_species ? s->n_species : 1;
    s->species = calloc(ns, sizeof *s->species);
    s->request_index = calloc(ns, sizeof *s->request_index);
    s->names = calloc(ns, sizeof *s->names);
    s->model_height = calloc(ns, sizeof *s->model_height);
    s->p_r = calloc(ns, sizeof *s->p_r);
    s->pop = calloc(ns, sizeof *s->pop);
    s->seeds = calloc(ns, sizeof *s->seeds);
    s->carry = calloc(ns, sizeof *s->carry);
    s->rng = calloc((size_t)ns * ECO_N_STREAMS, sizeof *s->rng);
    if (!s->species || !s->request_index || !s->names || !s->model_height || !s->p_r || !s->pop || !s->seeds ||
        !s->carry || !s->rng) {
        rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for %u species", s->n_species);
        goto fail;
    }
    uint32_t j = 0;
    double max_t_f = 0;
    for (uint32_t i = 0; i < req->n_species; i++) {
        if (!pick[i]) continue;
        const sylva_species_info *info = &req->species[i];
        const char *name = info->name ? info->name : "";
        s->request_index[j] = i;
        if (!(s->names[j] = strdup(name))) {
            rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the species' names");
            goto fail;
        }
        plugin_params block = plugin_params_in(reader, info->ecology);
        rc = eco_species_read(&block, name, &s->species[j], err);
        if (rc) goto fail;
        s->model_height[j] = info->model_height > 0 && isfinite(info->model_height) ? info->model_height : 1.0;
        if (s->species[j].t_f > max_t_f) max_t_f = s->species[j].t_f;
        if (s->species[j].r_s > s->max_r_s) s->max_r_s = s->species[j].r_s;
        j++;
    }
    for (j = 0; j < s->n_species; j++) s->p_r[j] = s->species[j].t_f / max_t_f; /* (4.19) */

    char msg[512];
    if (eco_terrain_build(&s->terrain, req->terrain, &cfg->factors, msg, sizeof msg)) {
        rc = plugin_fail_param(err, params, "patches", "%s", msg);
        goto fail;
    }
    if ((rc = growth_area(s, rnd, params, err)) || (rc = eco_habitat_build(s, req, err))) goto fail;
    s->config.mask = NULL; /* borrowed: not kept past this call */
    s->n_opt = eco_n_opt(s->max_r_s, s->terrain.k);

    /* Streams keyed by purpose, the purpose's seed and the species' name, so adding a species or
     * reordering the scene leaves every other species' draws alone. */
    for (j = 0; j < s->n_species; j++) {
        uint64_t name_key = fnv1a(FNV_START, s->names[j], strlen(s->names[j]));
        for (int p = 0; p < ECO_N_STREAMS; p++) {
            uint64_t seed = p < ECO_N_SEEDED_STREAMS ? cfg->stream_seeds[p] : 0;
            rnd->stream(rnd->ctx, &s->rng[(size_t)j * ECO_N_STREAMS + p], eco_stream_purposes[p],
                        name_key ^ (seed * 0x9e3779b97f4a7c15ull));
        }
    }
    s->fingerprint = sim_fingerprint(s);
    free(pick);
    *out = s;
    return SYLVA_OK;
fail:
    free(pick);
    eco_sim_free(s);
    return rc ? rc : plugin_fail(err, SYLVA_ERR_INTERNAL, "the ecology could not start");
}

int eco_sim_step(eco_sim *s, const eco_random *rnd, plugin_err *err)
{
    int rc = eco_reproduce(s, rnd, err);
    if (rc) return rc;
    eco_grow(s);
    if ((rc = eco_find_dominance(s, err))) return rc;
    eco_remove_dead(s, rnd);
    s->year++;
    return SYLVA_OK;
}
