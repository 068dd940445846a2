/* test_ifs_plugin.c — the terrain_ifs plugin through the real host: scene files written by the
 * test are loaded and built with the plugin from the build tree, so the schema, create(),
 * generate() and the heightfield, materials and water the host receives are all checked, and
 * bad input comes back as a located sentence. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <gdal.h>
#include <cpl_conv.h>
#include <ogr_srs_api.h>

#include "harness.h"
#include "plugin/plugin_host.h"
#include "scene/scene.h"
#include "scene_build/scene_build.h"
#include "scene/heightfield.h"
#include "scene_file/scene_file.h"
#include "render/accel.h"

#define OUT_DIR SYLVA_TEST_OUT_DIR

static plugin_registry *registry(void)
{
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open_path(SYLVA_PLUGIN_BUILD_DIR, &err);
    CHECK(reg != NULL);
    if (reg && !plugin_registry_find(reg, "terrain_ifs", SYLVA_KIND_TERRAIN, &err)) {
        fprintf(stderr, "terrain_ifs is not in %s: %s\n", SYLVA_PLUGIN_BUILD_DIR, err.msg);
        CHECK(0);
    }
    return reg;
}

/* Writes OUT_DIR/<name>.yaml with the given image seed and terrain keys (one "key: value" per
 * line, without indentation) and returns its path (static storage). */
static const char *scene_write(const char *name, int seed, const char *terrain_keys)
{
    static char path[512];
    mkdir(OUT_DIR, 0755);
    snprintf(path, sizeof path, "%s/%s.yaml", OUT_DIR, name);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return path;
    fprintf(f, "image: {width: 16, height: 16, spp: 1, seed: %d}\n"
               "camera: {position: [0, -300, 100], look_at: [0, 0, 0]}\n"
               "terrain:\n  plugin: terrain_ifs\n  threads: 2\n", seed);
    for (const char *p = terrain_keys; *p;) {
        const char *e = strchr(p, '\n');
        size_t n = e ? (size_t)(e - p) : strlen(p);
        fprintf(f, "  %.*s\n", (int)n, p);
        p += n + (e ? 1 : 0);
    }
    fclose(f);
    return path;
}

/* Loads and builds a scene with the site (CRS as WKT, or NULL for none, and origin) filled in as
 * the scene's site section would: the plugin receives them in its terrain request. NULL with err
 * set on failure. */
static scene *scene_with_site(const char *path, plugin_registry *reg, const char *wkt,
                              const double origin[3], err_buf *err)
{
    err_clear(err);
    scene_file *sf = scene_file_load(path, reg, err);
    if (!sf) return NULL;
    sf->site.crs_wkt = wkt;
    memcpy(sf->site.origin, origin, sizeof sf->site.origin);
    build_options opt = {.quiet = 1};
    scene *s = scene_build(sf, reg, &opt, err);
    sf->site.crs_wkt = NULL; /* the test's string */
    scene_file_free(sf);
    return s;
}

/* Loads and builds a scene without a site; NULL with err set on failure. */
static scene *scene_from(const char *path, plugin_registry *reg, err_buf *err)
{
    const double origin[3] = {0, 0, 0};
    return scene_with_site(path, reg, NULL, origin, err);
}

static scene *scene_ok(const char *name, int seed, const char *keys, plugin_registry *reg)
{
    err_buf err;
    scene *s = scene_from(scene_write(name, seed, keys), reg, &err);
    CHECK(s != NULL && s->terrain != NULL);
    if (!s) fprintf(stderr, "%s: %s\n", name, err.msg);
    return s;
}

TEST(descriptor_and_schema)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    err_buf err;
    const loaded_plugin *lp = plugin_registry_find(reg, "terrain_ifs", SYLVA_KIND_TERRAIN, &err);
    if (lp) {
        CHECK_INT(lp->desc->n_params, 46);
        CHECK(plugin_schema_check(lp->desc->params, lp->desc->n_params, &err) == 0);
        CHECK_STR_CONTAINS(lp->desc->summary, "IFS");
    }
    plugin_registry_free(reg);
}

/* An inline 5 x 5 DTM, placed, scaled and evaluated deterministically in bilinear mode: the
 * heightfield has (N - 1) refine + 1 nodes, spans the DTM's footprint around `centre`, and
 * passes through every (scaled) DTM node. */
