/* eco_dominance.c — which plants are dominated, 004 Algorithm 8 (Fig. 4.22): plant A is
 * dominated when some plant B overlaps its ecological circle, |p_A - p_B| < r_A + r_B (4.28–
 * 4.29), and is stronger, p_A < p_B. Plants of every species compete. Equal power — common,
 * since plants of one age on one patch share height and vigour — goes to the older plant, then
 * to the one earlier in the run's order (species, then birth): without it a cohort of seedlings
 * on a patch would never thin, and would seed on.
 *
 * B is looked for only within N_opt patches (4.27) of A, through lists of plants per cell of the
 * patch grid, rebuilt each year by a counting sort — never among all pairs. Each patch is cut
 * into m x m cells of about 2 m (m = floor(K / 2 m), at least 1) so that the many small plants
 * of a patch need not all be looked at; the window around A is ceil((r_A + r_max) / cell) cells,
 * r_max the largest radius among the patches around A that any plant of this year could reach A
 * from — a window that never reaches past N_opt patches. Each cell's list is
 * sorted strongest first, so the scan of a cell stops at the first plant no stronger than A, or
 * once no plant left in it is large enough to reach A. None of this changes the answer, only the
 * work: the flag is the one an all-pairs scan gives (a unit test checks it). The search draws no
 * random numbers and writes only A's flag, so it runs on worker threads with the same result for
 * any thread count. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "plugin_threads.h"
#include "eco_sim.h"

typedef struct eco_cell_entry {
    double x, y, z, r, power;
    double r_rest;    /* the largest radius from this entry to the end of its cell's list */
    eco_plant *owner;
    uint32_t age;     /* the owner's, copied: equal power is common, and the tie-break would
                       * otherwise read every rival's plant record (most of the search's time) */
    uint32_t order;   /* species-then-birth order: the tie-break that keeps the sort fixed */
    uint32_t cell;    /* index of its cell */
} eco_cell_entry;

typedef struct dominance_job {
    const eco_sim *s;
    double r_max;
} dominance_job;

/* Stronger first: more power; equal power, older; equal age, earlier in the run's order. */
static int stronger_first(const eco_cell_entry *a, const eco_cell_entry *b)
{
    if (a->power != b->power) return a->power > b->power ? -1 : 1;
    if (a->age != b->age) return a->age > b->age ? -1 : 1;
    return a->order < b->order ? -1 : a->order > b->order;
}

static int stronger_first_q(const void *a, const void *b) { return stronger_first(a, b); }

static void sort_cell(eco_cell_entry *e, uint32_t n)
{
    if (n > 24) {
        qsort(e, n, sizeof *e, stronger_first_q);
        return;
    }
    for (uint32_t i = 1; i < n; i++) {
        eco_cell_entry v = e[i];
        uint32_t j = i;
        while (j > 0 && stronger_first(&v, &e[j - 1]) < 0) e[j] = e[j - 1], j--;
        e[j] = v;
    }
}

/* Sorts each cell's list strongest first and notes the largest radius from each entry on. */
static void sort_range(void *ctx, size_t begin, size_t end)
{
    eco_sim *s = ctx;
    for (size_t c = begin; c < end; c++) {
        eco_cell_entry *e = s->cell + s->cell_start[c];
        uint32_t n = s->cell_start[c + 1] - s->cell_start[c];
        sort_cell(e, n);
        double rm = 0;
        for (uint32_t b = n; b-- > 0;) rm = e[b].r > rm ? e[b].r : rm, e[b].r_rest = rm;
    }
}

static void dominance_range(void *ctx, size_t begin, size_t end)
{
    const dominance_job *job = ctx;
    const eco_sim *s = job->s;
    const eco_terrain *t = &s->terrain;
    const uint32_t ni = s->cells_i, nk = s->cells_k;
    const double cx = t->kx / s->cells_per_patch, cy = t->ky / s->cells_per_patch;
    const uint32_t max_w = s->n_opt * s->cells_per_patch;
    const uint32_t m = s->cells_per_patch;
    for (size_t a = begin; a < end; a++) {
        const eco_cell_entry *A = &s->cell[a];
        uint32_t i = A->cell % ni, k = A->cell / ni;
        /* the largest radius among the patches that a plant of this year's r_max could reach A
         * from: no plant of the window can be larger */
        uint32_t pi = i / m, pk = k / m, np = (uint32_t)ceil((A->r + job->r_max) / t->k);
        if (np > s->n_opt) np = s->n_opt;
        double r_local = 0;
        for (uint32_t qk = pk > np ? pk - np : 0; qk <= pk + np && qk < t->nk; qk++)
            for (uint32_t qi = pi > np ? pi - np : 0; qi <= pi + np && qi < t->ni; qi++)
                r_local = s->patch_r_max[qi + (size_t)qk * t->ni] > r_local ? s->patch_r_max[qi + (size_t)qk * t->ni]
                                                                          : r_local;
        double reach = A->r + r_local;
        double wi = ceil(reach / cx), wk = ceil(reach / cy);
        uint32_t w_i = wi < max_w ? (uint32_t)wi : max_w, w_k = wk < max_w ? (uint32_t)wk : max_w;
        uint32_t i0 = i > w_i ? i - w_i : 0, i1 = i + w_i < ni ? i + w_i : ni - 1;
        uint32_t k0 = k > w_k ? k - w_k : 0, k1 = k + w_k < nk ? k + w_k : nk - 1;
        /* cells ring by ring outward from A's own, where a stronger neighbour is likeliest, so
         * a dominated plant is found early; a cell wholly beyond reach of A is not opened */
        int dominated = 0;
        uint32_t rings = w_i > w_k ? w_i : w_k;
        double reach2 = reach * reach;
        for (uint32_t ring = 0; ring <= rings && !dominated; ring++) {
            uint32_t rk0 = k > ring ? k - ring : 0, rk1 = k + ring < k1 ? k + ring : k1;
            if (rk0 < k0) rk0 = k0;
            for (uint32_t kk = rk0; kk <= rk1 && !dominated; kk++) {
                double ya = t->y0 + kk * cy, dy = A->y < ya ? ya - A->y : A->y > ya + cy ? A->y - ya - cy : 0;
                int whole_row = kk + ring == k || kk == k + ring; /* the ring's bottom or top row */
                int64_t step = whole_row || ring == 0 ? 1 : 2 * (int64_t)ring;
                for (int64_t c = (int64_t)i - ring; c <= (int64_t)i + ring && !dominated; c += step) {
                    if (c < (int64_t)i0 || c > (int64_t)i1) continue;
                    uint32_t ii = (uint32_t)c;
                    size_t q = ii + (size_t)kk * ni;
                    uint32_t b = s->cell_start[q], b1 = s->cell_start[q + 1];
                    if (b == b1) continue;
                    double xa = t->x0 + ii * cx;
                    double dx = A->x < xa ? xa - A->x : A->x > xa + cx ? A->x - xa - cx : 0;
                    double d2 = dx * dx + dy * dy;
                    if (d2 >= reach2) continue;
                    for (; b < b1; b++) {
                        const eco_cell_entry *B = &s->cell[b];
                        double reach_rest = A->r + B->r_rest;
                        if (d2 >= reach_rest * reach_rest) break; /* none of the rest reaches A */
                        if (stronger_first(B, A) >= 0) break;     /* the rest are no stronger */
                        double ex = A->x - B->x, ey = A->y - B->y, ez = A->z - B->z, r = A->r + B->r;
                        if (ex * ex + ey * ey + ez * ez < r * r) {
                            dominated = 1;
                            break;
                        }
                    }
                }
            }
        }
        A->owner->dominated = (uint8_t)dominated;
    }
}

