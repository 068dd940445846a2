/* ztv_canopy_compare.c — a ZTV screened by the canopy surface (`sylva ztv`, screening canopy)
 * against gdal_viewshed run on the surface model (terrain + canopy) from the same masts and
 * against exact sightlines, cell by cell, by what stands on the cell; prints the figures.
 *
 *   ztv_canopy_compare CANOPY.tif BARE.tif CHM.tif DTM.tif DSM.tif EYE H MASTS.txt GDAL_1.tif ...
 *
 * CANOPY.tif and BARE.tif are sylva's maps of the canopy mode and of bare earth (band 3 the cell
 * class, band 4 the developments seen, one bit each). MASTS.txt holds a line "E N C" per mast (map
 * coordinates of its cell's centre and the CHM there, canopy_ground.c); mast t is development t,
 * alone, H metres above the ground, and GDAL_t.tif is gdal_viewshed run from it over DSM.tif with
 * -oz H - C in its output mode GROUND: each cell's least target height above the surface model
 * from which the mast is in sight. CHM.tif, DTM.tif and DSM.tif are on the maps' grid.
 *
 * gdal_viewshed's usual run, -tz EYE, puts the observer EYE above the surface model: on the
 * treetops in a wood, and on the low vegetation elsewhere (an open cell's CHM, up to OPEN_BELOW,
 * is in the DSM), where sylva's eye stands EYE above the ground. From the least heights the tool
 * takes gdal's answer for sylva's eye, EYE less the cell's canopy above the surface model, on every
 * cell but woodland; there it keeps the treetop observer (-tz EYE), which sylva's screening has
 * none of. The usual run's agreement on the open cells is printed beside. Checks, failing (exit 1)
 * when one does not hold:
 *  - woodland (CHM above EYE): every cell is no viewpoint in sylva's canopy map (class 1, under the
 *    canopy), and no other cell is; gdal_viewshed, on the treetops, sees the masts from many of
 *    them (printed: why a surface model's viewshed is no screening analysis);
 *  - open cells (CHM below OPEN_BELOW, or no data: taken as no canopy): sylva's canopy map and
 *    gdal_viewshed agree on at least AGREEMENT_MIN of the (cell, mast) pairs, and on
 *    NEAR_AGREEMENT_MIN of them but for pairs within one cell of a visibility edge of either map:
 *    gdal_viewshed interpolates each cell's horizon from two cells nearer the observer (Wang et al.
 *    2000), which lowers a crown a cell or two across and smears the edges of its shadow;
 *  - exact sightlines (sightline_exact.h) over the surface model, from the eye above the DTM, on
 *    the open cells of every EXACT_STEP-th row and column: sylva agrees on EXACT_MIN of the pairs
 *    (gdal_viewshed's agreement with them is printed);
 *  - the canopy screens: on the open cells it hides at least HIDDEN_MIN of the pairs that bare
 *    earth sees, so that the agreement is not that of an unscreened map.
 * Low vegetation (CHM from OPEN_BELOW to EYE), where the usual run's eye stands the CHM higher, is
 * printed.
 * Exit 2 on bad usage or an unreadable file. */
#include <gdal.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "sightline_exact.h"
#include "ztv/ztv_raster.h"
#include "ztv_band.h"

#define TOOL "ztv_canopy_compare"
#define OPEN_BELOW 0.5          /* metres of canopy below which a cell is open ground */
#define AGREEMENT_MIN 0.96      /* share of the open cells' pairs on which the two agree */
#define NEAR_AGREEMENT_MIN 0.99 /* the same, a difference within one cell of an edge counted agreeing */
#define EXACT_MIN 0.995         /* share of the sampled open cells' pairs on which sylva and exact sightlines agree */
#define EXACT_STEP 3            /* exact sightlines on every EXACT_STEP-th row and column */
#define HIDDEN_MIN 0.05         /* share of the open cells' pairs bare earth sees that the canopy hides */
#define MAX_MASTS 24

