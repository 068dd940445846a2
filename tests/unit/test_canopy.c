/* test_canopy.c — a site's canopy heights (site/canopy_read.h, the canopy: section) and the
 * visibility map's canopy screening (ztv/ztv_canopy.h): a small CHM read onto the site's nodes
 * exactly (its no-data and its heights below the ground), a surface model less its terrain model
 * giving the same heights, bad sections and files refused at their keys, the shared ForestTools CHM
 * in longitude and latitude read onto a UTM site as GDAL's own nearest-neighbour warp reads it, and
 * a wall of canopy that hides a mast from the observers behind it in canopy mode, not on bare
 * earth, with the observers inside it under the canopy and bare earth unchanged by the canopy. The
 * shared-data case skips without ../shared/data. */
#include <gdal.h>
#include <gdal_utils.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "geotiff_fixture.h"
#include "harness.h"
#include "scene_build/scene_build.h"
#include "scene_build/scene_canopy.h"
#include "scene_file/scene_file.h"
#include "work_dir.h"
#include "ztv_fixture.h"

#define E0 500000.0  /* the site origin, UTM zone 11N */
#define N0 5500000.0
#define NO_DATA -9999.0f

/* A flat site of 5 x 3 nodes 10 m apart, local x -20 to 20 and y -10 to 10, then `tail`. */
static const char site_yaml[] = "site: {crs: \"EPSG:32611\", origin: [500000, 5500000]}\n"
                                "terrain: {grid: [[0, 0, 0, 0, 0], [0, 0, 0, 0, 0], [0, 0, 0, 0, 0]], "
                                "origin: [-20, -10], spacing: [10, 10]}\n%s";

/* The 5 x 3 CHM on that site's nodes (10 m pixels centred on them), rows north to south. */
static const float chm_cells[15] = {0, 3, 12.5f, -0.2f, NO_DATA, 1, 2, 3, 4, 5, -1.5f, 0, 30, 0, 7};

/* A Float32 GeoTIFF in the work folder, EPSG:32611, w x h cells of `cell` m from the north-west
 * corner (x0, y0), holding v (rows north to south) and no-data NO_DATA. */
static const char *raster_fixture(const char *name, const float *v, int w, int h, double cell, double x0, double y0)
{
    const char *path = work_path(name);
    GDALDatasetH ds = geotiff_create(path, 32611, x0, y0, cell, w, h, GDT_Float32);
    if (!ds) return NULL;
    GDALSetRasterNoDataValue(GDALGetRasterBand(ds, 1), NO_DATA);
    CPLErr e = GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, w, h, (void *)v, w, h, GDT_Float32, 0, 0);
    GDALClose(ds);
    return e == CE_None ? path : NULL;
}

/* The scene of text (written as NAME in the work folder), built quietly for an analysis, or NULL
 * with err set. */
static scene *build_text(const char *name, const char *text, err_buf *err)
{
    const char *path = work_file(name, text);
    scene_file *sf = path ? scene_file_load_with(path, NULL, SCENE_FILE_NO_CAMERA, err) : NULL;
    build_options opt = {.analysis = 1, .quiet = 1};
    scene *s = sf ? scene_build(sf, NULL, &opt, err) : NULL;
    scene_file_free(sf);
    return s;
}

/* The 5 x 3 site with canopy section `canopy`, or NULL with err set. */
static scene *small_site(const char *section, err_buf *err)
{
    char text[2048], tail[512];
    snprintf(tail, sizeof tail, "canopy: %s\n", section);
    snprintf(text, sizeof text, site_yaml, tail);
    return build_text("site.yaml", text, err);
}

/* The loader's sentence for a canopy section; "" when the scene loads. */
static const char *refusal(const char *section)
{
    static err_buf err;
    memset(&err, 0, sizeof err);
    scene *s = small_site(section, &err);
    scene_free(s);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    return s ? "" : err.msg;
}

