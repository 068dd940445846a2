/* ztv_output.c — the driver behind ztv_output.h: checks what the tracer hands over, turns each
 * block's layers into GeoTIFF bands, feeds the map and the summary, and at the end writes the
 * pictures and tables into temporaries and renames every file into place. */
#include "ztv/ztv_output.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "io/atomic_file.h"
#include "ztv/ztv_geotiff.h"
#include "ztv/ztv_layers.h"
#include "ztv/ztv_map.h"
#include "ztv/ztv_qml.h"
#include "ztv/ztv_summary.h"

#define MAX_FILES 48 /* pictures (PNG, its world file and PDF each) and tables: 4 modes, 3 hidden, 4
                     * cumulative, a planting's, 2 summaries, the GeoPackage, its 3 styles and a style
                     * per mode */

struct ztv_output {
    const ztv_info *info;            /* borrowed */
    char dir[ATOMIC_PATH_MAX - 64];
    uint32_t next_row;               /* the first row the next block must start at */
    int failed;                      /* a block or the finish failed: nothing more is taken */
    int finished;
    ztv_geotiff *tif[ZTV_MODES];     /* ztv_MODE.tif per computed mode; owned */
    ztv_geotiff *hidden[ZTV_MODES];  /* ztv_hidden_MODE.tif per screened mode; owned */
    float *bands;                    /* 4 planes of the largest block's cells; owned */
    size_t bands_cells;
    ztv_map *map;                    /* owned */
    ztv_summary *summary;            /* owned */
    atomic_file files[MAX_FILES];    /* pictures and tables written by finish, not yet renamed */
    int n_files;
};

static const char *const mode_bands[4] = {"targets visible", "fraction of the targets visible",
                                          "cell class (0 open, 1 under a crown, 2 in an object)",
                                          "developments visible (bit d: development d)"};
static const char *const hidden_bands[3] = {"targets hidden by the screening",
                                            "fraction of the targets hidden by the screening",
                                            "cell class with screening (0 open, 1 under a crown, 2 in an object)"};

/* 1 when the map writes the files of kind product (a ZTV_PRODUCT_* bit). */
static int wanted(const ztv_info *info, unsigned product)
{
    return !info->products || (info->products & product);
}

static int screened(const ztv_info *info, int m)
{
    return m != ZTV_BARE && info->computed[m] && info->computed[ZTV_BARE];
}

/* The mode a planting's map compares: the screened one (bare earth when only that was traced). */
static int planting_mode(const ztv_info *info)
{
    for (int m = ZTV_MODES - 1; m > ZTV_BARE; m--)
        if (info->computed[m]) return m;
    return ZTV_BARE;
}

static int check_info(const char *dir, const ztv_info *info, err_buf *err)
{
    if (!dir || !*dir) return err_fail(err, ERR_USAGE, "no output folder was named for the visibility map");
    if (!info) return err_fail(err, ERR_INTERNAL, "the visibility map's description is missing");
    const ztv_grid *g = &info->grid;
    if (!g->nx || !g->ny || g->nx > INT32_MAX || g->ny > INT32_MAX)
        return err_fail(err, ERR_LIMIT, "a visibility grid of %u x %u cells; each side must be 1 to %d",
                        g->nx, g->ny, INT32_MAX);
    if (!(g->cell > 0) || !isfinite(g->cell) || !isfinite(g->x0) || !isfinite(g->y0))
        return err_fail(err, ERR_INTERNAL, "the visibility grid's cell (%g m) must be positive and its "
                        "corner finite", g->cell);
    if (!isfinite(info->observer_height) || !isfinite(info->refraction) || !(info->radius > 0))
        return err_fail(err, ERR_INTERNAL, "the visibility map's observer height (%g m) and refraction (%g) "
                        "must be finite and its radius (%g m) positive", info->observer_height,
                        info->refraction, info->radius);
    int any = 0;
    for (int m = 0; m < ZTV_MODES; m++) any |= info->computed[m] != 0;
    if (!any) return err_fail(err, ERR_INTERNAL, "the visibility map computes no mode");
    if (!info->n_targets) return err_fail(err, ERR_INPUT, "a visibility map needs at least one target");
    if (info->n_developments > ZTV_MAX_DEVELOPMENTS)
        return err_fail(err, ERR_LIMIT, "%u developments in one visibility map; at most %u",
                        info->n_developments, ZTV_MAX_DEVELOPMENTS);
    struct stat st;
    if (stat(dir, &st) != 0)
        return err_fail(err, ERR_OUTPUT, "%s: the output folder cannot be used: %s", dir,
                        errno == ENOENT ? "it does not exist (create it first)" : strerror(errno));
    if (!S_ISDIR(st.st_mode)) return err_fail(err, ERR_OUTPUT, "%s: the output folder is not a folder", dir);
    if (strlen(dir) + 64 >= ATOMIC_PATH_MAX - 64) return err_fail(err, ERR_OUTPUT, "%s: the output folder's path is too long", dir);
    return 0;
}