enum { OPEN_DATA, OPEN_NO_DATA, LOW, WOOD, KINDS };
static const char *const kind_name[KINDS] = {"open (CHM < 0.5 m)", "open (no data)", "low (0.5 m to eye)",
                                             "woodland (CHM > eye)"};

typedef struct tally {
    long pairs, agree, near, sylva, gdal, bare; /* pairs; agreeing; agreeing or along an edge; seen by
                                                 * sylva's canopy map, gdal, sylva's bare map */
    long usual;                                 /* agreeing with gdal's usual run, -tz EYE */
} tally;

typedef struct maps {
    int nx, ny;
    const float *seen, *bare, *chm, *dtm, *dsm;
    raster chm_r;
    double eye, h;
} maps;

static int kind_of(const maps *m, size_t k)
{
    float h = m->chm[k];
    if (!isfinite(h) || h < -1e30f || (m->chm_r.has_nodata && h == (float)m->chm_r.nodata)) return OPEN_NO_DATA;
    return h < OPEN_BELOW ? OPEN_DATA : h <= m->eye ? LOW : WOOD;
}

static int same_grid(const raster *a, const raster *b, const char *what)
{
    for (int k = 0; k < 6; k++)
        if (a->nx != b->nx || a->ny != b->ny || fabs(a->gt[k] - b->gt[k]) > 1e-6 * fabs(b->gt[1])) {
            printf("FAIL: %s is not on the canopy map's grid\n", what);
            return 0;
        }
    return 1;
}

static double share(long a, long b) { return b ? (double)a / (double)b : 0.0; }

static int seen_by(const float *map, size_t k, int t) { return (uint32_t)map[k] >> t & 1u; }

/* The canopy the surface model holds at cell k: the CHM, no data and heights below 0 taken as 0
 * (canopy_ground.c). */
static double dsm_canopy(const maps *m, size_t k)
{
    double h = m->chm[k];
    return kind_of(m, k) == OPEN_NO_DATA || h < 0 ? 0.0 : h;
}

/* 1 when gdal's least heights g see the mast from cell k: sylva's eye, EYE above the ground, but
 * in woodland the usual run's, EYE above the treetops; with usual, the usual run's everywhere. */
static int gdal_sees(const maps *m, const float *g, size_t k, int usual)
{
    int treetop = usual || kind_of(m, k) == WOOD;
    return g[k] <= m->eye - (treetop ? 0.0 : dsm_canopy(m, k));
}

/* The cell classes of sylva's canopy map against the CHM: under the canopy exactly where it
 * stands above the eye (a thousandth of a metre either way is float rounding). */
static int classes_hold(const maps *m, const float *cls)
{
    long wrong = 0, under = 0, n = (long)m->nx * m->ny;
    for (long k = 0; k < n; k++) {
        int wood = kind_of(m, k) == WOOD, near = fabs(m->chm[k] - m->eye) < 1e-3;
        under += cls[k] == (float)ZTV_UNDER_CROWN;
        wrong += !near && (cls[k] == (float)ZTV_UNDER_CROWN) != wood;
        wrong += cls[k] != (float)ZTV_UNDER_CROWN && cls[k] != (float)ZTV_OPEN;
    }
    printf("cells under the canopy (no viewpoint): %ld of %ld; class against the CHM wrong on %ld\n", under, n, wrong);
    if (wrong) printf("FAIL: %ld cells are under the canopy where the CHM is below the eye, or the other way\n", wrong);
    return !wrong;
}

/* 1 when a cell within one of (i, j) has the other visibility of mast t than (i, j) in gdal's map g
 * or in sylva's. */
static int near_edge(const maps *m, const float *g, int t, int i, int j)
{
    size_t k = (size_t)j * m->nx + i;
    for (int dj = -1; dj <= 1; dj++)
        for (int di = -1; di <= 1; di++) {
            int ii = i + di, jj = j + dj;
            if (ii < 0 || jj < 0 || ii >= m->nx || jj >= m->ny) continue;
            size_t q = (size_t)jj * m->nx + ii;
            if (gdal_sees(m, g, q, 0) != gdal_sees(m, g, k, 0) || seen_by(m->seen, q, t) != seen_by(m->seen, k, t))
                return 1;
        }
    return 0;
}

