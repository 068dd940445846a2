/* cmd_ztv.c — `sylva ztv SCENE -o DIR`: the zone of theoretical visibility of the scene's
 * development (docs/ztv.md): for every cell of a map over the terrain, how many of the
 * development's targets an observer standing there sees, on bare earth and screened by the
 * forest and the buildings, written as GeoTIFFs, PNG maps and a summary. Under mpirun each rank
 * traces every N-th row of the map and rank 0 writes the files (cli/cli_mpi.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_mpi.h"
#include "cli/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "render/accel.h"
#include "scene/ground_departure.h"
#include "scene/heightfield.h"
#include "util/progress.h"
#include "ztv/ztv_grid.h"
#include "ztv/ztv_output.h"
#include "ztv/ztv_trace.h"

static const char ztv_about[] =
    "Maps where SCENE's development can be seen from (a zone of theoretical visibility):\n"
    "for every cell of a grid over the terrain, an observer at eye height above the ground\n"
    "looks for each target of the development (the scene's ztv: section: targets given by\n"
    "hand, heights above each development object, or points sampled on them) along a\n"
    "sightline over the curved Earth (earth: section), on bare earth and screened by what\n"
    "the scene holds. Writes into DIR (created when missing): ztv_bare.tif and ztv_MODE.tif\n"
    "(GeoTIFF on the site's CRS: targets visible, fraction visible, cell class, developments\n"
    "seen), ztv_hidden_MODE.tif (what the screening hides), PNG maps of each, and\n"
    "ztv_summary.csv / .json (areas in km2). See docs/ztv.md.\n";

static const char ztv_epilogue[] =
    "Under MPI (`mpirun -np N sylva ztv ...`, in a build with SYLVA_MPI), every rank builds\n"
    "the scene itself (on separate machines as soon as rank 0 could build and broadcast\n"
    "it, with no scene format to keep in step) and traces every N-th row of the map; rank 0\n"
    "gathers the rows and writes the files, byte for byte those of a single process. Only\n"
    "rank 0 prints. See docs/mpi.md.\n\n"
    "exit status: 0 done, 1 usage, 2 bad scene, plugin failure or nothing to map, 3 output\n"
    "not written, 4 out of memory or internal error\n";

static const char *const screening_names[] = {"none", "vegetation", "all", NULL}; /* ztv_mode's order */
static const char *const ground_names[] = {"surveyed", "refined", NULL};

static const char *const mode_names[ZTV_MODES] = {"bare earth", "vegetation", "all"};

/* Where the blocks of rows go: straight to the output in one process; in an MPI job, into a
 * copy of the block on every rank, in which rank 0 gathers the other ranks' rows before
 * writing it. */
typedef struct block_sink {
    cli_mpi *m;
    ztv_output *out; /* rank 0's; NULL on the other ranks */
    uint32_t nx;     /* cells in a row */
} block_sink;

#define BLOCK_ARRAYS (1 + 4 * ZTV_MODES) /* the ground, and four layers per computed mode */

