/* test_ifs_big_dtm.c — a landscape-scale DTM through the real host: a 10,000 x 10,000 GeoTIFF
 * (written by the test with GDAL's API into its work folder, work_dir.h) loads, and its Embree scene
 * builds, within the memory per node stated in docs/models/terrain_ifs.md, and a memory budget
 * too small for it is refused with a sentence before the DTM is read. Label slow: writing and
 * reading 400 MB, building a BVH over 100 M points. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gdal.h>
#include <ogr_srs_api.h>

#include "harness.h"
#include "work_dir.h"
#include "plugin/plugin_host.h"
#include "render/accel.h"
#include "scene/scene.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

#define BIG_SIDE 10000u
/* What the plugin and the host hold per node of a DTM refined once (refine: 1): the DTM's
 * double (8), the heightfield's height and material (4 + 4) and the class byte while
 * classifying (1); GDAL's cache holds one row of blocks beside it. */
#define BIG_BYTES_PER_NODE 17.0
/* ... and the renderer's grid vertex and BVH at the peak of its build (scene/heightfield.h) */
#define BIG_RENDER_BYTES_PER_NODE 32.0
#define BIG_SLACK (96.0 * 1024 * 1024)

static double big_height(uint32_t i, uint32_t j)
{
    return 800.0 + 150.0 * sin(i / 700.0) * cos(j / 900.0) + 0.01 * ((i * 7 + j * 13) % 101);
}

/* Writes the GeoTIFF (UTM zone 11N, 30 m pixels, tiled) in a child process, so that GDAL's
 * write cache does not count in this process's peak memory. */
static int write_big_geotiff(const char *path)
{
    pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        GDALAllRegister();
        char *opts[] = {"TILED=YES", "BLOCKXSIZE=256", "BLOCKYSIZE=256", NULL};
        GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path, BIG_SIDE, BIG_SIDE, 1,
                                     GDT_Float32, opts);
        if (!ds) _exit(1);
        double gt[6] = {400000, 30, 0, 4000000, 0, -30};
        GDALSetGeoTransform(ds, gt);
        OGRSpatialReferenceH srs = OSRNewSpatialReference(NULL);
        OSRImportFromEPSG(srs, 32611);
        GDALSetSpatialRef(ds, srs);
        OSRDestroySpatialReference(srs);
        GDALRasterBandH b = GDALGetRasterBand(ds, 1);
        float *rows = malloc((size_t)BIG_SIDE * 256 * sizeof *rows);
        if (!rows) _exit(1);
        for (uint32_t r0 = 0; r0 < BIG_SIDE; r0 += 256) {
            uint32_t n = BIG_SIDE - r0 < 256 ? BIG_SIDE - r0 : 256;
            for (uint32_t r = 0; r < n; r++)
                for (uint32_t i = 0; i < BIG_SIDE; i++)  /* file row 0 is the north edge */
                    rows[(size_t)r * BIG_SIDE + i] = (float)big_height(i, BIG_SIDE - 1 - (r0 + r));
            if (GDALRasterIO(b, GF_Write, 0, (int)r0, BIG_SIDE, (int)n, rows, BIG_SIDE, (int)n,
                             GDT_Float32, 0, 0) != CE_None)
                _exit(1);
        }
        free(rows);
        GDALClose(ds);
        _exit(0);
    }
    int status = 0;
    if (waitpid(pid, &status, 0) != pid) return -1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

static double peak_bytes(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss * 1024.0;
}

static scene *load(const char *scene_path, plugin_registry *reg, err_buf *err)
{
    err_clear(err);
    scene_file *sf = scene_file_load(scene_path, reg, err);
    if (!sf) return NULL;
    build_options opt = {.quiet = 1};
    scene *s = scene_build(sf, reg, &opt, err);
    scene_file_free(sf);
    return s;
}

