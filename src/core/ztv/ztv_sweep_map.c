/* ztv_sweep_map.c — the visibility map target by target, the bare-earth sweep first. */
#include "ztv/ztv_sweep_map.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/terrain_mesh.h"
#include "util/progress.h"
#include "util/task_pool.h"
#include "ztv/ztv_canopy.h"
#include "ztv/ztv_cover.h"
#include "ztv/ztv_grid.h"
#include "ztv/ztv_screen.h"
#include "ztv/ztv_sight.h"
#include "ztv/ztv_sweep.h"

/* Where the map's cells on the terrain lie among the heightfield's nodes. */
typedef struct window {
    uint32_t q0, r0, nx, ny;   /* the map's cells q0 .. q0 + nx - 1 east, r0 .. r0 + ny - 1 south */
    uint32_t i0, j0;           /* the heightfield node of cell (q0, r0 + ny - 1) */
} window;

/* One worker's counts over the window and its scratch; owned by the worker. */
typedef struct counts {
    uint16_t *visible[2];
    uint32_t *developments[2];
    uint8_t *status;
    ztv_sweep_scratch scratch;
    uint64_t pairs, rays, swept;
} counts;

typedef struct sweep_ctx {
    const ztv_job *job;
    window w;
    ztv_sweep_ground ground;
    float *eye, *height;       /* window cells: the eye and the ground, NAN off the map; owned */
    uint8_t *where, *cls;      /* window cells: the bare and the screened classes; owned */
    int screened;
    ztv_sight sight;
    ztv_sight screen_sight;    /* over the screening geometry alone, with screen_mask: the canopy
                                * surface in canopy mode, else the plants and objects (ztv_screen.h) */
    unsigned screen_mask;
    const ztv_canopy *canopy;
    progress *prog;
    counts *worker;            /* one per thread; owned */
    counts total;              /* the workers' counts added up */
} sweep_ctx;

/* The map's cells on the terrain as a window of the heightfield's nodes; -1 when the map's
 * lattice is not the heightfield's, -2 when the map and the heightfield do not overlap. */
static int window_of(const ztv_grid *g, const sylva_heightfield *h, window *w)
{
    double cell = g->cell;
    if (fabs(h->dx - cell) > 1e-9 * cell || fabs(h->dy - cell) > 1e-9 * cell) return -1;
    double fi = (g->x0 - h->x0) / cell, fj = (g->y0 - h->y0) / cell;
    long ioff = lround(fi), joff = lround(fj); /* node of cell (0, 0): (ioff + q, joff - r) */
    if (fabs(fi - ioff) > 1e-6 || fabs(fj - joff) > 1e-6) return -1;
    long qa = ioff < 0 ? -ioff : 0, qb = (long)h->nx - 1 - ioff;
    long ra = joff > (long)h->ny - 1 ? joff - ((long)h->ny - 1) : 0, rb = joff;
    if (qb > (long)g->nx - 1) qb = (long)g->nx - 1;
    if (rb > (long)g->ny - 1) rb = (long)g->ny - 1;
    if (qb - qa < 1 || rb - ra < 1) return -2;
    *w = (window){(uint32_t)qa, (uint32_t)ra, (uint32_t)(qb - qa + 1), (uint32_t)(rb - ra + 1), (uint32_t)(ioff + qa),
                  (uint32_t)(joff - rb)};
    return 0;
}

int ztv_sweep_map_fits(const ztv_job *job, char *why, size_t n)
{
    const sylva_heightfield *h = job->scene->terrain;
    const geom_info *ground = job->accel->top_geoms ? &job->accel->top_geoms[ACCEL_TOP_TERRAIN] : NULL;
    window w;
    int lattice;
    char spare[256];
    if (!why) why = spare, n = sizeof spare;
    if (job->sightlines) snprintf(why, n, "--sightlines asks for every pair's sightline");
    else if (job->parts > 1) snprintf(why, n, "a map shared between MPI ranks is traced by sightlines");
    else if (!h) snprintf(why, n, "the scene has no terrain");
    else if (terrain_grid_count(h) != 1)
        snprintf(why, n, "the ground is refined, in levels of detail (--ground refined)");
    else if (h->has_water) snprintf(why, n, "the terrain has water");
    else if (ground && ground->alpha) snprintf(why, n, "the ground has cut-out parts");
    else if ((lattice = window_of(&job->grid, h, &w)) == -1)
        snprintf(why, n, "the map's %.9g m cells are not centred on the DTM's nodes, %.9g x %.9g m apart; "
                 "--cell 0, or no cell:, maps one cell per node", job->grid.cell, h->dx, h->dy);
    else if (lattice) snprintf(why, n, "the map does not overlap the DTM");
    else if ((double)w.nx * w.ny > ZTV_SWEEP_MAX_CELLS)
        snprintf(why, n, "the map covers %.3g of the DTM's nodes, more than the sweep's %u", (double)w.nx * w.ny,
                 ZTV_SWEEP_MAX_CELLS);
    else if (job->targets->n == 0) snprintf(why, n, "there are no targets");
    else return 1;
    return 0;
}

