/* ground_cover_place.c — where the ground cover's tufts stand (see ground_cover_place.h). */
#include "geometry/ground_cover_place.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>

#include "geometry/camera_frame.h"
#include "geometry/ground_cover_models.h"
#include "scene/heightfield.h"
#include "scene/scene.h"
#include "util/rng.h"
#include "util/task_pool.h"

#define CELLS_PER_BLOCK 32     /* candidates are visited in blocks this many cells a side */
#define TUFT_REACH 0.6         /* metres: a tuft's size round its base, for the frustum test */
#define FADE_START 0.4         /* the tufts thin out from this fraction of the radius */
#define CANDIDATES_PER_TUFT 16 /* the count looks at most at about this many candidates per tuft */

double ground_cover_density(const float w[GROUND_KINDS], const double n[3])
{
    double share = w[GROUND_MEADOW] + 0.25 * w[GROUND_FOREST_FLOOR] + 0.1 * w[GROUND_SOIL] + 0.05 * w[GROUND_SCREE];
    /* full cover up to 35 degrees of slope, none from 55 */
    const double full = cos(35.0 * M_PI / 180.0), none = cos(55.0 * M_PI / 180.0);
    double slope = (n[2] - none) / (full - none);
    slope = slope < 0 ? 0 : slope > 1 ? 1 : slope;
    share *= slope;
    return share < 0 ? 0 : share > 1 ? 1 : share;
}

/* The view the tufts are placed for. */
typedef struct cover_view {
    double eye[3], forward[3], right[3], up[3];
    double tan_h, tan_v;       /* half the field of view across and up the image */
    int cylindrical;           /* a panorama: every bearing is in view */
} cover_view;

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* 1 when a sphere of radius reach round p may show in the view. */
static int in_view(const cover_view *v, const double p[3], double reach)
{
    double q[3] = {p[0] - v->eye[0], p[1] - v->eye[1], p[2] - v->eye[2]};
    double f = dot3(q, v->forward), x = dot3(q, v->right), y = dot3(q, v->up);
    if (v->cylindrical) return fabs(y) <= v->tan_v * sqrt(f * f + x * x) + reach * sqrt(1 + v->tan_v * v->tan_v);
    if (f < -reach) return 0;
    return fabs(x) <= v->tan_h * f + reach * sqrt(1 + v->tan_h * v->tan_h) &&
           fabs(y) <= v->tan_v * f + reach * sqrt(1 + v->tan_v * v->tan_v);
}

/* A tuft a candidate kept: its prototype and where it stands. */
typedef struct tuft {
    uint32_t prototype;
    xform3x4 xf;
} tuft;

/* The tufts of one block, in the order its cells are visited. */
typedef struct block_tufts {
    tuft *t;          /* owned by the pass (pass_free) */
    uint32_t n, cap;
    int out_of_memory;
} block_tufts;

/* A candidate the count kept: the place pass needs no more of it than its cell, its share before
 * the fade and its forest floor's weight, so it takes these instead of weighing the ground again
 * (the count's radius holds the place pass's, and the fade only lowers the share, so every tuft
 * placed is one of these). */
typedef struct survivor {
    int64_t ix, iy;
    double share;
    float forest_floor;
} survivor;

/* The survivors of one block, in the order its cells are visited; `whole` 0 when they were not
 * all kept (memory, or the pass's bound), and the place pass then visits the whole block. */
typedef struct block_survivors {
    survivor *s;      /* owned by the pass (pass_free) */
    uint32_t n, cap;
    int whole;
} block_survivors;

/* The survivors kept at most, as a multiple of max_instances: a count that keeps more than that
 * lets the place pass weigh the rest again rather than hold them. */
#define SURVIVORS_PER_TUFT 2

/* A block of CELLS_PER_BLOCK x CELLS_PER_BLOCK candidates that may show in the view. */
typedef struct cover_block {
    int64_t bx, by;
} cover_block;