static void file_path(const ztv_output *o, const char *prefix, int m, const char *ext, char *out, size_t n)
{
    snprintf(out, n, "%s/%s%s%s", o->dir, prefix, m >= 0 ? ztv_mode_name((ztv_mode)m) : "", ext);
}

ztv_output *ztv_output_open(const char *dir, const ztv_info *info, err_buf *err)
{
    if (check_info(dir, info, err)) return NULL;
    ztv_output *o = calloc(1, sizeof *o); /* owned by the caller: ztv_output_free */
    if (!o) {
        err_nomem(err, "out of memory for the visibility map's outputs");
        return NULL;
    }
    o->info = info;
    snprintf(o->dir, sizeof o->dir, "%s", dir);
    char path[ATOMIC_PATH_MAX];
    for (int m = 0; m < ZTV_MODES && wanted(info, ZTV_PRODUCT_RASTER); m++) {
        if (!info->computed[m]) continue;
        file_path(o, "ztv_", m, ".tif", path, sizeof path);
        if (!(o->tif[m] = ztv_geotiff_open(path, info, 4, mode_bands, err))) goto fail;
        if (!screened(info, m)) continue;
        file_path(o, "ztv_hidden_", m, ".tif", path, sizeof path);
        if (!(o->hidden[m] = ztv_geotiff_open(path, info, 3, hidden_bands, err))) goto fail;
    }
    if (wanted(info, ZTV_PRODUCT_MAPS) && !(o->map = ztv_map_new(info, err))) goto fail;
    if (wanted(info, ZTV_PRODUCT_SUMMARY) && !(o->summary = ztv_summary_new(info, err))) goto fail;
    return o;
fail:
    ztv_output_free(o);
    return NULL;
}

void ztv_output_free(ztv_output *o)
{
    if (!o) return;
    for (int m = 0; m < ZTV_MODES; m++) {
        ztv_geotiff_free(o->tif[m]);
        ztv_geotiff_free(o->hidden[m]);
    }
    for (int i = 0; i < o->n_files; i++) atomic_file_abort(&o->files[i]);
    free(o->bands);
    ztv_map_free(o->map);
    ztv_summary_free(o->summary);
    free(o);
}

/* --- blocks ----------------------------------------------------------------------------------- */