TEST(inline_dtm_deterministic)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    const double h[5][5] = {{10, 12, 15, 13, 11}, {11, 16, 20, 17, 12}, {12, 18, 30, 21, 14},
                            {11, 15, 22, 18, 13}, {10, 11, 14, 12, 10}};
    char keys[1024];
    int n = snprintf(keys, sizeof keys, "method: deterministic\nalpha: 0.3\nrefine: 4\n"
                     "cell_size: [10, 20]\ncentre: [100, 50]\nz_scale: 2\nz_offset: 5\nheights:");
    for (int j = 0; j < 5; j++)
        n += snprintf(keys + n, sizeof keys - n, "\n  - [%g, %g, %g, %g, %g]", h[j][0], h[j][1],
                      h[j][2], h[j][3], h[j][4]);
    scene *s = scene_ok("inline_deterministic", 1, keys, reg);
    if (s && s->terrain) {
        const sylva_heightfield *t = s->terrain;
        CHECK_INT(t->nx, 17);
        CHECK_INT(t->ny, 17);
        CHECK_NEAR(t->dx, 2.5, 1e-12);
        CHECK_NEAR(t->dy, 5, 1e-12);
        CHECK_NEAR(t->x0, 80, 1e-12);
        CHECK_NEAR(t->y0, 10, 1e-12);
        double worst = 0;
        for (int j = 0; j < 5; j++)
            for (int i = 0; i < 5; i++)
                worst = fmax(worst, fabs(t->z[(size_t)(4 * j) * 17 + 4 * i] - (2 * h[j][i] + 5)));
        CHECK(worst <= 65 * 1.2e-7);
        CHECK(t->material != NULL);
        for (uint32_t k = 0; t->material && k < 17 * 17; k++)
            CHECK(t->material[k] >= 0 && (uint32_t)t->material[k] < s->n_materials);
        CHECK_INT(t->has_water, 0);
        scene_free(s);
    }
    plugin_registry_free(reg);
}

/* The default method interpolates: with no method key, every DTM node's height on the built
 * heightfield (and on every level of detail that holds the node) is the DTM's, to the float
 * rounding of the heightfield, at alpha 0, 0.3 and 0.5 (000 §2: the attractor is the graph of a
 * function through the DTM's points). The random iteration averaged the points around each
 * node and missed this rough DTM's nodes by metres. */
TEST(default_surface_passes_through_every_node)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    enum { N = 17 };
    double h[N][N];
    char heights[8192];
    int n = snprintf(heights, sizeof heights, "heights:");
    for (int j = 0; j < N; j++) {
        n += snprintf(heights + n, sizeof heights - n, "\n  - [");
        for (int i = 0; i < N; i++) {
            /* rolling relief plus a rough, fractional part: departures of tens of metres */
            double rough = sin(12.9898 * i + 78.233 * j) * 43758.5453;
            h[j][i] = 60 + 35 * sin(0.7 * i) * cos(0.45 * j) + 9 * (rough - floor(rough)) + 0.013 * i * j;
            n += snprintf(heights + n, sizeof heights - n, "%s%.17g", i ? ", " : "", h[j][i]);
        }
        n += snprintf(heights + n, sizeof heights - n, "]");
    }
    static const double alphas[3] = {0, 0.3, 0.5};
    /* uniform, and levels of detail around the camera (at (0, -300), over the footprint) */
    static const char *const layouts[2] = {"refine: 4", "refine: 8\ndetail_radius: 60\n"
                                           "centre: [0, -300]"};
    for (int a = 0; a < 3; a++)
        for (int l = 0; l < 2; l++) {
            char keys[9000];
            snprintf(keys, sizeof keys, "alpha: %g\ncell_size: [20, 20]\n%s\n%s", alphas[a],
                     layouts[l], heights);
            scene *s = scene_ok("default_through_nodes", 3, keys, reg);
            if (!s || !s->terrain) {
                scene_free(s);
                continue;
            }
            const sylva_heightfield *t = s->terrain;
            uint32_t r = l == 0 ? 4 : 1; /* heightfield nodes per DTM cell */
            CHECK_INT(t->nx, (N - 1) * r + 1);
            CHECK(l == 0 ? t->n_levels == 0 : t->n_levels == 3);
            double worst = 0, worst_excess = 0;
            uint32_t checked = 0;
            for (uint32_t k = 0; k <= t->n_levels; k++) {
                const sylva_terrain_level *lv = k ? &t->levels[k - 1] : NULL;
                uint32_t nx = lv ? lv->nx : t->nx, ny = lv ? lv->ny : t->ny;
                uint32_t step = lv ? lv->refine : r, i0 = lv ? lv->i0 : 0, j0 = lv ? lv->j0 : 0;
                const float *z = lv ? lv->z : t->z;
                for (uint32_t j = 0; j < ny; j += step)
                    for (uint32_t i = 0; i < nx; i += step) {
                        double want = h[j0 + j / step][i0 + i / step];
                        double miss = fabs(z[(size_t)j * nx + i] - want);
                        /* float keeps the height to half a unit in its last place */
                        double precision = 0.5 * FLT_EPSILON * fabs(want) + 1e-9;
                        worst = fmax(worst, miss);
                        worst_excess = fmax(worst_excess, miss - precision);
                        checked++;
                    }
            }
            fprintf(stderr, "  alpha %.1f, %-26s %4u node heights, largest miss %.3g m\n",
                    alphas[a], l ? "levels of detail:" : "uniform refine 4:", checked, worst);
            CHECK(checked >= N * N);
            CHECK(worst_excess <= 0);
            scene_free(s);
        }
    plugin_registry_free(reg);
}

