/* terrain_big.c — a landscape-scale terrain end to end: a DTM of SIDE x SIDE nodes (default
 * 10,000 x 10,000: 100 M points) written as a GeoTIFF into a temporary folder, loaded and
 * refined by terrain_ifs (deterministic f_K, alpha 0.1, the default refine 4 in levels of
 * detail around the camera: the DTM's nodes everywhere), its Embree scene built and
 * the first pixel rendered, with the time of each stage and the peak memory. The baseline is
 * measured in the same run: raw Embree building the same heightfield (a BASE x BASE crop of it,
 * default 5,000 x 5,000, as the triangle mesh would not fit beside it at full size) as plain
 * indexed triangles, against the grid geometry sylva uses on the same crop, each in its own
 * process so that its peak is its own.
 *
 * usage: terrain_big [SIDE [BASE]]   (BASE 0: no baseline) */
#include <embree3/rtcore.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <gdal.h>
#include <ogr_srs_api.h>

#include "bench_machine.h"
#include "plugin/plugin_host.h"
#include "render/render.h"
#include "scene/scene.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

/* VmHWM or VmRSS of this process in bytes (/proc/self/status). */
static double proc_bytes(const char *key)
{
    FILE *f = fopen("/proc/self/status", "r");
    char line[256];
    double kb = 0;
    while (f && fgets(line, sizeof line, f))
        if (!strncmp(line, key, strlen(key))) kb = atof(line + strlen(key) + 1);
    if (f) fclose(f);
    return kb * 1024.0;
}

static double height(uint32_t i, uint32_t j)
{
    return 900.0 + 300.0 * sin(i / 900.0) * cos(j / 1100.0) + 40.0 * sin(i / 61.0 + j / 47.0);
}

static int write_geotiff(const char *path, uint32_t side)
{
    GDALAllRegister();
    char *opts[] = {"TILED=YES", NULL};
    GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path, (int)side, (int)side, 1, GDT_Float32, opts);
    if (!ds) return -1;
    double gt[6] = {400000, 30, 0, 4000000, 0, -30};
    GDALSetGeoTransform(ds, gt);
    OGRSpatialReferenceH srs = OSRNewSpatialReference(NULL);
    OSRImportFromEPSG(srs, 32611);
    GDALSetSpatialRef(ds, srs);
    OSRDestroySpatialReference(srs);
    float *row = malloc((size_t)side * sizeof *row);
    int rc = row ? 0 : -1;
    for (uint32_t r = 0; !rc && r < side; r++) {
        for (uint32_t i = 0; i < side; i++) row[i] = (float)height(i, side - 1 - r);
        if (GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, (int)r, (int)side, 1, row, (int)side, 1,
                         GDT_Float32, 0, 0) != CE_None)
            rc = -1;
    }
    free(row);
    GDALClose(ds);
    return rc;
}

/* Raw Embree on a base x base crop of hf: plain indexed triangles (grid 0) or grid geometry
 * (grid 1), in a child process; prints its build time and memory. */
static void raw_embree(const sylva_heightfield *hf, uint32_t base, int grid)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid != 0) {
        waitpid(pid, NULL, 0);
        return;
    }
    double rss0 = proc_bytes("VmRSS:"), t0 = now();
    size_t nv = (size_t)base * base;
    float *v = malloc((nv * 3 + 1) * sizeof *v);
    if (!v) _exit(1);
    for (uint32_t j = 0; j < base; j++)
        for (uint32_t i = 0; i < base; i++) {
            float *p = v + ((size_t)(grid ? base - 1 - j : j) * base + i) * 3;
            p[0] = (float)(hf->x0 + i * hf->dx), p[1] = (float)(hf->y0 + j * hf->dy);
            p[2] = hf->z[(size_t)j * hf->nx + i];
        }
    RTCDevice d = rtcNewDevice("threads=2");
    RTCScene s = rtcNewScene(d);
    RTCGeometry g = rtcNewGeometry(d, grid ? RTC_GEOMETRY_TYPE_GRID : RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, v, 0, 12, nv);
    if (grid) {
        struct RTCGrid *t = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_GRID, 0, RTC_FORMAT_GRID, sizeof *t, 1);
        *t = (struct RTCGrid){.startVertexID = 0, .stride = base, .width = (unsigned short)base,
                              .height = (unsigned short)base};
    } else {
        size_t nt = (size_t)(base - 1) * (base - 1) * 2, k = 0;
        unsigned *ix = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, nt);
        for (uint32_t j = 0; j + 1 < base; j++)
            for (uint32_t i = 0; i + 1 < base; i++) {
                unsigned a = j * base + i, b = a + 1, c = a + base, e = c + 1;
                unsigned q[6] = {a, b, e, a, e, c};
                memcpy(ix + k, q, sizeof q), k += 6;
            }
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(s, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(s);
    double t1 = now(), grown = proc_bytes("VmHWM:") - rss0;
    printf("  raw Embree, %u x %u nodes as %-19s build %6.2f s, peak %6.0f MB = %5.1f bytes a node\n", base,
           base, grid ? "grid geometry:" : "indexed triangles:", t1 - t0, grown / 1048576.0, grown / nv);
    fflush(stdout);
    _exit(0);
}

