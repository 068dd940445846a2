/* test_ifs_model.c — the terrain_ifs model on its own: the maps (8)-(12) against hand-computed
 * coefficients, the properties MODELS.md §1 names (every DTM node on the bilinear-mode surface,
 * alpha = 0 is the bilinear surface, roughness rising with |alpha|, same seed same heights),
 * the random iteration landing on the attractor, the probability field, the seeded generator,
 * nodata filling and the ground-cover rules. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dtm.h"
#include "dtm_generate.h"
#include "harness.h"
#include "seeded_dtm.h"
#include "ifs_chaos.h"
#include "ifs_eval.h"
#include "ifs_maps.h"
#include "surface_classes.h"
#include "util/rng.h"

static uint64_t next_u64(sylva_rng *r) { return rng_next_u64(r); }

/* A DTM with heights from the rows given (row 0 south). */
static ifs_dtm *dtm_of(uint32_t nx, uint32_t ny, double dx, double dy, const double *rows)
{
    ifs_dtm *d = NULL;
    plugin_err err = {0};
    CHECK(ifs_dtm_from_rows(rows, nx, ny, dx, dy, &d, &err) == 0);
    if (!d) fprintf(stderr, "dtm_of: %s\n", err.msg);
    return d;
}

/* A rough test DTM: a seeded generated grid. */
static ifs_dtm *generated_dtm(uint32_t n, double relief, uint64_t seed) { return seeded_dtm(n, 20, relief, 0.8, seed); }

static ifs_maps *maps_of(const ifs_dtm *d, ifs_mode mode, double alpha, const double *alpha_field,
                         const double *probability)
{
    ifs_maps_params p = {.mode = mode, .alpha = alpha, .alpha_field = alpha_field,
                         .probability = probability};
    ifs_maps *m = NULL;
    plugin_err err = {0};
    CHECK(ifs_maps_build(d, &p, &m, &err) == 0);
    if (!m) fprintf(stderr, "maps_of: %s\n", err.msg);
    return m;
}