/* The generated DTM with random iteration: the same scene gives the same heights, another seed
 * other heights; water stands at y_w of the DTM's range with the plugin's water material. */
TEST(generated_dtm_random_iteration)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    const char *keys = "method: random\nalpha: 0.2\niterations: 300000\nwater_level: 0.3\n"
                       "generated: {nodes: [9, 9], relief: 60}\nwater_albedo: [0.1, 0.2, 0.3]";
    scene *a = scene_ok("generated_a", 7, keys, reg);
    scene *b = scene_ok("generated_b", 7, keys, reg);
    scene *c = scene_ok("generated_c", 8, keys, reg);
    if (a && b && c) {
        const sylva_heightfield *t = a->terrain;
        CHECK_INT(t->nx, 33);
        CHECK_NEAR(t->dx, 25.0 * 8 / 32, 1e-12);
        CHECK(memcmp(t->z, b->terrain->z, 33 * 33 * sizeof(float)) == 0);
        CHECK(memcmp(t->z, c->terrain->z, 33 * 33 * sizeof(float)) != 0);
        CHECK_INT(t->has_water, 1);
        CHECK_NEAR(t->water_level, 18.0, 1e-9); /* generated heights span [0, 60] */
        CHECK(t->water_material >= 0 && (uint32_t)t->water_material < a->n_materials);
        if (t->water_material >= 0) {
            const material *w = &a->materials[t->water_material];
            CHECK_NEAR(w->albedo.x, 0.1, 1e-6);
            CHECK_NEAR(w->albedo.z, 0.3, 1e-6);
            CHECK_STR_CONTAINS(w->name, "water");
        }
        /* more than one ground class on a rough 60 m relief */
        int first = t->material[0], varied = 0;
        for (uint32_t k = 0; k < 33 * 33; k++) varied |= t->material[k] != first;
        CHECK(varied);
    }
    scene_free(a), scene_free(b), scene_free(c);
    plugin_registry_free(reg);
}

/* surface: scene leaves the ground to the scene's terrain material (no per-node ids). */
TEST(surface_from_scene)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    scene *s = scene_ok("surface_scene", 1, "surface: scene\nmode: affine\nmethod: deterministic", reg);
    if (s) {
        CHECK(s->terrain->material == NULL);
        CHECK_INT(s->terrain->nx, 65);
        scene_free(s);
    }
    plugin_registry_free(reg);
}

static void write_humidity(const char *path, uint8_t value)
{
    GDALAllRegister();
    GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path, 4, 4, 1, GDT_Byte, NULL);
    CHECK(ds != NULL);
    if (!ds) return;
    uint8_t v[16];
    memset(v, value, sizeof v);
    CHECK(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 4, 4, v, 4, 4, GDT_Byte, 0, 0) == CE_None);
    GDALClose(ds);
}

/* A flat meadow is grass; under a dry humidity map it is dry grass. The map's path is relative
 * to the scene file. */
TEST(humidity_map_dries_grass)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    char path[512];
    snprintf(path, sizeof path, "%s/dry.tif", OUT_DIR);
    mkdir(OUT_DIR, 0755);
    write_humidity(path, 20);
    snprintf(path, sizeof path, "%s/wet.tif", OUT_DIR);
    write_humidity(path, 240);
    const char *flat = "heights: [[5, 5, 5], [5, 5, 5], [5, 5, 5]]\nmethod: deterministic\n";
    char keys[512];
    snprintf(keys, sizeof keys, "%shumidity_map: dry.tif", flat);
    scene *dry = scene_ok("humidity_dry", 1, keys, reg);
    snprintf(keys, sizeof keys, "%shumidity_map: wet.tif", flat);
    scene *wet = scene_ok("humidity_wet", 1, keys, reg);
    if (dry && wet) {
        CHECK_STR_CONTAINS(dry->materials[dry->terrain->material[4]].name, "dry grass");
        const char *n = wet->materials[wet->terrain->material[4]].name;
        CHECK_STR_CONTAINS(n, "grass");
        CHECK(strstr(n, "dry") == NULL);
    }
    scene_free(dry), scene_free(wet);
    plugin_registry_free(reg);
}

