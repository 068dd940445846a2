/* scene_canopy.c — the canopy heights onto the ground as surveyed, and the woodland's plants fitted
 * to them (scene_canopy.h). */
#include "scene_build/scene_canopy.h"

#include <math.h>
#include <stdio.h>

#include "site/canopy_read.h"

int scene_build_canopy(scene *s, const scene_file *sf, int quiet, err_buf *err)
{
    const canopy_spec *spec = &sf->canopy;
    if (!spec->given) return 0;
    const sylva_heightfield *hf = s->surveyed;
    if (!hf)
        return err_at(err, ERR_INPUT, sf->path, spec->line, spec->column,
                      "the canopy's heights are read onto the site's ground, but the scene has no terrain; add a "
                      "terrain: section (a DTM, or a grid)");
    landcover_grid grid = {sf->site.crs_wkt, {sf->site.origin[0], sf->site.origin[1]}, hf->nx, hf->ny,
                           hf->x0, hf->y0, hf->dx, hf->dy};
    canopy_fault fault;
    canopy *c = canopy_read(&spec->source, &grid, stderr, quiet ? NULL : stderr, &fault, err);
    if (!c) {
        err_default(err, ERR_INPUT);
        if (err->status == ERR_NOMEM) return -1;
        return fault == CANOPY_FAULT_DTM ? err_locate(err, sf->path, spec->dtm_line, spec->dtm_column)
                                         : err_locate(err, sf->path, spec->line, spec->column);
    }
    s->canopy = c;
    return 0;
}

/* What the canopy does to a plant. */
typedef enum plant_fit { FIT_SCALED, FIT_KEPT, FIT_REMOVED, FIT_NO_DATA, FITS } plant_fit;

typedef struct fit_tally {
    uint64_t n[FITS];
    double lo, hi; /* the least and the most a scaled plant's height was multiplied by */
} fit_tally;

/* The fit of plant in; when scaled, its new prototype in *proto and the factor on its transform's
 * linear part in *factor. */
static plant_fit fit_of(const scene *s, const instance *in, uint32_t *proto, double *factor)
{
    const prototype *pr = &s->prototypes[in->prototype];
    double scale = in->xf.m[2][2], grown = pr->height * scale; /* upright: T R_z S */
    double h = canopy_height_at(s->canopy, in->xf.m[0][3], in->xf.m[1][3]);
    if (isnan(h)) return FIT_NO_DATA;
    if (h < CANOPY_OPEN) return grown > CANOPY_OPEN ? FIT_REMOVED : FIT_KEPT;
    const species *sp = &s->species[pr->species];
    double full = s->prototypes[sp->first_prototype + sp->n_variants - 1].height;
    if (!(grown >= CANOPY_REACH * h) || !(full * CANOPY_STRETCH >= h) || !(scale > 0)) return FIT_KEPT;
    *proto = sp->first_prototype + scene_variant_nearest_height(s, pr->species, h);
    double ph = s->prototypes[*proto].height;
    if (!(ph > 0)) return FIT_KEPT;
    *factor = h / ph / scale;
    return FIT_SCALED;
}

static void report_fit(const fit_tally *t, uint64_t plants)
{
    fprintf(stderr, "sylva: canopy: the woodland's %llu plants fitted to the canopy: %llu scaled to its height (x%.2f "
            "to x%.2f of their grown height), %llu kept (understorey, or below %.1f m), %llu removed where it is "
            "below %.1f m, %llu on no data kept as grown\n", (unsigned long long)plants,
            (unsigned long long)t->n[FIT_SCALED], t->n[FIT_SCALED] ? t->lo : 1.0, t->n[FIT_SCALED] ? t->hi : 1.0,
            (unsigned long long)t->n[FIT_KEPT], CANOPY_OPEN, (unsigned long long)t->n[FIT_REMOVED], CANOPY_OPEN,
            (unsigned long long)t->n[FIT_NO_DATA]);
}

int scene_canopy_fit_plants(scene *s, const scene_file *sf, uint32_t first, int quiet)
{
    if (!s->canopy || !sf->canopy.fit_plants || first >= s->n_instances) return 0;
    fit_tally t = {.lo = INFINITY, .hi = 0};
    uint32_t kept = first, plants = s->n_instances - first;
    for (uint32_t i = first; i < s->n_instances; i++) {
        instance in = s->instances[i];
        uint32_t proto = in.prototype;
        double factor = 1.0, before = s->prototypes[in.prototype].height;
        plant_fit f = in.development ? FIT_KEPT : fit_of(s, &in, &proto, &factor);
        t.n[f]++;
        if (f == FIT_REMOVED) continue;
        if (f == FIT_SCALED) {
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++) in.xf.m[r][c] = (float)(in.xf.m[r][c] * factor);
            double ratio = s->prototypes[proto].height * factor / before;
            t.lo = fmin(t.lo, ratio), t.hi = fmax(t.hi, ratio);
            in.prototype = proto;
        }
        s->instances[kept++] = in;
    }
    s->n_instances = kept;
    if (!quiet) report_fit(&t, plants);
    return 0;
}