/* The CHM on the nodes, exactly: no data NAN, heights below the ground 0. */
TEST(chm_on_the_nodes)
{
    CHECK(raster_fixture("chm.tif", chm_cells, 5, 3, 10, E0 - 25, N0 + 15) != NULL);
    err_buf err = {{0}};
    scene *s = small_site("{chm: chm.tif}", &err);
    CHECK(s != NULL && s->canopy != NULL);
    if (!s || !s->canopy) return;
    const canopy *c = s->canopy;
    CHECK_INT(c->nx, 5);
    CHECK_INT(c->ny, 3);
    CHECK_INT(c->no_data, 1);
    for (int row = 0; row < 3; row++)
        for (int i = 0; i < 5; i++) {
            float want = chm_cells[row * 5 + i], got = c->height[(2 - row) * 5 + i];
            if (want == NO_DATA) CHECK(isnan(got));
            else CHECK_NEAR(got, fmaxf(want, 0.0f), 0.0);
        }
    CHECK_NEAR(canopy_height_at(c, 0, 10), 12.5, 0.0); /* north row, middle node */
    CHECK_NEAR(canopy_height_at(c, 4.9, -10), 30, 0.0);
    CHECK(isnan(canopy_height_at(c, 20, 10)) && isnan(canopy_height_at(c, 26, 0)));
    scene_free(s);
}

/* A surface model less its terrain model (sloping, in a coarser and shifted grid of its own) gives
 * the CHM's heights at every node. */
TEST(dsm_less_dtm_is_the_chm)
{
    float dtm[7 * 5], dsm[15];
    for (int j = 0; j < 5; j++)
        for (int i = 0; i < 7; i++) dtm[j * 7 + i] = 800.0f + 0.5f * (float)i - 0.25f * (float)j;
    for (int row = 0; row < 3; row++)
        for (int i = 0; i < 5; i++) {
            /* node (i, row) lies in the DTM's cell (i + 1, row + 1) */
            float h = chm_cells[row * 5 + i];
            dsm[row * 5 + i] = h == NO_DATA ? NO_DATA : dtm[(row + 1) * 7 + i + 1] + h;
        }
    CHECK(raster_fixture("dtm.tif", dtm, 7, 5, 10, E0 - 35, N0 + 25) != NULL);
    CHECK(raster_fixture("dsm.tif", dsm, 5, 3, 10, E0 - 25, N0 + 15) != NULL);
    CHECK(raster_fixture("chm.tif", chm_cells, 5, 3, 10, E0 - 25, N0 + 15) != NULL);
    err_buf err = {{0}};
    scene *a = small_site("{chm: chm.tif}", &err), *b = small_site("{dsm: dsm.tif, dtm: dtm.tif}", &err);
    CHECK(a && b && a->canopy && b->canopy);
    for (int k = 0; a && b && a->canopy && b->canopy && k < 15; k++) {
        float x = a->canopy->height[k], y = b->canopy->height[k];
        CHECK((isnan(x) && isnan(y)) || fabsf(x - y) < 1e-4f);
    }
    CHECK(b && b->canopy && strstr(b->canopy->source, "dsm.tif less dtm.tif"));
    scene_free(a), scene_free(b);
}

