/* ztv_study.c — a whole ZTV study of a built scene (ztv_study.h): settings, targets, grid,
 * sightlines, files. */
#include "ztv/ztv_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/output_folder.h"
#include "render/accel.h"
#include "site/ground_departure.h"
#include "scene/heightfield.h"
#include "scene_file/scene_file.h"
#include "ztv/ztv_features.h"
#include "ztv/ztv_grid.h"
#include "ztv/ztv_labels.h"
#include "ztv/ztv_output.h"
#include "ztv/ztv_sweep_map.h"
#include "ztv/ztv_trace.h"

static const char *const mode_names[ZTV_MODES] = {"bare earth", "vegetation", "all", "the canopy surface"};

/* Where the blocks of rows go: straight to the output in one part; in a job of several, into a
 * copy of the block on every part, in which part 0 gathers the other parts' rows before
 * writing it. */
typedef struct block_sink {
    const run_parts *parts;
    ztv_output *out; /* part 0's; NULL on the others */
    uint32_t nx;     /* cells in a row */
} block_sink;

#define BLOCK_ARRAYS (1 + 4 * ZTV_MODES) /* the ground, and four layers per computed mode */

static int sink_block(void *user, const ztv_block *b, err_buf *err)
{
    block_sink *s = user;
    if (s->parts->parts < 2) return ztv_output_block(s->out, b, err);
    const void *from[BLOCK_ARRAYS];
    size_t cell_bytes[BLOCK_ARRAYS];
    unsigned n = 0;
    from[n] = b->ground, cell_bytes[n++] = sizeof *b->ground;
    for (int md = 0; md < ZTV_MODES; md++) {
        const ztv_layer *l = b->layer[md];
        if (!l) continue;
        from[n] = l->visible, cell_bytes[n++] = sizeof *l->visible;
        from[n] = l->fraction, cell_bytes[n++] = sizeof *l->fraction;
        from[n] = l->cls, cell_bytes[n++] = sizeof *l->cls;
        from[n] = l->developments, cell_bytes[n++] = sizeof *l->developments;
    }
    /* each array at a multiple of 8 bytes, aligned for its type */
    size_t cells = (size_t)b->rows * s->nx, at[BLOCK_ARRAYS + 1] = {0};
    for (unsigned k = 0; k < n; k++) at[k + 1] = at[k] + (cells * cell_bytes[k] + 7) / 8 * 8;
    uint8_t *copy = malloc(at[n]); /* owned: the block's arrays one after another */
    if (!copy) return err_nomem(err, "out of memory for a copy of %zu cells of the map", cells);
    run_rows rows[BLOCK_ARRAYS];
    for (unsigned k = 0; k < n; k++) {
        memcpy(copy + at[k], from[k], cells * cell_bytes[k]);
        rows[k] = (run_rows){copy + at[k], s->nx * cell_bytes[k]};
    }
    int rc = s->parts->gather_rows(s->parts->job, rows, n, b->j0, b->rows, 1, err);
    if (!rc && !s->parts->part) {
        ztv_layer layers[ZTV_MODES];
        ztv_block whole = {.j0 = b->j0, .rows = b->rows, .ground = rows[0].data};
        for (int md = 0, k = 1; md < ZTV_MODES; md++) {
            if (!b->layer[md]) continue;
            layers[md] = (ztv_layer){rows[k].data, rows[k + 1].data, rows[k + 2].data, rows[k + 3].data};
            whole.layer[md] = &layers[md];
            k += 4;
        }
        rc = ztv_output_block(s->out, &whole, err);
    }
    free(copy);
    return rc;
}

/* The options with the scene's ztv: keys where they give none; a screened mode with nothing in
 * it is bare earth again. */
static ztv_study_options settled(const ztv_study_options *o, const scene_file *sf, const scene *sc)
{
    ztv_study_options s = *o;
    const ztv_settings *z = &sf->ztv;
    if (isnan(s.radius)) s.radius = z->radius;
    else if (s.radius == 0) s.radius = INFINITY;
    if (isnan(s.cell)) s.cell = z->cell;
    if (isnan(s.eye)) s.eye = z->observer_height;
    if (s.screening < 0) s.screening = z->screening;
    int has_plants = sc->n_instances > 0, has_objects = 0;
    for (uint32_t k = 0; k < sc->n_objects; k++) has_objects |= !sc->objects[k].development;
    if (s.screening == ZTV_ALL && !has_objects) s.screening = has_plants ? ZTV_VEGETATION : ZTV_BARE;
    if (s.screening == ZTV_VEGETATION && !has_plants) s.screening = ZTV_BARE;
    return s;
}

/* The ground the sightlines trace, described (into ground), and a warning (part 0) when the
 * refinement moves the mapped ground from the DTM as surveyed. */