/* Mast t's pairs against gdal's map g, by kind of cell. */
static void tally_mast(const maps *m, const float *g, int t, tally *by_kind)
{
    for (int j = 0; j < m->ny; j++)
        for (int i = 0; i < m->nx; i++) {
            size_t k = (size_t)j * m->nx + i;
            tally *c = &by_kind[kind_of(m, k)];
            int s = seen_by(m->seen, k, t), v = gdal_sees(m, g, k, 0);
            c->pairs++, c->agree += s == v, c->usual += s == gdal_sees(m, g, k, 1);
            c->sylva += s, c->gdal += v, c->bare += seen_by(m->bare, k, t);
            c->near += s == v || near_edge(m, g, t, i, j);
        }
}

/* Exact sightlines from the eyes of the sampled open cells to mast t at cell (ti, tj), against
 * sylva's map and gdal's g: pairs, sylva's agreements and gdal's into e[0..2]. */
static void exact_mast(const maps *m, const float *g, int t, int ti, int tj, long e[3])
{
    const double dx = m->chm_r.gt[1], dy = -m->chm_r.gt[5];
    dtm surface = {m->nx, m->ny, dx, dy, m->dsm};
    size_t tk = (size_t)tj * m->nx + ti;
    double target[3] = {ti * dx, (m->ny - 1 - tj) * dy, m->dtm[tk] + m->h};
    for (int j = 0; j < m->ny; j += EXACT_STEP)
        for (int i = 0; i < m->nx; i += EXACT_STEP) {
            size_t k = (size_t)j * m->nx + i;
            if (kind_of(m, k) > OPEN_NO_DATA) continue;
            double eye[3] = {i * dx, (m->ny - 1 - j) * dy, m->dtm[k] + m->eye};
            int clear = sightline_clear(&surface, eye, target, 0.0);
            e[0]++, e[1] += clear == seen_by(m->seen, k, t), e[2] += clear == gdal_sees(m, g, k, 0);
        }
}

static void print_tally(const char *name, const tally *t)
{
    printf("%-22s %8ld pairs  agree %7.3f %% (%7.3f %% but within a cell of an edge)  visible: sylva canopy %5.1f %%, "
           "gdal on the DSM %5.1f %%, sylva bare %5.1f %%\n", name, t->pairs, 100 * share(t->agree, t->pairs),
           100 * share(t->near, t->pairs), 100 * share(t->sylva, t->pairs), 100 * share(t->gdal, t->pairs),
           100 * share(t->bare, t->pairs));
}

/* The checks on the open cells' figures (eye: the eyes' height); prints them and the failures. */
static int open_checks(const tally *t, const long exact[3], double eye)
{
    tally o = {0};
    for (int k = OPEN_DATA; k <= OPEN_NO_DATA; k++)
        o.pairs += t[k].pairs, o.agree += t[k].agree, o.near += t[k].near, o.sylva += t[k].sylva,
        o.gdal += t[k].gdal, o.bare += t[k].bare, o.usual += t[k].usual;
    print_tally("all open cells", &o);
    printf("gdal_viewshed's usual run (-tz %.1f: its eye on the open cells' low vegetation) agrees on %.3f %% of "
           "them\n", eye, 100 * share(o.usual, o.pairs));
    printf("exact sightlines on %ld open pairs (a cell in %d x %d): sylva agrees on %.3f %%, gdal_viewshed on "
           "%.3f %%\n", exact[0], EXACT_STEP, EXACT_STEP, 100 * share(exact[1], exact[0]),
           100 * share(exact[2], exact[0]));
    printf("the canopy hides %.1f %% of what bare earth sees from the open cells\n",
           100 * share(o.bare - o.sylva, o.bare));
    int ok = 1;
    if (share(o.agree, o.pairs) < AGREEMENT_MIN || share(o.near, o.pairs) < NEAR_AGREEMENT_MIN)
        printf("FAIL: over the open cells sylva and gdal_viewshed agree on %.3f %% of the pairs (%.3f %% but along "
               "edges), below %.0f %% (%.0f %%)\n", 100 * share(o.agree, o.pairs), 100 * share(o.near, o.pairs),
               100 * AGREEMENT_MIN, 100 * NEAR_AGREEMENT_MIN), ok = 0;
    if (share(exact[1], exact[0]) < EXACT_MIN)
        printf("FAIL: sylva agrees with exact sightlines on %.3f %% of the open pairs, below %.1f %%\n",
               100 * share(exact[1], exact[0]), 100 * EXACT_MIN), ok = 0;
    if (share(o.bare - o.sylva, o.bare) < HIDDEN_MIN)
        printf("FAIL: the canopy hides less than %.0f %% of what bare earth sees from the open cells\n",
               100 * HIDDEN_MIN), ok = 0;
    return ok;
}

