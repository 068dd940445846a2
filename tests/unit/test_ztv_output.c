/* test_ztv_output.c — the visibility map's files from hand-made blocks of rows: the GeoTIFFs
 * read back through GDAL with the grid's geotransform, the CRS, the band values and nodata; the
 * summary's areas are the exact counts of the hand-made pattern and add up to the grid; the
 * maps are PNGs of the documented size whose legend shows the band colours, whose structures are
 * dots at their places and whose world files place a viewpoint on its pixel; an unfinished
 * output leaves nothing; a planted link is replaced, not written through; blocks out of order
 * or incomplete are refused.
 *
 * The pattern (20 x 15 cells of 10 m, 4 targets, developments T1 and T2): column 0 is not
 * computed; on bare earth (i - 1) % 5 targets are visible from column i; with vegetation row 7
 * stands under crowns, rows 0-3 see as on bare earth, rows 4-6 half (rounded down) and rows
 * 8-14 nothing. T1 is seen where one target or more is, T2 where three or more are. */
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include "harness.h"
#include "io/image_io.h"
#include "work_dir.h"
#include "ztv/ztv_map.h"
#include "ztv/ztv_output.h"
#include "ztv/ztv_summary.h"

#define NX 20
#define NY 15
#define CELLS (NX * NY)

static const char *const names[2] = {"T1", "T2"};
static const double dev_xy[2][2] = {{60, 100}, {150, 40}};
static const double target_xy[4][2] = {{55, 100}, {65, 100}, {145, 40}, {155, 40}};
static const uint32_t target_dev[4] = {0, 0, 1, 1};

typedef struct pattern {
    float ground[CELLS];
    uint16_t visible[2][CELLS];
    float fraction[2][CELLS];
    uint8_t cls[2][CELLS];
    uint32_t dev[2][CELLS];
    ztv_layer layer[2];
    char *wkt; /* CPLFree */
    ztv_info info;
} pattern;

static uint32_t dev_bits(int visible) { return (visible >= 1 ? 1u : 0u) | (visible >= 3 ? 2u : 0u); }

static void make_pattern(pattern *p)
{
    memset(p, 0, sizeof *p);
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            int k = j * NX + i;
            int bare = i == 0 ? 0 : (i - 1) % 5;
            int veg = j < 4 ? bare : j < 7 ? bare / 2 : 0;
            p->ground[k] = i == 0 ? NAN : (float)(100 + 2 * i + (j % 3));
            p->cls[0][k] = i == 0 ? ZTV_OUTSIDE : ZTV_OPEN;
            p->cls[1][k] = i == 0 ? ZTV_OUTSIDE : j == 7 ? ZTV_UNDER_CROWN : ZTV_OPEN;
            if (p->cls[0][k] == ZTV_OPEN) p->visible[0][k] = (uint16_t)bare;
            if (p->cls[1][k] == ZTV_OPEN) p->visible[1][k] = (uint16_t)veg;
            for (int m = 0; m < 2; m++) {
                p->fraction[m][k] = p->visible[m][k] / 4.0f;
                p->dev[m][k] = dev_bits(p->visible[m][k]);
            }
        }
    OGRSpatialReferenceH srs = OSRNewSpatialReference(NULL);
    OSRImportFromEPSG(srs, 32632);
    OSRExportToWkt(srs, &p->wkt);
    OSRDestroySpatialReference(srs);
    ztv_info *in = &p->info;
    in->grid = (ztv_grid){NX, NY, 5, 145, 10};
    in->crs_wkt = p->wkt;
    in->crs_name = "WGS 84 / UTM zone 32N";
    in->origin[0] = 500000, in->origin[1] = 4000000, in->origin[2] = 100;
    in->computed[ZTV_BARE] = in->computed[ZTV_VEGETATION] = 1;
    in->observer_height = 2;
    in->radius = 5000;
    in->curvature = 1;
    in->refraction = 0.13;
    in->n_targets = 4;
    in->n_developments = 2;
    in->development_names = names;
    in->development_xy = dev_xy;
    in->target_xy = target_xy;
    in->target_development = target_dev;
}

static void free_pattern(pattern *p) { CPLFree(p->wkt); }

/* The block of rows [j0, j0 + rows) of the pattern. */
static ztv_block block_of(pattern *p, uint32_t j0, uint32_t rows)
{
    ztv_block b = {.j0 = j0, .rows = rows, .ground = p->ground + j0 * NX};
    for (int m = 0; m < 2; m++) {
        size_t at = (size_t)j0 * NX;
        p->layer[m] = (ztv_layer){p->visible[m] + at, p->fraction[m] + at, p->cls[m] + at, p->dev[m] + at};
        b.layer[m] = &p->layer[m];
    }
    return b;
}

/* A new empty folder in the work folder. */
static const char *fresh_dir(const char *name)
{
    static char path[1200];
    snprintf(path, sizeof path, "%s", work_path(name));
    mkdir(path, 0700);
    return path;
}


/* Runs the whole pattern in blocks of `rows` rows (the last one shorter) into dir; 0 on
 * success. */
static int write_in_blocks(pattern *p, const char *dir, uint32_t rows, err_buf *err)
{
    ztv_output *o = ztv_output_open(dir, &p->info, err);
    if (!o) return -1;
    int rc = 0;
    for (uint32_t j0 = 0; !rc && j0 < NY; j0 += rows) {
        ztv_block b = block_of(p, j0, j0 + rows <= NY ? rows : NY - j0);
        rc = ztv_output_block(o, &b, err);
    }
    if (!rc) rc = ztv_output_finish(o, err);
    ztv_output_free(o);
    return rc;
}