static int check_block(const ztv_output *o, const ztv_block *b, err_buf *err)
{
    const ztv_info *info = o->info;
    if (!b) return err_fail(err, ERR_INTERNAL, "no block of rows was given");
    if (b->j0 != o->next_row)
        return err_fail(err, ERR_INTERNAL, "blocks of rows must come north to south, each row once: "
                        "the next block starts at row %u, not %u", o->next_row, b->j0);
    if (b->rows == 0 || b->rows > info->grid.ny - b->j0)
        return err_fail(err, ERR_INTERNAL, "a block of %u rows from row %u does not fit the %u rows "
                        "of the grid", b->rows, b->j0, info->grid.ny);
    if (!b->ground) return err_fail(err, ERR_INTERNAL, "the block from row %u has no ground heights", b->j0);
    for (int m = 0; m < ZTV_MODES; m++) {
        const ztv_layer *l = b->layer[m];
        if (!info->computed[m] != !l)
            return err_fail(err, ERR_INTERNAL, "the block from row %u %s %s results, which the map %s",
                            b->j0, l ? "has" : "lacks", ztv_mode_name((ztv_mode)m),
                            l ? "does not compute" : "computes");
        if (l && (!l->visible || !l->fraction || !l->cls || !l->developments))
            return err_fail(err, ERR_INTERNAL, "the block from row %u lacks part of its %s results", b->j0,
                            ztv_mode_name((ztv_mode)m));
        size_t n = (size_t)b->rows * info->grid.nx;
        for (size_t k = 0; l && k < n; k++)
            if (l->cls[k] >= ZTV_CLASSES || !(l->fraction[k] >= 0 && l->fraction[k] <= 1) ||
                l->visible[k] > info->n_targets)
                return err_fail(err, ERR_INTERNAL, "cell (%zu, %zu) of the %s results is not valid: class "
                                "%u, %u targets visible of %u, fraction %g",
                                k % info->grid.nx, b->j0 + k / info->grid.nx, ztv_mode_name((ztv_mode)m),
                                l->cls[k], l->visible[k], info->n_targets, (double)l->fraction[k]);
    }
    return 0;
}

/* The four bands of ztv_MODE.tif for a block's cells (n each). */
static void mode_planes(const ztv_layer *l, size_t n, float *out)
{
    for (size_t k = 0; k < n; k++) {
        int outside = !ztv_class_on_ground(l->cls[k]);
        out[k] = outside ? ZTV_GEOTIFF_NODATA : (float)l->visible[k];
        out[n + k] = outside ? ZTV_GEOTIFF_NODATA : l->fraction[k];
        out[2 * n + k] = outside ? ZTV_GEOTIFF_NODATA : (float)l->cls[k];
        out[3 * n + k] = outside ? ZTV_GEOTIFF_NODATA : (float)l->developments[k];
    }
}

/* The three bands of ztv_hidden_MODE.tif: bare earth minus screened where the cell is a
 * viewpoint in both, nodata elsewhere (band 3 tells why). A target only the screened trace
 * sees (a grazing ray) counts as not hidden. */
static void hidden_planes(const ztv_layer *bare, const ztv_layer *l, size_t n, float *out)
{
    for (size_t k = 0; k < n; k++) {
        int outside = !ztv_class_on_ground(bare->cls[k]) || !ztv_class_on_ground(l->cls[k]);
        int viewpoint = bare->cls[k] == ZTV_OPEN && l->cls[k] == ZTV_OPEN;
        int targets = (int)bare->visible[k] - (int)l->visible[k];
        float fraction = bare->fraction[k] - l->fraction[k];
        out[k] = viewpoint ? (float)(targets > 0 ? targets : 0) : ZTV_GEOTIFF_NODATA;
        out[n + k] = viewpoint ? (fraction > 0 ? fraction : 0) : ZTV_GEOTIFF_NODATA;
        out[2 * n + k] = outside ? ZTV_GEOTIFF_NODATA : (float)l->cls[k];
    }
}