TEST(bad_sections_refused_at_their_keys)
{
    CHECK(raster_fixture("chm.tif", chm_cells, 5, 3, 10, E0 - 25, N0 + 15) != NULL);
    CHECK_STR_CONTAINS(refusal("{chm: chm.tif, dsm: chm.tif}"),
                       "site.yaml:3:29: 'canopy' gives both 'chm' and 'dsm'; give one source of heights: chm: FILE");
    CHECK_STR_CONTAINS(refusal("{chm: chm.tif, dtm: chm.tif}"), "site.yaml:3:29: 'canopy' gives both 'chm' and 'dtm'");
    CHECK_STR_CONTAINS(refusal("{dsm: chm.tif}"), "site.yaml:3:15: 'dsm' needs dtm: FILE, the terrain model under it");
    CHECK_STR_CONTAINS(refusal("{dtm: chm.tif}"), "site.yaml:3:15: 'dtm' is the terrain model under a surface model");
    CHECK_STR_CONTAINS(refusal("{}"), "site.yaml:3:1: 'canopy' names no heights; give chm: FILE");
    CHECK_STR_CONTAINS(refusal("{chm: nowhere.tif}"), "site.yaml:3:15: the canopy's 'chm':");
    CHECK_STR_CONTAINS(refusal("{dsm: chm.tif, dtm: nowhere.tif}"), "site.yaml:3:29: the canopy's 'dtm':");
    work_file("notes.txt", "not a raster\n");
    CHECK_STR_CONTAINS(refusal("{chm: notes.txt}"), "site.yaml:3:15: the canopy height model");
    CHECK_STR_CONTAINS(refusal("{chm: notes.txt}"), "it is not a raster GDAL reads");
    CHECK_STR_CONTAINS(refusal("{chm: chm.tif, height: 3}"), "site.yaml:3:24:");
    /* read onto the grid: a model off the site, one of elevations, no site */
    CHECK(raster_fixture("far.tif", chm_cells, 5, 3, 10, E0 + 5000, N0 + 15) != NULL);
    CHECK_STR_CONTAINS(refusal("{chm: far.tif}"), "site.yaml:3:15: the canopy height model");
    CHECK_STR_CONTAINS(refusal("{chm: far.tif}"), "it covers none of the site's 5 x 3 nodes (10 m apart)");
    float high[15];
    for (int k = 0; k < 15; k++) high[k] = 812.0f + (float)k;
    CHECK(raster_fixture("dem.tif", high, 5, 3, 10, E0 - 25, N0 + 15) != NULL);
    CHECK_STR_CONTAINS(refusal("{chm: dem.tif}"), "site.yaml:3:15: the canopy height model");
    CHECK_STR_CONTAINS(refusal("{chm: dem.tif}"), "it holds elevations (a surface model); give dsm: FILE and dtm: FILE");
    CHECK_STR_CONTAINS(refusal("{dsm: far.tif, dtm: chm.tif}"), "site.yaml:3:15: the surface model");
    const char *path = work_file("nosite.yaml", "terrain: {grid: [[0, 0], [0, 0]]}\ncanopy: {chm: chm.tif}\n");
    err_buf err = {{0}};
    scene_file *sf = path ? scene_file_load_with(path, NULL, SCENE_FILE_NO_CAMERA, &err) : NULL;
    CHECK(sf == NULL);
    CHECK_STR_CONTAINS(err.msg, "nosite.yaml:2:1: 'canopy' puts heights on the site, but the scene has no 'site:'");
    scene_file_free(sf);
}

/* The heights GDAL's warper gives the canopy's nodes from the raster at path (nearest neighbour,
 * exact transformation), row j = 0 south, NAN where it has none; NULL on failure. */
static float *warped_heights(const char *path, const canopy *c, const scene *s)
{
    GDALDatasetH src = GDALOpen(path, GA_ReadOnly);
    GDALDatasetH dst = GDALCreate(GDALGetDriverByName("MEM"), "", (int)c->nx, (int)c->ny, 1, GDT_Float32, NULL);
    double gt[6] = {s->site.origin[0] + c->x0 - 0.5 * c->dx, c->dx, 0, s->site.origin[1] + c->y0 + (c->ny - 0.5) * c->dy,
                    0, -c->dy};
    GDALSetGeoTransform(dst, gt);
    GDALSetProjection(dst, s->site.crs_wkt);
    GDALSetRasterNoDataValue(GDALGetRasterBand(dst, 1), NAN);
    GDALFillRaster(GDALGetRasterBand(dst, 1), NAN, 0);
    char *args[] = {"-r", "near", "-et", "0", NULL};
    GDALWarpAppOptions *o = GDALWarpAppOptionsNew(args, NULL);
    int usage = 0;
    GDALDatasetH done = src && dst && o ? GDALWarp(NULL, dst, 1, &src, o, &usage) : NULL;
    float *h = done ? malloc((size_t)c->nx * c->ny * sizeof *h) : NULL;
    for (uint32_t j = 0; h && j < c->ny; j++)
        if (GDALRasterIO(GDALGetRasterBand(dst, 1), GF_Read, 0, (int)(c->ny - 1 - j), (int)c->nx, 1,
                         h + (size_t)j * c->nx, (int)c->nx, 1, GDT_Float32, 0, 0) != CE_None)
            free(h), h = NULL;
    GDALWarpAppOptionsFree(o);
    if (dst) GDALClose(dst);
    if (src) GDALClose(src);
    return h;
}