static void describe_ground(const scene *sc, const ztv_grid *g, const run_parts *parts, int quiet, char *ground,
                            size_t n)
{
    char described[192];
    heightfield_describe(sc->terrain, described, sizeof described);
    snprintf(ground, n, "%s: %s", sc->terrain == sc->surveyed ? "the DTM as surveyed"
             : "the terrain refined around the development", described);
    if (!quiet) fprintf(stderr, "ztv: ground: %s\n", ground);
    if (sc->terrain == sc->surveyed) return;
    double rms, top;
    ground_departure_over(sc, g->x0, g->y0 - (g->ny - 1) * g->cell, g->x0 + (g->nx - 1) * g->cell, g->y0, &rms, &top);
    if (top > GROUND_DEPARTURE_TOLERANCE && !parts->part)
        fprintf(stderr, "sylva: warning: over the map the refined ground departs from the DTM as surveyed by "
                "%.2f m RMS, at most %.2f m (tolerance %.1f m); the surveyed ground is the default\n", rms, top,
                GROUND_DEPARTURE_TOLERANCE);
}

/* Part 0 opens the output (the folder created when missing) for the job's grid and targets,
 * described in *info, which the caller keeps until the output is freed (ztv_output.h). */
static int open_output(const scene_file *sf, const scene *sc, const ztv_job *job, const ztv_study_options *o,
                       const char *ground, ztv_features *features, ztv_info *info, ztv_labels *labels,
                       ztv_output **out, err_buf *err)
{
    const ztv_targets *t = job->targets;
    if (ztv_features_gather(features, sf, sc, o->views, o->n_views, err)) return err_default(err, ERR_NOMEM);
    *info = (ztv_info){.grid = job->grid, .crs_wkt = sf->site.crs_wkt, .crs_name = sf->site.crs_name,
                     .observer_height = o->eye, .ground = ground, .radius = o->radius,
                     .curvature = job->earth && job->earth->curvature, .refraction = sc->earth.refraction,
                     .n_targets = t->n, .n_developments = t->n_developments, .development_names = t->names,
                     .development_xy = (const double(*)[2])t->centre, .target_xy = (const double(*)[2])t->xy,
                     .target_development = t->development, .study_views = features->viewpoints,
                     .n_study_views = features->n_viewpoints, .structures = features->structures,
                     .n_structures = features->n_structures, .planting_before = o->planting_before,
                     .planting_year = o->planting_year, .products = o->products};
    if (sf->site.crs_wkt) memcpy(info->origin, sf->site.origin, sizeof info->origin);
    info->computed[ZTV_BARE] = 1;
    info->computed[job->screened] = 1;
    ztv_labels_fill(labels, sf, info);
    if (output_folder_make(o->dir, err) || !(*out = ztv_output_open(o->dir, info, err)))
        return err_default(err, ERR_OUTPUT);
    return 0;
}

/* Traces the grid, each block written (gathered first in a job) as it comes, and finishes the
 * files on part 0. */
static int trace_and_write(ztv_job *job, const run_parts *parts, ztv_output *out, phase_times *times, int quiet,
                           err_buf *err)
{
    ztv_stats st;
    block_sink sink = {.parts = parts, .out = out, .nx = job->grid.nx};
    phase_mark t_phase = phase_start();
    int failed = ztv_trace(job, sink_block, &sink, &st, err) ? err_default(err, ERR_OUTPUT) : 0;
    t_phase = phase_stop(times, PHASE_RENDER, t_phase);
    if (parts->agree(parts->job, failed, err)) return -1;
    uint64_t total[3] = {st.cells, st.pairs, st.rays};
    parts->sum(parts->job, total, 3);
    if (parts->part) return 0;
    if (ztv_output_finish(out, err)) return err_default(err, ERR_OUTPUT);
    phase_stop(times, PHASE_OUTPUT, t_phase);
    if (!quiet) {
        char ranks[32] = "";
        if (parts->parts > 1) snprintf(ranks, sizeof ranks, " on %d ranks", parts->parts);
        char why[256], unswept[300] = "";
        if (!ztv_sweep_map_fits(job, why, sizeof why)) snprintf(unswept, sizeof unswept, " (not run: %s)", why);
        fprintf(stderr, "ztv: %llu cells x %u targets in %.2fs%s: %.3g pairs/s, %.2f rays each, %.1f %% of "
                "the pairs settled by the bare-earth sweep%s\n",
                (unsigned long long)total[0], job->targets->n, st.seconds, ranks, total[1] / fmax(st.seconds, 1e-9),
                total[1] ? (double)total[2] / total[1] : 0.0, total[1] ? 100.0 * st.swept / total[1] : 0.0, unswept);
        phase_times_print(times, stderr);
    }
    return 0;
}

/* The plants the map's sightlines can meet: none on bare earth or the canopy surface; else those
 * reaching the rectangle of its cells' centres and its targets, which every sightline of the map
 * stays over (each runs straight, seen from above, from a cell's centre to a target), widened by
 * ZTV_PLANTS_MARGIN for the rays' single precision. The BVH then holds nothing the map does not
 * need: on a site planted far beyond the map's radius most plants are left out. */
