/* planting_ecology.c — a planting plan's blocks and belts grown by the scene's ecology
 * (planting_ecology.h): the session of the ecology plugin that placed the scene's ecology (or
 * one opened here: its terrain factors computed, no year simulated), asked for the fate of the
 * plan's plants, which depends on the run's terrain and species, not on its plants. */
#include "scene_build/planting_ecology.h"

#include <math.h>
#include <stdlib.h>

#include "scene_build/ecology_session.h"
#include "scene_build/planting_growth.h"

/* The year from which thinning takes plant p out, or 0 (docs/mitigation.md, "How a plant grows"). */
static uint32_t thinned_from(const planting_spec *plan, const planted_plant *p)
{
    if (!(plan->thinning_year > 0) || p->thinning_rank < plan->thinning_keep) return 0;
    return (uint32_t)ceil(plan->thinning_year);
}

int planting_ecology_wanted(const scene_file *sf, const build_options *opt)
{
    const planting_spec *plan = &sf->planting;
    int cohort = 0;
    for (uint32_t f = 0; f < plan->n_features && !cohort; f++)
        cohort = plan->features[f].kind == PLANTING_BLOCK || plan->features[f].kind == PLANTING_BELT;
    return opt->planting_shown && cohort && plan->ecology && sf->ecology.plugin && !opt->no_ecology;
}

int planting_ecology_fates(scene *s, const scene_file *sf, const plugin_registry *reg, ecology_session *ecology,
                           const build_options *opt, const planted_plant *plants, uint32_t n, double years,
                           uint32_t **died, const char **why, err_buf *err)
{
    const planting_spec *plan = &sf->planting;
    *died = NULL, *why = NULL;
    uint32_t cohort = 0;
    for (uint32_t i = 0; i < n; i++) cohort += plan->features[plants[i].feature].kind != PLANTING_TREE;
    if (!plan->ecology) *why = "the plan as drawn: 'ecology: false'";
    else if (!sf->ecology.plugin) *why = "the scene has no ecology";
    else if (opt->no_ecology) *why = "the ecology left out";
    else if (!cohort) *why = "no block or belt";
    if (*why) return 0;
    uint32_t steps = years > 0 ? (uint32_t)fmin(floor(years), 100000) : 0;
    sylva_ecology_planted *set_out = malloc((size_t)cohort * sizeof *set_out); /* owned here */
    uint32_t *index = malloc((size_t)cohort * sizeof *index);                  /* owned here: plan's number */
    uint32_t *fate = malloc((size_t)cohort * sizeof *fate);                    /* owned here */
    uint32_t *out = calloc(n, sizeof *out);                                     /* the caller's on success */
    int rc = 0;
    if (!set_out || !index || !fate || !out) {
        rc = err_nomem(err, "planting: out of memory for the fate of %u plants", n);
        goto done;
    }
    uint32_t c = 0;
    for (uint32_t i = 0; i < n; i++) {
        const planted_plant *p = &plants[i];
        if (plan->features[p->feature].kind == PLANTING_TREE) continue;
        double age = planting_age_for_height(s, p->species, plan->full_grown_age, p->stock_height);
        set_out[c] = (sylva_ecology_planted){.species = p->species, .position = {p->xy[0], p->xy[1]},
                                             .height = p->stock_height, .age = fmax(age, 0),
                                             .taken_out = thinned_from(plan, p),
                                             .replaced_until = plan->maintenance_years};
        index[c++] = i;
    }
    ecology_session *own = ecology ? NULL : ecology_session_open(sf, s, reg, opt, err); /* owned here */
    ecology_session *e = ecology ? ecology : own;
    rc = e ? ecology_session_planted_fate(e, set_out, cohort, steps, plan->seed, fate, err) : -1;
    ecology_session_free(own);
    if (rc) {
        err_prefix(err, "planting: ");
        goto done;
    }
    for (uint32_t k = 0; k < cohort; k++) out[index[k]] = fate[k];
    *died = out, out = NULL;
done:
    free(set_out), free(index), free(fate), free(out);
    return rc ? -1 : 0;
}