/* The cell of a point, clamped to the grid. */
static uint32_t cell_of(const eco_sim *s, double x, double y)
{
    const eco_terrain *t = &s->terrain;
    double gi = (x - t->x0) / (t->kx / s->cells_per_patch), gk = (y - t->y0) / (t->ky / s->cells_per_patch);
    uint32_t i = gi <= 0 ? 0 : gi >= s->cells_i - 1 ? s->cells_i - 1 : (uint32_t)gi;
    uint32_t k = gk <= 0 ? 0 : gk >= s->cells_k - 1 ? s->cells_k - 1 : (uint32_t)gk;
    return i + k * s->cells_i;
}

int eco_find_dominance(eco_sim *s, plugin_err *err)
{
    const eco_terrain *t = &s->terrain;
    if (!s->cells_per_patch) {
        uint32_t m = (uint32_t)floor(t->k / 2.0);
        if (m < 1) m = 1;
        while (m > 1 && (uint64_t)t->ni * m * t->nk * m > (1u << 24)) m--;
        s->cells_per_patch = m, s->cells_i = t->ni * m, s->cells_k = t->nk * m;
    }
    size_t n_cells = (size_t)s->cells_i * s->cells_k;
    uint32_t n = eco_sim_count(s);
    if (!s->cell_start) {
        s->cell_start = malloc((n_cells + 1) * sizeof *s->cell_start);
        s->patch_r_max = malloc((size_t)t->ni * t->nk * sizeof *s->patch_r_max);
        if (!s->cell_start || !s->patch_r_max)
            return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the dominance grid");
    }
    if (n > s->cell_cap) {
        uint32_t cap = n + n / 2 + 1024;
        eco_cell_entry *c = realloc(s->cell, (size_t)cap * sizeof *c);
        if (!c) return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the dominance search of %u plants", n);
        s->cell = c, s->cell_cap = cap;
    }
    /* Counting sort by cell: start[c + 1] counts cell c, then prefix sums give the starts. */
    uint32_t *start = s->cell_start;
    for (size_t c = 0; c <= n_cells; c++) start[c] = 0;
    double r_max = 0;
    size_t n_patches = (size_t)t->ni * t->nk;
    for (size_t p = 0; p < n_patches; p++) s->patch_r_max[p] = 0;
    for (uint32_t j = 0; j < s->n_species; j++)
        for (uint32_t q = 0; q < s->pop[j].n; q++) {
            const eco_plant *pl = &s->pop[j].plants[q];
            start[cell_of(s, pl->x, pl->y) + 1]++;
            if (pl->r > r_max) r_max = pl->r;
            if (pl->r > s->patch_r_max[pl->patch]) s->patch_r_max[pl->patch] = pl->r;
        }
    for (size_t c = 0; c < n_cells; c++) start[c + 1] += start[c];
    uint32_t order = 0;
    for (uint32_t j = 0; j < s->n_species; j++)
        for (uint32_t q = 0; q < s->pop[j].n; q++) {
            eco_plant *pl = &s->pop[j].plants[q];
            uint32_t c = cell_of(s, pl->x, pl->y);
            s->cell[start[c]++] = (eco_cell_entry){.x = pl->x, .y = pl->y, .z = pl->z, .r = pl->r, .power = pl->power,
                                                   .owner = pl, .age = pl->age, .order = order++, .cell = c};
        }
    /* start[c] now holds the end of cell c: shift back to starts. */
    for (size_t c = n_cells; c > 0; c--) start[c] = start[c - 1];
    start[0] = 0;
    plugin_threads_for(s->config.threads, n_cells, sort_range, s);
    dominance_job job = {s, r_max};
    plugin_threads_for(s->config.threads, n, dominance_range, &job);
    return SYLVA_OK;
}