/* In blocks of 4, 4, 4 and 3 rows. */
static int write_all(pattern *p, const char *dir, err_buf *err) { return write_in_blocks(p, dir, 4, err); }

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *text = calloc(1, 1 << 16);
    if (text) fread(text, 1, (1 << 16) - 1, f);
    fclose(f);
    return text;
}

static float pixel(GDALDatasetH ds, int band, int i, int j)
{
    float v = -99;
    if (GDALRasterIO(GDALGetRasterBand(ds, band), GF_Read, i, j, 1, 1, &v, 1, 1, GDT_Float32, 0, 0) != CE_None)
        return -99;
    return v;
}

TEST(geotiff_reads_back)
{
    pattern p;
    make_pattern(&p);
    const char *dir = fresh_dir("geotiff");
    err_buf err = {{0}};
    CHECK_INT(write_all(&p, dir, &err), 0);
    if (err.msg[0]) fprintf(stderr, "%s\n", err.msg);
    char path[1300];
    snprintf(path, sizeof path, "%s/ztv_bare.tif", dir);
    GDALAllRegister();
    GDALDatasetH ds = GDALOpen(path, GA_ReadOnly);
    CHECK(ds != NULL);
    if (!ds) return free_pattern(&p);
    CHECK_INT(GDALGetRasterXSize(ds), NX);
    CHECK_INT(GDALGetRasterYSize(ds), NY);
    CHECK_INT(GDALGetRasterCount(ds), 4);
    double t[6];
    CHECK(GDALGetGeoTransform(ds, t) == CE_None);
    CHECK_NEAR(t[0], 500000, 1e-9);
    CHECK_NEAR(t[1], 10, 1e-12);
    CHECK_NEAR(t[2], 0, 0);
    CHECK_NEAR(t[3], 4000150, 1e-9);
    CHECK_NEAR(t[4], 0, 0);
    CHECK_NEAR(t[5], -10, 1e-12);
    OGRSpatialReferenceH want = OSRNewSpatialReference(p.wkt);
    OGRSpatialReferenceH got = GDALGetSpatialRef(ds);
    CHECK(got && OSRIsSame(got, want));
    OSRDestroySpatialReference(want);
    for (int band = 1; band <= 4; band++) {
        int has = 0;
        CHECK_NEAR(GDALGetRasterNoDataValue(GDALGetRasterBand(ds, band), &has), -1, 0);
        CHECK(has);
        CHECK(GDALGetRasterDataType(GDALGetRasterBand(ds, band)) == GDT_Float32);
        CHECK(strlen(GDALGetDescription(GDALGetRasterBand(ds, band))) > 5);
        CHECK_NEAR(pixel(ds, band, 0, 3), -1, 0); /* column 0: not computed */
    }
    CHECK_NEAR(pixel(ds, 1, 9, 4), 3, 0); /* (9 - 1) % 5 targets */
    CHECK_NEAR(pixel(ds, 2, 9, 4), 0.75, 0);
    CHECK_NEAR(pixel(ds, 3, 9, 4), ZTV_OPEN, 0);
    CHECK_NEAR(pixel(ds, 4, 9, 4), 3, 0); /* T1 and T2 */
    CHECK_NEAR(pixel(ds, 1, 6, 14), 0, 0);
    CHECK_NEAR(pixel(ds, 4, 7, 14), 1, 0); /* one target: T1 only */
    GDALClose(ds);
    /* the screened mode, and what its screening hides */
    snprintf(path, sizeof path, "%s/ztv_vegetation.tif", dir);
    ds = GDALOpen(path, GA_ReadOnly);
    CHECK(ds != NULL);
    if (ds) {
        CHECK_NEAR(pixel(ds, 3, 9, 7), ZTV_UNDER_CROWN, 0);
        CHECK_NEAR(pixel(ds, 1, 9, 5), 1, 0);
        GDALClose(ds);
    }
    snprintf(path, sizeof path, "%s/ztv_hidden_vegetation.tif", dir);
    ds = GDALOpen(path, GA_ReadOnly);
    CHECK(ds != NULL);
    if (ds) {
        CHECK_INT(GDALGetRasterCount(ds), 3);
        CHECK_NEAR(pixel(ds, 1, 9, 5), 2, 0);     /* 3 on bare earth, 1 with vegetation */
        CHECK_NEAR(pixel(ds, 2, 9, 5), 0.5, 0);
        CHECK_NEAR(pixel(ds, 1, 9, 10), 3, 0);    /* all hidden */
        CHECK_NEAR(pixel(ds, 1, 9, 2), 0, 0);     /* nothing hidden */
        CHECK_NEAR(pixel(ds, 1, 9, 7), -1, 0);    /* under a crown: no viewpoint */
        CHECK_NEAR(pixel(ds, 3, 9, 7), ZTV_UNDER_CROWN, 0);
        CHECK_NEAR(pixel(ds, 3, 0, 7), -1, 0);
        GDALClose(ds);
    }
    free_pattern(&p);
}