/* What one pass over the candidates does with those it keeps. The blocks are shared out between
 * threads; each writes only its own histogram (count) or its block's tufts (place), and the
 * tufts join the scene afterwards in block order, so the result never depends on the threads. */
typedef struct cover_pass {
    const scene *s;
    const ground_cover_map *ground;
    const cover_view *view;
    const ground_cover_models *models;
    uint64_t seed;
    double cell;               /* metres */
    double radius;             /* metres */
    int place;                 /* 0: count into the histograms (no fade); 1: keep the tufts */
    cover_block *blocks;       /* the blocks in view, owned by the pass */
    uint32_t n_blocks;
    uint64_t *histograms;      /* count pass: tufts per metre of distance, one row per worker */
    size_t histogram_len;      /* radius + 2 */
    block_tufts *tufts;        /* place pass: one per block, owned by the pass */
    block_survivors *survivors; /* count pass: one per block, owned by the pass; NULL: none kept */
    atomic_uint_fast64_t n_survivors; /* kept so far, against max_survivors */
    uint64_t max_survivors;
} cover_pass;

static void keep_tuft(block_tufts *b, uint32_t proto, const xform3x4 *xf)
{
    if (b->out_of_memory) return;
    if (b->n == b->cap) {
        uint32_t cap = b->cap ? 2 * b->cap : 64;
        tuft *t = realloc(b->t, (size_t)cap * sizeof *t);
        if (!t) {
            b->out_of_memory = 1;
            return;
        }
        b->t = t, b->cap = cap;
    }
    b->t[b->n++] = (tuft){proto, *xf};
}

/* The count's survivor (ix, iy) of block k kept for the place pass, unless the bound is reached. */
static void keep_survivor(cover_pass *c, uint32_t k, int64_t ix, int64_t iy, double share, float forest_floor)
{
    block_survivors *b = &c->survivors[k];
    if (!b->whole) return;
    if (b->n == b->cap) {
        uint32_t cap = b->cap ? 2 * b->cap : 64;
        survivor *more = atomic_fetch_add(&c->n_survivors, cap - b->cap) + cap - b->cap <= c->max_survivors
                             ? realloc(b->s, (size_t)cap * sizeof *more) : NULL;
        if (!more) {
            b->whole = 0;
            return;
        }
        b->s = more, b->cap = cap;
    }
    b->s[b->n++] = (survivor){ix, iy, share, forest_floor};
}

/* The tuft of a candidate that stands at p, d from the eye, with its share before the fade: kept
 * into block k's tufts when the faded share keeps it. */
static void place_candidate(cover_pass *c, uint32_t k, double p[3], double d, double share, float forest_floor,
                            double keep, double pick, double turn, double size)
{
    double t = (d / c->radius - FADE_START) / (1.0 - FADE_START);
    if (t > 0) share *= t >= 1 ? 0 : 1.0 - t * t * (3.0 - 2.0 * t);
    if (!(keep < share)) return;
    /* a herb for one tuft in ten on meadow, for one in two on the forest floor */
    double herb_share = 0.1 + 0.4 * forest_floor;
    uint32_t proto = pick < herb_share
                         ? c->models->herb_first + (uint32_t)(pick / herb_share * GROUND_COVER_HERB_VARIANTS)
                         : c->models->grass_first +
                               (uint32_t)((pick - herb_share) / (1.0 - herb_share) * GROUND_COVER_GRASS_VARIANTS);
    p[2] -= 0.01; /* the base a centimetre into the ground, so that no tuft floats over a facet */
    xform3x4 xf = plant_transform(p, 360.0 * turn, 0.7 + 0.6 * size);
    keep_tuft(&c->tufts[k], proto, &xf);
}

/* A candidate's draws: where it stands (on the ground, d from the eye) and its four numbers. */
typedef struct cell_draws {
    double p[3], d;
    double keep, pick, turn, size;
} cell_draws;

