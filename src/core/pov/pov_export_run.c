/* pov_export_run.c — the whole scene or one species as POV-Ray files (pov_export_run.h). */
#include "pov/pov_export_run.h"

#include <stdio.h>
#include <string.h>

#include "util/progress.h"

/* The species r names, checked with its variant: its index, or -1 with err set. */
static int64_t find_species(const scene *s, const pov_export_request *r, err_buf *err)
{
    uint32_t k = 0;
    while (k < s->n_species && strcmp(s->species[k].name, r->species)) k++;
    if (k == s->n_species) {
        char names[ERR_MSG_MAX / 2] = "";
        for (uint32_t j = 0, used = 0; j < s->n_species && used < sizeof names; j++)
            used += (uint32_t)snprintf(names + used, sizeof names - used, "%s '%s'", j ? "," : "", s->species[j].name);
        return err_fail(err, ERR_INPUT, "the scene has no species '%s'; it has:%s", r->species,
                        s->n_species ? names : " none");
    }
    if (r->variant >= 0 && (uint32_t)r->variant >= s->species[k].n_variants)
        return err_fail(err, ERR_INPUT, "species '%s' has variants 0 to %u; --variant %lld does not exist", r->species,
                        s->species[k].n_variants ? s->species[k].n_variants - 1 : 0, (long long)r->variant);
    return k;
}

int pov_export_run(const scene *s, const pov_export_request *r, err_buf *err)
{
    double t1 = progress_now();
    pov_export_stats st;
    if (r->species) {
        int64_t k = find_species(s, r, err);
        if (k < 0) return -1;
        if (pov_export_species(s, (uint32_t)k, r->variant, r->out, r->source, &st, err))
            return err_default(err, ERR_OUTPUT);
    } else {
        pov_export_options po = r->scene;
        po.source = r->source;
        if (s->earth.curvature && !r->quiet)
            fprintf(stderr, "sylva export-pov: note: POV-Ray cannot bend rays for the Earth's curvature "
                            "(earth.curvature is on); the exported scene shows it on a flat Earth, as "
                            "sylva render --flat-earth would\n");
        if (pov_export_scene(s, r->out, &po, &st, err)) return err_default(err, ERR_OUTPUT);
    }
    if (!r->quiet)
        fprintf(stderr, "exported %u files, %.1f MB (%llu plants, %llu left out) in %.2fs; scene built in %.2fs\n",
                st.files, st.bytes / 1e6, (unsigned long long)st.instances, (unsigned long long)st.skipped,
                progress_now() - t1, r->scene_seconds);
    return 0;
}
