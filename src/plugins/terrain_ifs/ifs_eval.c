/* ifs_eval.c — f_K of the IFS at points and over output grids. */
#include "ifs_eval.h"

#include <math.h>

#include "sylva/plugin.h"

/* The cell holding index position s along an axis of `cells` cells, and the position inside it. */
static inline uint32_t cell_of(double s, uint32_t cells, double *frac)
{
    uint32_t c = s <= 0.0 ? 0 : (uint32_t)s;
    if (c >= cells) c = cells - 1;
    *frac = s - c;
    return c;
}

double ifs_bilinear_at(const ifs_maps *m, double sx, double sy)
{
    double t, u;
    uint32_t i = cell_of(sx, m->ncx, &t), j = cell_of(sy, m->ncy, &u);
    const double *z = m->node_z + (size_t)j * m->nx + i;
    double south = z[0] + t * (z[1] - z[0]);
    double north = z[m->nx] + t * (z[m->nx + 1] - z[m->nx]);
    return south + u * (north - south);
}

double ifs_eval_at(const ifs_maps *m, double sx, double sy, uint32_t depth)
{
    double sum = 0.0, weight = 1.0;
    for (uint32_t k = 0; k < depth; k++) {
        double u, v;
        uint32_t cn = cell_of(sx, m->ncx, &u), cm = cell_of(sy, m->ncy, &v);
        ifs_map map = ifs_maps_cell(m, cm * m->ncx + cn);
        const ifs_map *w = &map;
        /* (u, v) = (L_n^-1(x), V_m^-1(y)) in unit coordinates; F without its alpha z term there */
        sum += weight * (w->c0 + w->cu * u + w->cv * v + w->cuv * u * v);
        weight *= w->alpha;
        if (weight == 0.0) return sum;
        sx = u * m->ncx, sy = v * m->ncy;
    }
    return sum + weight * ifs_bilinear_at(m, sx, sy);
}

uint32_t ifs_eval_auto_depth(const ifs_maps *m, uint32_t nx_out, uint32_t ny_out)
{
    /* level k cells measure (N - 1)^-k of the footprint */
    uint32_t k_res = 1;
    double cells_x = m->ncx, cells_y = m->ncy;
    while (k_res < IFS_MAX_DEPTH && (cells_x < nx_out - 1.0 || cells_y < ny_out - 1.0))
        cells_x *= m->ncx, cells_y *= m->ncy, k_res++;
    uint32_t k_amp = 1;
    if (m->alpha_max > 0.0) {
        double k = ceil(log(IFS_DEPTH_TOLERANCE) / log(m->alpha_max));
        k_amp = k > IFS_MAX_DEPTH ? IFS_MAX_DEPTH : (uint32_t)k;
    }
    uint32_t k = k_res > k_amp ? k_res : k_amp;
    return k < 1 ? 1 : k > IFS_MAX_DEPTH ? IFS_MAX_DEPTH : k;
}

typedef struct eval_job {
    const ifs_maps *m;
    uint32_t nx, ny, depth;
    ifs_window w;
    float *z;
} eval_job;

static void eval_row(void *ctx, uint32_t worker, uint64_t row)
{
    const eval_job *job = ctx;
    uint32_t j = job->w.j0 + (uint32_t)row;
    double sy = (double)j * job->m->ncy / (job->ny - 1);
    float *out = job->z + (size_t)row * job->w.nx;
    for (uint32_t k = 0; k < job->w.nx; k++) {
        double sx = (double)(job->w.i0 + k) * job->m->ncx / (job->nx - 1);
        out[k] = (float)ifs_eval_at(job->m, sx, sy, job->depth);
    }
}

int ifs_eval_grid(const ifs_maps *m, uint32_t nx_out, uint32_t ny_out, uint32_t depth,
                  uint32_t threads, float *z, plugin_progress_fn progress, void *pctx, plugin_err *err)
{
    ifs_window whole = {0, 0, nx_out, ny_out};
    return ifs_eval_window(m, nx_out, ny_out, &whole, depth, threads, z, progress, pctx, err);
}

int ifs_eval_window(const ifs_maps *m, uint32_t nx_out, uint32_t ny_out, const ifs_window *w,
                    uint32_t depth, uint32_t threads, float *z, plugin_progress_fn progress,
                    void *pctx, plugin_err *err)
{
    if (nx_out < 2 || ny_out < 2)
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "an output grid of %u x %u nodes is too small; it needs 2 x 2 at least",
                        nx_out, ny_out);
    if (depth > IFS_MAX_DEPTH)
        return plugin_fail(err, SYLVA_ERR_PARAM, "depth %u is deeper than %u levels", depth,
                        IFS_MAX_DEPTH);
    if (!w->nx || !w->ny || w->i0 + (uint64_t)w->nx > nx_out || w->j0 + (uint64_t)w->ny > ny_out)
        return plugin_fail(err, SYLVA_ERR_PARAM, "the window of %u x %u nodes from node (%u, %u) does "
                        "not lie inside the %u x %u output grid", w->nx, w->ny, w->i0, w->j0,
                        nx_out, ny_out);
    eval_job job = {.m = m, .nx = nx_out, .ny = ny_out, .depth = depth, .w = *w, .z = z};
    plugin_threads_run(threads, w->ny, eval_row, &job, progress, pctx);
    return SYLVA_OK;
}