int ztv_output_block(ztv_output *o, const ztv_block *b, err_buf *err)
{
    if (o->failed || o->finished)
        return err_fail(err, ERR_INTERNAL, "the visibility map's outputs take no more blocks (%s)",
                        o->finished ? "finished" : "an earlier step failed");
    if (check_block(o, b, err)) return -1;
    size_t n = (size_t)b->rows * o->info->grid.nx;
    if (n > o->bands_cells) {
        float *grown = realloc(o->bands, 4 * n * sizeof *grown);
        if (!grown) {
            o->failed = 1;
            return err_nomem(err, "out of memory for a block of %u rows of the visibility map", b->rows);
        }
        o->bands = grown, o->bands_cells = n;
    }
    for (int m = 0; m < ZTV_MODES; m++) {
        if (!o->tif[m]) continue;
        mode_planes(b->layer[m], n, o->bands);
        if (ztv_geotiff_rows(o->tif[m], b->j0, b->rows, o->bands, err)) goto fail;
        if (!o->hidden[m]) continue;
        hidden_planes(b->layer[ZTV_BARE], b->layer[m], n, o->bands);
        if (ztv_geotiff_rows(o->hidden[m], b->j0, b->rows, o->bands, err)) goto fail;
    }
    if (o->map) ztv_map_block(o->map, b);
    if (o->summary) ztv_summary_block(o->summary, b);
    o->next_row += b->rows;
    return 0;
fail:
    o->failed = 1;
    return -1;
}

/* --- the end ---------------------------------------------------------------------------------- */

typedef int (*draw_fn)(const ztv_map *, ztv_mode, FILE *png, FILE *pdf, err_buf *);

/* The PNG's world file (ztv_map.h), that a GIS places the page by. */
static int write_world_file(ztv_output *o, const char *prefix, int m, err_buf *err)
{
    char path[ATOMIC_PATH_MAX];
    file_path(o, prefix, m, ".pgw", path, sizeof path);
    FILE *f = atomic_file_open_stream(&o->files[o->n_files], path, err);
    if (!f) return -1;
    o->n_files++;
    double w[6];
    ztv_map_world_file(o->info, w);
    int bad = 0;
    for (int k = 0; k < 6; k++) bad |= fprintf(f, "%.10f\n", w[k]) < 0;
    return bad ? err_fail(err, ERR_OUTPUT, "%s: cannot write the world file", path) : 0;
}

/* Draws one map of mode m and writes it as a PNG with its world file and a PDF into new
 * temporaries, kept for the renaming; the files are named prefix + the mode's name, or prefix alone
 * when named_by_mode is 0. */
static int write_picture(ztv_output *o, draw_fn draw, int m, const char *prefix, int named_by_mode, err_buf *err)
{
    char png[ATOMIC_PATH_MAX], pdf[ATOMIC_PATH_MAX];
    int name = named_by_mode ? m : -1;
    file_path(o, prefix, name, ".png", png, sizeof png);
    file_path(o, prefix, name, ".pdf", pdf, sizeof pdf);
    if (write_world_file(o, prefix, name, err)) return -1;
    FILE *f_png = atomic_file_open_stream(&o->files[o->n_files], png, err);
    if (!f_png) return -1;
    o->n_files++;
    FILE *f_pdf = atomic_file_open_stream(&o->files[o->n_files], pdf, err);
    if (!f_pdf) return -1;
    o->n_files++;
    return draw(o->map, (ztv_mode)m, f_png, f_pdf, err) ? err_prefix(err, "%s: ", png) : 0;
}

typedef int (*table_fn)(const ztv_summary *, FILE *, err_buf *);

static int write_table(ztv_output *o, table_fn write, const char *name, err_buf *err)
{
    char path[ATOMIC_PATH_MAX];
    file_path(o, name, -1, "", path, sizeof path);
    atomic_file *af = &o->files[o->n_files];
    FILE *f = atomic_file_open_stream(af, path, err);
    if (!f) return -1;
    o->n_files++;
    return write(o->summary, f, err) ? err_prefix(err, "%s: ", path) : 0;
}

/* The GeoPackage of the viewpoints, rings and structures (ztv_layers.h). */
static int write_layers(ztv_output *o, err_buf *err)
{
    char path[ATOMIC_PATH_MAX];
    file_path(o, "ztv_layers.gpkg", -1, "", path, sizeof path);
    atomic_file *af = &o->files[o->n_files];
    FILE *f = atomic_file_open_stream(af, path, err);
    if (!f) return -1;
    o->n_files++;
    return ztv_layers_write(o->info, f, err) ? err_prefix(err, "%s: ", path) : 0;
}