/* ForestTools' CHM in longitude and latitude (EPSG:4326) read onto a UTM site 1 m apart: the node
 * heights are those of GDAL's nearest-neighbour warp, and within 1 m of the UTM original's. */
TEST(foresttools_chm_in_degrees)
{
    const char *dir = SYLVA_SHARED_DATA_DIR "/canopy/foresttools";
    struct stat st;
    if (stat(SYLVA_SHARED_DATA_DIR "/canopy/foresttools/CHM_latlon.tif", &st) != 0)
        SKIP("the shared data set is not at %s", dir);
    static char text[65536];
    int at = snprintf(text, sizeof text, "site: {crs: \"EPSG:32611\", origin: [439944.125, 5526694.125]}\n"
                      "terrain: {origin: [-50, -40], spacing: [1, 1], grid: [");
    for (int j = 0; j <= 80; j++) {
        at += snprintf(text + at, sizeof text - at, "%s[", j ? ", " : "");
        for (int i = 0; i <= 100; i++) at += snprintf(text + at, sizeof text - at, "%s800", i ? ", " : "");
        at += snprintf(text + at, sizeof text - at, "]");
    }
    char tail[512];
    snprintf(tail, sizeof tail, "]}\ncanopy: {chm: %s/CHM_latlon.tif}\n", dir);
    snprintf(text + at, sizeof text - at, "%s", tail);
    err_buf err = {{0}};
    scene *s = build_text("latlon.yaml", text, &err);
    snprintf(tail, sizeof tail, "]}\ncanopy: {chm: %s/CHM_test.tif}\n", dir);
    snprintf(text + at, sizeof text - at, "%s", tail);
    scene *u = build_text("utm.yaml", text, &err);
    CHECK(s && s->canopy && u && u->canopy);
    if (!s || !s->canopy || !u || !u->canopy) return scene_free(s), scene_free(u);
    char path[1024];
    snprintf(path, sizeof path, "%s/CHM_latlon.tif", dir);
    float *w = warped_heights(path, s->canopy, s);
    CHECK(w != NULL);
    size_t n = (size_t)s->canopy->nx * s->canopy->ny, same = 0, near_utm = 0, both = 0;
    for (size_t k = 0; w && k < n; k++) {
        float a = s->canopy->height[k], b = w[k] < 0 ? 0 : w[k], c = u->canopy->height[k];
        same += (isnan(a) && isnan(b)) || a == b;
        if (!isnan(a) && !isnan(c)) both++, near_utm += fabsf(a - c) <= 1.0f;
    }
    fprintf(stderr, "CHM_latlon on %zu UTM nodes: %.3f %% as GDAL's warp; %.1f %% within 1 m of CHM_test.tif\n", n,
            100.0 * same / n, 100.0 * near_utm / both);
    CHECK(same >= 0.999 * n);
    CHECK(near_utm >= 0.95 * both);
    free(w);
    scene_free(s), scene_free(u);
}

/* The modelled height of instance i: its prototype's height times its vertical scale. */
static double plant_height(const scene *s, uint32_t i)
{
    return s->prototypes[s->instances[i].prototype].height * s->instances[i].xf.m[2][2];
}

/* Plants fitted to the CHM of the small site, one at a node of each case: a fir (a 10 m box) that
 * reaches the canopy scaled to it; a fir under a canopy no fir reaches (30 m over a 10 m model)
 * kept; a shrub (2 m) scaled up to a 3 m canopy and one under a 5 m canopy kept; firs where the
 * canopy is 0 and below the ground removed; a fir on no data kept as grown; a fir of the
 * development kept where the canopy is below 0.5 m. The survivors keep their order and positions. */
