/* canopy_read.c — canopy heights from a CHM, or a DSM less its DTM, onto the site grid
 * (canopy_read.h). */
#include "site/canopy_read.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "site/height_raster.h"
#include "util/memory_budget.h"

static const char *const model_phrase[] = {"the canopy height model", "the surface model", "the terrain model"};

static const char *path_of(const canopy_source *src, canopy_fault f)
{
    return f == CANOPY_FAULT_CHM ? src->chm : f == CANOPY_FAULT_DSM ? src->dsm : src->dtm;
}

int canopy_check(const canopy_source *src, canopy_fault *fault, err_buf *err)
{
    const canopy_fault files[2] = {src->chm ? CANOPY_FAULT_CHM : CANOPY_FAULT_DSM, CANOPY_FAULT_DTM};
    for (int k = 0; k < (src->chm ? 1 : 2); k++) {
        *fault = files[k];
        if (height_raster_check(path_of(src, files[k]), err))
            return err_prefix(err, "%s '%s': ", model_phrase[files[k]], path_of(src, files[k]));
    }
    return 0;
}

/* File f onto g into h; a message names the file. */
static int read_model(const canopy_source *src, canopy_fault f, const landcover_grid *g, float *h,
                      canopy_fault *fault, err_buf *err)
{
    uint64_t covered;
    *fault = f;
    if (height_raster_read(path_of(src, f), g, h, &covered, err))
        return err->status == ERR_NOMEM ? -1 : err_prefix(err, "%s '%s': ", model_phrase[f], path_of(src, f));
    if (!covered)
        return err_set(err, "%s '%s': it covers none of the site's %u x %u nodes (%g m apart); check that the "
                       "model is of the site's area and that its CRS is right", model_phrase[f], path_of(src, f),
                       g->nx, g->ny, g->dx);
    return 0;
}

/* The heights above the ground into h: the CHM's, or the DSM's less the DTM's. */
static int read_heights(const canopy_source *src, const landcover_grid *g, float *h, canopy_fault *fault,
                        err_buf *err)
{
    if (src->chm) return read_model(src, CANOPY_FAULT_CHM, g, h, fault, err);
    size_t n = (size_t)g->nx * g->ny;
    if (memory_check(n * sizeof(float), "the terrain model's heights under the site", err)) return -1;
    float *ground = malloc(n * sizeof *ground); /* freed below */
    if (!ground) return err_nomem(err, "out of memory for the terrain model's heights at %zu nodes", n);
    int rc = read_model(src, CANOPY_FAULT_DSM, g, h, fault, err) ||
             read_model(src, CANOPY_FAULT_DTM, g, ground, fault, err) ? -1 : 0;
    for (size_t k = 0; !rc && k < n; k++) h[k] -= ground[k]; /* no data in either: NAN */
    free(ground);
    return rc;
}

/* What the heights hold, over the nodes with data. */
typedef struct canopy_stats {
    uint64_t with_data, below, tall;
    double sum, highest, lowest;
} canopy_stats;

/* Counts the heights and takes those below the ground as no canopy. */
static canopy_stats settle(canopy *c)
{
    canopy_stats st = {.highest = 0, .lowest = 0};
    size_t n = (size_t)c->nx * c->ny;
    for (size_t k = 0; k < n; k++) {
        float v = c->height[k];
        if (isnan(v)) {
            c->no_data++;
            continue;
        }
        st.with_data++;
        st.lowest = fmin(st.lowest, v);
        st.below += v < -CANOPY_BELOW_GROUND_WARN;
        if (v < 0) v = c->height[k] = 0.0f;
        st.sum += v, st.highest = fmax(st.highest, v), st.tall += v > CANOPY_TALL;
    }
    return st;
}

