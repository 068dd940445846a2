/* test_ifs_dtm_file.c — DTM input through GDAL: a GeoTIFF written with GDAL's API and ESRI ASCII
 * grids written as text by the test itself, nodata, a degree grid, crop and step, a humidity
 * map, bad files; and, when the shared data (SYLVA_SHARED_DATA_DIR) has dem/, every DEM there loads
 * or gives a clear error (skipped otherwise). */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include <fcntl.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include "dtm_file.h"
#include "harness.h"
#include "humidity_map.h"
#include "sylva/plugin.h"

#define OUT_DIR SYLVA_TEST_OUT_DIR

static const char *out_path(const char *name)
{
    static char path[4][512];
    static int slot;
    mkdir(OUT_DIR, 0755);
    char *p = path[slot++ % 4];
    snprintf(p, 512, "%s/%s", OUT_DIR, name);
    return p;
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

static const ifs_dtm_file_options defaults = {.band = 1, .step = 1};

/* A 5 x 4 Float32 GeoTIFF in UTM 33N, 30 m pixels, north-up, heights 10 * file row + column,
 * with nodata -9999 at file row 1, column 2. */
static void write_geotiff(const char *path, int epsg, double x0, double y0, double px)
{
    GDALAllRegister();
    GDALDriverH drv = GDALGetDriverByName("GTiff");
    CHECK(drv != NULL);
    if (!drv) return;
    GDALDatasetH ds = GDALCreate(drv, path, 5, 4, 1, GDT_Float32, NULL);
    CHECK(ds != NULL);
    if (!ds) return;
    double gt[6] = {x0, px, 0, y0, 0, -px};
    GDALSetGeoTransform(ds, gt);
    OGRSpatialReferenceH srs = OSRNewSpatialReference(NULL);
    OSRImportFromEPSG(srs, epsg);
    OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
    GDALSetSpatialRef(ds, srs);
    OSRDestroySpatialReference(srs);
    GDALRasterBandH b = GDALGetRasterBand(ds, 1);
    GDALSetRasterNoDataValue(b, -9999);
    float v[20];
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 5; c++) v[r * 5 + c] = (float)(10 * r + c);
    v[1 * 5 + 2] = -9999;
    CHECK(GDALRasterIO(b, GF_Write, 0, 0, 5, 4, v, 5, 4, GDT_Float32, 0, 0) == CE_None);
    GDALClose(ds);
}

TEST(geotiff_projected)
{
    const char *path = out_path("utm.tif");
    write_geotiff(path, 32633, 500000, 5000000, 30);
    ifs_dtm *d = NULL;
    ifs_dtm_file_info info;
    plugin_err err = {0};
    CHECK(ifs_dtm_read_file(path, &defaults, &d, &info, &err) == 0);
    if (!d) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    CHECK_INT(d->nx, 5);
    CHECK_INT(d->ny, 4);
    CHECK_NEAR(d->dx, 30, 1e-12);
    CHECK_NEAR(d->dy, 30, 1e-12);
    CHECK_STR_CONTAINS(info.driver, "GTiff");
    CHECK_STR_CONTAINS(info.type_name, "Float32");
    CHECK_INT(info.degrees, 0);
    CHECK_INT(info.units_guessed, 0);
    /* DTM row 0 is the south edge: the file's last row */
    CHECK_NEAR(d->z[0], 30, 0);
    CHECK_NEAR(d->z[4], 34, 0);
    CHECK_NEAR(d->z[3 * 5 + 0], 0, 0);
    /* the nodata node (file row 1 = DTM row 2, column 2) is filled from its 8 neighbours,
     * which lie on the plane 10 row + column: the mean is 12 */
    CHECK_INT(info.nodata_filled, 1);
    CHECK_NEAR(d->z[2 * 5 + 2], 12, 1e-9);
    ifs_dtm_free(d);
}