/* The cells' eyes, ground and classes, as the row by row tracer sets them. */
static int cells_set(sweep_ctx *c, const ztv_cover *cover, err_buf *err)
{
    const ztv_job *job = c->job;
    const ztv_grid *g = &job->grid;
    const window *w = &c->w;
    float *row_eye = malloc((size_t)g->nx * sizeof *row_eye); /* freed below */
    uint8_t *under = malloc(g->nx), *inside = malloc(g->nx);
    if (!row_eye || !under || !inside) {
        free(row_eye), free(under), free(inside);
        return err_nomem(err, "out of memory for a row of %u cells", g->nx);
    }
    for (uint32_t r = 0; r < w->ny; r++) {
        uint32_t j = w->r0 + r;
        for (uint32_t i = 0; i < g->nx; i++) row_eye[i] = NAN;
        for (uint32_t a = 0; a < w->nx; a++) {
            size_t k = (size_t)r * w->nx + a;
            double x, y, ground;
            ztv_cell_centre(g, w->q0 + a, j, &x, &y);
            int near = ztv_within_radius(job->targets, job->radius, x, y);
            int on = near && !ztv_ground(job->scene, x, y, &ground);
            c->where[k] = on ? ZTV_OPEN : near ? ZTV_NO_TERRAIN : ZTV_OUTSIDE;
            c->height[k] = on ? (float)ground : NAN;
            c->eye[k] = row_eye[w->q0 + a] = on ? (float)(ground + job->observer_height) : NAN;
        }
        if (!c->screened) continue;
        memset(under, 0, g->nx), memset(inside, 0, g->nx);
        if (cover) ztv_cover_crowns(cover, j, row_eye, under);
        if (cover && job->screened == ZTV_ALL) ztv_cover_objects(cover, j, row_eye, inside);
        if (c->canopy) ztv_canopy_under(c->canopy, g, j, row_eye, under);
        for (uint32_t a = 0; a < w->nx; a++) {
            size_t k = (size_t)r * w->nx + a;
            c->cls[k] = isnan(c->eye[k]) ? c->where[k] : inside[w->q0 + a] ? ZTV_IN_OBJECT
                        : under[w->q0 + a]                                  ? ZTV_UNDER_CROWN
                                                                            : ZTV_OPEN;
        }
    }
    free(row_eye), free(under), free(inside);
    return 0;
}

static int counts_alloc(counts *n, size_t cells, int screened, const ztv_sweep_ground *g)
{
    memset(n, 0, sizeof *n);
    for (int m = 0; m < 1 + screened; m++) {
        n->visible[m] = calloc(cells, sizeof *n->visible[m]);
        n->developments[m] = calloc(cells, sizeof *n->developments[m]);
        if (!n->visible[m] || !n->developments[m]) return -1;
    }
    n->status = malloc(cells);
    return !n->status || (g && ztv_sweep_scratch_alloc(&n->scratch, g)) ? -1 : 0;
}

static void counts_free(counts *n)
{
    for (int m = 0; m < 2; m++) free(n->visible[m]), free(n->developments[m]);
    free(n->status);
    ztv_sweep_scratch_free(&n->scratch);
}

/* Target t's pairs with every cell into the worker's counts. */
static void target_pass(sweep_ctx *c, counts *n, uint32_t t)
{
    const ztv_job *job = c->job;
    const double *p = job->targets->p[t];
    uint32_t bit = 1u << job->targets->development[t];
    ztv_sweep_target(&c->ground, p, n->status, &n->scratch);
    for (uint32_t r = 0; r < c->w.ny; r++)
        for (uint32_t a = 0; a < c->w.nx; a++) {
            size_t k = (size_t)r * c->w.nx + a;
            if (isnan(c->eye[k])) continue;
            uint8_t s = n->status[k];
            n->swept += s != ZTV_DOUBT, n->pairs++;
            if (s == ZTV_HIDDEN) continue;
            /* the cell's position only where a sightline is cast */
            double eye[3] = {0, 0, c->eye[k]};
            if (s == ZTV_DOUBT || (c->screened && c->cls[k] == ZTV_OPEN))
                ztv_cell_centre(&job->grid, c->w.q0 + a, c->w.r0 + r, &eye[0], &eye[1]);
            if (s == ZTV_DOUBT && !ztv_sight_clear(&c->sight, eye, p, ACCEL_MASK_GROUND, &n->rays)) continue;
            n->visible[0][k]++, n->developments[0][k] |= bit;
            if (!c->screened || c->cls[k] != ZTV_OPEN) continue;
            /* bare earth leaves the pair clear: the screening geometry alone is asked */
            if (ztv_sight_clear(&c->screen_sight, eye, p, c->screen_mask, &n->rays)) n->visible[1][k]++, n->developments[1][k] |= bit;
        }
}