#define ZTV_PLANTS_MARGIN 1.0 /* metres */
static accel_plants plants_reached(const ztv_job *job)
{
    if (job->screened != ZTV_VEGETATION && job->screened != ZTV_ALL) return (accel_plants){.kind = ACCEL_PLANTS_NONE};
    const ztv_grid *g = &job->grid;
    double west, north, east, south;
    ztv_cell_centre(g, 0, 0, &west, &north);
    ztv_cell_centre(g, g->nx - 1, g->ny - 1, &east, &south);
    accel_plants w = {ACCEL_PLANTS_WITHIN, {west, south}, {east, north}};
    for (uint32_t t = 0; t < job->targets->n; t++)
        for (int k = 0; k < 2; k++) {
            w.lo[k] = fmin(w.lo[k], job->targets->p[t][k]);
            w.hi[k] = fmax(w.hi[k], job->targets->p[t][k]);
        }
    for (int k = 0; k < 2; k++) w.lo[k] -= ZTV_PLANTS_MARGIN, w.hi[k] += ZTV_PLANTS_MARGIN;
    return w;
}

/* The canopy mode asked of a scene without canopy heights: refused at the ztv: key that asked, or
 * as the option's. Returns 0 when the mode has what it screens with. */
static int refuse_canopy_without_heights(const ztv_study_options *opt, const scene_file *sf, const scene *sc,
                                         int screening, err_buf *err)
{
    if (screening != ZTV_CANOPY || sc->canopy) return 0;
    static const char what[] = "screening canopy screens with the canopy surface, but the scene has no canopy "
                               "heights; add a canopy: section (chm: FILE, or dsm: FILE with dtm: FILE)";
    if (opt->screening >= 0) return err_fail(err, ERR_INPUT, "--%s", what);
    return err_at(err, ERR_INPUT, sf->path, sf->ztv.line, sf->ztv.column, "ztv: %s", what);
}

int ztv_study_run(const scene_file *sf, const scene *sc, const ztv_study_options *opt, const run_parts *parts,
                  phase_times *times, err_buf *err)
{
    if (parts->same_scene(parts->job, sc, err)) return err_default(err, ERR_INPUT);
    ztv_study_options o = settled(opt, sf, sc);
    if (refuse_canopy_without_heights(opt, sf, sc, o.screening, err)) return -1;
    ztv_targets targets = {0};
    accel acc = {0};
    ztv_output *out = NULL;
    ztv_info info; /* what out describes; lives as long as out */
    ztv_features features = {0}; /* the viewpoints and structures info points to */
    ztv_labels labels = {0}; /* the names info points at */
    ztv_job job = {.scene = sc, .accel = &acc, .targets = &targets, .observer_height = o.eye, .radius = o.radius,
                   .screened = (ztv_mode)o.screening, .earth = o.flat_earth ? NULL : &sc->earth,
                   .threads = o.threads, .quiet = o.quiet, .part = (uint32_t)parts->part,
                   .parts = (uint32_t)parts->parts, .sightlines = o.sightlines};
    int rc = -1;
    if (ztv_targets_build(&targets, sf, sc, sf->image.seed, err) ||
        ztv_grid_make(sc, &targets, o.cell, o.radius, &job.grid, err)) {
        err_default(err, ERR_INPUT);
        goto done;
    }
    char past_edge[256]; /* said even with -q: the map is not what the radius asked for */
    if (!parts->part && !ztv_grid_past_edge_text(&job.grid, o.radius, past_edge, sizeof past_edge))
        fprintf(stderr, "sylva ztv: %s; its cells there are mapped as no terrain\n", past_edge);
    if (!o.quiet)
        fprintf(stderr, "ztv: %u targets of %u development%s, %u x %u cells of %g m, observer %g m, %s%s\n",
                targets.n, targets.n_developments, targets.n_developments == 1 ? "" : "s", job.grid.nx,
                job.grid.ny, job.grid.cell, o.eye, job.screened == ZTV_BARE ? "bare earth only" : "bare earth and ",
                job.screened == ZTV_BARE ? "" : mode_names[job.screened]);
    phase_mark t_phase = phase_start();
    accel_plants plants = plants_reached(&job);
    if (accel_build_plants(&acc, sc, o.threads, &plants, err)) {
        err_default(err, ERR_INTERNAL);
        goto done;
    }
    phase_stop(times, PHASE_BVH, t_phase);
    char ground[256];
    describe_ground(sc, &job.grid, parts, o.quiet, ground, sizeof ground);
    if (!parts->part && open_output(sf, sc, &job, &o, ground, &features, &info, &labels, &out, err)) goto done; /* part 0 alone writes */
    rc = trace_and_write(&job, parts, out, times, o.quiet, err);
done:
    ztv_output_free(out);
    ztv_features_free(&features);
    accel_free(&acc);
    ztv_targets_free(&targets);
    return rc;
}
