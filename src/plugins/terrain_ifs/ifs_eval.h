/* ifs_eval.h — deterministic evaluation of the IFS surface (MODELS.md §1): no randomness, the
 * same heights on any machine and thread count.
 *
 *   f_0     = the bilinear interpolation of the DTM;
 *   f_k(x, y) = F_{n,m}(L_n^-1(x), V_m^-1(y), f_{k-1}(L_n^-1(x), V_m^-1(y)))
 *             on the cell (n, m) that holds (x, y).
 *
 * A point on a cell edge belongs to the cell east (north) of it, except on the footprint's east
 * (north) edge. Positions are given in DTM index units, sx in [0, N - 1] and sy in [0, M - 1],
 * so that a DTM node is an exact number.
 */
#ifndef TERRAIN_IFS_EVAL_H
#define TERRAIN_IFS_EVAL_H

#include <stdint.h>

#include "plugin_err.h"
#include "ifs_maps.h"
#include "plugin_threads.h"

#define IFS_MAX_DEPTH 64u          /* deepest f_K evaluated */
#define IFS_DEPTH_TOLERANCE 1e-4   /* auto depth: the weight alpha_max^K of what is left out */

/* f_0 at (sx, sy). */
double ifs_bilinear_at(const ifs_maps *m, double sx, double sy);

/* f_depth at (sx, sy). depth 0 is f_0. */
double ifs_eval_at(const ifs_maps *m, double sx, double sy, uint32_t depth);

/* The depth K used when none is given for an output grid of nx_out x ny_out nodes: the larger of
 * the levels needed before a level's cells are finer than the output spacing and the levels
 * needed before alpha_max^K <= IFS_DEPTH_TOLERANCE, at least 1 and at most IFS_MAX_DEPTH. */
uint32_t ifs_eval_auto_depth(const ifs_maps *m, uint32_t nx_out, uint32_t ny_out);

/* f_depth at every node of an nx_out x ny_out grid spanning the DTM's footprint (node (i, j) at
 * sx = i (N - 1) / (nx_out - 1), sy likewise), row 0 south, into z (nx_out * ny_out floats).
 * Rows are shared among `threads` workers; the result does not depend on their number. */
int ifs_eval_grid(const ifs_maps *m, uint32_t nx_out, uint32_t ny_out, uint32_t depth,
                  uint32_t threads, float *z, plugin_progress_fn progress, void *pctx, plugin_err *err);

/* A window of an output grid: its nodes [i0, i0 + nx) x [j0, j0 + ny). */
typedef struct ifs_window {
    uint32_t i0, j0, nx, ny;
} ifs_window;

/* As ifs_eval_grid over window w of the nx_out x ny_out grid only (w inside it), into z
 * (w->nx * w->ny floats, row 0 the window's southern row): each node the same number as in the
 * whole grid. */
int ifs_eval_window(const ifs_maps *m, uint32_t nx_out, uint32_t ny_out, const ifs_window *w,
                    uint32_t depth, uint32_t threads, float *z, plugin_progress_fn progress,
                    void *pctx, plugin_err *err);

#endif
