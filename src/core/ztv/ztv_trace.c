/* ztv_trace.c — the visibility map's cells, a block of rows at a time on every thread. */
#include "ztv/ztv_trace.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "render/render.h"
#include "util/interleave.h"
#include "util/progress.h"
#include "ztv/ztv_canopy.h"
#include "ztv/ztv_cover.h"
#include "ztv/ztv_grid.h"
#include "ztv/ztv_screen.h"
#include "ztv/ztv_sight.h"
#include "ztv/ztv_sweep_map.h"

/* One mode's arrays over a block; owned. */
typedef struct layer_buf {
    uint16_t *visible;
    float *fraction;
    uint8_t *cls;
    uint32_t *developments;
} layer_buf;

typedef struct trace_ctx {
    const ztv_job *job;
    ztv_sight sight;
    ztv_sight screen_sight;        /* over the screening geometry alone, with screen_mask: the canopy
                                    * surface in canopy mode, else the plants and objects (ztv_screen.h) */
    unsigned screen_mask;
    const ztv_cover *cover;        /* vegetation and all modes */
    const ztv_canopy *canopy;      /* canopy mode */
    uint32_t j0, rows;             /* the block being computed */
    uint32_t first, step, own;     /* its rows of this part: first + k * step, k < own */
    atomic_uint next_row;
    float *ground;                 /* block cells; owned */
    layer_buf layer[2];            /* [0] bare earth, [1] the screened mode */
    int screened;                  /* 1: layer[1] is computed */
    progress *prog;
    pthread_mutex_t lock;          /* guards the totals below */
    uint64_t cells, pairs, rays;
} trace_ctx;

/* Scratch of one worker for one row; owned by the worker. The counts of the pairs it traced
 * so far choose which sightline of a pair to cast first (the answer does not depend on it). */
typedef struct row_scratch {
    float *eye;
    uint8_t *under, *inside;
    uint8_t *where;    /* ZTV_OPEN on the terrain within the radius, else ZTV_OUTSIDE or ZTV_NO_TERRAIN */
    uint64_t bare_clear, screened_blocked;
} row_scratch;

/* Whether target t is in sight of eye on bare earth (*bare) and screened (*screened, 0 when the
 * cell is no viewpoint screened or no screened mode is computed). */
static void pair_sight(const trace_ctx *c, row_scratch *w, int viewpoint, const double eye[3], const double t[3],
                       int *bare, int *screened, uint64_t *rays)
{
    *screened = 0;
    if (!c->screened || !viewpoint) {
        *bare = ztv_sight_clear(&c->sight, eye, t, ACCEL_MASK_GROUND, rays);
        return;
    } else if (c->canopy || w->bare_clear < w->screened_blocked) {
        /* bare earth hides most: what it hides, the screening hides too, and what it leaves clear
         * is asked of the screening geometry alone (the canopy surface holds no apron or water) */
        *bare = ztv_sight_clear(&c->sight, eye, t, ACCEL_MASK_GROUND, rays);
        *screened = *bare && ztv_sight_clear(&c->screen_sight, eye, t, c->screen_mask, rays);
    } else {
        /* the screening hides little: what it lets through, bare earth does too */
        *screened = ztv_sight_clear(&c->sight, eye, t, ztv_mode_mask(c->job->screened), rays);
        *bare = *screened || ztv_sight_clear(&c->sight, eye, t, ACCEL_MASK_GROUND, rays);
    }
    w->bare_clear += *bare, w->screened_blocked += !*screened;
}