/* Candidate (ix, iy)'s jittered point and draws; 0 when it stands off the terrain or beyond
 * c->radius. */
static int draw_cell(const cover_pass *c, int64_t ix, int64_t iy, cell_draws *o)
{
    sylva_rng r;
    rng_stream(&r, c->seed, "ground cover", ((uint64_t)(uint32_t)ix << 32) | (uint32_t)iy);
    o->p[0] = ((double)ix + rng_next_double(&r)) * c->cell;
    o->p[1] = ((double)iy + rng_next_double(&r)) * c->cell;
    o->p[2] = 0;
    o->keep = rng_next_double(&r), o->pick = rng_next_double(&r), o->turn = rng_next_double(&r);
    o->size = rng_next_double(&r);
    double dx = o->p[0] - c->view->eye[0], dy = o->p[1] - c->view->eye[1];
    if (dx * dx + dy * dy > c->radius * c->radius) return 0;
    if (heightfield_surface_height(c->s->terrain, o->p[0], o->p[1], &o->p[2])) return 0;
    double dz = o->p[2] - c->view->eye[2];
    o->d = sqrt(dx * dx + dy * dy + dz * dz);
    return o->d <= c->radius;
}

/* Survivor v of the count in the place pass: the same point and draws as visit_cell's, within
 * the place pass's radius; its weighing (the same view, ground and point as the count's) taken
 * from the count. */
static void visit_survivor(cover_pass *c, uint32_t k, const survivor *v)
{
    cell_draws q;
    if (draw_cell(c, v->ix, v->iy, &q))
        place_candidate(c, k, q.p, q.d, v->share, v->forest_floor, q.keep, q.pick, q.turn, q.size);
}

/* Candidate (ix, iy) of block k, for worker w: its jittered point, whether it is kept, and what
 * stands there. */
static void visit_cell(cover_pass *c, unsigned w, uint32_t k, int64_t ix, int64_t iy)
{
    cell_draws q;
    if (!draw_cell(c, ix, iy, &q)) return;
    double *p = q.p, d = q.d, keep = q.keep;
    double mid[3] = {p[0], p[1], p[2] + 0.2};
    if (!in_view(c->view, mid, TUFT_REACH)) return;
    float wk[GROUND_KINDS];
    double n[3];
    ground_cover_weights(c->ground, p[0], p[1], wk);
    if (heightfield_normal(c->s->terrain, p[0], p[1], n)) return;
    double share = ground_cover_density(wk, n) * land_cover_herb_share(c->s->land_cover, p[0], p[1]);
    if (c->place) {
        place_candidate(c, k, p, d, share, wk[GROUND_FOREST_FLOOR], keep, q.pick, q.turn, q.size);
        return;
    }
    if (!(keep < share)) return;
    c->histograms[w * c->histogram_len + (size_t)d]++;
    if (c->survivors) keep_survivor(c, k, ix, iy, share, wk[GROUND_FOREST_FLOOR]);
}

/* task_pool task: every candidate of block k. */
static void visit_block(void *ctx, unsigned worker, uint32_t k)
{
    cover_pass *c = ctx;
    const cover_block *b = &c->blocks[k];
    if (c->place && c->survivors && c->survivors[k].whole) {
        for (uint32_t i = 0; i < c->survivors[k].n; i++) visit_survivor(c, k, &c->survivors[k].s[i]);
        return;
    }
    for (int64_t iy = b->by * CELLS_PER_BLOCK; iy < (b->by + 1) * CELLS_PER_BLOCK; iy++)
        for (int64_t ix = b->bx * CELLS_PER_BLOCK; ix < (b->bx + 1) * CELLS_PER_BLOCK; ix++)
            visit_cell(c, worker, k, ix, iy);
}

/* The blocks within c->radius of the eye that may show in the view, into c->blocks in row
 * order. Returns 0, or -1 with err set (out of memory). */