TEST(plants_fitted_to_the_canopy)
{
    CHECK(raster_fixture("chm.tif", chm_cells, 5, 3, 10, E0 - 25, N0 + 15) != NULL);
    static const char plants[] =
        "{chm: chm.tif}\nspecies:\n  fir: {shape: box, size: [1, 1, 10]}\n  shrub: {shape: box, size: [1, 1, 2]}\n"
        "plants:\n"
        "  - {species: fir, position: [0, 10], rotation: 30}\n"    /* 12.5 m: scaled to it */
        "  - {species: fir, position: [0, -10]}\n"                 /* 30 m: kept */
        "  - {species: shrub, position: [-10, 10]}\n"              /* 3 m: scaled to it */
        "  - {species: shrub, position: [20, 0]}\n"                /* 5 m: understorey, kept */
        "  - {species: fir, position: [-20, 10]}\n"                /* 0 m: removed */
        "  - {species: fir, position: [20, 10], scale: 0.8}\n"     /* no data: kept as grown */
        "  - {species: fir, position: [10, 10]}\n"                 /* -0.2 m: removed */
        "  - {species: fir, position: [-10, -10], development: true}\n";
    err_buf err = {{0}};
    scene *s = small_site(plants, &err);
    CHECK(s != NULL);
    if (!s) return;
    CHECK_INT(s->n_instances, 8); /* hand-placed plants are not fitted by the build */
    const char *path = work_path("site.yaml");
    scene_file *sf = scene_file_load_with(path, NULL, SCENE_FILE_NO_CAMERA, &err);
    CHECK(sf != NULL);
    if (sf) scene_canopy_fit_plants(s, sf, 0, 0);
    static const double want[6][3] = {{0, 10, 12.5}, {0, -10, 10}, {-10, 10, 3}, {20, 0, 2}, {20, 10, 8},
                                      {-10, -10, 10}};
    CHECK_INT(s->n_instances, 6);
    for (uint32_t i = 0; i < 6 && i < s->n_instances; i++) {
        CHECK_NEAR(s->instances[i].xf.m[0][3], want[i][0], 1e-6);
        CHECK_NEAR(s->instances[i].xf.m[1][3], want[i][1], 1e-6);
        CHECK_NEAR(plant_height(s, i), want[i][2], 1e-4);
    }
    const float(*m)[4] = s->instances[0].xf.m; /* still turned by 30 degrees, uniformly scaled */
    CHECK_NEAR(atan2(m[1][0], m[0][0]) * 180 / M_PI, 30, 1e-3);
    CHECK_NEAR(hypot(m[0][0], m[1][0]), 1.25, 1e-5);
    scene_file_free(sf);
    scene_free(s);
}

/* Every block's canopy layer and bare layer, copied into whole-map arrays. */
typedef struct map_copy {
    uint32_t nx;
    uint16_t *visible[2]; /* bare, canopy */
    uint8_t *cls[2];
} map_copy;

static int copy_block(void *user, const ztv_block *b, err_buf *err)
{
    (void)err;
    map_copy *m = user;
    const ztv_layer *l[2] = {b->layer[ZTV_BARE], b->layer[ZTV_CANOPY]};
    for (int k = 0; k < 2; k++) {
        if (!l[k]) continue;
        memcpy(m->visible[k] + (size_t)b->j0 * m->nx, l[k]->visible, (size_t)b->rows * m->nx * sizeof(uint16_t));
        memcpy(m->cls[k] + (size_t)b->j0 * m->nx, l[k]->cls, (size_t)b->rows * m->nx);
    }
    return 0;
}

/* The map's arrays for its grid. */
static void map_alloc(void *user, const ztv_grid *g)
{
    map_copy *m = user;
    size_t n = (size_t)g->nx * g->ny;
    m->nx = g->nx;
    for (int k = 0; k < 2; k++) m->visible[k] = calloc(n, sizeof(uint16_t)), m->cls[k] = calloc(n, 1);
}