/* A DTM file named relative to the scene, cropped and resampled. */
TEST(dtm_file_relative_to_scene)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    char path[512], text[4096];
    snprintf(path, sizeof path, "%s/scene_dtm.asc", OUT_DIR);
    mkdir(OUT_DIR, 0755);
    int n = snprintf(text, sizeof text, "ncols 11\nnrows 9\nxllcorner 500000\nyllcorner 4000000\n"
                     "cellsize 10\nNODATA_value -9999\n");
    for (int r = 0; r < 9; r++) {
        for (int c = 0; c < 11; c++)
            n += snprintf(text + n, sizeof text - n, "%d ", r == 4 && c == 4 ? -9999 : 300 + 2 * r + c);
        n += snprintf(text + n, sizeof text - n, "\n");
    }
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
    scene *s = scene_ok("dtm_file", 1, "dtm: scene_dtm.asc\ncrop: [1, 0, 9, 9]\nstep: 2\n"
                        "method: deterministic\nalpha: 0.1\nrefine: 2", reg);
    if (s) {
        /* 9 x 9 window, step 2: 5 x 5 nodes 20 m apart, 9 x 9 output nodes 10 m apart */
        CHECK_INT(s->terrain->nx, 9);
        CHECK_NEAR(s->terrain->dx, 10, 1e-12);
        CHECK_NEAR(s->terrain->x0, -40, 1e-12);
        /* south-west DTM node: file row 8, column 1 */
        CHECK_NEAR(s->terrain->z[0], 300 + 16 + 1, 1e-4);
        scene_free(s);
    }
    plugin_registry_free(reg);
}

/* Every bad input stops the scene with a sentence saying what is wrong. */
TEST(bad_input_is_refused_clearly)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    char empty[512];
    snprintf(empty, sizeof empty, "%s/empty_dtm.asc", OUT_DIR);
    mkdir(OUT_DIR, 0755);
    FILE *f = fopen(empty, "w");
    if (f) fclose(f);
    static const struct {
        const char *keys, *expect;
    } cases[] = {
        {"alpha: 1.5", "'alpha' must be in (-1, 1), got 1.5"},
        {"alpha: -1", "'alpha' must be in (-1, 1)"},
        {"iterations: 0", "'iterations' must be an integer in [1, 1000000000]"},
        {"iterations: 5000000000", "'iterations' must be an integer in [1, 1000000000]"},
        {"heights: []", "needs at least one row"},
        {"heights: [[5]]", "1 x 1 nodes; the IFS needs at least 3 x 3"},
        {"heights: [[1, 2], [3, 4]]", "2 x 2 nodes; the IFS needs at least 3 x 3"},
        {"dtm: no_such_dtm.tif", "cannot read the DTM"},
        {"dtm: empty_dtm.asc", "cannot read the DTM"},
        {"alpha_field: [[0.1, 0.2]]", "alpha_field has 1 rows of 2 values; the DTM has 16 rows of 16 cells"},
        {"alpha_field: [[0.1, 1.0]]", "must be in (-1, 1)"},
        {"probability_field: [[0.1, -1]]", ">= 0"},
        {"dtm: x.tif\nheights: [[1, 2, 3], [1, 2, 3], [1, 2, 3]]", "give dtm or heights, not both"},
        {"step: 2", "step applies to a dtm file"},
        {"method: deterministic\niterations: 10", "iterations and start belong to method: random"},
        {"iterations: 10", "evaluated deterministically (the default): add method: random, or "
                           "remove iterations"},
        {"start: [0, 0, 10]", "add method: random, or remove start"},
        {"output_nodes: [20000, 20000]", "the output grid would have 20000 x 20000 nodes"},
        {"output_nodes: [100]", "output_nodes must be two whole numbers"},
        {"method: random\nstart: [100000, 0, 0]", "lies outside the DTM"},
        {"method: random\nstart: [0, 0]", "start has 2 numbers"},
        {"scree_slope: 50", "scree_slope 50 exceeds rock_slope 42"},
        {"surface: scene\nsnow_line: 0.5", "belongs to surface: classes"},
        {"humidity_map: no_such_humidity.tif", "cannot read the humidity map"},
        {"humidity_range: [0, 255]", "describe a humidity_map; this terrain has none"},
        {"humidity_map: x.png\nhumidity_range: [5, 5]", "humidity_range must be two different numbers"},
        {"dtm: empty_dtm.asc\ncrop: [0, 0, 5]", "crop has 3 numbers"},
        {"generated: {nodes: [2, 17]}", "must be"},
        {"generated: {nodes: [17.5, 17]}", "whole numbers"},
        {"mode: trilinear", "'mode' must be one of bilinear, affine"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        err_buf err;
        char name[32];
        snprintf(name, sizeof name, "bad_%zu", k);
        const char *path = scene_write(name, 1, cases[k].keys);
        scene *s = scene_from(path, reg, &err);
        CHECK(s == NULL);
        if (s) {
            fprintf(stderr, "  case %zu (%s) was accepted\n", k, cases[k].keys);
            scene_free(s);
            continue;
        }
        CHECK_STR_CONTAINS(err.msg, cases[k].expect);
        CHECK_STR_CONTAINS(err.msg, name); /* located in the scene file */
        fprintf(stderr, "  %-45.45s -> %s\n", cases[k].keys, err.msg + strlen(OUT_DIR) + 1);
    }
    plugin_registry_free(reg);
}