static void trace_row(trace_ctx *c, uint32_t row, row_scratch *w, uint64_t *cells, uint64_t *pairs, uint64_t *rays)
{
    const ztv_job *job = c->job;
    const ztv_grid *g = &job->grid;
    const ztv_targets *t = job->targets;
    uint32_t j = c->j0 + row;
    size_t base = (size_t)row * g->nx;
    for (uint32_t i = 0; i < g->nx; i++) {
        double x, y, ground;
        ztv_cell_centre(g, i, j, &x, &y);
        int near = ztv_within_radius(job->targets, job->radius, x, y);
        int ground_there = !ztv_ground(job->scene, x, y, &ground);
        int on = near && ground_there;
        w->where[i] = on ? ZTV_OPEN : near ? ZTV_NO_TERRAIN : ZTV_OUTSIDE;
        c->ground[base + i] = on ? (float)ground : NAN;
        w->eye[i] = on ? (float)(ground + job->observer_height) : NAN;
    }
    memset(w->under, 0, g->nx), memset(w->inside, 0, g->nx);
    if (c->cover) ztv_cover_crowns(c->cover, j, w->eye, w->under);
    if (c->cover && job->screened == ZTV_ALL) ztv_cover_objects(c->cover, j, w->eye, w->inside);
    if (c->canopy) ztv_canopy_under(c->canopy, g, j, w->eye, w->under);
    for (uint32_t i = 0; i < g->nx; i++) {
        size_t k = base + i;
        int on = !isnan(w->eye[i]);
        uint8_t cls_s = !on ? w->where[i] : w->inside[i] ? ZTV_IN_OBJECT : w->under[i] ? ZTV_UNDER_CROWN : ZTV_OPEN;
        uint32_t vis[2] = {0, 0}, devs[2] = {0, 0};
        if (on) {
            double x, y;
            ztv_cell_centre(g, i, j, &x, &y);
            double eye[3] = {x, y, w->eye[i]};
            (*cells)++;
            for (uint32_t n = 0; n < t->n; n++) {
                uint32_t bit = 1u << t->development[n];
                int bare, screened;
                pair_sight(c, w, cls_s == ZTV_OPEN, eye, t->p[n], &bare, &screened, rays);
                if (bare) vis[0]++, devs[0] |= bit;
                if (screened) vis[1]++, devs[1] |= bit;
                (*pairs)++;
            }
        }
        for (int m = 0; m < 1 + c->screened; m++) {
            layer_buf *l = &c->layer[m];
            l->cls[k] = m == 0 ? w->where[i] : cls_s;
            l->visible[k] = (uint16_t)vis[m];
            l->fraction[k] = (float)((double)vis[m] / t->n);
            l->developments[k] = devs[m];
        }
    }
}

static void *trace_worker(void *arg)
{
    trace_ctx *c = arg;
    uint32_t nx = c->job->grid.nx;
    row_scratch w = {malloc((size_t)nx * sizeof(float)), malloc(nx), malloc(nx), malloc(nx), 0, 0}; /* freed below */
    uint64_t cells = 0, pairs = 0, rays = 0;
    for (uint32_t k; w.eye && w.under && w.inside && w.where && (k = atomic_fetch_add(&c->next_row, 1)) < c->own;) {
        trace_row(c, c->first + k * c->step, &w, &cells, &pairs, &rays);
        progress_advance(c->prog, 1);
    }
    free(w.eye), free(w.under), free(w.inside), free(w.where);
    pthread_mutex_lock(&c->lock);
    c->cells += cells, c->pairs += pairs, c->rays += rays;
    pthread_mutex_unlock(&c->lock);
    return NULL;
}

static int layer_alloc(layer_buf *l, size_t n)
{
    l->visible = malloc(n * sizeof *l->visible);
    l->fraction = malloc(n * sizeof *l->fraction);
    l->cls = malloc(n);
    l->developments = malloc(n * sizeof *l->developments);
    return l->visible && l->fraction && l->cls && l->developments ? 0 : -1;
}

static void layer_free(layer_buf *l)
{
    free(l->visible), free(l->fraction), free(l->cls), free(l->developments);
}