/* The map of the scene of text in mode, on threads threads, into *m (arrays the caller frees). */
static int map_of(const char *text, ztv_mode mode, unsigned threads, map_copy *m)
{
    err_buf err = {{0}};
    const char *path = work_file("wall.yaml", text);
    scene_file *sf = path ? scene_file_load_with(path, NULL, SCENE_FILE_NO_CAMERA, &err) : NULL;
    build_options bo = {.analysis = 1, .quiet = 1};
    scene *s = sf ? scene_build(sf, NULL, &bo, &err) : NULL;
    int rc = s ? ztv_fixture_trace(sf, s, mode, threads, map_alloc, copy_block, m, &err) : -1;
    if (rc) fprintf(stderr, "%s\n", err.msg);
    scene_free(s);
    scene_file_free(sf);
    return rc;
}

static void map_free(map_copy *m)
{
    for (int k = 0; k < 2; k++) free(m->visible[k]), free(m->cls[k]);
}

/* A wall of canopy 15 m high along x = 0 (the CHM's column of nodes there; the surface slopes to it
 * from the nodes 5 m either side), a mast 10 m high at x = 100 on a flat site. An observer 2 m up
 * west of the wall is hidden from the mast: the sightline from (x, 2) passes x = 0 at most at
 * 2 + 8 * 5 / 105 m. Observers on the wall's nodes stand under the canopy; east of it, all see the
 * mast. Bare earth sees it from everywhere, the same with and without the canopy, and the canopy
 * map is the same on one thread and on three. */
TEST(canopy_wall_hides_the_mast)
{
    float wall[41 * 5];
    for (int k = 0; k < 41 * 5; k++) wall[k] = k % 41 == 20 ? 15.0f : 0.0f;
    CHECK(raster_fixture("wall.tif", wall, 41, 5, 5, E0 - 102.5, N0 + 12.5) != NULL);
    static char text[8192];
    int at = snprintf(text, sizeof text, "site: {crs: \"EPSG:32611\", origin: [500000, 5500000]}\n"
                      "earth: {curvature: false}\nterrain: {origin: [-100, -10], spacing: [5, 5], grid: [");
    for (int j = 0; j < 5; j++) {
        at += snprintf(text + at, sizeof text - at, "%s[", j ? ", " : "");
        for (int i = 0; i <= 40; i++) at += snprintf(text + at, sizeof text - at, "%s0", i ? ", " : "");
        at += snprintf(text + at, sizeof text - at, "]");
    }
    at += snprintf(text + at, sizeof text - at, "]}\nztv: {targets: [{position: [100, 0], height_above_ground: 10}]}\n");
    map_copy bare = {0}, one = {0}, three = {0};
    CHECK_INT(map_of(text, ZTV_BARE, 2, &bare), 0);
    snprintf(text + at, sizeof text - at, "canopy: {chm: wall.tif}\n");
    CHECK_INT(map_of(text, ZTV_CANOPY, 1, &one), 0);
    CHECK_INT(map_of(text, ZTV_CANOPY, 3, &three), 0);
    size_t n = 41 * 5;
    for (size_t k = 0; one.cls[1] && k < n; k++) {
        int i = (int)(k % 41);
        CHECK_INT(bare.visible[0][k], 1);
        CHECK_INT(one.visible[0][k], bare.visible[0][k]);
        CHECK_INT(one.cls[1][k], i == 20 ? ZTV_UNDER_CROWN : ZTV_OPEN);
        CHECK_INT(one.visible[1][k], i > 20 ? 1 : 0);
    }
    CHECK(one.cls[1] && three.cls[1] && !memcmp(one.cls[1], three.cls[1], n));
    CHECK(one.visible[1] && three.visible[1] && !memcmp(one.visible[1], three.visible[1], n * sizeof(uint16_t)));
    map_free(&bare), map_free(&one), map_free(&three);
}

TEST_LIST(TEST_CASE(chm_on_the_nodes), TEST_CASE(dsm_less_dtm_is_the_chm), TEST_CASE(bad_sections_refused_at_their_keys),
          TEST_CASE(foresttools_chm_in_degrees), TEST_CASE(canopy_wall_hides_the_mast),
          TEST_CASE(plants_fitted_to_the_canopy))