TEST(geotiff_10000_squared_loads)
{
    char tif[1200];
    snprintf(tif, sizeof tif, "%s/big.tif", work_dir());
    double t0 = harness_seconds();
    CHECK(write_big_geotiff(tif) == 0);
    double t1 = harness_seconds();
    const char *yaml = work_file("big.yaml",
                                 "image: {width: 16, height: 16, spp: 1}\n"
                                 "camera: {position: [0, -300, 1500], look_at: [0, 0, 800]}\n"
                                 "terrain:\n  plugin: terrain_ifs\n  dtm: big.tif\n  refine: 1\n"
                                 "  method: deterministic\n  alpha: 0\n  threads: 2\n");
    CHECK(yaml != NULL);
    if (!yaml) return;
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open_path(SYLVA_PLUGIN_BUILD_DIR, &err);
    CHECK(reg != NULL);
    if (reg) {
        /* a budget too small: refused before the DTM is read, naming the DTM and both sizes */
        setenv("SYLVA_MEMORY_LIMIT", "1G", 1);
        scene *s = load(yaml, reg, &err);
        unsetenv("SYLVA_MEMORY_LIMIT");
        CHECK(s == NULL);
        scene_free(s);
        CHECK_STR_CONTAINS(err.msg, "10000 x 10000 node DTM");
        CHECK_STR_CONTAINS(err.msg, "SYLVA_MEMORY_LIMIT");
        fprintf(stderr, "refused: %s\n", err.msg);

        double before = peak_bytes(), t2 = harness_seconds();
        s = load(yaml, reg, &err);
        double t3 = harness_seconds(), grown = peak_bytes() - before;
        CHECK(s != NULL && s->terrain != NULL);
        if (!s) fprintf(stderr, "%s\n", err.msg);
        if (s && s->terrain) {
            const sylva_heightfield *t = s->terrain;
            CHECK_INT(t->nx, BIG_SIDE);
            CHECK_INT(t->ny, BIG_SIDE);
            CHECK_NEAR(t->dx, 30, 1e-9);
            const uint32_t probe[4][2] = {{0, 0}, {9999, 0}, {1234, 8765}, {9999, 9999}};
            for (int k = 0; k < 4; k++) {
                uint32_t i = probe[k][0], j = probe[k][1];
                CHECK_NEAR(t->z[(size_t)j * BIG_SIDE + i], (float)big_height(i, j), 1e-3);
            }
            double bound = BIG_BYTES_PER_NODE * BIG_SIDE * BIG_SIDE + BIG_SLACK;
            fprintf(stderr, "written in %.1f s; loaded in %.1f s; peak memory grew %.0f MB "
                    "(%.1f bytes a node; bound %.0f MB)\n", t1 - t0, t3 - t2, grown / 1048576.0,
                    grown / ((double)BIG_SIDE * BIG_SIDE), bound / 1048576.0);
            CHECK(grown <= bound);
            /* the Embree scene over all 100 M points */
            accel a;
            double t4 = harness_seconds();
            CHECK_INT(accel_build(&a, s, 2, &err), 0);
            double t5 = harness_seconds(), all = peak_bytes() - before;
            double all_bound = (BIG_BYTES_PER_NODE + BIG_RENDER_BYTES_PER_NODE) * BIG_SIDE * BIG_SIDE + BIG_SLACK;
            fprintf(stderr, "Embree scene built in %.1f s; peak memory grew %.0f MB in all (%.1f bytes a node; "
                    "bound %.0f MB)\n", t5 - t4, all / 1048576.0, all / ((double)BIG_SIDE * BIG_SIDE),
                    all_bound / 1048576.0);
            CHECK(all <= all_bound);
            /* a ray straight down onto node (1234, 8765) finds its height */
            struct RTCRayHit rh = {.ray = {.org_x = (float)(t->x0 + 1234 * t->dx), .org_y = (float)(t->y0 + 8765 * t->dy),
                                           .org_z = 5000, .dir_z = -1, .tfar = INFINITY, .mask = 0xffffffffu},
                                   .hit = {.geomID = RTC_INVALID_GEOMETRY_ID, .instID = {RTC_INVALID_GEOMETRY_ID}}};
            struct RTCIntersectContext ic;
            rtcInitIntersectContext(&ic);
            rtcIntersect1(a.top, &ic, &rh);
            CHECK_INT(rh.hit.geomID, ACCEL_TOP_TERRAIN);
            CHECK_NEAR(5000 - rh.ray.tfar, big_height(1234, 8765), 0.01);
            accel_free(&a);
        }
        scene_free(s);
        plugin_registry_free(reg);
    }
}

TEST_LIST(TEST_CASE(geotiff_10000_squared_loads))