/* A model of elevations rather than heights, or none at all, refused; 0 when the heights hold. */
static int refuse_implausible(const canopy_source *src, const canopy_stats *st, canopy_fault *fault, err_buf *err)
{
    *fault = src->chm ? CANOPY_FAULT_CHM : CANOPY_FAULT_DSM;
    if (!st->with_data)
        return err_set(err, "the surface model '%s' and the terrain model '%s' have data together at none of the "
                       "site's nodes; give models of the same area", src->dsm, src->dtm);
    double mean = st->sum / (double)st->with_data;
    if (mean <= CANOPY_MEAN_MAX) return 0;
    if (src->chm)
        return err_set(err, "the canopy height model '%s': its heights average %.0f m above the ground over the "
                       "site, more than any forest's %.0f m: it holds elevations (a surface model); give dsm: FILE "
                       "and dtm: FILE instead", src->chm, mean, CANOPY_MEAN_MAX);
    return err_set(err, "the surface model '%s' stands %.0f m above the terrain model '%s' on average over the "
                   "site, more than any forest's %.0f m; are they of the same place and vertical datum?", src->dsm,
                   mean, src->dtm, CANOPY_MEAN_MAX);
}

static void report(const canopy *c, const canopy_source *src, const canopy_stats *st, FILE *warnings,
                   FILE *summary)
{
    double n = (double)c->nx * c->ny;
    if (warnings && st->below)
        fprintf(warnings, "sylva: warning: canopy: %s puts %llu of the nodes more than %.1f m below the ground (the "
                "lowest %.2f m): taken as no canopy%s\n", c->source, (unsigned long long)st->below,
                CANOPY_BELOW_GROUND_WARN, -st->lowest,
                src->chm ? "" : "; are the two models of the same survey and vertical datum?");
    if (!summary) return;
    fprintf(summary, "sylva: canopy: %s, %u x %u nodes %g m apart: %.1f %% with data (%llu nodes without, taken as "
            "no canopy), heights mean %.2f m, highest %.2f m, %.1f %% above %g m\n", c->source, c->nx, c->ny, c->dx,
            100.0 * (double)st->with_data / n, (unsigned long long)c->no_data,
            st->sum / (double)st->with_data, st->highest, 100.0 * (double)st->tall / (double)st->with_data,
            CANOPY_TALL);
}

/* "CHM.tif", or "DSM.tif less DTM.tif": the files' names for messages (malloc'ed). */
static char *source_name(const canopy_source *src)
{
    const char *a = src->chm ? src->chm : src->dsm, *b = src->chm ? NULL : src->dtm;
    const char *sa = strrchr(a, '/'), *sb = b ? strrchr(b, '/') : NULL;
    sa = sa ? sa + 1 : a, sb = sb ? sb + 1 : b;
    size_t len = strlen(sa) + (sb ? strlen(sb) + 6 : 0) + 1;
    char *s = malloc(len);
    if (s) snprintf(s, len, sb ? "%s less %s" : "%s", sa, sb);
    return s;
}

canopy *canopy_read(const canopy_source *src, const landcover_grid *grid, FILE *warnings, FILE *summary,
                    canopy_fault *fault, err_buf *err)
{
    size_t n = (size_t)grid->nx * grid->ny;
    *fault = src->chm ? CANOPY_FAULT_CHM : CANOPY_FAULT_DSM;
    if (memory_check(n * sizeof(float), "the canopy's heights at the site's nodes", err)) return NULL;
    canopy *c = calloc(1, sizeof *c); /* the caller's: canopy_free */
    if (c) *c = (canopy){grid->nx, grid->ny, grid->x0, grid->y0, grid->dx, grid->dy, malloc(n * sizeof(float)), 0,
                         source_name(src)};
    if (!c || !c->height || !c->source) {
        canopy_free(c);
        err_nomem(err, "out of memory for the canopy's heights at %zu nodes", n);
        return NULL;
    }
    canopy_stats st;
    if (read_heights(src, grid, c->height, fault, err) || (st = settle(c), refuse_implausible(src, &st, fault, err))) {
        canopy_free(c);
        return NULL;
    }
    report(c, src, &st, warnings, summary);
    return c;
}