/* The area rows of one mode in the CSV, summed: every cell of the grid is in exactly one. */
static double csv_sum(const char *csv, const char *mode)
{
    double sum = 0;
    char pattern_text[64];
    for (const char *line = csv; line && *line; line = strchr(line, '\n'), line = line ? line + 1 : NULL) {
        const char *quantities[] = {"area_visible_", "area_under_crown,", "area_in_object,", "area_not_computed,"};
        for (int q = 0; q < 4; q++) {
            if (strncmp(line, quantities[q], strlen(quantities[q]))) continue;
            snprintf(pattern_text, sizeof pattern_text, ",%s,,", mode);
            const char *at = strstr(line, pattern_text);
            const char *end = strchr(line, '\n');
            if (at && (!end || at < end)) sum += atof(at + strlen(pattern_text));
        }
    }
    return sum;
}

TEST(summary_areas)
{
    pattern p;
    make_pattern(&p);
    const char *dir = fresh_dir("summary");
    err_buf err = {{0}};
    CHECK_INT(write_all(&p, dir, &err), 0);
    char path[1300];
    snprintf(path, sizeof path, "%s/ztv_summary.csv", dir);
    char *csv = read_text(path);
    CHECK(csv != NULL);
    if (!csv) return free_pattern(&p);
    CHECK_STR_CONTAINS(csv, "quantity,mode,development,value,unit\n");
    CHECK_STR_CONTAINS(csv, "\ncrs,,,\"WGS 84 / UTM zone 32N\",\n");
    CHECK_STR_CONTAINS(csv, "\nobserver_height,,,2,");
    CHECK_STR_CONTAINS(csv, "\nradius,,,5000,m\n");
    CHECK_STR_CONTAINS(csv, "\nrefraction_k,,,0.13,\n");
    CHECK_STR_CONTAINS(csv, "\ntargets,,,4,\n");
    /* bare earth: 4 of 19 columns each see 0, 1, 2, 3 targets, 3 columns all 4; 100 m2 a cell */
    CHECK_STR_CONTAINS(csv, "\narea_visible_0,bare,,0.006,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_visible_1_25,bare,,0.006,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_visible_25_50,bare,,0.006,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_visible_50_75,bare,,0.006,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_visible_75_100,bare,,0,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_visible_100,bare,,0.0045,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_not_computed,bare,,0.0015,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_development_visible,bare,\"T1\",0.0225,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_development_visible,bare,\"T2\",0.0105,km2\n");
    /* vegetation: 173, 40, 25, 16, 0, 12 cells by band, 19 under crowns */
    CHECK_STR_CONTAINS(csv, "\narea_visible_0,vegetation,,0.0173,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_visible_1_25,vegetation,,0.004,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_visible_25_50,vegetation,,0.0025,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_visible_50_75,vegetation,,0.0016,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_visible_100,vegetation,,0.0012,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_under_crown,vegetation,,0.0019,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_development_visible,vegetation,\"T1\",0.0093,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_development_visible,vegetation,\"T2\",0.0028,km2\n");
    /* what the screening hides of the 225 cells that see something on bare earth */
    CHECK_STR_CONTAINS(csv, "\narea_hidden_by_screening,vegetation,,0.0117,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_partly_hidden_by_screening,vegetation,,0.0033,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_still_visible_with_screening,vegetation,,0.006,km2\n");
    CHECK_STR_CONTAINS(csv, "\narea_bare_visible_not_a_viewpoint,vegetation,,0.0015,km2\n");
    CHECK_NEAR(csv_sum(csv, "bare"), 0.03, 1e-12);
    CHECK_NEAR(csv_sum(csv, "vegetation"), 0.03, 1e-12);
    free(csv);
    snprintf(path, sizeof path, "%s/ztv_summary.json", dir);
    char *json = read_text(path);
    CHECK(json != NULL);
    if (json) {
        const char *veg = strstr(json, "\"vegetation\": {");
        CHECK(veg != NULL);
        CHECK_STR_CONTAINS(json, "\"100%\": {\"cells\": 45, \"km2\": 0.0045}");
        CHECK_STR_CONTAINS(veg, "\"0%\": {\"cells\": 173, \"km2\": 0.0173}");
        CHECK_STR_CONTAINS(veg, "\"under_crown\": {\"cells\": 19, \"km2\": 0.0019}");
        CHECK_STR_CONTAINS(json, "\"hidden\": {\"cells\": 117, \"km2\": 0.0117}");
        CHECK_STR_CONTAINS(json, "\"crs\": \"WGS 84 / UTM zone 32N\"");
        CHECK_STR_CONTAINS(json, "\"radius_m\": 5000,");
        CHECK_STR_CONTAINS(json, "\"developments\": [\"T1\", \"T2\"]");
        CHECK_STR_CONTAINS(json, "\"T2\": {\"cells\": 28, \"km2\": 0.0028}");
        CHECK_STR_CONTAINS(json, "\"grid\": {\"columns\": 20, \"rows\": 15, \"cell_m\": 10, \"west_edge\": 500000, "
                                 "\"north_edge\": 4000150}");
        free(json);
    }
    free_pattern(&p);
}

/* Reads a PNG's pixel (x, y) as 8-bit RGB. */
static void png_rgb(const image_f32 *img, uint32_t x, uint32_t y, int rgb[3])
{
    const float *px = img->pixels + ((size_t)y * img->width + x) * img->channels;
    for (int c = 0; c < 3; c++) rgb[c] = (int)lroundf(px[c] * 255);
}