/* The share of heightfield nodes whose material is the named ground-cover class. */
static double class_share(const scene *s, const char *class_name)
{
    const sylva_heightfield *t = s->terrain;
    uint64_t n = 0, total = (uint64_t)t->nx * t->ny;
    char want[48];
    snprintf(want, sizeof want, "terrain_ifs %s", class_name);
    for (uint64_t k = 0; k < total; k++)
        if (t->material[k] >= 0 && !strcmp(s->materials[t->material[k]].name, want)) n++;
    return (double)n / total;
}

/* Snow and scree lie by altitude in metres and slope in degrees: a 50 m-relief site has no
 * snow by default (the fractions of the height range put 20 % of it under snow before), a site
 * from 2,000 to 3,200 m has snow exactly on the gentle nodes from snow_altitude up, the older
 * fractions still work when given, and giving both forms is refused. */
TEST(snow_and_scree_in_metres)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    scene *s = scene_ok("low_relief", 3, "method: deterministic\ngenerated: {nodes: [17, 17], "
                        "relief: 50}", reg);
    if (s && s->terrain) {
        CHECK(class_share(s, "snow") == 0.0);
        CHECK(class_share(s, "grass") > 0.5);
    }
    scene_free(s);
    s = scene_ok("alpine", 3, "method: deterministic\nz_offset: 2000\nsnow_altitude: 2900\n"
                 "generated: {nodes: [17, 17], relief: 1200}\ncell_size: [400, 400]", reg);
    if (s && s->terrain) {
        const sylva_heightfield *t = s->terrain;
        uint32_t wrong = 0, snow = 0;
        for (uint32_t j = 0; j < t->ny; j++)
            for (uint32_t i = 0; i < t->nx; i++) {
                size_t k = (size_t)j * t->nx + i;
                const char *name = s->materials[t->material[k]].name;
                int is_snow = !strcmp(name, "terrain_ifs snow"), is_rock = !strcmp(name, "terrain_ifs rock");
                snow += is_snow;
                if (is_snow != (t->z[k] >= 2900 && !is_rock)) wrong++;
            }
        CHECK_INT(wrong, 0);
        CHECK(snow > 0);
    }
    scene_free(s);
    s = scene_ok("fractions", 3, "method: deterministic\nsnow_line: 0.8\nscree_line: 0.6\n"
                 "generated: {nodes: [17, 17], relief: 50}", reg);
    if (s && s->terrain) CHECK(class_share(s, "snow") > 0.0);
    scene_free(s);
    err_buf err;
    s = scene_from(scene_write("both_forms", 3, "snow_line: 0.8\nsnow_altitude: 2000"), reg, &err);
    CHECK(s == NULL);
    scene_free(s);
    CHECK_STR_CONTAINS(err.msg, "give snow_altitude (metres) or snow_line");
    plugin_registry_free(reg);
}

/* The height of the site test's DTM at map point (e, n) of EPSG:32611: a tilted plane. */
static double site_plane(double e, double n) { return 1000.0 + 0.05 * (e - 500000) + 0.03 * (n - 4098800); }

static char *wkt_of_epsg(int code)
{
    OGRSpatialReferenceH srs = OSRNewSpatialReference(NULL);
    char *wkt = NULL, *copy = NULL;
    if (srs && OSRImportFromEPSG(srs, code) == OGRERR_NONE && OSRExportToWkt(srs, &wkt) == OGRERR_NONE)
        copy = strdup(wkt);
    CPLFree(wkt);
    OSRDestroySpatialReference(srs);
    return copy;
}

/* A site places the DTM by its georeferencing: in the DTM's own CRS node (E, N) stands at
 * (E - origin E, N - origin N), heights minus the origin's; in another CRS (UTM zone 10 for a
 * zone 11 file) the DTM is warped (bilinear) so that every local point carries the height of
 * its map point, found back in the file's CRS through PROJ. */