static int sink_block(void *user, const ztv_block *b, err_buf *err)
{
    block_sink *s = user;
    if (s->m->ranks < 2) return ztv_output_block(s->out, b, err);
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
    cli_rows rows[BLOCK_ARRAYS];
    for (unsigned k = 0; k < n; k++) {
        memcpy(copy + at[k], from[k], cells * cell_bytes[k]);
        rows[k] = (cli_rows){copy + at[k], s->nx * cell_bytes[k]};
    }
    int rc = cli_mpi_gather_rows(s->m, rows, n, b->j0, b->rows, 1, err);
    if (!rc && !s->m->rank) {
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

static int ztv_run(cli_mpi *m, int argc, char **argv)
{
    const char *scene_path = NULL, *dir = NULL, *season = NULL;
    double radius = NAN, cell = NAN, eye = NAN;
    int screening = -1, flat = 0;
    unsigned threads = 0;
    build_options bo = {.analysis = 1}; /* the ground as surveyed, whatever the camera */
    int refined = 0;
    const cli_option options[] = {
        {.names = "-o, --output", .type = CLI_PATH, .value = "DIR", .target = &dir, .flags = CLI_REQUIRED,
         .help = "folder for the maps (required)"},
        CLI_OPT_NUMBER("--radius", "M", "metres", radius, 0, 1e7, 0, "map cells within M metres of the nearest "
                       "target (0: the whole terrain)"),
        CLI_OPT_NUMBER("--cell", "M", "metres", cell, 0, 1e6, 0, "cell size in metres (0: one cell per terrain node)"),
        CLI_OPT_NUMBER("--observer-height", "M", "metres", eye, 0, 1e4, 0, "eye height above the ground (default 2)"),
        CLI_OPT_CHOICE("--screening", screening, screening_names, "what screens besides bare earth (default all: "
                       "the plants and the objects)"),
        CLI_OPT_CHOICE("--ground", refined, ground_names, "the ground the sightlines trace: the DTM as surveyed "
                       "(default; a ZTV is a property of the DTM and the development), or the terrain plugin's "
                       "refinement, with its levels of detail around the development, not the camera"),
        CLI_OPT_FLAG("--flat-earth", flat, "straight sightlines, whatever the earth: section says"),
        CLI_OPT_TEXT("--season", "S", season, CLI_HELP_SEASON),
        CLI_OPT_WHOLE("--threads", "N", bo.threads, 1, 1024, "threads for every phase (default: one per core, "
                      "shared out between the ranks of an MPI job on one machine); the maps do not depend on it"),
        CLI_OPTS_SCENE_COMMON(bo),
    };
    const cli_command_spec spec = {"ztv", "SCENE", ztv_about, "options (each overrides the scene's ztv: key of the "
                                   "same name):", options, sizeof options / sizeof *options, ztv_epilogue,
                                   cli_operand_scene, &scene_path};
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    threads = bo.threads;
    bo.analysis = !refined, bo.detail_at_development = refined;
    if (!threads) threads = bo.threads = m->threads;
    if (m->rank) bo.quiet = 1;

    err_buf err = {{0}};
    cli_scene cs;
    ztv_targets targets = {0};
    accel acc = {0};
    ztv_output *out = NULL;
    int rc = cli_scene_open(&cs, "ztv", scene_path, NULL, season, &bo);
    if (!rc) rc = cli_outputs_check("ztv", cs.sf, NULL, 0, NULL, 0); /* the folder's files */
    if (rc) goto done;
    if (cli_mpi_same_scene(m, cs.scene, &err)) {
        rc = cli_fail("ztv", &err, ERR_INPUT);
        goto done;
    }
    const scene_file *sf = cs.sf;
    const scene *sc = cs.scene;
    const ztv_settings *z = &sf->ztv;
    if (isnan(radius)) radius = z->radius;
    else if (radius == 0) radius = INFINITY;
    if (isnan(cell)) cell = z->cell;
    if (isnan(eye)) eye = z->observer_height;
    if (screening < 0) screening = z->screening;
    /* a screened mode with nothing in it is bare earth again */
    int has_plants = sc->n_instances > 0, has_objects = 0;
    for (uint32_t o = 0; o < sc->n_objects; o++) has_objects |= !sc->objects[o].development;
    if (screening == ZTV_ALL && !has_objects) screening = has_plants ? ZTV_VEGETATION : ZTV_BARE;
    if (screening == ZTV_VEGETATION && !has_plants) screening = ZTV_BARE;

    ztv_job job = {.scene = sc, .accel = &acc, .targets = &targets, .observer_height = eye, .radius = radius,
                   .screened = (ztv_mode)screening, .earth = flat ? NULL : &sc->earth, .threads = threads,
                   .quiet = bo.quiet, .part = (uint32_t)m->rank, .parts = (uint32_t)m->ranks};
    if (ztv_targets_build(&targets, sf, sc, sf->image.seed, &err) ||
        ztv_grid_make(sc, &targets, cell, radius, &job.grid, &err)) {
        rc = cli_fail("ztv", &err, ERR_INPUT);
        goto done;
    }
    char past_edge[256]; /* said even with -q: the map is not what the radius asked for */
    if (!m->rank && !ztv_grid_past_edge_text(&job.grid, radius, past_edge, sizeof past_edge))
        fprintf(stderr, "sylva ztv: %s; its cells there are mapped as no terrain\n", past_edge);
    if (!bo.quiet)
        fprintf(stderr, "ztv: %u targets of %u development%s, %u x %u cells of %g m, observer %g m, %s%s\n",
                targets.n, targets.n_developments, targets.n_developments == 1 ? "" : "s", job.grid.nx,
                job.grid.ny, job.grid.cell, eye, job.screened == ZTV_BARE ? "bare earth only" : "bare earth and ",
                job.screened == ZTV_BARE ? "" : mode_names[job.screened]);
    phase_mark t_phase = phase_start();
    if (accel_build(&acc, sc, threads, &err)) {
        rc = cli_fail("ztv", &err, ERR_INTERNAL);
        goto done;
    }
    t_phase = phase_stop(&cs.times, PHASE_BVH, t_phase);
    char ground[256], described[192];
    heightfield_describe(sc->terrain, described, sizeof described);
    snprintf(ground, sizeof ground, "%s: %s", sc->terrain == sc->surveyed ? "the DTM as surveyed"
             : "the terrain refined around the development", described);
    if (!bo.quiet) fprintf(stderr, "ztv: ground: %s\n", ground);
    if (sc->terrain != sc->surveyed) { /* a warning when the refinement moves the mapped ground */
        double rms, top;
        ground_departure_over(sc, job.grid.x0, job.grid.y0 - (job.grid.ny - 1) * job.grid.cell,
                              job.grid.x0 + (job.grid.nx - 1) * job.grid.cell, job.grid.y0, &rms, &top);
        if (top > GROUND_DEPARTURE_TOLERANCE && !m->rank)
            fprintf(stderr, "sylva: warning: over the map the refined ground departs from the DTM as surveyed by "
                    "%.2f m RMS, at most %.2f m (tolerance %.1f m); the surveyed ground is the default\n", rms, top,
                    GROUND_DEPARTURE_TOLERANCE);
    }
    ztv_info info = {.grid = job.grid, .crs_wkt = sf->site.crs_wkt, .crs_name = sf->site.crs_name,
                     .observer_height = eye, .ground = ground, .radius = radius, .curvature = job.earth && job.earth->curvature,
                     .refraction = sc->earth.refraction, .n_targets = targets.n,
                     .n_developments = targets.n_developments, .development_names = targets.names,
                     .development_xy = (const double(*)[2])targets.centre,
                     .target_xy = (const double(*)[2])targets.xy, .target_development = targets.development};
    if (sf->site.crs_wkt) memcpy(info.origin, sf->site.origin, sizeof info.origin);
    info.computed[ZTV_BARE] = 1;
    info.computed[job.screened] = 1;
    /* rank 0 alone writes */
    if (!m->rank && (cli_make_folder(dir, &err) || !(out = ztv_output_open(dir, &info, &err)))) {
        rc = cli_fail("ztv", &err, ERR_OUTPUT);
        goto done;
    }
    ztv_stats st;
    block_sink sink = {.m = m, .out = out, .nx = job.grid.nx};
    t_phase = phase_start(); /* the grid's rays, its blocks written as they come */
    if (ztv_trace(&job, sink_block, &sink, &st, &err)) rc = cli_fail("ztv", &err, ERR_OUTPUT);
    t_phase = phase_stop(&cs.times, PHASE_RENDER, t_phase);
    if ((rc = cli_mpi_agree(m, rc))) goto done;
    uint64_t total[3] = {st.cells, st.pairs, st.rays};
    cli_mpi_sum(m, total, 3);
    if (m->rank) goto done;
    if (ztv_output_finish(out, &err)) {
        rc = cli_fail("ztv", &err, ERR_OUTPUT);
        goto done;
    }
    phase_stop(&cs.times, PHASE_OUTPUT, t_phase);
    if (!bo.quiet) {
        char ranks[32] = "";
        if (m->ranks > 1) snprintf(ranks, sizeof ranks, " on %d ranks", m->ranks);
        fprintf(stderr, "ztv: %llu cells x %u targets in %.2fs%s: %.3g sightlines/s, %.2f rays each\n",
                (unsigned long long)total[0], targets.n, st.seconds, ranks, total[1] / fmax(st.seconds, 1e-9),
                total[1] ? (double)total[2] / total[1] : 0.0);
        phase_times_print(&cs.times, stderr);
    }
    printf("%s\n", dir);
done:
    ztv_output_free(out);
    accel_free(&acc);
    ztv_targets_free(&targets);
    cli_scene_close(&cs);
    return rc;
}

int cmd_ztv(int argc, char **argv)
{
    cli_mpi m;
    int rc = cli_mpi_begin(&m, "ztv", argc, argv);
    if (!rc) rc = ztv_run(&m, argc, argv);
    return cli_mpi_end(&m, rc);
}