/* Whether some pixel with x >= x_from is rgb (each channel within 1). */
static int has_colour(const image_f32 *img, uint32_t x_from, const int want[3])
{
    for (uint32_t y = 0; y < img->height; y++)
        for (uint32_t x = x_from; x < img->width; x++) {
            int rgb[3];
            png_rgb(img, x, y, rgb);
            if (abs(rgb[0] - want[0]) <= 1 && abs(rgb[1] - want[1]) <= 1 && abs(rgb[2] - want[2]) <= 1)
                return 1;
        }
    return 0;
}

/* The page pixel of local point (gx, gy) on a map of info (ztv_map.h's layout, ZTV_MAP_DPI). */
static void page_px(const ztv_info *info, double gx, double gy, uint32_t *x, uint32_t *y)
{
    ztv_map_layout l = ztv_map_layout_of(info);
    double k = ZTV_MAP_DPI / 25.4;
    *x = (uint32_t)floor((l.x + (gx - l.west) * l.mm_per_m) * k);
    *y = (uint32_t)floor((l.y + (l.north - gy) * l.mm_per_m) * k);
}

/* The page pixel of cell (i, j)'s centre. */
static void cell_px(const ztv_info *info, int i, int j, uint32_t *x, uint32_t *y)
{
    page_px(info, info->grid.x0 + i * info->grid.cell, info->grid.y0 - j * info->grid.cell, x, y);
}

TEST(maps)
{
    pattern p;
    make_pattern(&p);
    static const ztv_viewpoint vp[1] = {{.name = "hill", .number = 1, .xy = {105, 75}}};
    static const ztv_structure st[2] = {{.name = "K1", .development = "T1", .xy = {55, 100}},
                                        {.name = "K2", .development = "T2", .xy = {155, 40}}};
    p.info.study_views = vp, p.info.n_study_views = 1;
    p.info.structures = st, p.info.n_structures = 2;
    const char *dir = fresh_dir("maps");
    err_buf err = {{0}};
    CHECK_INT(write_all(&p, dir, &err), 0);
    const char *names_png[] = {"ztv_bare.png", "ztv_vegetation.png", "ztv_hidden_vegetation.png",
                               "ztv_cumulative_bare.png", "ztv_cumulative_vegetation.png"};
    ztv_map_layout l = ztv_map_layout_of(&p.info);
    uint32_t panel_x = (uint32_t)((l.x + l.w + 10) * ZTV_MAP_DPI / 25.4);
    for (size_t i = 0; i < sizeof names_png / sizeof names_png[0]; i++) {
        char path[1300];
        snprintf(path, sizeof path, "%s/%s", dir, names_png[i]);
        image_f32 img = {0};
        CHECK_INT(image_read(path, &img, &err), 0);
        /* A3 landscape at 150 dpi */
        CHECK_INT(img.width, 2480);
        CHECK_INT(img.height, 1754);
        snprintf(path + strlen(path) - 3, 4, "pdf");
        CHECK(access(path, R_OK) == 0);
        int rgb[3];
        uint32_t x, y;
        if (img.pixels) { /* the viewpoint: a red dot beside its number, at its place */
            page_px(&p.info, vp[0].xy[0], vp[0].xy[1], &x, &y);
            png_rgb(&img, x - (uint32_t)(1.3 * ZTV_MAP_DPI / 25.4), y, rgb);
            CHECK(abs(rgb[0] - 204) <= 2 && abs(rgb[1] - 13) <= 2 && abs(rgb[2] - 13) <= 2);
            for (int k = 0; k < 2; k++) { /* each structure: a dark dot at its place */
                page_px(&p.info, st[k].xy[0], st[k].xy[1], &x, &y);
                png_rgb(&img, x, y, rgb);
                CHECK(rgb[0] < 50 && rgb[1] < 50 && rgb[2] < 50);
            }
            /* the world file beside the PNG puts the viewpoint on its pixel */
            char pgw[1300];
            snprintf(pgw, sizeof pgw, "%s/%.*spgw", dir, (int)strlen(names_png[i]) - 3, names_png[i]);
            FILE *f = fopen(pgw, "r");
            double w[6] = {0};
            int got = 0;
            while (f && got < 6 && fscanf(f, "%lf", &w[got]) == 1) got++;
            if (f) fclose(f);
            CHECK_INT(got, 6);
            CHECK(w[1] == 0 && w[2] == 0 && w[3] == -w[0] && w[0] > 0);
            if (got == 6 && w[0] > 0) {
                double col = (p.info.origin[0] + vp[0].xy[0] - w[4]) / w[0];
                double row = (p.info.origin[1] + vp[0].xy[1] - w[5]) / w[3];
                page_px(&p.info, vp[0].xy[0], vp[0].xy[1], &x, &y);
                CHECK_NEAR(col + 0.5, x + 0.5, 1.0);
                CHECK_NEAR(row + 0.5, y + 0.5, 1.0);
            }
        }
        if (i == 0 && img.pixels) {
            /* the legend's swatches: 100 % (120, 0, 50) and 1-25 % (255, 230, 80) at opacity 0.65
             * over level ground's grey 207 */
            CHECK(has_colour(&img, panel_x, (const int[3]){150, 72, 105}));
            CHECK(has_colour(&img, panel_x, (const int[3]){238, 222, 124}));
            /* the map: cell (5, 1) sees every target, cell (1, 1) none, column 0 is not computed */
            cell_px(&p.info, 5, 1, &x, &y);
            png_rgb(&img, x, y, rgb);
            CHECK(rgb[0] > rgb[1] + 50);
            cell_px(&p.info, 1, 1, &x, &y);
            png_rgb(&img, x, y, rgb);
            CHECK(abs(rgb[0] - rgb[1]) < 4 && abs(rgb[1] - rgb[2]) < 4);
            cell_px(&p.info, 0, 3, &x, &y);
            png_rgb(&img, x, y, rgb);
            CHECK_INT(rgb[0], 242);
        }
        if (i == 2 && img.pixels) {
            /* fully hidden (25, 80, 200), partly hidden (110, 190, 240) */
            CHECK(has_colour(&img, panel_x, (const int[3]){89, 124, 202}));
            cell_px(&p.info, 9, 10, &x, &y);
            png_rgb(&img, x, y, rgb); /* all hidden */
            CHECK(rgb[2] > rgb[0] + 60);
        }
        image_free(&img);
    }
    free_pattern(&p);
}