int main(int argc, char **argv)
{
    uint32_t side = argc > 1 ? (uint32_t)atoi(argv[1]) : 10000, base = argc > 2 ? (uint32_t)atoi(argv[2]) : 5000;
    if (side < 3 || side > 32767 || base > side) {
        fprintf(stderr, "usage: terrain_big [SIDE (3..32767) [BASE (0..SIDE)]]\n");
        return 2;
    }
    char cpu[128];
    bench_cpu_model(cpu, sizeof cpu);
    printf("terrain_big: %u x %u DTM (%.0f M points), 2 threads, %s\n", side, side, side * (double)side / 1e6, cpu);
    char dir[] = "/tmp/sylva-terrain-big-XXXXXX", tif[96], yaml[96];
    if (!mkdtemp(dir)) return 1;
    snprintf(tif, sizeof tif, "%s/dtm.tif", dir);
    snprintf(yaml, sizeof yaml, "%s/scene.yaml", dir);
    double t0 = now();
    pid_t pid = fork();
    if (pid == 0) _exit(write_geotiff(tif, side) ? 1 : 0);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status)) {
        fprintf(stderr, "terrain_big: could not write %s\n", tif);
        return 1;
    }
    printf("  GeoTIFF written (input, not timed below): %.1f s\n", now() - t0);
    FILE *f = fopen(yaml, "w");
    if (!f) return 1;
    double mid = (side - 1) * 30.0 / 2;
    fprintf(f, "image: {width: 1, height: 1, spp: 1}\n"
               "camera: {position: [0, %g, 2500], look_at: [0, 0, 900]}\n"
               "terrain:\n  plugin: terrain_ifs\n  dtm: dtm.tif\n  method: deterministic\n"
               "  alpha: 0.1\n  threads: 2\n", -mid);
    fclose(f);

    err_buf err = {{0}};
    double t1 = now();
    plugin_registry *reg = plugin_registry_open_path(SYLVA_PLUGIN_BUILD_DIR, &err);
    scene_file *sf = reg ? scene_file_load(yaml, reg, &err) : NULL;
    build_options bo = {.quiet = 1};
    scene *s = sf ? scene_build(sf, reg, &bo, &err) : NULL;
    double t2 = now();
    if (!s) {
        fprintf(stderr, "terrain_big: %s\n", err.msg);
        return 1;
    }
    render_options ro = {.threads = 2, .quiet = 1};
    render_stats st = {0};
    film *fm = render_scene(s, &ro, &st, &err);
    double t3 = now();
    if (!fm) {
        fprintf(stderr, "terrain_big: %s\n", err.msg);
        return 1;
    }
    double peak = proc_bytes("VmHWM:"), n = (double)side * side;
    uint64_t level_nodes = 0;
    for (uint32_t k = 0; k < s->terrain->n_levels; k++)
        level_nodes += (uint64_t)s->terrain->levels[k].nx * s->terrain->levels[k].ny;
    printf("  sylva: DTM read and refined (terrain_ifs, f_K, ground cover): %6.2f s; %u levels of detail, "
           "%.1f M nodes\n", t2 - t1, s->terrain->n_levels, level_nodes / 1e6);
    printf("  sylva: Embree scene built %.2f s, first pixel %.3f s\n", st.build_seconds, st.render_seconds);
    printf("  sylva: scene built and first pixel rendered: %.2f s (goal 30 s); peak memory %.0f MB = %.1f bytes "
           "a point\n", t3 - t1, peak / 1048576.0, peak / n);
    if (base >= 2) {
        raw_embree(s->terrain, base, 0);
        raw_embree(s->terrain, base, 1);
    }
    film_free(fm);
    scene_free(s);
    scene_file_free(sf);
    plugin_registry_free(reg);
    unlink(tif), unlink(yaml), rmdir(dir);
    return 0;
}