TEST(geotiff_geographic_in_degrees)
{
    const char *path = out_path("wgs84.tif");
    write_geotiff(path, 4326, 10.0, 46.0, 1.0 / 1200); /* 3 arc-second pixels near 46 N */
    ifs_dtm *d = NULL;
    ifs_dtm_file_info info;
    plugin_err err = {0};
    CHECK(ifs_dtm_read_file(path, &defaults, &d, &info, &err) == 0);
    if (!d) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    CHECK_INT(info.degrees, 1);
    CHECK_INT(info.units_guessed, 0);
    /* centre latitude 46 - 2 pixels; WGS 84 radii of curvature there, by hand */
    double phi = (46.0 - 2.0 / 1200) * M_PI / 180, a = 6378137, f = 1 / 298.257223563;
    double e2 = f * (2 - f), w = sqrt(1 - e2 * sin(phi) * sin(phi));
    double dx = a / w * cos(phi) * (M_PI / 180) / 1200;
    double dy = a * (1 - e2) / (w * w * w) * (M_PI / 180) / 1200;
    CHECK_NEAR(info.centre_lat, 46.0 - 2.0 / 1200, 1e-12);
    CHECK_NEAR(d->dx, dx, 1e-9);
    CHECK_NEAR(d->dy, dy, 1e-9);
    fprintf(stderr, "  3\" grid at %.4f N: %.4f m x %.4f m between nodes\n", info.centre_lat, d->dx, d->dy);
    CHECK(d->dx > 64.5 && d->dx < 64.6); /* 1/1200 degree of longitude at 46 N */
    CHECK(d->dy > 92.6 && d->dy < 92.7);
    ifs_dtm_free(d);
}

/* ESRI ASCII grid: a 6 x 4 grid, nodata -9999, values 100 * row + column in file order. */
static const char *ascii_grid =
    "ncols 6\nnrows 4\nxllcorner 1000\nyllcorner 2000\ncellsize 5\nNODATA_value -9999\n"
    "0 1 2 3 4 5\n"
    "100 101 -9999 -9999 104 105\n"
    "200 201 -9999 -9999 204 205\n"
    "300 301 302 303 304 305\n";

TEST(ascii_grid_with_nodata)
{
    const char *path = out_path("grid.asc");
    write_text(path, ascii_grid);
    ifs_dtm *d = NULL;
    ifs_dtm_file_info info;
    plugin_err err = {0};
    CHECK(ifs_dtm_read_file(path, &defaults, &d, &info, &err) == 0);
    if (!d) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    CHECK_STR_CONTAINS(info.driver, "AAIGrid");
    CHECK_INT(d->nx, 6);
    CHECK_INT(d->ny, 4);
    CHECK_NEAR(d->dx, 5, 0);
    CHECK_INT(info.units_guessed, 1);
    CHECK_INT(info.degrees, 0); /* cell size 5 is not a degree grid */
    CHECK_NEAR(d->z[0], 300, 0);  /* south-west: the file's last row */
    CHECK_NEAR(d->z[3 * 6 + 5], 5, 0);
    CHECK_INT(info.nodata_filled, 4);
    for (int k = 0; k < 24; k++) CHECK(isfinite(d->z[k]) && d->z[k] >= 0 && d->z[k] <= 305);
    /* The 2 x 2 hole is one ring, so each node takes its known neighbours only. DTM node (2, 1)
     * is file row 2, column 2: 201 west and 302 south (weight 1), 101, 301 and 303 diagonal. */
    double w = M_SQRT1_2;
    double z21 = (201 + 302 + w * (101 + 301 + 303)) / (2 + 3 * w);
    CHECK_NEAR(d->z[1 * 6 + 2], z21, 1e-9);
    ifs_dtm_free(d);
}