static int find_blocks(cover_pass *c, err_buf *err)
{
    const double block = CELLS_PER_BLOCK * c->cell, half_diagonal = block * M_SQRT1_2;
    const double *eye = c->view->eye;
    int64_t b0x = (int64_t)floor((eye[0] - c->radius) / block), b1x = (int64_t)floor((eye[0] + c->radius) / block);
    int64_t b0y = (int64_t)floor((eye[1] - c->radius) / block), b1y = (int64_t)floor((eye[1] + c->radius) / block);
    uint32_t cap = 0;
    for (int64_t by = b0y; by <= b1y; by++)
        for (int64_t bx = b0x; bx <= b1x; bx++) {
            double centre[3] = {(bx + 0.5) * block, (by + 0.5) * block, 0};
            double dx = fmax(fabs(centre[0] - eye[0]) - 0.5 * block, 0), dy = fmax(fabs(centre[1] - eye[1]) - 0.5 * block, 0);
            if (dx * dx + dy * dy > c->radius * c->radius) continue;
            centre[2] = heightfield_height_clamped(c->s->terrain, centre[0], centre[1]);
            /* the ground within the block may climb or fall by its half-diagonal (45 degrees) */
            if (!in_view(c->view, centre, 2.0 * half_diagonal + TUFT_REACH + 1.0)) continue;
            if (c->n_blocks == cap) {
                cap = cap ? 2 * cap : 256;
                cover_block *more = realloc(c->blocks, (size_t)cap * sizeof *more);
                if (!more) return err_nomem(err, "out of memory for the ground cover's blocks");
                c->blocks = more;
            }
            c->blocks[c->n_blocks++] = (cover_block){bx, by};
        }
    return 0;
}

static void pass_free(cover_pass *c)
{
    for (uint32_t k = 0; c->tufts && k < c->n_blocks; k++) free(c->tufts[k].t);
    free(c->tufts);
    for (uint32_t k = 0; c->survivors && k < c->n_blocks; k++) free(c->survivors[k].s);
    free(c->survivors);
    free(c->histograms);
    free(c->blocks);
}

/* The count: tufts per metre of distance without the fade, summed over the workers into
 * histogram (radius + 2 long). Returns 0, or -1 with err set. */
static int count_tufts(cover_pass *c, unsigned threads, uint64_t *histogram, err_buf *err)
{
    if (!threads) threads = task_pool_default_threads();
    c->histogram_len = (size_t)c->radius + 2;
    c->histograms = calloc((size_t)threads * c->histogram_len, sizeof *c->histograms);
    if (!c->histograms) return err_nomem(err, "out of memory for the ground cover");
    c->place = 0;
    /* the survivors kept for the place pass where memory allows (none kept: it weighs them all) */
    c->survivors = calloc(c->n_blocks ? c->n_blocks : 1, sizeof *c->survivors);
    for (uint32_t k = 0; c->survivors && k < c->n_blocks; k++) c->survivors[k].whole = 1;
    task_pool_run(threads, c->n_blocks, visit_block, c);
    for (unsigned w = 0; w < threads; w++)
        for (size_t i = 0; i < c->histogram_len; i++) histogram[i] += c->histograms[w * c->histogram_len + i];
    return 0;
}

/* The tufts kept within c->radius, added to the scene in block order, at most max of them.
 * Returns 0, or -1 with err set. */
static int place_tufts(cover_pass *c, unsigned threads, uint32_t max, scene *s, err_buf *err)
{
    c->tufts = calloc(c->n_blocks ? c->n_blocks : 1, sizeof *c->tufts);
    if (!c->tufts) return err_nomem(err, "out of memory for the ground cover");
    c->place = 1;
    task_pool_run(threads, c->n_blocks, visit_block, c);
    uint32_t placed = 0;
    for (uint32_t k = 0; k < c->n_blocks; k++) {
        const block_tufts *b = &c->tufts[k];
        if (b->out_of_memory) return err_nomem(err, "out of memory for the ground cover's tufts");
        /* the count keeps the total within max; the check only guards the scene */
        for (uint32_t i = 0; i < b->n && placed < max; i++, placed++)
            if (scene_add_instance(s, b->t[i].prototype, &b->t[i].xf, err) < 0) return -1;
    }
    return 0;
}

