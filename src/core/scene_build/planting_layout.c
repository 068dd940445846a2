/* planting_layout.c — a planting plan's plants laid out from its seed (planting_layout.h). */
#include "scene_build/planting_layout.h"

#include <math.h>
#include <stdlib.h>

#include "util/rng.h"

/* How far a plant may stand from its station, as a share of the spacing: planted by hand. */
#define PLANTING_JITTER 0.15

typedef struct layout {
    const planting_spec *plan;
    planted_plant *plants; uint32_t n, cap; /* owned until returned */
    uint64_t max;
} layout;

int planting_ring_contains(const double (*xy)[2], uint32_t n, double x, double y)
{
    int in = 0;
    for (uint32_t i = 0, j = n - 1; i < n; j = i++)
        if ((xy[i][1] > y) != (xy[j][1] > y) &&
            x < (xy[j][0] - xy[i][0]) * (y - xy[i][1]) / (xy[j][1] - xy[i][1]) + xy[i][0])
            in = !in;
    return in;
}

/* A uniform number in [0, 1) for the plant's `purpose`, from the seed, its feature and station. */
static double draw(const layout *L, uint32_t feature, uint64_t station, uint64_t purpose)
{
    uint64_t key = rng_combine(rng_combine(L->plan->seed, feature), rng_combine(station, purpose));
    return (double)(rng_mix64(key) >> 11) * (1.0 / 9007199254740992.0);
}

/* A block's species by its shares, for the draw u. */
static uint32_t species_by_share(const planting_feature *f, double u)
{
    double acc = 0;
    for (uint32_t i = 0; i + 1 < f->n_species; i++)
        if (u < (acc += f->share[i])) return f->species[i];
    return f->species[f->n_species - 1];
}

/* Adds the plant at station `station` of feature `fi`: its jitter, turn, stock and rank drawn. */
static int add_plant(layout *L, uint32_t fi, uint64_t station, double x, double y, uint32_t species, err_buf *err)
{
    const planting_feature *f = &L->plan->features[fi];
    if (L->n == L->cap) {
        if ((uint64_t)L->n >= L->max)
            return err_set(err, "%s: the planting plan holds more than %llu plants; is a spacing in metres?", f->name,
                           (unsigned long long)L->max);
        uint32_t cap = L->cap ? 2 * L->cap : 256;
        planted_plant *grown = realloc(L->plants, (size_t)cap * sizeof *grown);
        if (!grown) return err_nomem(err, "out of memory laying out the planting plan");
        L->plants = grown, L->cap = cap;
    }
    double jitter = f->kind == PLANTING_TREE ? 0 : PLANTING_JITTER * f->spacing;
    double r = jitter * sqrt(draw(L, fi, station, 1)), a = 2 * M_PI * draw(L, fi, station, 2);
    double stock = f->stock_height[0] + (f->stock_height[1] - f->stock_height[0]) * draw(L, fi, station, 4);
    L->plants[L->n++] = (planted_plant){.feature = fi, .species = species, .xy = {x + r * cos(a), y + r * sin(a)},
                                        .rotation_deg = 360.0 * draw(L, fi, station, 3), .stock_height = stock,
                                        .thinning_rank = draw(L, fi, station, 5)};
    return 0;
}

/* A block: a square grid of its spacing over the polygon's bounds, each node inside planted. */
static int lay_block(layout *L, uint32_t fi, err_buf *err)
{
    const planting_feature *f = &L->plan->features[fi];
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (uint32_t k = 0; k < f->n_xy; k++)
        for (int c = 0; c < 2; c++) lo[c] = fmin(lo[c], f->xy[k][c]), hi[c] = fmax(hi[c], f->xy[k][c]);
    uint64_t nx = (uint64_t)floor((hi[0] - lo[0]) / f->spacing) + 1, ny = (uint64_t)floor((hi[1] - lo[1]) / f->spacing) + 1;
    if (nx * ny > L->max) return err_set(err, "%s: the block's grid of %g m holds more than %llu plants", f->name,
                                         f->spacing, (unsigned long long)L->max);
    for (uint64_t j = 0; j < ny; j++)
        for (uint64_t i = 0; i < nx; i++) {
            double x = lo[0] + f->spacing * (i + 0.5), y = lo[1] + f->spacing * (j + 0.5);
            if (!planting_ring_contains((const double (*)[2])f->xy, f->n_xy, x, y)) continue;
            uint64_t station = j * nx + i;
            if (add_plant(L, fi, station, x, y, species_by_share(f, draw(L, fi, station, 0)), err)) return -1;
        }
    return 0;
}

/* A belt: rows side by side along the line, each a plant every spacing metres from half a
 * spacing in, alternate rows staggered by half a spacing; row r's k-th plant takes the
 * sequence's species (k + r) mod n. Each plant is offset across its own segment of the line. */
static int lay_belt(layout *L, uint32_t fi, err_buf *err)
{
    const planting_feature *f = &L->plan->features[fi];
    double length = 0;
    for (uint32_t k = 0; k + 1 < f->n_xy; k++)
        length += hypot(f->xy[k + 1][0] - f->xy[k][0], f->xy[k + 1][1] - f->xy[k][1]);
    if ((uint64_t)(length / f->spacing + 1) * f->rows > L->max)
        return err_set(err, "%s: the belt's rows of %g m spacing hold more than %llu plants", f->name, f->spacing,
                       (unsigned long long)L->max);
    for (uint32_t r = 0; r < f->rows; r++) {
        double offset = ((double)r - 0.5 * (f->rows - 1)) * f->row_spacing;
        uint32_t seg = 0;
        double seg_start = 0;
        uint64_t k = 0;
        for (double s = f->spacing * (r % 2 ? 1.0 : 0.5); s <= length; s += f->spacing, k++) {
            double len;
            while ((len = hypot(f->xy[seg + 1][0] - f->xy[seg][0], f->xy[seg + 1][1] - f->xy[seg][1])),
                   seg + 2 < f->n_xy && s > seg_start + len)
                seg_start += len, seg++;
            double t = len > 0 ? (s - seg_start) / len : 0;
            double dx = len > 0 ? (f->xy[seg + 1][0] - f->xy[seg][0]) / len : 1, dy = len > 0 ? (f->xy[seg + 1][1] - f->xy[seg][1]) / len : 0;
            double x = f->xy[seg][0] + t * len * dx - offset * dy, y = f->xy[seg][1] + t * len * dy + offset * dx;
            if (add_plant(L, fi, ((uint64_t)r << 32) | k, x, y, f->species[(k + r) % f->n_species], err)) return -1;
        }
    }
    return 0;
}

planted_plant *planting_layout_new(const planting_spec *plan, uint64_t max_plants, uint32_t *n, err_buf *err)
{
    layout L = {.plan = plan, .max = max_plants};
    int rc = 0;
    for (uint32_t fi = 0; fi < plan->n_features && !rc; fi++) {
        const planting_feature *f = &plan->features[fi];
        if (f->kind == PLANTING_BLOCK) rc = lay_block(&L, fi, err);
        else if (f->kind == PLANTING_BELT) rc = lay_belt(&L, fi, err);
        else if (f->kind == PLANTING_TREE) rc = add_plant(&L, fi, 0, f->xy[0][0], f->xy[0][1], f->species[0], err);
    }
    if (rc) {
        free(L.plants);
        return NULL;
    }
    *n = L.n;
    if (!L.plants && !(L.plants = malloc(sizeof *L.plants))) {
        err_nomem(err, "out of memory laying out the planting plan");
        return NULL;
    }
    return L.plants;
}