/* Task t of the pool: target t, on worker w's counts. */
static void sweep_task(void *arg, unsigned w, uint32_t t)
{
    sweep_ctx *c = arg;
    target_pass(c, &c->worker[w], t);
    progress_advance(c->prog, 1);
}

/* Adds worker n's counts into the total. */
static void counts_add(sweep_ctx *c, const counts *n)
{
    size_t cells = (size_t)c->w.nx * c->w.ny;
    for (int m = 0; m < 1 + c->screened; m++)
        for (size_t k = 0; k < cells; k++) {
            c->total.visible[m][k] += n->visible[m][k];
            c->total.developments[m][k] |= n->developments[m][k];
        }
    c->total.pairs += n->pairs, c->total.rays += n->rays, c->total.swept += n->swept;
}

/* Hands the map to the sink a block of rows at a time, as ztv_trace does. */
static int hand_over(const sweep_ctx *c, ztv_sink sink, void *user, err_buf *err)
{
    const ztv_job *job = c->job;
    const ztv_grid *g = &job->grid;
    const window *w = &c->w;
    uint32_t block_rows = g->nx >= ZTV_BLOCK_CELLS ? 1 : ZTV_BLOCK_CELLS / g->nx;
    if (block_rows > g->ny) block_rows = g->ny;
    size_t n = (size_t)block_rows * g->nx;
    struct {
        uint16_t *visible;
        float *fraction;
        uint8_t *cls;
        uint32_t *developments;
    } l[2] = {{0}};
    float *ground = malloc(n * sizeof *ground); /* the block's arrays; freed below */
    int rc = ground ? 0 : -1;
    for (int m = 0; m < 1 + c->screened; m++) {
        l[m].visible = malloc(n * sizeof *l[m].visible), l[m].fraction = malloc(n * sizeof *l[m].fraction);
        l[m].cls = malloc(n), l[m].developments = malloc(n * sizeof *l[m].developments);
        if (!l[m].visible || !l[m].fraction || !l[m].cls || !l[m].developments) rc = -1;
    }
    if (rc) rc = err_nomem(err, "out of memory for a block of %zu cells of the map", n);
    for (uint32_t j0 = 0; !rc && j0 < g->ny; j0 += block_rows) {
        uint32_t rows = g->ny - j0 < block_rows ? g->ny - j0 : block_rows;
        for (uint32_t r = 0; r < rows; r++)
            for (uint32_t i = 0; i < g->nx; i++) {
                uint32_t j = j0 + r;
                size_t b = (size_t)r * g->nx + i, k = 0;
                int in = j >= w->r0 && j < w->r0 + w->ny && i >= w->q0 && i < w->q0 + w->nx;
                uint8_t where;
                if (in) {
                    k = (size_t)(j - w->r0) * w->nx + (i - w->q0);
                    where = c->where[k];
                    ground[b] = c->height[k];
                } else {
                    double x, y;
                    ztv_cell_centre(g, i, j, &x, &y);
                    where = ztv_within_radius(job->targets, job->radius, x, y) ? ZTV_NO_TERRAIN : ZTV_OUTSIDE;
                    ground[b] = NAN;
                }
                for (int m = 0; m < 1 + c->screened; m++) {
                    uint32_t vis = in ? c->total.visible[m][k] : 0;
                    l[m].visible[b] = (uint16_t)vis;
                    l[m].fraction[b] = (float)((double)vis / job->targets->n);
                    l[m].developments[b] = in ? c->total.developments[m][k] : 0;
                    l[m].cls[b] = m == 0 || !in ? where : c->cls[k];
                }
            }
        ztv_layer layers[2];
        ztv_block blk = {.j0 = j0, .rows = rows, .ground = ground};
        for (int m = 0; m < 1 + c->screened; m++) {
            layers[m] = (ztv_layer){l[m].visible, l[m].fraction, l[m].cls, l[m].developments};
            blk.layer[m ? job->screened : ZTV_BARE] = &layers[m];
        }
        rc = sink(user, &blk, err);
    }
    free(ground);
    for (int m = 0; m < 2; m++) free(l[m].visible), free(l[m].fraction), free(l[m].cls), free(l[m].developments);
    return rc;
}