static double det3(const double a[3][3])
{
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

/* --------------------------------------------------------------------------------------------
 * The maps (8)-(12)
 */

/* A 3 x 3 DTM 10 m x 20 m apart with its first node at (100, 200), alpha 0.25. For the cell
 * whose south-west node is (1, 0) — the paper's w_{3,2} — (11) gives by hand:
 *   P = z(1,0) - a z(0,0) = 2 - 0.25 = 1.75,  Q = z(2,0) - a z(2,0) = 4 - 1 = 3,
 *   S = z(2,1) - a z(2,2) = 6 - 2.25 = 3.75,   D = (120 - 100)(240 - 200) = 800,
 *   a = D1/D = (Q - P) 40 / 800 = 0.0625, b = D2/D = (S - Q) 20 / 800 = 0.01875,
 *   c = D3/D = (100 (200 S - 240 Q) - 200 (120 S - 120 Q) + P (120 240 - 200 120)) / 800 = -8.25. */
TEST(affine_matches_hand_computed_coefficients)
{
    const double rows[] = {1, 2, 4, /* south */ 3, 5, 6, /* */ 2, 7, 9 /* north */};
    ifs_dtm *d = dtm_of(3, 3, 10, 20, rows);
    ifs_maps *m = d ? maps_of(d, IFS_MODE_AFFINE, 0.25, NULL, NULL) : NULL;
    if (!m) goto done;
    double a, b, e, c;
    ifs_map_paper_coefficients(m, 1, 0, 100, 200, &a, &b, &e, &c);
    CHECK_NEAR(a, 0.0625, 1e-12);
    CHECK_NEAR(b, 0.01875, 1e-12);
    CHECK_NEAR(c, -8.25, 1e-12);
    CHECK_NEAR(e, 0.0, 0);
    /* and the same from the determinants of (11), written out for every cell */
    double x1 = 100, xN = 120, y1 = 200, yM = 240, alpha = 0.25;
    double z11 = rows[0], zN1 = rows[2], zNM = rows[8];
    for (uint32_t cm = 0; cm < 2; cm++)
        for (uint32_t cn = 0; cn < 2; cn++) {
            double P = rows[cm * 3 + cn] - alpha * z11, Q = rows[cm * 3 + cn + 1] - alpha * zN1;
            double S = rows[(cm + 1) * 3 + cn + 1] - alpha * zNM;
            double D[3][3] = {{x1, y1, 1}, {xN, y1, 1}, {xN, yM, 1}};
            double D1[3][3] = {{P, y1, 1}, {Q, y1, 1}, {S, yM, 1}};
            double D2[3][3] = {{x1, P, 1}, {xN, Q, 1}, {xN, S, 1}};
            double D3[3][3] = {{x1, y1, P}, {xN, y1, Q}, {xN, yM, S}};
            ifs_map_paper_coefficients(m, cn, cm, x1, y1, &a, &b, &e, &c);
            CHECK_NEAR(a, det3(D1) / det3(D), 1e-12);
            CHECK_NEAR(b, det3(D2) / det3(D), 1e-12);
            CHECK_NEAR(c, det3(D3) / det3(D), 1e-11);
            /* (10) with (11)'s third condition: the three global corners go to the cell's */
            CHECK_NEAR(a * x1 + b * y1 + alpha * z11 + c, rows[cm * 3 + cn], 1e-12);
            CHECK_NEAR(a * xN + b * y1 + alpha * zN1 + c, rows[cm * 3 + cn + 1], 1e-12);
            CHECK_NEAR(a * xN + b * yM + alpha * zNM + c, rows[(cm + 1) * 3 + cn + 1], 1e-12);
        }
done:
    ifs_maps_free(m);
    ifs_dtm_free(d);
}

/* Bilinear mode: all four global corners map onto the cell's corners, and (8) maps the
 * footprint onto the cell. */
TEST(bilinear_maps_fix_all_four_corners)
{
    ifs_dtm *d = generated_dtm(9, 50, 7);
    ifs_maps *m = d ? maps_of(d, IFS_MODE_BILINEAR, -0.4, NULL, NULL) : NULL;
    if (!m) goto done;
    const double U[4] = {0, 1, 1, 0}, V[4] = {0, 0, 1, 1};
    const uint32_t ci[4] = {0, 8, 8, 0}, cj[4] = {0, 0, 8, 8};
    double worst = 0;
    for (uint32_t cm = 0; cm < 8; cm++)
        for (uint32_t cn = 0; cn < 8; cn++) {
            ifs_map map = ifs_maps_cell(m, cm * 8 + cn);
            const ifs_map *w = &map;
            for (int k = 0; k < 4; k++) {
                double zg = d->z[cj[k] * 9 + ci[k]];
                double f = w->c0 + w->cu * U[k] + w->cv * V[k] + w->cuv * U[k] * V[k] + w->alpha * zg;
                double want = d->z[(cm + (uint32_t)V[k]) * 9 + cn + (uint32_t)U[k]];
                worst = fmax(worst, fabs(f - want));
            }
            CHECK_NEAR(w->u0 + 0 * m->su, cn / 8.0, 1e-15);
            CHECK_NEAR(w->u0 + 1 * m->su, (cn + 1) / 8.0, 1e-15);
            CHECK_NEAR(w->v0 + 1 * m->sv, (cm + 1) / 8.0, 1e-15);
        }
    CHECK(worst < 1e-12);
done:
    ifs_maps_free(m);
    ifs_dtm_free(d);
}

/* --------------------------------------------------------------------------------------------
 * Properties of the surface
 */

/* In bilinear mode the surface passes through every DTM node, for any alpha and for a per-cell
 * alpha field: exactly in double precision, and to float precision on an output grid. */
TEST(bilinear_surface_passes_through_every_node)
{
    ifs_dtm *d = generated_dtm(9, 80, 11);
    double field[64];
    for (int k = 0; k < 64; k++) field[k] = -0.6 + 1.2 * ((k * 37) % 64) / 63.0;
    const double alphas[] = {0.1, 0.5, -0.7, 0.9};
    for (int pass = 0; d && pass < 5; pass++) {
        ifs_maps *m = maps_of(d, IFS_MODE_BILINEAR, pass < 4 ? alphas[pass] : 0, pass == 4 ? field : NULL, NULL);
        if (!m) break;
        double worst = 0, range = 80;
        for (uint32_t j = 0; j < 9; j++)
            for (uint32_t i = 0; i < 9; i++)
                worst = fmax(worst, fabs(ifs_eval_at(m, i, j, 40) - d->z[j * 9 + i]));
        CHECK(worst <= 1e-12 * range);
        /* output grid 8 nodes per cell: node (8 i, 8 j) is DTM node (i, j) */
        float *z = malloc(65 * 65 * sizeof *z);
        plugin_err err = {0};
        CHECK(ifs_eval_grid(m, 65, 65, ifs_eval_auto_depth(m, 65, 65), 2, z, NULL, NULL, &err) == 0);
        double worst_f = 0;
        for (uint32_t j = 0; j < 9; j++)
            for (uint32_t i = 0; i < 9; i++)
                worst_f = fmax(worst_f, fabs(z[(8 * j) * 65 + 8 * i] - d->z[j * 9 + i]));
        CHECK(worst_f <= 80 * 6e-8); /* one float rounding of heights up to 80 m */
        char label[32];
        if (pass < 4) snprintf(label, sizeof label, "%g", alphas[pass]);
        else snprintf(label, sizeof label, "field");
        fprintf(stderr, "  alpha %s: largest miss at the 81 nodes %.3g m (double), %.3g m (float grid)\n",
                label, worst, worst_f);
        free(z);
        ifs_maps_free(m);
    }
    ifs_dtm_free(d);
}

/* The paper's affine map enforces three corners only: nodes that are a cell's south-west corner
 * are on the surface, but not the north edge's (which need the fourth condition). */
TEST(affine_surface_misses_the_unenforced_corner)
{
    ifs_dtm *d = generated_dtm(9, 80, 11);
    ifs_maps *m = d ? maps_of(d, IFS_MODE_AFFINE, 0.3, NULL, NULL) : NULL;
    if (!m) goto done;
    double worst_sw = 0, worst_north = 0;
    for (uint32_t j = 0; j < 9; j++)
        for (uint32_t i = 0; i < 9; i++) {
            double miss = fabs(ifs_eval_at(m, i, j, 40) - d->z[j * 9 + i]);
            if (i < 8 && j < 8) worst_sw = fmax(worst_sw, miss);
            if (j == 8 && i < 8) worst_north = fmax(worst_north, miss);
        }
    fprintf(stderr, "  affine: largest miss at south-west corners %.3g m, on the north edge %.3g m\n",
            worst_sw, worst_north);
    CHECK(worst_sw < 1e-10);
    CHECK(worst_north > 0.01);
done:
    ifs_maps_free(m);
    ifs_dtm_free(d);
}

/* alpha = 0: every f_K is the bilinear interpolation of the DTM, and every random point lies on it. */
TEST(alpha_zero_is_bilinear_interpolation)
{
    ifs_dtm *d = generated_dtm(17, 120, 3);
    ifs_maps *m = d ? maps_of(d, IFS_MODE_BILINEAR, 0.0, NULL, NULL) : NULL;
    if (!m) goto done;
    sylva_rng r;
    rng_stream(&r, 5, "test.points", 0);
    double worst = 0;
    for (int k = 0; k < 20000; k++) {
        double sx = 16 * rng_next_double(&r), sy = 16 * rng_next_double(&r);
        worst = fmax(worst, fabs(ifs_eval_at(m, sx, sy, 12) - ifs_bilinear_at(m, sx, sy)));
    }
    CHECK(worst < 1e-10);
    double *uvz = malloc(3 * 50000 * sizeof *uvz);
    sylva_rng chain;
    rng_stream(&chain, 9, "terrain_ifs.chaos", 0);
    ifs_chaos_points(m, 0, 0, d->z[0], &chain, next_u64, 50000, uvz);
    double worst_points = 0;
    for (int k = 0; k < 50000; k++)
        worst_points = fmax(worst_points, fabs(uvz[3 * k + 2] - ifs_bilinear_at(m, 16 * uvz[3 * k], 16 * uvz[3 * k + 1])));
    CHECK(worst_points < 1e-10);
    /* random iteration on a grid: means of points near each node; a bilinear surface averages to
     * its node value up to the curvature within half an output spacing */
    float *z = malloc(129 * 129 * sizeof *z), *exact = malloc(129 * 129 * sizeof *z);
    sylva_rng streams[8];
    for (int c = 0; c < 8; c++) rng_stream(&streams[c], 9, "terrain_ifs.chaos", (uint64_t)c);
    ifs_chaos_job job = {.points = 8u * IFS_CHAIN_POINTS, .start_z = d->z[0], .streams = streams,
                         .rng_u64 = next_u64, .nx = 129, .ny = 129, .depth = 4, .threads = 2};
    plugin_err err = {0};
    CHECK(ifs_chaos_grid(m, &job, z, NULL, &err) == 0);
    CHECK(ifs_eval_grid(m, 129, 129, 4, 2, exact, NULL, NULL, &err) == 0);
    double worst_grid = 0;
    for (int k = 0; k < 129 * 129; k++) worst_grid = fmax(worst_grid, fabs(z[k] - exact[k]));
    fprintf(stderr, "  alpha 0: f_K vs bilinear %.2g m, random points %.2g m, random grid vs bilinear %.3g m\n",
            worst, worst_points, worst_grid);
    CHECK(worst_grid < 2.0); /* 120 m relief over 16 cells: slopes change by < 2 m per half spacing */
    free(uvz), free(z), free(exact);
done:
    ifs_maps_free(m);
    ifs_dtm_free(d);
}

/* Every point of the random iteration lies on the graph of f (the attractor): its height is
 * f_K at its (x, y), apart from the first points of a chain that sit exactly on cell edges
 * (where f may jump and rounding picks the cell). */
TEST(random_points_lie_on_the_attractor)
{
    ifs_dtm *d = generated_dtm(9, 60, 21);
    const ifs_mode modes[2] = {IFS_MODE_BILINEAR, IFS_MODE_AFFINE};
    for (int mi = 0; d && mi < 2; mi++) {
        ifs_maps *m = maps_of(d, modes[mi], 0.35, NULL, NULL);
        if (!m) break;
        enum { N = 40000, SKIP = 64 };
        double *uvz = malloc(3 * N * sizeof *uvz);
        sylva_rng chain;
        rng_stream(&chain, 77, "terrain_ifs.chaos", 0);
        ifs_chaos_points(m, 0, 0, d->z[0], &chain, next_u64, N, uvz);
        int off = 0;
        double worst = 0;
        for (int k = SKIP; k < N; k++) {
            double miss = fabs(uvz[3 * k + 2] - ifs_eval_at(m, 8 * uvz[3 * k], 8 * uvz[3 * k + 1], 40));
            if (miss > 1e-6 * 60) off++;
            else worst = fmax(worst, miss);
        }
        fprintf(stderr, "  %s: %d of %d points off the surface; largest miss of the others %.2g m\n",
                mi ? "affine" : "bilinear", off, N - SKIP, worst);
        CHECK(off <= (N - SKIP) / 1000);
        free(uvz);
        ifs_maps_free(m);
    }
    ifs_dtm_free(d);
}

/* Roughness of east-west profiles as the fractal dimension D = 2 - s/2 from the slope s of the
 * log variogram over lags of 1, 2, 4 and 8 output spacings. */
static double profile_dimension(const float *z, uint32_t nx, uint32_t ny)
{
    double lx[4], ly[4];
    for (int q = 0; q < 4; q++) {
        uint32_t h = 1u << q;
        double sum = 0;
        uint64_t count = 0;
        for (uint32_t j = 0; j < ny; j++)
            for (uint32_t i = 0; i + h < nx; i++) {
                double dz = (double)z[j * nx + i + h] - z[j * nx + i];
                sum += dz * dz, count++;
            }
        lx[q] = log((double)h), ly[q] = log(sum / count);
    }
    double mx = 0, my = 0, sxy = 0, sxx = 0;
    for (int q = 0; q < 4; q++) mx += lx[q] / 4, my += ly[q] / 4;
    for (int q = 0; q < 4; q++) sxy += (lx[q] - mx) * (ly[q] - my), sxx += (lx[q] - mx) * (lx[q] - mx);
    return 2.0 - 0.5 * sxy / sxx;
}

/* The output grid has 300 nodes a side so that its nodes are not points of a level-k lattice of
 * the 17 x 17 DTM ((N - 1)^k / 299 is never whole): at lattice points f is fixed by k levels
 * alone, and a grid made of them would hide the finer levels whose amplitude alpha sets. */
TEST(roughness_rises_with_alpha)
{
    ifs_dtm *d = generated_dtm(17, 120, 5);
    if (!d) return;
    const double alphas[] = {0.0, 0.1, 0.2, 0.3, 0.5, 0.7};
    enum { NA = sizeof alphas / sizeof alphas[0], NO = 300 };
    float *z = malloc((size_t)NO * NO * sizeof *z);
    double det_pos[NA], det_neg[NA], rnd[NA];
    for (int a = 0; a < NA; a++) {
        for (int sign = 0; sign < 2; sign++) {
            ifs_maps *m = maps_of(d, IFS_MODE_BILINEAR, sign ? -alphas[a] : alphas[a], NULL, NULL);
            if (!m) break;
            plugin_err err = {0};
            uint32_t depth = ifs_eval_auto_depth(m, NO, NO);
            CHECK(ifs_eval_grid(m, NO, NO, depth, 2, z, NULL, NULL, &err) == 0);
            (sign ? det_neg : det_pos)[a] = profile_dimension(z, NO, NO);
            if (!sign) {
                sylva_rng streams[8];
                for (int c = 0; c < 8; c++) rng_stream(&streams[c], 1, "terrain_ifs.chaos", (uint64_t)c);
                ifs_chaos_job job = {.points = 8u * IFS_CHAIN_POINTS, .start_z = d->z[0],
                                     .streams = streams, .rng_u64 = next_u64, .nx = NO, .ny = NO,
                                     .depth = depth, .threads = 2};
                CHECK(ifs_chaos_grid(m, &job, z, NULL, &err) == 0);
                rnd[a] = profile_dimension(z, NO, NO);
            }
            ifs_maps_free(m);
        }
    }
    fprintf(stderr, "  profile dimension D = 2 - s/2 (s: log-log variogram slope over lags 1, 2, 4, 8\n"
                    "  of a 300 x 300 output grid from a 17 x 17 DTM, 120 m relief):\n");
    fprintf(stderr, "  %8s %15s %15s %15s\n", "|alpha|", "determ. +alpha", "determ. -alpha", "random +alpha");
    for (int a = 0; a < NA; a++)
        fprintf(stderr, "  %8.2f %15.4f %15.4f %15.4f\n", alphas[a], det_pos[a], det_neg[a], rnd[a]);
    CHECK_NEAR(det_pos[0], 1.0, 0.05); /* alpha 0: piecewise linear profiles */
    for (int a = 1; a < NA; a++) {
        CHECK(det_pos[a] > det_pos[a - 1] + 0.02);
        CHECK(det_neg[a] > det_neg[a - 1] + 0.02);
        CHECK(rnd[a] > rnd[a - 1] + 0.01);
    }
    free(z);
    ifs_dtm_free(d);
}

/* Same seed, same heights, for any thread count; another seed, other heights. */
TEST(same_seed_same_heights)
{
    ifs_dtm *d = generated_dtm(17, 90, 8);
    ifs_maps *m = d ? maps_of(d, IFS_MODE_BILINEAR, 0.3, NULL, NULL) : NULL;
    if (!m) goto done;
    enum { NO = 129 };
    float *z[4];
    for (int k = 0; k < 4; k++) z[k] = malloc(NO * NO * sizeof(float));
    const uint32_t threads[4] = {1, 2, 3, 1};
    const uint64_t seeds[4] = {42, 42, 42, 43};
    uint64_t points = 5u * IFS_CHAIN_POINTS + 12345;
    for (int k = 0; k < 4; k++) {
        uint64_t chains = ifs_chaos_chain_count(points);
        sylva_rng *streams = malloc(chains * sizeof *streams);
        for (uint64_t c = 0; c < chains; c++) rng_stream(&streams[c], seeds[k], "terrain_ifs.chaos", c);
        ifs_chaos_job job = {.points = points, .start_z = d->z[0], .streams = streams,
                             .rng_u64 = next_u64, .nx = NO, .ny = NO, .depth = 6, .threads = threads[k]};
        plugin_err err = {0};
        ifs_chaos_stats st;
        CHECK(ifs_chaos_grid(m, &job, z[k], &st, &err) == 0);
        CHECK_INT(st.workers, threads[k]);
        free(streams);
    }
    CHECK(memcmp(z[0], z[1], NO * NO * sizeof(float)) == 0);
    CHECK(memcmp(z[0], z[2], NO * NO * sizeof(float)) == 0);
    CHECK(memcmp(z[0], z[3], NO * NO * sizeof(float)) != 0);
    /* deterministic evaluation: 1 and 2 threads agree to the bit */
    plugin_err err = {0};
    CHECK(ifs_eval_grid(m, NO, NO, 9, 1, z[0], NULL, NULL, &err) == 0);
    CHECK(ifs_eval_grid(m, NO, NO, 9, 2, z[1], NULL, NULL, &err) == 0);
    CHECK(memcmp(z[0], z[1], NO * NO * sizeof(float)) == 0);
    for (int k = 0; k < 4; k++) free(z[k]);
done:
    ifs_maps_free(m);
    ifs_dtm_free(d);
}

/* --------------------------------------------------------------------------------------------
 * Probability field, limits, generator, nodata, ground cover
 */

TEST(probability_field_sets_map_frequencies)
{
    ifs_dtm *d = generated_dtm(3, 10, 1);
    const double weights[4] = {1, 0, 3, 4};
    ifs_maps *m = d ? maps_of(d, IFS_MODE_BILINEAR, 0.2, NULL, weights) : NULL;
    if (!m) goto done;
    uint64_t count[4] = {0};
    sylva_rng r;
    rng_stream(&r, 3, "test.pick", 0);
    enum { N = 800000 };
    for (int k = 0; k < N; k++) count[ifs_maps_pick(m, rng_next_u64(&r))]++;
    for (int c = 0; c < 4; c++) {
        double p = weights[c] / 8.0, sigma = sqrt(N * p * (1 - p));
        fprintf(stderr, "  cell %d: weight %.0f, picked %llu times (expected %.0f)\n", c, weights[c],
                (unsigned long long)count[c], N * p);
        CHECK(fabs((double)count[c] - N * p) <= 4 * sigma + 1);
    }
    CHECK_INT(count[1], 0);
done:
    ifs_maps_free(m);
    ifs_dtm_free(d);
}

TEST(bad_maps_and_iterations_are_refused)
{
    ifs_dtm *d = generated_dtm(5, 10, 1);
    if (!d) return;
    ifs_maps *m = NULL;
    plugin_err err = {0};
    ifs_maps_params p = {.mode = IFS_MODE_BILINEAR, .alpha = 1.0};
    CHECK(ifs_maps_build(d, &p, &m, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "outside (-1, 1)");
    double field[16];
    for (int k = 0; k < 16; k++) field[k] = 0.2;
    field[5] = -1.0;
    p = (ifs_maps_params){.alpha_field = field};
    CHECK(ifs_maps_build(d, &p, &m, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "cell (1, 1) is -1");
    double zero[16] = {0};
    p = (ifs_maps_params){.alpha = 0.1, .probability = zero};
    CHECK(ifs_maps_build(d, &p, &m, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "every probability weight is 0");
    CHECK(m == NULL);
    m = maps_of(d, IFS_MODE_BILINEAR, 0.1, NULL, NULL);
    float z[4];
    sylva_rng s;
    rng_stream(&s, 1, "x", 0);
    ifs_chaos_job job = {.points = 0, .streams = &s, .rng_u64 = next_u64, .nx = 2, .ny = 2, .threads = 1};
    CHECK(ifs_chaos_grid(m, &job, z, NULL, &err) == SYLVA_ERR_LIMIT);
    CHECK_STR_CONTAINS(err.msg, "runs 1 to 1000000000");
    job.points = IFS_MAX_POINTS + 1;
    CHECK(ifs_chaos_grid(m, &job, z, NULL, &err) == SYLVA_ERR_LIMIT);
    job.points = 10, job.start_u = 1.5;
    CHECK(ifs_chaos_grid(m, &job, z, NULL, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "outside the DTM");
    job.start_u = 0.5, job.start_z = 2 * m->z_bound;
    CHECK(ifs_chaos_grid(m, &job, z, NULL, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "start near the DTM's surface");
    ifs_maps_free(m);
    /* grids too small for an IFS */
    ifs_dtm *tiny = NULL;
    double one = 5;
    CHECK(ifs_dtm_from_rows(&one, 1, 1, 1, 1, &tiny, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "1 x 1 nodes; the IFS needs at least 3 x 3");
    double four[4] = {1, 2, 3, 4};
    CHECK(ifs_dtm_from_rows(four, 2, 2, 1, 1, &tiny, &err) == SYLVA_ERR_PARAM);
    CHECK(ifs_dtm_check_size(70000, 10, &err) == SYLVA_ERR_LIMIT);
    CHECK_STR_CONTAINS(err.msg, "crop it or raise the resampling step");
    CHECK(ifs_dtm_check_size(10000, 10000, &err) == SYLVA_OK); /* sized by memory, not a cap */
    CHECK(tiny == NULL);
    ifs_dtm_free(d);
}

TEST(auto_depth)
{
    ifs_dtm *d = generated_dtm(65, 100, 2);
    ifs_maps *m = d ? maps_of(d, IFS_MODE_BILINEAR, 0.5, NULL, NULL) : NULL;
    if (m) {
        CHECK_INT(ifs_eval_auto_depth(m, 2049, 2049), 14); /* 0.5^14 <= 1e-4 < 0.5^13 */
        ifs_maps_free(m);
    }
    m = d ? maps_of(d, IFS_MODE_BILINEAR, 0.0, NULL, NULL) : NULL;
    if (m) {
        CHECK_INT(ifs_eval_auto_depth(m, 2049, 2049), 2); /* 64 cells, then 4096 >= 2048 */
        CHECK_INT(ifs_eval_auto_depth(m, 65, 65), 1);
        ifs_maps_free(m);
    }
    ifs_dtm_free(d);
}

TEST(generated_dtm_is_seeded)
{
    ifs_dtm *a = generated_dtm(33, 75, 4), *b = generated_dtm(33, 75, 4), *c = generated_dtm(33, 75, 5);
    if (a && b && c) {
        CHECK(memcmp(a->z, b->z, 33 * 33 * sizeof(double)) == 0);
        CHECK(memcmp(a->z, c->z, 33 * 33 * sizeof(double)) != 0);
        double lo, hi;
        ifs_dtm_range(a, &lo, &hi);
        CHECK_NEAR(lo, 0, 1e-12);
        CHECK_NEAR(hi, 75, 1e-9);
        CHECK_NEAR(a->dx, 20, 0);
    }
    ifs_dtm_free(a), ifs_dtm_free(b), ifs_dtm_free(c);
}

TEST(nodata_is_filled_from_neighbours)
{
    /* a plane z = 2x + 3y with a single hole and a 3 x 3 hole */
    double rows[8 * 7];
    for (int j = 0; j < 7; j++)
        for (int i = 0; i < 8; i++) rows[j * 8 + i] = 2.0 * i + 3.0 * j;
    rows[1 * 8 + 1] = NAN;
    for (int j = 3; j < 6; j++)
        for (int i = 4; i < 7; i++) rows[j * 8 + i] = NAN;
    ifs_dtm *d = dtm_of(8, 7, 1, 1, rows);
    if (!d) return;
    uint64_t filled = 0;
    plugin_err err = {0};
    CHECK(ifs_dtm_fill_nodata(d, &filled, &err) == 0);
    CHECK_INT(filled, 10);
    CHECK_NEAR(d->z[1 * 8 + 1], 2.0 + 3.0, 1e-12); /* all 8 neighbours known: symmetric mean */
    CHECK_NEAR(d->z[4 * 8 + 5], 2.0 * 5 + 3.0 * 4, 1e-9); /* the centre of the 3 x 3 hole */
    for (int k = 0; k < 56; k++) CHECK(isfinite(d->z[k]));
    for (int k = 0; k < 56; k++) d->z[k] = NAN;
    CHECK(ifs_dtm_fill_nodata(d, &filled, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "every one of the DTM's 8 x 7 nodes is nodata");
    ifs_dtm_free(d);
}

TEST(ground_cover_rules)
{
    ifs_surface_rules r = {.snow_z = 80, .scree_z = 60, .scree_slope = 30, .rock_slope = 42,
                           .dry_humidity = 0.3};
    CHECK_INT(ifs_surface_class_of(10, 20, 1.0, &r), IFS_SURFACE_GRASS);
    CHECK_INT(ifs_surface_class_of(10, 20, 0.1, &r), IFS_SURFACE_DRY_GRASS);
    CHECK_INT(ifs_surface_class_of(35, 20, 1.0, &r), IFS_SURFACE_SCREE);
    CHECK_INT(ifs_surface_class_of(10, 70, 1.0, &r), IFS_SURFACE_SCREE);
    CHECK_INT(ifs_surface_class_of(50, 90, 1.0, &r), IFS_SURFACE_ROCK);
    CHECK_INT(ifs_surface_class_of(20, 90, 1.0, &r), IFS_SURFACE_SNOW);
    /* a ramp rising 1 m per metre (45 degrees) along x on a grid 1 m apart */
    float z[5 * 3];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 5; i++) z[j * 5 + i] = (float)i;
    CHECK_NEAR(ifs_surface_slope(z, 5, 3, 1, 1, 2, 1), 45.0, 1e-9);
    uint8_t cls[15];
    ifs_surface_classify(z, 5, 3, 1, 1, NULL, &r, cls);
    CHECK_INT(cls[7], IFS_SURFACE_ROCK);
    ifs_surface_classify(z, 5, 3, 4, 4, NULL, &r, cls); /* 14 degrees */
    CHECK_INT(cls[5], IFS_SURFACE_GRASS);
    CHECK_STR_CONTAINS(ifs_surface_class_name(IFS_SURFACE_DRY_GRASS), "dry grass");
}

TEST_LIST(TEST_CASE(affine_matches_hand_computed_coefficients),
          TEST_CASE(bilinear_maps_fix_all_four_corners),
          TEST_CASE(bilinear_surface_passes_through_every_node),
          TEST_CASE(affine_surface_misses_the_unenforced_corner),
          TEST_CASE(alpha_zero_is_bilinear_interpolation),
          TEST_CASE(random_points_lie_on_the_attractor),
          TEST_CASE(roughness_rises_with_alpha),
          TEST_CASE(same_seed_same_heights),
          TEST_CASE(probability_field_sets_map_frequencies),
          TEST_CASE(bad_maps_and_iterations_are_refused),
          TEST_CASE(auto_depth),
          TEST_CASE(generated_dtm_is_seeded),
          TEST_CASE(nodata_is_filled_from_neighbours),
          TEST_CASE(ground_cover_rules))