TEST(site_places_and_warps_the_dtm)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    char tif[512];
    snprintf(tif, sizeof tif, "%s/site_dtm.tif", OUT_DIR);
    mkdir(OUT_DIR, 0755);
    GDALAllRegister();
    GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), tif, 50, 40, 1, GDT_Float32, NULL);
    CHECK(ds != NULL);
    if (!ds) return;
    double gt[6] = {500000, 30, 0, 4100000, 0, -30};
    GDALSetGeoTransform(ds, gt);
    OGRSpatialReferenceH srs = OSRNewSpatialReference(NULL);
    OSRImportFromEPSG(srs, 32611);
    GDALSetSpatialRef(ds, srs);
    float v[40][50];
    for (int r = 0; r < 40; r++)
        for (int c = 0; c < 50; c++) v[r][c] = (float)site_plane(500000 + 30 * (c + 0.5), 4100000 - 30 * (r + 0.5));
    CHECK(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 50, 40, v, 50, 40, GDT_Float32, 0, 0) == CE_None);
    GDALClose(ds);
    const char *keys = "dtm: site_dtm.tif\nrefine: 1\nmethod: deterministic\nalpha: 0\ncentre: [7, 9]";
    const double origin[3] = {500600, 4099400, 900};
    char *utm11 = wkt_of_epsg(32611), *utm10 = wkt_of_epsg(32610);
    CHECK(utm11 && utm10);
    err_buf err;
    scene *s = utm11 ? scene_with_site(scene_write("site_same_crs", 1, keys), reg, utm11, origin, &err) : NULL;
    CHECK(s && s->terrain);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    if (s && s->terrain) {
        const sylva_heightfield *t = s->terrain;
        CHECK_INT(t->nx, 50);
        CHECK_NEAR(t->x0, 500015 - origin[0], 1e-9); /* node (0, 0): the south-west pixel centre */
        CHECK_NEAR(t->y0, 4098815 - origin[1], 1e-9);
        CHECK_NEAR(t->z[0], site_plane(500015, 4098815) - origin[2], 1e-3);
        CHECK_NEAR(t->z[39 * 50 + 49], site_plane(501485, 4099985) - origin[2], 1e-3);
    }
    scene_free(s);
    /* a site is local: in zone 10 the origin is the DTM's place there (zone 11's coordinates of it
     * would lie 533 km off, and are refused) */
    const double origin10[3] = {1034600, 4116300, 900};
    s = utm10 ? scene_with_site(scene_write("site_other_crs", 1, keys), reg, utm10, origin10, &err) : NULL;
    CHECK(s && s->terrain);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    if (s && s->terrain) {
        /* every local point inside the file's footprint: its zone 10 map point, back in zone 11 */
        OGRSpatialReferenceH z10 = OSRNewSpatialReference(utm10);
        OSRSetAxisMappingStrategy(z10, OAMS_TRADITIONAL_GIS_ORDER);
        OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
        OGRCoordinateTransformationH to11 = OCTNewCoordinateTransformation(z10, srs);
        const sylva_heightfield *t = s->terrain;
        double worst = 0;
        int inside = 0;
        for (uint32_t j = 1; j + 1 < t->ny; j += 3)
            for (uint32_t i = 1; i + 1 < t->nx; i += 3) {
                double x = t->x0 + i * t->dx + 0.37 * t->dx, y = t->y0 + j * t->dy + 0.61 * t->dy, z;
                double e = x + origin10[0], n = y + origin10[1];
                if (!OCTTransform(to11, 1, &e, &n, NULL)) continue;
                /* away from the file's edge, where the warped raster has no data of its own */
                if (e < 500000 + 60 || e > 501500 - 60 || n < 4098800 + 60 || n > 4100000 - 60) continue;
                if (heightfield_height(t, x, y, &z)) continue;
                inside++;
                worst = fmax(worst, fabs(z - (site_plane(e, n) - origin10[2])));
            }
        fprintf(stderr, "warped: %u x %u nodes %.2f x %.2f m apart; %d points, worst %.4f m\n", t->nx, t->ny,
                t->dx, t->dy, inside, worst);
        CHECK(inside > 50);
        CHECK(worst < 0.05);
        OCTDestroyCoordinateTransformation(to11);
        OSRDestroySpatialReference(z10);
    }
    scene_free(s);
    /* without a site, the DTM stands at centre as before */
    s = scene_ok("site_none", 1, keys, reg);
    if (s && s->terrain) CHECK_NEAR(s->terrain->x0, 7 - 0.5 * 49 * 30, 1e-9);
    scene_free(s);
    OSRDestroySpatialReference(srs);
    free(utm11), free(utm10);
    plugin_registry_free(reg);
}

/* Writes OUT_DIR/<name>.yaml: a 33 x 33 generated DTM 25 m apart seen from a camera at (x, y),
 * with the terrain keys given. */