/* The ground the sweep walks: the window's nodes, their steepness into steep (owned by the
 * caller). */
static void ground_set(sweep_ctx *c, float *steep)
{
    const sylva_heightfield *h = c->job->scene->terrain;
    ztv_sweep_ground *gr = &c->ground;
    *gr = (ztv_sweep_ground){.z = h->z, .stride = h->nx, .i0 = c->w.i0, .j0 = c->w.j0, .nx = c->w.nx,
                             .ny = c->w.ny, .x0 = h->x0, .y0 = h->y0, .cell = c->job->grid.cell, .eye = c->eye,
                             .observer_height = c->job->observer_height, .c = c->sight.c};
    ztv_sweep_steepness(gr, steep);
    double most = 0;
    for (size_t k = 0; k < (size_t)(gr->nx - 1) * (gr->ny - 1); k++) most = fmax(most, steep[k]);
    gr->steep = steep, gr->steepest = most;
}

int ztv_sweep_map(const ztv_job *job, ztv_sink sink, void *user, ztv_stats *stats, err_buf *err)
{
    double t0 = progress_now();
    sweep_ctx c = {.job = job, .screened = job->screened != ZTV_BARE};
    window_of(&job->grid, job->scene->terrain, &c.w);
    size_t cells = (size_t)c.w.nx * c.w.ny;
    ztv_sight_init(&c.sight, job->accel->top, job->earth);
    unsigned threads = 0;
    ztv_cover *cover = NULL;
    ztv_canopy *surface = NULL;
    ztv_screen screen = {0};
    int rc = 0;
    c.eye = malloc(cells * sizeof *c.eye), c.height = malloc(cells * sizeof *c.height); /* freed below */
    c.where = malloc(cells), c.cls = malloc(cells);
    float *steep = malloc((size_t)(c.w.nx - 1) * (c.w.ny - 1) * sizeof *steep);
    if (!c.eye || !c.height || !c.where || !c.cls || !steep || counts_alloc(&c.total, cells, c.screened, NULL)) {
        rc = err_nomem(err, "out of memory for the %zu cells of the map", cells);
        goto done;
    }
    if (job->screened == ZTV_CANOPY) surface = ztv_canopy_new(job->scene, job->accel, err);
    else if (c.screened) cover = ztv_cover_new(job->scene, job->accel, &job->grid, err);
    uint64_t pairs = (uint64_t)cells * job->targets->n;
    unsigned mask = ztv_mode_mask(job->screened);
    if (c.screened && (cover ? ztv_screen_open(&screen, job->accel, mask, pairs, err) : !surface)) {
        rc = -1;
        goto done;
    }
    c.canopy = surface;
    if (c.screened) ztv_sight_init(&c.screen_sight, surface ? ztv_canopy_scene(surface) : screen.scene, job->earth);
    c.screen_mask = surface ? ~0u : screen.mask;
    if ((rc = cells_set(&c, cover, err))) goto done;
    ground_set(&c, steep);
    threads = job->threads ? job->threads : task_pool_default_threads();
    if (threads > job->targets->n) threads = job->targets->n;
    c.worker = calloc(threads, sizeof *c.worker); /* freed below */
    for (unsigned w = 0; !rc && c.worker && w < threads; w++)
        if (counts_alloc(&c.worker[w], cells, c.screened, &c.ground)) rc = -1;
    if (!c.worker || rc) {
        rc = err_nomem(err, "out of memory for the counts over %zu cells of %u threads", cells, threads);
        goto done;
    }
    progress prog;
    progress_begin(&prog, "ztv", job->targets->n, job->quiet);
    c.prog = &prog;
    task_pool_run(threads, job->targets->n, sweep_task, &c);
    progress_end(&prog);
    for (unsigned w = 0; w < threads; w++) counts_add(&c, &c.worker[w]);
    if (accel_device_error(job->accel, err)) rc = -1;
    else rc = hand_over(&c, sink, user, err);
done:
    if (stats) {
        uint64_t on = 0;
        for (size_t k = 0; c.eye && k < cells; k++) on += !isnan(c.eye[k]);
        *stats = (ztv_stats){.cells = on, .pairs = c.total.pairs, .rays = c.total.rays, .swept = c.total.swept,
                             .seconds = progress_now() - t0};
    }
    ztv_cover_free(cover);
    ztv_canopy_free(surface);
    ztv_screen_close(&screen);
    free(c.eye), free(c.height), free(c.where), free(c.cls), free(steep);
    counts_free(&c.total);
    for (unsigned w = 0; c.worker && w < threads; w++) counts_free(&c.worker[w]);
    free(c.worker);
    return rc;
}