/* The bare-earth map of info's whole grid given as one block (layer, ground), written into a
 * fresh folder `name` and read back into img. */
static void write_bare_map(const ztv_info *info, ztv_layer *layer, float *ground, const char *name, image_f32 *img)
{
    const char *dir = fresh_dir(name);
    err_buf err = {{0}};
    ztv_output *o = ztv_output_open(dir, info, &err);
    CHECK(o != NULL);
    ztv_block b = {.j0 = 0, .rows = info->grid.ny, .ground = ground, .layer = {layer, NULL, NULL}};
    CHECK_INT(o ? ztv_output_block(o, &b, &err) : -1, 0);
    CHECK_INT(o ? ztv_output_finish(o, &err) : -1, 0);
    ztv_output_free(o);
    char path[1300];
    snprintf(path, sizeof path, "%s/ztv_bare.png", dir);
    CHECK_INT(image_read(path, img, &err), 0);
}

/* The darkest red channel among the pixels within 3 of (x, y). */
static int darkest_near(const image_f32 *img, uint32_t x, uint32_t y)
{
    int least = 255;
    for (uint32_t v = y - 3; v <= y + 3; v++)
        for (uint32_t u = x - 3; u <= x + 3; u++) {
            int rgb[3];
            png_rgb(img, u, v, rgb);
            if (rgb[0] < least) least = rgb[0];
        }
    return least;
}

/* A 5 x 5 km map of one target in the middle, radius 2 km, whose terrain ends 1.5 km east of the
 * target: the 1 km ring at 1 km, the radius at 2 km, "no terrain" past the edge. */
TEST(map_rings_and_no_terrain)
{
    enum { N = 100 };
    size_t n = (size_t)N * N;
    uint8_t *cls = malloc(n);                                           /* each freed at the end */
    uint16_t *visible = calloc(n, sizeof *visible);
    uint32_t *devs = calloc(n, sizeof *devs);
    float *ground = calloc(n, sizeof *ground), *fraction = calloc(n, sizeof *fraction);
    for (size_t k = 0; k < n; k++) {
        int past = (int)(k % N) * 50 + 25 > 4000; /* x past 4000 m */
        visible[k] = !past, fraction[k] = (float)!past, devs[k] = !past;
        cls[k] = past ? ZTV_NO_TERRAIN : ZTV_OPEN;
        ground[k] = past ? NAN : 0;
    }
    static const double xy[1][2] = {{2500, 2500}};
    static const uint32_t tdev[1] = {0};
    ztv_info info = {.grid = {N, N, 25, 4975, 50}, .computed = {1, 0, 0}, .observer_height = 2, .radius = 2000,
                     .n_targets = 1, .n_developments = 1, .development_xy = xy, .target_xy = xy,
                     .target_development = tdev};
    ztv_layer layer = {visible, fraction, cls, devs};
    image_f32 img = {0};
    write_bare_map(&info, &layer, ground, "rings", &img);
    uint32_t x, y;
    for (int dir_k = 0; img.pixels && dir_k < 2; dir_k++) { /* north and south of the target */
        double sign = dir_k ? -1 : 1;
        page_px(&info, 2500, 2500 + sign * 1000, &x, &y);
        CHECK(darkest_near(&img, x, y) < 110); /* the 1 km ring */
        page_px(&info, 2500, 2500 + sign * 2000, &x, &y);
        CHECK(darkest_near(&img, x, y) < 110); /* the radius */
        page_px(&info, 2500 - 300, 2500 + sign * 1500, &x, &y);
        CHECK(darkest_near(&img, x, y) > 120); /* between them: the map's colour */
    }
    if (img.pixels) { /* past the DTM: no terrain's colour, and the words in white there */
        int rgb[3];
        page_px(&info, 4800, 300, &x, &y);
        png_rgb(&img, x, y, rgb);
        CHECK(abs(rgb[0] - 60) <= 1 && abs(rgb[1] - 70) <= 1 && abs(rgb[2] - 90) <= 1);
        uint32_t x0, y0, x1, y1, white = 0;
        page_px(&info, 4000, 5000, &x0, &y0);
        page_px(&info, 5000, 0, &x1, &y1);
        for (uint32_t v = y0 + 2; v < y1 - 2; v++)
            for (uint32_t u = x0 + 4; u < x1 - 8; u++) {
                png_rgb(&img, u, v, rgb);
                white += rgb[0] > 240 && rgb[1] > 240 && rgb[2] > 240;
            }
        CHECK(white > 20);
    }
    image_free(&img);
    free(ground), free(fraction), free(visible), free(cls), free(devs);
}