int ztv_trace(const ztv_job *job, ztv_sink sink, void *user, ztv_stats *stats, err_buf *err)
{
    if (ztv_sweep_map_fits(job, NULL, 0)) return ztv_sweep_map(job, sink, user, stats, err);
    const ztv_grid *g = &job->grid;
    double t0 = progress_now();
    trace_ctx c = {.job = job, .screened = job->screened != ZTV_BARE};
    ztv_sight_init(&c.sight, job->accel->top, job->earth);
    pthread_mutex_init(&c.lock, NULL);
    uint32_t block_rows = g->nx >= ZTV_BLOCK_CELLS ? 1 : ZTV_BLOCK_CELLS / g->nx;
    if (block_rows > g->ny) block_rows = g->ny;
    size_t n = (size_t)block_rows * g->nx;
    int rc = 0;
    ztv_cover *cover = NULL;
    ztv_canopy *surface = NULL;
    ztv_screen screen = {0};
    c.ground = malloc(n * sizeof *c.ground);
    if (!c.ground || layer_alloc(&c.layer[0], n) || (c.screened && layer_alloc(&c.layer[1], n))) {
        rc = err_nomem(err, "out of memory for a block of %zu cells of the map", n);
        goto done;
    }
    if (job->screened == ZTV_CANOPY) surface = ztv_canopy_new(job->scene, job->accel, err);
    else if (c.screened) cover = ztv_cover_new(job->scene, job->accel, g, err);
    uint64_t pairs = (uint64_t)g->nx * g->ny * job->targets->n;
    unsigned mask = ztv_mode_mask(job->screened);
    if (c.screened && (cover ? ztv_screen_open(&screen, job->accel, mask, pairs, err) : !surface)) {
        rc = -1;
        goto done;
    }
    c.cover = cover, c.canopy = surface;
    if (c.screened) ztv_sight_init(&c.screen_sight, surface ? ztv_canopy_scene(surface) : screen.scene, job->earth);
    c.screen_mask = surface ? ~0u : screen.mask;
    unsigned threads = job->threads ? job->threads : render_default_threads();
    progress prog;
    uint32_t parts = job->parts > 1 ? job->parts : 1, part = parts > 1 ? job->part : 0;
    progress_begin(&prog, "ztv", interleave_count(g->ny, part, parts), job->quiet);
    c.prog = &prog;
    pthread_t *tids = calloc(threads, sizeof *tids); /* freed below */
    for (uint32_t j0 = 0; !rc && j0 < g->ny; j0 += block_rows) {
        c.j0 = j0;
        c.rows = g->ny - j0 < block_rows ? g->ny - j0 : block_rows;
        c.first = (part + parts - j0 % parts) % parts, c.step = parts;
        c.own = interleave_count(c.rows, c.first, parts);
        atomic_init(&c.next_row, 0);
        unsigned started = 0;
        if (tids)
            for (; started + 1 < threads; started++)
                if (pthread_create(&tids[started], NULL, trace_worker, &c)) break;
        trace_worker(&c);
        for (unsigned k = 0; k < started; k++) pthread_join(tids[k], NULL);
        if (atomic_load(&c.next_row) < c.own) { /* the workers could not get their scratch */
            rc = err_nomem(err, "out of memory for the rows of the map");
            break;
        }
        if (accel_device_error(job->accel, err)) {
            rc = -1;
            break;
        }
        ztv_layer layers[2];
        ztv_block b = {.j0 = c.j0, .rows = c.rows, .ground = c.ground};
        for (int m = 0; m < 1 + c.screened; m++) {
            layers[m] = (ztv_layer){c.layer[m].visible, c.layer[m].fraction, c.layer[m].cls, c.layer[m].developments};
            b.layer[m ? job->screened : ZTV_BARE] = &layers[m];
        }
        rc = sink(user, &b, err);
    }
    free(tids);
    progress_end(&prog);
done:
    if (stats)
        *stats = (ztv_stats){.cells = c.cells, .pairs = c.pairs, .rays = c.rays, .seconds = progress_now() - t0};
    ztv_cover_free(cover);
    ztv_canopy_free(surface);
    ztv_screen_close(&screen);
    free(c.ground);
    layer_free(&c.layer[0]);
    layer_free(&c.layer[1]);
    pthread_mutex_destroy(&c.lock);
    return rc;
}