/* The masts' cells from MASTS.txt into ij; their count, or -1. */
static int read_masts(const char *path, const raster *r, int ij[MAX_MASTS][2])
{
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    int n = 0;
    double e, north, c;
    while (n < MAX_MASTS && fscanf(f, "%lf %lf %lf", &e, &north, &c) == 3) {
        ij[n][0] = (int)floor((e - r->gt[0]) / r->gt[1]), ij[n][1] = (int)floor((north - r->gt[3]) / r->gt[5]);
        n++;
    }
    fclose(f);
    return n;
}

int main(int argc, char **argv)
{
    if (argc < 10) {
        fprintf(stderr, "usage: %s CANOPY.tif BARE.tif CHM.tif DTM.tif DSM.tif EYE H MASTS.txt GDAL_1.tif ...\n", TOOL);
        return 2;
    }
    GDALAllRegister();
    raster zr, br, dr, sr;
    maps m = {.eye = atof(argv[6]), .h = atof(argv[7])};
    float *cls = read_band(TOOL, argv[1], 3, &zr), *seen = read_band(TOOL, argv[1], 4, &zr);
    float *bare = read_band(TOOL, argv[2], 4, &br), *chm = read_band(TOOL, argv[3], 1, &m.chm_r);
    float *dtm_z = read_band(TOOL, argv[4], 1, &dr), *dsm_z = read_band(TOOL, argv[5], 1, &sr);
    int ij[MAX_MASTS][2], n_masts = read_masts(argv[8], &zr, ij);
    if (!cls || !seen || !bare || !chm || !dtm_z || !dsm_z || n_masts != argc - 9 || !(m.eye > 0)) return 2;
    m.nx = zr.nx, m.ny = zr.ny, m.seen = seen, m.bare = bare, m.chm = chm, m.dtm = dtm_z, m.dsm = dsm_z;
    int ok = same_grid(&br, &zr, argv[2]) && same_grid(&m.chm_r, &zr, argv[3]) && same_grid(&dr, &zr, argv[4]) &&
             same_grid(&sr, &zr, argv[5]) && classes_hold(&m, cls);
    tally t[KINDS] = {{0}};
    long exact[3] = {0, 0, 0};
    for (int k = 0; ok && k < n_masts; k++) {
        raster gr;
        float *g = read_band(TOOL, argv[9 + k], 1, &gr);
        if (!g) return 2;
        if ((ok = same_grid(&gr, &zr, argv[9 + k]))) tally_mast(&m, g, k, t), exact_mast(&m, g, k, ij[k][0], ij[k][1], exact);
        free(g);
    }
    for (int k = 0; ok && k < KINDS; k++) print_tally(kind_name[k], &t[k]);
    ok = ok && open_checks(t, exact, m.eye);
    free(cls), free(seen), free(bare), free(chm), free(dtm_z), free(dsm_z);
    return ok ? 0 : 1;
}