int ground_cover_add(scene *s, const ground_cover_settings *gc, uint32_t width, uint32_t height, unsigned threads,
                     ground_cover_report *rep, err_buf *err)
{
    ground_cover_report local = {0};
    if (!rep) rep = &local;
    *rep = (ground_cover_report){0};
    if (!gc->enabled || !(gc->density > 0) || !gc->max_instances || !s->terrain || !width || !height) return 0;

    cover_view v = {.cylindrical = s->camera.cylindrical};
    for (int k = 0; k < 3; k++) v.eye[k] = s->camera.position[k];
    camera_frame(&s->camera, v.forward, v.right, v.up);
    double fov = s->camera.fov_deg * M_PI / 180.0;
    double focal_px;
    if (v.cylindrical) {
        focal_px = width / fov;                  /* pixels per radian across */
        v.tan_v = 0.5 * height / focal_px;       /* the image's height on the unit cylinder */
    } else {
        v.tan_h = tan(0.5 * fov);
        v.tan_v = v.tan_h * height / width;
        focal_px = 0.5 * width / v.tan_h;
    }
    rep->pixel_radius = focal_px * GROUND_COVER_BLADE_LENGTH;
    double radius = gc->radius > 0 ? gc->radius : rep->pixel_radius;
    /* The count visits every candidate of the sector in view, 0.5 fov r^2 density of them: keep
     * that within CANDIDATES_PER_TUFT times the cap, so that no radius makes the count slow. */
    double sector = v.cylindrical ? M_PI : 0.5 * fmax(fov, 0.35);
    double reach = sqrt(CANDIDATES_PER_TUFT * (double)gc->max_instances / (sector * gc->density));
    if (radius > reach) radius = reach, rep->capped = 1;

    ground_cover_models models;
    err->msg[0] = '\0';
    ground_cover_map *ground = ground_cover_map_new(s, err); /* owned here */
    if (!ground) return err->msg[0] ? -1 : 0; /* a terrain of scene materials: no cover */
    uint32_t first_instance = s->n_instances;
    cover_pass c = {.s = s, .ground = ground, .view = &v, .models = &models, .seed = s->image.seed,
                    .cell = 1.0 / sqrt(gc->density), .radius = radius,
                    .max_survivors = SURVIVORS_PER_TUFT * (uint64_t)gc->max_instances};
    atomic_init(&c.n_survivors, 0);
    int rc = -1;
    /* count what the radius holds, metre by metre, and shrink it to the cap */
    uint64_t *histogram = calloc((size_t)radius + 2, sizeof *histogram); /* owned here */
    if (!histogram) {
        err_nomem(err, "out of memory for the ground cover");
        goto done;
    }
    if (find_blocks(&c, err) || count_tufts(&c, threads, histogram, err)) goto done;
    uint64_t total = 0;
    size_t fits = 0;
    while (fits <= (size_t)radius && total + histogram[fits] <= gc->max_instances) total += histogram[fits++];
    if (fits <= (size_t)radius) c.radius = (double)fits, rep->capped = 1;
    rep->radius = c.radius;
    if (!total) {
        rc = 0;
        goto done;
    }
    /* the prototypes, then the tufts: each one a candidate the count kept */
    if (ground_cover_models_add(s, s->image.seed, &models, err) ||
        place_tufts(&c, threads, gc->max_instances, s, err))
        goto done;
    rep->instances = s->n_instances - first_instance;
    rc = 0;
done:
    free(histogram);
    pass_free(&c);
    ground_cover_map_free(ground);
    return rc;
}