static const char *lod_scene(const char *name, double x, double y, const char *keys)
{
    static char path[512];
    snprintf(path, sizeof path, "%s/%s.yaml", OUT_DIR, name);
    mkdir(OUT_DIR, 0755);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return path;
    fprintf(f, "image: {width: 16, height: 16, spp: 1, seed: 4}\n"
               "camera: {position: [%g, %g, 150], look_at: [0, 0, 0]}\n"
               "terrain:\n  plugin: terrain_ifs\n  threads: 2\n  refine: 8\n  alpha: 0.3\n"
               "  generated: {nodes: [33, 33], relief: 120}\n  %s\n", x, y, keys);
    fclose(f);
    return path;
}

/* Levels of detail: around the camera the finest window equals the uniform refinement there
 * (deterministic evaluation and random iteration alike), coarser rings follow at halving
 * refine, the DTM's nodes stay as they are, and the levels meet without cracks: every vertical
 * ray along and across each window's sides hits the terrain. */
TEST(levels_of_detail_match_uniform_and_close)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    static const char *const methods[2] = {"method: deterministic",
                                           "method: random\n  iterations: 2000000"};
    for (int m = 0; m < 2; m++) {
        char keys[160];
        snprintf(keys, sizeof keys, "%s\n  detail_radius: 60", methods[m]);
        err_buf err;
        scene *lod = scene_from(lod_scene("lod_levels", 110, -40, keys), reg, &err);
        scene *uni = scene_from(lod_scene("lod_uniform", 110, -40, methods[m]), reg, &err);
        CHECK(lod && lod->terrain && uni && uni->terrain);
        if (!lod || !uni) {
            fprintf(stderr, "%s\n", err.msg);
            scene_free(lod), scene_free(uni);
            continue;
        }
        const sylva_heightfield *t = lod->terrain, *u = uni->terrain;
        CHECK_INT(t->nx, 33);
        CHECK_INT(u->nx, 257);
        CHECK_INT(t->n_levels, 3); /* refine 2, 4, 8 */
        uint32_t differ = 0, nodes_moved = 0;
        for (uint32_t j = 0; j < 33; j++)
            for (uint32_t i = 0; i < 33; i++) /* the DTM's nodes (bilinear maps pass through them) */
                if (fabs(t->z[j * 33 + i] - u->z[(size_t)(8 * j) * 257 + 8 * i]) > 1e-3) nodes_moved++;
        if (t->n_levels == 3) {
            const sylva_terrain_level *f = &t->levels[2];
            CHECK_INT(f->refine, 8);
            CHECK(f->cells_x >= 4 && f->cells_x <= 6);
            for (uint32_t j = 1; j + 1 < f->ny; j++)
                for (uint32_t i = 1; i + 1 < f->nx; i++) /* inside the rim */
                    if (f->z[(size_t)j * f->nx + i] != u->z[(size_t)(f->j0 * 8 + j) * 257 + f->i0 * 8 + i]) differ++;
            for (uint32_t k = 1; k < 3; k++) { /* nested, strictly inside */
                const sylva_terrain_level *c = &t->levels[k - 1], *l = &t->levels[k];
                CHECK(l->i0 > c->i0 && l->j0 > c->j0 && l->i0 + l->cells_x < c->i0 + c->cells_x &&
                      l->j0 + l->cells_y < c->j0 + c->cells_y);
                CHECK_INT(l->refine, 2 * c->refine);
            }
        }
        CHECK_INT(differ, 0);
        if (m == 0) CHECK_INT(nodes_moved, 0);
        /* no cracks: vertical rays on and across every window's sides */
        accel a;
        CHECK_INT(accel_build(&a, lod, 2, &err), 0);
        uint32_t rays = 0, misses = 0;
        for (uint32_t k = 0; k < t->n_levels; k++) {
            const sylva_terrain_level *l = &t->levels[k];
            double xs[2] = {t->x0 + l->i0 * t->dx, t->x0 + (l->i0 + l->cells_x) * t->dx};
            double ys[2] = {t->y0 + l->j0 * t->dy, t->y0 + (l->j0 + l->cells_y) * t->dy};
            for (int side = 0; side < 2; side++)
                for (int q = 0; q <= 4000; q++) {
                    double along = (double)q / 4000, off = ((q % 5) - 2) * 1e-4 * t->dx;
                    double px[2] = {xs[side] + off, xs[0] + along * (xs[1] - xs[0])};
                    double py[2] = {ys[0] + along * (ys[1] - ys[0]), ys[side] + off};
                    for (int dir = 0; dir < 2; dir++) {
                        struct RTCRayHit rh = {.ray = {.org_x = (float)px[dir], .org_y = (float)py[dir],
                                                       .org_z = 1000, .dir_z = -1, .tfar = INFINITY,
                                                       .mask = 0xffffffffu},
                                               .hit = {.geomID = RTC_INVALID_GEOMETRY_ID,
                                                       .instID = {RTC_INVALID_GEOMETRY_ID}}};
                        struct RTCIntersectContext ic;
                        rtcInitIntersectContext(&ic);
                        rtcIntersect1(a.top, &ic, &rh);
                        rays++;
                        if (rh.hit.geomID != ACCEL_TOP_TERRAIN) misses++;
                    }
                }
        }
        fprintf(stderr, "%s: %u rays across the levels' sides, %u missed\n", methods[m], rays, misses);
        CHECK(rays > 40000);
        CHECK_INT(misses, 0);
        accel_free(&a);
        scene_free(lod), scene_free(uni);
    }
    plugin_registry_free(reg);
}