/* A QGIS style into a file named prefix + mode (m >= 0) + ".qml". */
static int write_style(ztv_output *o, ztv_qml_style style, const char *prefix, int m, err_buf *err)
{
    char path[ATOMIC_PATH_MAX];
    file_path(o, prefix, m, ".qml", path, sizeof path);
    atomic_file *af = &o->files[o->n_files];
    FILE *f = atomic_file_open_stream(af, path, err);
    if (!f) return -1;
    o->n_files++;
    return fputs(ztv_qml_text(style), f) < 0 ? err_fail(err, ERR_OUTPUT, "%s: cannot write the style", path) : 0;
}

static int write_styles(ztv_output *o, err_buf *err)
{
    if (wanted(o->info, ZTV_PRODUCT_LAYERS) &&
        (write_layers(o, err) || write_style(o, ZTV_QML_VIEWPOINTS, "ztv_viewpoints", -1, err) ||
         write_style(o, ZTV_QML_RINGS, "ztv_distance_rings", -1, err) ||
         write_style(o, ZTV_QML_DEVELOPMENTS, "ztv_developments", -1, err)))
        return -1;
    for (int m = 0; m < ZTV_MODES && wanted(o->info, ZTV_PRODUCT_RASTER); m++)
        if (o->info->computed[m] && write_style(o, ZTV_QML_VISIBILITY, "ztv_", m, err)) return -1;
    return 0;
}

int ztv_output_finish(ztv_output *o, err_buf *err)
{
    if (o->failed || o->finished)
        return err_fail(err, ERR_INTERNAL, "the visibility map's outputs cannot be finished (%s)",
                        o->finished ? "already finished" : "an earlier step failed");
    const ztv_info *info = o->info;
    if (o->next_row != info->grid.ny)
        return err_fail(err, ERR_INTERNAL, "the visibility map's outputs were given %u of the grid's "
                        "%u rows", o->next_row, info->grid.ny);
    o->failed = 1; /* until every file is in place */
    for (int m = 0; m < ZTV_MODES; m++) {
        if (o->tif[m] && ztv_geotiff_finish(o->tif[m], err)) return -1;
        if (o->hidden[m] && ztv_geotiff_finish(o->hidden[m], err)) return -1;
    }
    for (int m = 0; m < ZTV_MODES && o->map; m++) {
        if (!info->computed[m]) continue;
        if (write_picture(o, ztv_map_write_mode, m, "ztv_", 1, err)) return -1;
        if (screened(info, m) && write_picture(o, ztv_map_write_hidden, m, "ztv_hidden_", 1, err)) return -1;
        if (info->n_developments > 1 && write_picture(o, ztv_map_write_cumulative, m, "ztv_cumulative_", 1, err))
            return -1;
    }
    if (o->map && info->planting_before && write_picture(o, ztv_map_write_planting, planting_mode(info),
                                               "ztv_hidden_by_planting", 0, err))
        return -1;
    if (o->summary && (write_table(o, ztv_summary_write_csv, "ztv_summary.csv", err) ||
                       write_table(o, ztv_summary_write_json, "ztv_summary.json", err)))
        return -1;
    if (write_styles(o, err)) return -1;
    /* everything is written: rename it all into place */
    for (int m = 0; m < ZTV_MODES; m++) {
        if (o->tif[m] && ztv_geotiff_commit(o->tif[m], err)) return -1;
        if (o->hidden[m] && ztv_geotiff_commit(o->hidden[m], err)) return -1;
    }
    for (int i = 0; i < o->n_files; i++)
        if (atomic_file_commit(&o->files[i], err)) return -1;
    o->n_files = 0;
    o->failed = 0;
    o->finished = 1;
    return 0;
}