/* Whole file contents; *size set. NULL when unreadable. */
static unsigned char *read_bytes(const char *path, long *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    *size = ftell(f);
    rewind(f);
    unsigned char *bytes = malloc((size_t)*size + 1);
    if (bytes && fread(bytes, 1, (size_t)*size, f) != (size_t)*size) {
        free(bytes);
        bytes = NULL;
    }
    fclose(f);
    return bytes;
}

/* The same map handed over in blocks of 1, 4 or 15 rows (as different thread counts make
 * them) gives the same bytes in every file. */
TEST(same_bytes_whatever_the_blocks)
{
    pattern p;
    make_pattern(&p);
    const char *files[] = {"ztv_bare.tif", "ztv_vegetation.tif", "ztv_hidden_vegetation.tif", "ztv_bare.png",
                           "ztv_hidden_vegetation.png", "ztv_cumulative_vegetation.png", "ztv_summary.csv",
                           "ztv_summary.json"};
    const uint32_t rows[3] = {4, 1, 15};
    char dirs[3][1200];
    err_buf err = {{0}};
    for (int r = 0; r < 3; r++) {
        char name[32];
        snprintf(name, sizeof name, "blocks-%u", rows[r]);
        snprintf(dirs[r], sizeof dirs[r], "%s", fresh_dir(name));
        CHECK_INT(write_in_blocks(&p, dirs[r], rows[r], &err), 0);
    }
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        char path[1300];
        long size0 = 0, size = 0;
        snprintf(path, sizeof path, "%s/%s", dirs[0], files[i]);
        unsigned char *first = read_bytes(path, &size0);
        CHECK(first != NULL);
        for (int r = 1; r < 3 && first; r++) {
            snprintf(path, sizeof path, "%s/%s", dirs[r], files[i]);
            unsigned char *other = read_bytes(path, &size);
            CHECK(other && size == size0 && !memcmp(first, other, (size_t)size));
            if (!(other && size == size0 && !memcmp(first, other, (size_t)size)))
                fprintf(stderr, "%s differs with blocks of %u rows\n", files[i], rows[r]);
            free(other);
        }
        free(first);
    }
    free_pattern(&p);
}