TEST(ascii_grid_crop_and_step)
{
    /* 9 x 7, value 100 * file row + column */
    char text[4096];
    int n = snprintf(text, sizeof text, "NCOLS 9\nNROWS 7\nXLLCORNER 0\nYLLCORNER 0\nCELLSIZE 2\n");
    for (int r = 0; r < 7; r++) {
        for (int c = 0; c < 9; c++) n += snprintf(text + n, sizeof text - n, "%d ", 100 * r + c);
        n += snprintf(text + n, sizeof text - n, "\n");
    }
    const char *path = out_path("crop.asc");
    write_text(path, text);
    ifs_dtm_file_options o = {.band = 1, .step = 2, .has_crop = 1, .crop = {2, 1, 6, 6}};
    ifs_dtm *d = NULL;
    ifs_dtm_file_info info;
    plugin_err err = {0};
    CHECK(ifs_dtm_read_file(path, &o, &d, &info, &err) == 0);
    if (!d) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    /* columns 2, 4, 6 (the window's 6 columns trimmed to 5 so the step ends on a node) and
     * file rows 1, 3, 5; DTM row 0 is file row 5 */
    CHECK_INT(d->nx, 3);
    CHECK_INT(d->ny, 3);
    CHECK_NEAR(d->dx, 4, 0);
    CHECK_INT(info.window[2], 5);
    CHECK_INT(info.window[3], 5);
    const double want[9] = {502, 504, 506, 302, 304, 306, 102, 104, 106};
    for (int k = 0; k < 9; k++) CHECK_NEAR(d->z[k], want[k], 0);
    ifs_dtm_free(d);
    o.crop[2] = 10;
    CHECK(ifs_dtm_read_file(path, &o, &d, &info, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "does not lie inside");
    CHECK_STR_CONTAINS(err.msg, "9 columns and 7 rows");
    o = (ifs_dtm_file_options){.band = 1, .step = 4};
    CHECK(ifs_dtm_read_file(path, &o, &d, &info, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "3 x 2 nodes; the IFS needs at least 3 x 3");
    o = (ifs_dtm_file_options){.band = 2, .step = 1};
    CHECK(ifs_dtm_read_file(path, &o, &d, &info, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "band 2 does not exist");
    CHECK(d == NULL);
}

/* An ASCII grid with no coordinate system and a cell of 3 arc seconds near Boulder, Colorado
 * is read as degrees; units: metres overrides that; cell_size replaces the spacing. */
TEST(ascii_degree_grid)
{
    char text[4096];
    int n = snprintf(text, sizeof text, "ncols 4\nnrows 3\nxllcorner -105.5\nyllcorner 40.0\n"
                     "cellsize 0.000833333333\nNODATA_value 0\n");
    for (int r = 0; r < 3; r++) n += snprintf(text + n, sizeof text - n, "2000 2010 2020 2030\n");
    const char *path = out_path("degrees.asc");
    write_text(path, text);
    ifs_dtm *d = NULL;
    ifs_dtm_file_info info;
    plugin_err err = {0};
    CHECK(ifs_dtm_read_file(path, &defaults, &d, &info, &err) == 0);
    if (!d) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    CHECK_INT(info.degrees, 1);
    CHECK_INT(info.units_guessed, 1);
    CHECK_NEAR(info.centre_lat, 40.0 + 1.5 * 0.000833333333, 1e-9);
    double per_lon, per_lat;
    ifs_metres_per_degree(40.0, &per_lon, &per_lat);
    CHECK_NEAR(per_lon, 85393.86, 0.01); /* a degree of longitude and of latitude at 40 N, WGS 84 */
    CHECK_NEAR(per_lat, 111034.63, 0.01);
    ifs_metres_per_degree(info.centre_lat, &per_lon, &per_lat);
    CHECK_NEAR(d->dx, 0.000833333333 * per_lon, 1e-9);
    CHECK_NEAR(d->dy, 0.000833333333 * per_lat, 1e-9);
    fprintf(stderr, "  degree grid at %.5f N: %.3f x %.3f m between nodes\n", info.centre_lat, d->dx, d->dy);
    ifs_dtm_free(d);
    ifs_dtm_file_options o = {.band = 1, .step = 1, .units = IFS_UNITS_METRES};
    CHECK(ifs_dtm_read_file(path, &o, &d, &info, &err) == 0);
    if (d) CHECK_NEAR(d->dx, 0.000833333333, 1e-15);
    ifs_dtm_free(d);
    o = (ifs_dtm_file_options){.band = 1, .step = 1, .cell_size = {90, 92}};
    CHECK(ifs_dtm_read_file(path, &o, &d, &info, &err) == 0);
    if (d) {
        CHECK_NEAR(d->dx, 90, 0);
        CHECK_NEAR(d->dy, 92, 0);
    }
    ifs_dtm_free(d);
}

TEST(bad_files_give_clear_errors)
{
    ifs_dtm *d = NULL;
    plugin_err err = {0};
    const char *missing = out_path("no_such_dtm.tif");
    CHECK(ifs_dtm_read_file(missing, &defaults, &d, NULL, &err) == SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "cannot read the DTM");
    CHECK_STR_CONTAINS(err.msg, "no_such_dtm.tif': No such file or directory");
    const char *empty = out_path("empty.asc");
    write_text(empty, "");
    CHECK(ifs_dtm_read_file(empty, &defaults, &d, NULL, &err) == SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "empty.asc");
    const char *junk = out_path("junk.asc");
    write_text(junk, "this is not a raster\n");
    CHECK(ifs_dtm_read_file(junk, &defaults, &d, NULL, &err) == SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "give a raster GDAL reads");
    const char *one = out_path("one.asc");
    write_text(one, "ncols 1\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n7\n");
    CHECK(ifs_dtm_read_file(one, &defaults, &d, NULL, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "1 x 1 nodes; the IFS needs at least 3 x 3");
    const char *holes = out_path("all_nodata.asc");
    write_text(holes, "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -1\n"
                      "-1 -1 -1\n-1 -1 -1\n-1 -1 -1\n");
    CHECK(ifs_dtm_read_file(holes, &defaults, &d, NULL, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "every one of the DTM's 3 x 3 nodes is nodata");
    const char *pole = out_path("pole.asc");
    write_text(pole, "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 89.95\ncellsize 0.01\n1 2 3\n4 5 6\n7 8 9\n");
    CHECK(ifs_dtm_read_file(pole, &defaults, &d, NULL, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "latitude");
    CHECK(d == NULL);
}

TEST(humidity_map_is_resampled)
{
    /* 3 x 2 pixels of 8-bit humidity (255 = 1), tiling the footprint */
    GDALAllRegister();
    const char *path = out_path("humidity.tif");
    GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path, 3, 2, 1, GDT_Byte, NULL);
    CHECK(ds != NULL);
    if (!ds) return;
    uint8_t v[6] = {0, 255, 255, /* north row */ 51, 51, 51};
    CHECK(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 3, 2, v, 3, 2, GDT_Byte, 0, 0) == CE_None);
    GDALClose(ds);
    float h[5 * 3];
    plugin_err err = {0};
    ifs_humidity_source src = {.path = path, .band = 1};
    CHECK(ifs_humidity_read(&src, 5, 3, h, &err) == 0);
    CHECK_NEAR(h[0], 0.2, 1e-6);            /* south-west: the map's last row */
    CHECK_NEAR(h[2 * 5 + 0], 0.0, 1e-6);    /* north-west */
    CHECK_NEAR(h[2 * 5 + 4], 1.0, 1e-6);    /* north-east */
    /* node (1, 1) lies a quarter across and halfway up: pixel (0.25, 0.5) between centres,
     * north row 0 + 0.25 (1 - 0) = 0.25, south row 0.2, halfway: 0.225 */
    CHECK_NEAR(h[1 * 5 + 1], 0.225, 1e-6);
    src.path = out_path("no_such_humidity.tif");
    CHECK(ifs_humidity_read(&src, 5, 3, h, &err) == SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "cannot read the humidity map");
}

/* A colour-ramp PNG like the humidity.png of `sylva factors`: humidity in the green band, from
 * 15 (humidity 0) to 200 (humidity 1), read with band 2 and that range. */
TEST(humidity_from_a_colour_ramp_png)
{
    GDALAllRegister();
    GDALDatasetH mem = GDALCreate(GDALGetDriverByName("MEM"), "", 4, 4, 3, GDT_Byte, NULL);
    CHECK(mem != NULL);
    if (!mem) return;
    uint8_t rgb[3][16];
    for (int k = 0; k < 16; k++) {
        double hum = (k % 4) / 3.0; /* 0 at the west edge to 1 at the east edge */
        rgb[0][k] = (uint8_t)lround(15 + hum * 25), rgb[1][k] = (uint8_t)lround(15 + hum * 185);
        rgb[2][k] = (uint8_t)lround(15 + hum * 45);
    }
    for (int b = 0; b < 3; b++)
        CHECK(GDALRasterIO(GDALGetRasterBand(mem, b + 1), GF_Write, 0, 0, 4, 4, rgb[b], 4, 4, GDT_Byte, 0, 0) == CE_None);
    const char *path = out_path("humidity_ramp.png");
    GDALDatasetH png = GDALCreateCopy(GDALGetDriverByName("PNG"), path, mem, FALSE, NULL, NULL, NULL);
    CHECK(png != NULL);
    if (png) GDALClose(png);
    GDALClose(mem);
    float h[4 * 4];
    plugin_err err = {0};
    ifs_humidity_source src = {.path = path, .band = 2, .has_range = 1, .range = {15, 200}};
    /* 4 nodes across 4 pixels: node i at pixel coordinate 4 i / 3 - 0.5, clamped; the green
     * values of humidity 1/3 and 2/3 are 77 and 138 (62/185 and 123/185 after the range) */
    CHECK(ifs_humidity_read(&src, 4, 4, h, &err) == 0);
    CHECK_NEAR(h[0], 0.0, 1e-6);
    CHECK_NEAR(h[1], 5.0 / 6.0 * 62.0 / 185.0, 1e-6);
    CHECK_NEAR(h[2], 123.0 / 185.0 + (1.0 - 123.0 / 185.0) / 6.0, 1e-6);
    CHECK_NEAR(h[3], 1.0, 1e-6);
    src.range[1] = 15;
    CHECK(ifs_humidity_read(&src, 4, 4, h, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "humidity range [15, 15] is empty");
    src = (ifs_humidity_source){.path = path, .band = 4};
    CHECK(ifs_humidity_read(&src, 4, 4, h, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "band 4 does not exist");
}

/* Every DEM under ../shared/data/dem loads or fails with a sentence naming it; none crashes. */
static int corpus_files(const char *dir, char paths[][512], int max, int n)
{
    DIR *d = opendir(dir);
    if (!d) return n;
    struct dirent *e;
    while ((e = readdir(d)) && n < max) {
        if (e->d_name[0] == '.') continue;
        char p[512];
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        struct stat st;
        if (stat(p, &st)) continue;
        if (S_ISDIR(st.st_mode)) n = corpus_files(p, paths, max, n);
        else snprintf(paths[n++], 512, "%s", p);
    }
    closedir(d);
    return n;
}

static int by_name(const void *a, const void *b) { return strcmp(a, b); }

TEST(shared_dem_corpus)
{
    const char *shared = harness_shared_data("dem");
    if (!shared) SKIP("the shared DEMs (dem/ in SYLVA_SHARED_DATA_DIR) are not there");
    char dir[512];
    snprintf(dir, sizeof dir, "%s", shared);
    static char paths[256][512];
    int n = corpus_files(dir, paths, 256, 0);
    qsort(paths, (size_t)n, sizeof paths[0], by_name);
    CHECK(n > 0);
    int loaded = 0;
    for (int k = 0; k < n; k++) {
        ifs_dtm *d = NULL;
        ifs_dtm_file_info info;
        plugin_err err = {0};
        int rc = ifs_dtm_read_file(paths[k], &defaults, &d, &info, &err);
        const char *name = paths[k] + strlen(dir) + 1;
        if (rc == 0) {
            loaded++;
            double lo, hi;
            ifs_dtm_range(d, &lo, &hi);
            fprintf(stderr, "  %-52s %4u x %-4u %8.3f x %-8.3f m  z %7.1f..%-7.1f nodata filled %-6llu%s\n",
                    name, d->nx, d->ny, d->dx, d->dy, lo, hi, (unsigned long long)info.nodata_filled,
                    info.degrees ? (info.units_guessed ? " degrees (guessed)" : " degrees") : "");
            CHECK(d->dx > 0 && d->dy > 0);
            for (size_t i = 0; i < (size_t)d->nx * d->ny; i++)
                if (!isfinite(d->z[i])) {
                    CHECK(isfinite(d->z[i]));
                    break;
                }
        } else {
            fprintf(stderr, "  %-52s refused: %s\n", name, err.msg);
            CHECK(rc < 0 && err.msg[0]);
            CHECK_STR_CONTAINS(err.msg, name);
        }
        ifs_dtm_free(d);
    }
    fprintf(stderr, "  %d of %d files loaded\n", loaded, n);
}


/* A 300 x 300 ESRI ASCII grid cut off after 150 rows fails in well under 2 s with a sentence
 * naming the missing row (read bottom-up it kept GDAL busy for minutes); an alarm fails the test
 * should it hang again. */
TEST(truncated_ascii_grid_fails_fast)
{
    const char *path = out_path("truncated.asc");
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    fprintf(f, "ncols 300\nnrows 300\nxllcorner 0\nyllcorner 0\ncellsize 10\n");
    for (int r = 0; r < 150; r++)
        for (int c = 0; c < 300; c++) fprintf(f, "%d%c", (r * 7 + c) % 100, c == 299 ? '\n' : ' ');
    fclose(f);
    ifs_dtm *d = NULL;
    plugin_err err = {0};
    alarm(30);
    double t0 = harness_seconds();
    CHECK(ifs_dtm_read_file(path, &defaults, &d, NULL, &err) == SYLVA_ERR_IO);
    double took = harness_seconds() - t0;
    alarm(0);
    fprintf(stderr, "  truncated grid refused in %.2f s: %s\n", took, err.msg);
    CHECK(took < 2.0);
    CHECK_STR_CONTAINS(err.msg, "truncated.asc' is an ESRI ASCII grid of 300 x 300 values but "
                                "holds 45000: it is truncated");
    CHECK(d == NULL);
}

/* GDAL reads a word where a number belongs as 0 and a short last row as complete; the grid is
 * refused instead, without quoting the word. */
TEST(ascii_grid_with_junk_is_refused)
{
    const char *junk = out_path("junk_value.asc");
    write_text(junk, "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 10\n"
                     "1 2 3\n4 SECRETWORD 6\n7 8 9\n");
    ifs_dtm *d = NULL;
    plugin_err err = {0};
    CHECK(ifs_dtm_read_file(junk, &defaults, &d, NULL, &err) == SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "junk_value.asc' is an ESRI ASCII grid whose value 5 (row 2, "
                                "column 2, on line 7) is not a number");
    CHECK(!strstr(err.msg, "SECRET"));
    const char *short_row = out_path("short_row.asc");
    write_text(short_row, "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 10\n"
                          "1 2 3\n4 5 6\n7 8\n");
    CHECK(ifs_dtm_read_file(short_row, &defaults, &d, NULL, &err) == SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "grid of 3 x 3 values but holds 8: it is truncated");
    CHECK(d == NULL);
}

/* A grid of nan values is not "truncated": the first value that is not a finite number is named
 * at its line and column, unless NODATA_value says nan (then those cells are nodata); a negative
 * cell size is refused at its place in the header. */
TEST(ascii_grid_nan_values_and_negative_cellsize)
{
    const char *nan_grid = out_path("nan_values.asc");
    write_text(nan_grid, "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 10\n"
                         "1 2 3\n4  nan 6\n");
    ifs_dtm *d = NULL;
    plugin_err err = {0};
    CHECK(ifs_dtm_read_file(nan_grid, &defaults, &d, NULL, &err) == SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "nan_values.asc:7:4: the DTM is an ESRI ASCII grid whose value 5 (row 2, column 2) "
                                "is not a finite number (NaN or infinity)");
    CHECK(!strstr(err.msg, "truncated"));
    CHECK(d == NULL);
    const char *all_nan = out_path("all_nan.asc");
    write_text(all_nan, "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value -9999\n"
                        "nan nan\nnan nan\n");
    CHECK(ifs_dtm_read_file(all_nan, &defaults, &d, NULL, &err) == SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "all_nan.asc:7:1: the DTM is an ESRI ASCII grid whose value 1 (row 1, column 1) is "
                                "not a finite number");
    CHECK(!strstr(err.msg, "truncated"));
    /* NODATA_value nan: the nan cells are holes, filled from their neighbours */
    const char *nodata_nan = out_path("nodata_nan.asc");
    write_text(nodata_nan, "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value nan\n"
                           "1 2 3\n4 nan 6\n7 8 9\n");
    int rc = ifs_dtm_read_file(nodata_nan, &defaults, &d, NULL, &err);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    CHECK_INT(rc, SYLVA_OK);
    ifs_dtm_free(d);
    d = NULL;
    const char *negative = out_path("negative_cell.asc");
    write_text(negative, "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize   -10\n1 2 3\n4 5 6\n");
    CHECK(ifs_dtm_read_file(negative, &defaults, &d, NULL, &err) == SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "negative_cell.asc:5:12: the DTM is an ESRI ASCII grid whose cellsize is -10; the "
                                "size of a cell must be a positive number");
    CHECK(d == NULL);
}

/* A FIFO or a device named as the DTM is refused before GDAL opens it (the FIFO used to block
 * the open for ever). */
TEST(special_files_are_refused)
{
    const char *fifo = out_path("dtm.fifo");
    remove(fifo);
    CHECK(mkfifo(fifo, 0600) == 0);
    ifs_dtm *d = NULL;
    plugin_err err = {0};
    alarm(10);
    CHECK(ifs_dtm_read_file(fifo, &defaults, &d, NULL, &err) == SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "dtm.fifo': it is a FIFO (named pipe), not a regular file");
    CHECK(ifs_dtm_read_file("/dev/zero", &defaults, &d, NULL, &err) == SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "'/dev/zero': it is a character device, not a regular file");
    alarm(0);
    CHECK(d == NULL);
    remove(fifo);
}

/* A local VRT whose source is an HTTP URL: GDAL must not connect. A listening socket on the
 * loopback stands in for the server; it must see no connection. */
TEST(local_vrt_stays_offline)
{
    int srv = socket(AF_INET, SOCK_STREAM, 0);
    CHECK(srv >= 0);
    if (srv < 0) return;
    struct sockaddr_in a = {.sin_family = AF_INET, .sin_addr.s_addr = htonl(INADDR_LOOPBACK)};
    socklen_t len = sizeof a;
    CHECK(bind(srv, (struct sockaddr *)&a, sizeof a) == 0);
    CHECK(listen(srv, 4) == 0);
    CHECK(getsockname(srv, (struct sockaddr *)&a, &len) == 0);
    char vrt[1024];
    snprintf(vrt, sizeof vrt,
             "<VRTDataset rasterXSize=\"4\" rasterYSize=\"4\">\n"
             "  <GeoTransform>0, 10, 0, 40, 0, -10</GeoTransform>\n"
             "  <VRTRasterBand dataType=\"Float32\" band=\"1\">\n"
             "    <SimpleSource>\n"
             "      <SourceFilename relativeToVRT=\"0\">/vsicurl/http://127.0.0.1:%u/dem.tif</SourceFilename>\n"
             "      <SourceBand>1</SourceBand>\n"
             "    </SimpleSource>\n"
             "  </VRTRasterBand>\n"
             "</VRTDataset>\n", (unsigned)ntohs(a.sin_port));
    const char *path = out_path("remote_source.vrt");
    write_text(path, vrt);
    ifs_dtm *d = NULL;
    plugin_err err = {0};
    /* should GDAL connect, the silent server would keep it waiting: let it give up soon */
    CPLSetConfigOption("GDAL_HTTP_TIMEOUT", "2");
    CPLSetConfigOption("GDAL_HTTP_MAX_RETRY", "0");
    alarm(30);
    CHECK(ifs_dtm_read_file(path, &defaults, &d, NULL, &err) != 0);
    alarm(0);
    CPLSetConfigOption("GDAL_HTTP_TIMEOUT", NULL);
    CPLSetConfigOption("GDAL_HTTP_MAX_RETRY", NULL);
    CHECK(d == NULL);
    fcntl(srv, F_SETFL, O_NONBLOCK);
    int conn = accept(srv, NULL, NULL);
    if (conn >= 0) {
        fprintf(stderr, "  GDAL connected to the loopback server\n");
        close(conn);
    }
    CHECK(conn < 0);
    close(srv);
}

/* Heights of +-1e34 (a damaged file) are refused; real heights beyond the default range load
 * once height_range is widened. */
TEST(corrupted_heights_are_refused)
{
    const char *path = out_path("corrupt.asc");
    write_text(path, "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 10\n"
                     "100 101 102\n103 -1e34 105\n106 107 108\n");
    ifs_dtm *d = NULL;
    plugin_err err = {0};
    CHECK(ifs_dtm_read_file(path, &defaults, &d, NULL, &err) == SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "corrupt.asc' holds the height -1e+34 m at DTM node (1, 1)");
    CHECK_STR_CONTAINS(err.msg, "outside the plausible range [-500, 9000] m");
    CHECK(d == NULL);
    const char *feet = out_path("feet.asc");
    write_text(feet, "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 10\n"
                     "29000 29010 29020\n29030 29032 29020\n29000 29010 29020\n");
    CHECK(ifs_dtm_read_file(feet, &defaults, &d, NULL, &err) == SYLVA_ERR_PARAM);
    ifs_dtm_file_options wide = defaults;
    wide.height_range[0] = -1000, wide.height_range[1] = 30000;
    CHECK(ifs_dtm_read_file(feet, &wide, &d, NULL, &err) == 0);
    if (d) CHECK_NEAR(d->z[1 * 3 + 1], 29032, 0);
    ifs_dtm_free(d);
}

TEST_LIST(TEST_CASE(geotiff_projected),
          TEST_CASE(geotiff_geographic_in_degrees),
          TEST_CASE(ascii_grid_with_nodata),
          TEST_CASE(ascii_grid_crop_and_step),
          TEST_CASE(ascii_degree_grid),
          TEST_CASE(bad_files_give_clear_errors),
          TEST_CASE(humidity_map_is_resampled),
          TEST_CASE(humidity_from_a_colour_ramp_png),
          TEST_CASE(shared_dem_corpus),
          TEST_CASE(truncated_ascii_grid_fails_fast),
          TEST_CASE(ascii_grid_with_junk_is_refused), TEST_CASE(ascii_grid_nan_values_and_negative_cellsize),
          TEST_CASE(special_files_are_refused),
          TEST_CASE(local_vrt_stays_offline),
          TEST_CASE(corrupted_heights_are_refused))