/* Rays from eye in every direction from 0.01 to about 60 degrees below the horizontal: how many
 * miss everything (*rays: of how many). */
static uint32_t sky_below_horizon(const accel *a, const double eye[3], uint32_t *rays)
{
    uint32_t misses = 0;
    *rays = 0;
    for (int az = 0; az < 360; az += 2)
        for (int e = 0; e < 40; e++) {
            double el = -0.01 * pow(1.25, e) * M_PI / 180; /* -0.01 to about -60 degrees */
            double t = az * M_PI / 180;
            struct RTCRayHit rh = {.ray = {.org_x = (float)eye[0], .org_y = (float)eye[1], .org_z = (float)eye[2],
                                           .dir_x = (float)(cos(el) * cos(t)), .dir_y = (float)(cos(el) * sin(t)),
                                           .dir_z = (float)sin(el), .tfar = INFINITY, .mask = 0xffffffffu},
                                   .hit = {.geomID = RTC_INVALID_GEOMETRY_ID, .instID = {RTC_INVALID_GEOMETRY_ID}}};
            struct RTCIntersectContext ic;
            rtcInitIntersectContext(&ic);
            rtcIntersect1(a->top, &ic, &rh);
            (*rays)++;
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) misses++;
        }
    return misses;
}

/* Beyond the DTM's edge the ground goes on: from a camera over a 800 m DTM (on its node lines,
 * so some rays run exactly along cell edges; levels of detail reaching the DTM's edge, so the
 * apron meets them there), every ray below the horizontal, toward the edges
 * and the corners, down to 0.01 degrees under the horizon, meets the ground; with beyond_edge:
 * void the sky shows there (the old behaviour). */
TEST(no_void_under_the_horizon)
{
    plugin_registry *reg = registry();
    if (!reg) return;
    for (int edge = 0; edge < 2; edge++) {
        char path[512];
        snprintf(path, sizeof path, "%s/apron_%d.yaml", OUT_DIR, edge);
        mkdir(OUT_DIR, 0755);
        FILE *f = fopen(path, "w");
        CHECK(f != NULL);
        if (!f) break;
        fprintf(f, "image: {width: 16, height: 16, spp: 1}\n"
                   "camera: {position: [100, 50, 160], look_at: [1000, 50, 160]}\n"
                   "terrain:\n  plugin: terrain_ifs\n  method: deterministic\n  refine: 8\n"
                   "  detail_radius: 100\n  alpha: 0.3\n"
                   "  generated: {nodes: [33, 33], relief: 120}\n  beyond_edge: %s\n",
                   edge ? "void" : "flat");
        fclose(f);
        err_buf err;
        scene *s = scene_from(path, reg, &err);
        CHECK(s && s->terrain);
        if (!s) {
            fprintf(stderr, "%s\n", err.msg);
            continue;
        }
        CHECK_INT(s->terrain->n_levels, 3);
        if (s->terrain->n_levels) CHECK_INT(s->terrain->levels[0].i0 + s->terrain->levels[0].cells_x, 32);
        accel a;
        CHECK_INT(accel_build(&a, s, 2, &err), 0);
        uint32_t rays, misses = sky_below_horizon(&a, s->camera.position, &rays);
        fprintf(stderr, "beyond_edge %s: %u of %u rays under the horizon see the sky\n", edge ? "void" : "flat",
                misses, rays);
        if (edge) CHECK(misses > rays / 4);
        else CHECK_INT(misses, 0);
        accel_free(&a);
        scene_free(s);
    }
    plugin_registry_free(reg);
}

TEST_LIST(TEST_CASE(descriptor_and_schema),
          TEST_CASE(no_void_under_the_horizon),
          TEST_CASE(levels_of_detail_match_uniform_and_close),
          TEST_CASE(site_places_and_warps_the_dtm),
          TEST_CASE(snow_and_scree_in_metres),
          TEST_CASE(inline_dtm_deterministic),
          TEST_CASE(default_surface_passes_through_every_node),
          TEST_CASE(generated_dtm_random_iteration),
          TEST_CASE(surface_from_scene),
          TEST_CASE(humidity_map_dries_grass),
          TEST_CASE(dtm_file_relative_to_scene),
          TEST_CASE(bad_input_is_refused_clearly))