TEST(unfinished_leaves_nothing)
{
    pattern p;
    make_pattern(&p);
    const char *dir = fresh_dir("unfinished");
    err_buf err = {{0}};
    ztv_output *o = ztv_output_open(dir, &p.info, &err);
    CHECK(o != NULL);
    ztv_block b = block_of(&p, 0, 4);
    CHECK_INT(ztv_output_block(o, &b, &err), 0);
    CHECK(work_dir_entries(dir) > 0); /* the GeoTIFFs' temporaries */
    /* finishing with rows missing is refused, and still nothing is in place */
    CHECK_INT(ztv_output_finish(o, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "4 of the grid's 15 rows");
    char path[1300];
    snprintf(path, sizeof path, "%s/ztv_bare.tif", dir);
    CHECK_INT(access(path, F_OK), -1);
    ztv_output_free(o);
    CHECK_INT(work_dir_entries(dir), 0);
    free_pattern(&p);
}

/* SIGTERM while the tracer is between blocks: the process ends by the signal and the GeoTIFFs'
 * temporaries are gone. */
TEST(signal_leaves_nothing)
{
    const char *dir = fresh_dir("signal");
    int ready[2];
    CHECK_INT(pipe(ready), 0);
    pid_t child = fork();
    CHECK(child >= 0);
    if (child == 0) {
        pattern p;
        make_pattern(&p);
        err_buf err;
        ztv_output *o = ztv_output_open(dir, &p.info, &err);
        if (!o) _exit(3);
        ztv_block b = block_of(&p, 0, 4);
        if (ztv_output_block(o, &b, &err)) _exit(4);
        if (write(ready[1], "x", 1) != 1) _exit(5);
        for (;;) pause();
    }
    char c;
    CHECK_INT(read(ready[0], &c, 1), 1);
    CHECK_INT(work_dir_entries(dir), 3); /* two modes' GeoTIFFs and the hidden one */
    kill(child, SIGTERM);
    int status = 0;
    waitpid(child, &status, 0);
    CHECK(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
    CHECK_INT(work_dir_entries(dir), 0);
    close(ready[0]);
    close(ready[1]);
}

TEST(planted_link_not_followed)
{
    pattern p;
    make_pattern(&p);
    const char *dir = fresh_dir("link");
    char victim[1300], link_path[1300];
    snprintf(victim, sizeof victim, "%s", work_file("victim.txt", "keep me\n"));
    const char *targets[] = {"ztv_bare.tif", "ztv_bare.png", "ztv_summary.csv"};
    for (int i = 0; i < 3; i++) {
        snprintf(link_path, sizeof link_path, "%s/%s", dir, targets[i]);
        CHECK_INT(symlink(victim, link_path), 0);
    }
    err_buf err = {{0}};
    CHECK_INT(write_all(&p, dir, &err), 0);
    char *text = read_text(victim);
    CHECK(text && !strcmp(text, "keep me\n"));
    free(text);
    for (int i = 0; i < 3; i++) {
        snprintf(link_path, sizeof link_path, "%s/%s", dir, targets[i]);
        struct stat st;
        CHECK(lstat(link_path, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 100);
    }
    free_pattern(&p);
}

TEST(blocks_out_of_order)
{
    pattern p;
    make_pattern(&p);
    const char *dir = fresh_dir("order");
    err_buf err = {{0}};
    ztv_output *o = ztv_output_open(dir, &p.info, &err);
    CHECK(o != NULL);
    ztv_block b = block_of(&p, 4, 4);
    CHECK_INT(ztv_output_block(o, &b, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "north to south, each row once: the next block starts at row 0, not 4");
    b = block_of(&p, 0, 4);
    err = (err_buf){{0}};
    CHECK_INT(ztv_output_block(o, &b, &err), 0);
    CHECK_INT(ztv_output_block(o, &b, &err), -1); /* the same rows again */
    CHECK_STR_CONTAINS(err.msg, "the next block starts at row 4, not 0");
    b = block_of(&p, 4, 12); /* past the grid's last row */
    CHECK_INT(ztv_output_block(o, &b, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "does not fit the 15 rows");
    b = block_of(&p, 4, 4);
    b.layer[ZTV_VEGETATION] = NULL; /* a computed mode missing */
    CHECK_INT(ztv_output_block(o, &b, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "lacks vegetation results");
    b = block_of(&p, 4, 4);
    p.cls[0][4 * NX + 3] = 7; /* not a class */
    CHECK_INT(ztv_output_block(o, &b, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "cell (3, 4) of the bare results is not valid");
    ztv_output_free(o);
    CHECK_INT(work_dir_entries(dir), 0);
    free_pattern(&p);
}

TEST(bad_folder_and_info)
{
    pattern p;
    make_pattern(&p);
    err_buf err = {{0}};
    CHECK(ztv_output_open(work_path("no-such-folder"), &p.info, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "it does not exist");
    p.info.grid.cell = 0;
    CHECK(ztv_output_open(fresh_dir("bad"), &p.info, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "must be positive");
    p.info.grid.cell = 10;
    p.info.n_developments = 25;
    CHECK(ztv_output_open(fresh_dir("bad"), &p.info, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "at most 24");
    p.info.n_developments = 2;
    p.info.observer_height = NAN; /* would make the JSON summary invalid */
    CHECK(ztv_output_open(fresh_dir("bad"), &p.info, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "must be finite");
    CHECK_INT(work_dir_entries(fresh_dir("bad")), 0);
    free_pattern(&p);
}

TEST(band_boundaries)
{
    CHECK_INT(ztv_band_of(0.0f), ZTV_BAND_NONE);
    CHECK_INT(ztv_band_of(1e-6f), ZTV_BAND_1_25);
    CHECK_INT(ztv_band_of(0.25f), ZTV_BAND_1_25);
    CHECK_INT(ztv_band_of(nextafterf(0.25f, 1)), ZTV_BAND_25_50);
    CHECK_INT(ztv_band_of(0.5f), ZTV_BAND_25_50);
    CHECK_INT(ztv_band_of(0.75f), ZTV_BAND_50_75);
    CHECK_INT(ztv_band_of(nextafterf(1.0f, 0)), ZTV_BAND_75_100);
    CHECK_INT(ztv_band_of(1.0f), ZTV_BAND_ALL);
    CHECK_INT(ztv_band_of(NAN), ZTV_BAND_NONE);
}

/* A scene in local metres over the whole of a long grid (3,300 x 40 cells of 25 m) with five
 * developments, bare earth only: one target of development d stands in every fifth column
 * band; the map is drawn one cell in 3 x 3, the cumulative map counts developments. */
TEST(local_long_grid_many_developments)
{
    enum { W = 3300, H = 40 };
    size_t n = (size_t)W * H;
    float *ground = malloc(n * sizeof *ground), *fraction = malloc(n * sizeof *fraction);
    uint16_t *visible = malloc(n * sizeof *visible);
    uint8_t *cls = calloc(n, 1);
    uint32_t *devs = malloc(n * sizeof *devs);
    const char *dev_names[5] = {"A", "B", "C", "D", "E"};
    double xy[5][2], txy[5][2];
    uint32_t tdev[5];
    for (int d = 0; d < 5; d++) xy[d][0] = txy[d][0] = 25.0 * (660 * d + 330), xy[d][1] = txy[d][1] = -500, tdev[d] = (uint32_t)d;
    for (size_t k = 0; k < n; k++) {
        int i = (int)(k % W);
        int seen = 1 + i / 660; /* 1 to 5 developments, westmost first */
        ground[k] = (float)(50 * sin(i * 0.01));
        visible[k] = (uint16_t)seen;
        fraction[k] = seen / 5.0f;
        devs[k] = (1u << seen) - 1;
    }
    ztv_info info = {.grid = {W, H, 12.5, -12.5, 25}, .computed = {1, 0, 0}, .observer_height = 1.5,
                     .radius = INFINITY, .n_targets = 5, .n_developments = 5, .development_names = dev_names,
                     .development_xy = (const double (*)[2])xy, .target_xy = (const double (*)[2])txy,
                     .target_development = tdev};
    const char *dir = fresh_dir("long");
    err_buf err = {{0}};
    ztv_output *o = ztv_output_open(dir, &info, &err);
    CHECK(o != NULL);
    for (uint32_t j0 = 0; o && j0 < H; j0 += 7) {
        uint32_t rows = j0 + 7 <= H ? 7 : H - j0;
        size_t at = (size_t)j0 * W;
        ztv_layer l = {visible + at, fraction + at, cls + at, devs + at};
        ztv_block b = {.j0 = j0, .rows = rows, .ground = ground + at, .layer = {&l, NULL, NULL}};
        CHECK_INT(ztv_output_block(o, &b, &err), 0);
    }
    CHECK_INT(ztv_output_finish(o, &err), 0);
    ztv_output_free(o);
    char path[1300];
    snprintf(path, sizeof path, "%s/ztv_bare.tif", dir);
    GDALAllRegister();
    GDALDatasetH ds = GDALOpen(path, GA_ReadOnly);
    CHECK(ds != NULL);
    if (ds) {
        CHECK(GDALGetSpatialRef(ds) == NULL); /* local metres: no CRS */
        double t[6];
        CHECK(GDALGetGeoTransform(ds, t) == CE_None);
        CHECK_NEAR(t[0], 0, 0);
        CHECK_NEAR(t[3], 0, 0);
        CHECK_NEAR(pixel(ds, 4, 3299, 39), 31, 0); /* all five */
        CHECK_NEAR(pixel(ds, 2, 700, 20), 0.4f, 0);
        GDALClose(ds);
    }
    snprintf(path, sizeof path, "%s/ztv_summary.json", dir);
    char *json = read_text(path);
    CHECK_STR_CONTAINS(json, "\"crs\": null");
    CHECK_STR_CONTAINS(json, "\"radius_m\": null");
    CHECK_STR_CONTAINS(json, "\"earth_curvature\": false");
    CHECK_STR_CONTAINS(json, "\"100%\": {\"cells\": 26400, \"km2\": 16.5}"); /* 660 columns of 40 */
    CHECK_STR_CONTAINS(json, "\"E\": {\"cells\": 26400, \"km2\": 16.5}");
    CHECK(json && !strstr(json, "\"screening\": {\n"));
    free(json);
    /* one cell in 3 x 3: 1,100 x 14 map pixels on an A3 page at 150 dpi */
    const char *maps[2] = {"ztv_bare.png", "ztv_cumulative_bare.png"};
    ztv_map_layout lay = ztv_map_layout_of(&info);
    uint32_t panel_x = (uint32_t)((lay.x + lay.w + 10) * ZTV_MAP_DPI / 25.4);
    for (int i = 0; i < 2; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, maps[i]);
        image_f32 img = {0};
        CHECK_INT(image_read(path, &img, &err), 0);
        CHECK_INT(img.width, 2480);
        /* the cumulative legend counts developments: 5 in dark red (205, 35, 35) over grey */
        if (i == 1 && img.pixels) CHECK(has_colour(&img, panel_x, (const int[3]){206, 95, 95}));
        image_free(&img);
    }
    snprintf(path, sizeof path, "%s/ztv_hidden_bare.png", dir);
    CHECK_INT(access(path, F_OK), -1);
    free(ground), free(fraction), free(visible), free(cls), free(devs);
}

/* A grid drawn one cell in 3 x 3 shows the cell nearest each pixel's centre: on a 3,300 x 600 grid
 * of level ground where only every third column from column 1 sees everything, every map pixel
 * is the 100 % colour. */
TEST(reduced_map_takes_the_nearest_cell)
{
    enum { W = 3300, H = 600 };
    size_t n = (size_t)W * H;
    float *ground = calloc(n, sizeof *ground), *fraction = malloc(n * sizeof *fraction);
    uint16_t *visible = malloc(n * sizeof *visible);
    uint8_t *cls = calloc(n, 1);
    uint32_t *devs = malloc(n * sizeof *devs);
    for (size_t k = 0; k < n; k++) {
        int seen = k % W % 3 == 1;
        visible[k] = (uint16_t)seen, fraction[k] = (float)seen, devs[k] = (uint32_t)seen;
    }
    double xy[1][2] = {{-1e6, 0}}; /* off the map: no marker over the pixels looked at */
    uint32_t tdev[1] = {0};
    ztv_info info = {.grid = {W, H, 0.5, H - 0.5, 1}, .computed = {1, 0, 0}, .observer_height = 2,
                     .radius = INFINITY, .n_targets = 1, .n_developments = 1,
                     .development_xy = (const double (*)[2])xy, .target_xy = (const double (*)[2])xy,
                     .target_development = tdev};
    ztv_layer layer = {visible, fraction, cls, devs};
    image_f32 img = {0};
    write_bare_map(&info, &layer, ground, "nearest", &img);
    /* every map pixel samples a seen cell (the cell nearest its centre: 3 u + 1), so the whole row
     * across the map's middle is the 100 % colour */
    for (double gx = 20; img.pixels && gx < W - 20; gx += 37) {
        int rgb[3];
        uint32_t x, y;
        page_px(&info, gx, H / 2.0, &x, &y);
        png_rgb(&img, x, y, rgb);
        CHECK(abs(rgb[0] - 150) <= 1 && abs(rgb[1] - 72) <= 1 && abs(rgb[2] - 105) <= 1);
    }
    image_free(&img);
    free(ground), free(fraction), free(visible), free(cls), free(devs);
}

TEST_LIST(TEST_CASE(band_boundaries), TEST_CASE(reduced_map_takes_the_nearest_cell), TEST_CASE(local_long_grid_many_developments),
          TEST_CASE(geotiff_reads_back), TEST_CASE(summary_areas), TEST_CASE(maps), TEST_CASE(map_rings_and_no_terrain),
          TEST_CASE(same_bytes_whatever_the_blocks), TEST_CASE(unfinished_leaves_nothing), TEST_CASE(signal_leaves_nothing), TEST_CASE(planted_link_not_followed),
          TEST_CASE(blocks_out_of_order), TEST_CASE(bad_folder_and_info))
