/* pov_bench.c — the POV-Ray exporter's speed and size, and sylva's verification mode against
 * POV-Ray on the same scene.
 *
 *  1. Export: a forest of N plants (default 1,000,000) of one species with 4 variants, placed
 *     at random over 10 km x 10 km with random turn and size, exported with pov_export_scene.
 *     Prints seconds, bytes per plant in the plants file and the whole export's size. Goal:
 *     <= 5 s and <= 120 bytes per plant. With --parse, POV-Ray also parses the export (slow).
 *  2. Verification mode vs POV-Ray: a scene (default scenes/default.yaml) at its own size and
 *     spp, K runs (default 3) of the cross-check; prints for each renderer the best run:
 *     sylva = scene load and build + BVH + render, POV-Ray = parse + bounding + trace from its
 *     own statistics (and each process's wall time), the ratio POV-Ray / sylva as the median of
 *     the runs' own ratios (goal >= 3), and the agreement metrics.
 * Usage:
 *   pov_bench [--instances N] [--scene PATH] [--size WxH] [--spp N] [--runs K] [--parse]
 *             [--skip-export] [--skip-render]
 * Temporary files go to a fresh folder under $TMPDIR (or /tmp) and are removed. */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "crosscheck/crosscheck.h"
#include "crosscheck/povray_run.h"
#include "pov/pov_write.h"
#include "plugin/plugin_host.h"
#include "render/render.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "scene_build/shapes.h"
#include "util/progress.h"
#include "util/rng.h"

#define VARIANTS 4

static void print_machine(void)
{
    char model[256] = "unknown";
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f))
            if (!strncmp(line, "model name", 10)) {
                char *c = strchr(line, ':');
                if (c) snprintf(model, sizeof model, "%s", c + 2);
                model[strcspn(model, "\n")] = '\0';
                break;
            }
        fclose(f);
    }
    printf("machine: %s, %u cores\n", model, render_default_threads());
}

/* Removes every file in dir, then dir (the benchmark's own temporary folder: no subfolders). */
static void remove_folder(const char *dir)
{
    DIR *d = opendir(dir);
    if (d) {
        struct dirent *e;
        char path[4200];
        while ((e = readdir(d)))
            if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
                snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
                remove(path);
            }
        closedir(d);
    }
    rmdir(dir);
}

static scene *forest_scene(uint32_t n, err_buf *err)
{
    scene *s = scene_new();
    if (!s) return NULL;
    s->image = (image_settings){.width = 640, .height = 360, .spp = 16, .seed = 1, .max_depth = 4};
    s->camera = (camera_settings){.position = {5000, -800, 400}, .has_look_at = 1, .look_at = {5000, 2000, 0},
                                  .up = {0, 0, 1}, .fov_deg = 60};
    s->sun = (sun_settings){.enabled = 1, .direction = {-0.5, -0.5, 0.707}, .irradiance = 1, .color = {1, 1, 1}};
    s->sky = (sky_settings){.model = SKY_CONSTANT, .scale = 1, .color = {0.3, 0.4, 0.6}, .ambient = {0.2, 0.2, 0.2}};
    sylva_material_desc bark = {.size = sizeof bark, .name = "bark", .bsdf = SYLVA_BSDF_LAMBERT,
                                .albedo = {0.3f, 0.2f, 0.1f}, .texture = -1};
    int32_t mat = scene_add_material(s, &bark, err);
    if (mat < 0) goto fail;
    s->species = calloc(1, sizeof(species));
    if (!s->species) goto fail;
    s->species[0] = (species){.name = strdup("beech"), .first_prototype = 0, .n_variants = VARIANTS};
    s->n_species = 1;
    if (!s->species[0].name) goto fail;
    for (uint32_t v = 0; v < VARIANTS; v++) {
        mesh *m = mesh_new();
        shape_spec crown = {.kind = SHAPE_SPHERE, .radius = 2.0 + v, .subdivisions = 2};
        if (!m || shape_build(&crown, mat, m, err) || scene_add_prototype(s, 0, v, (v + 1.0) / VARIANTS, 4.0 + 2 * v, m, err) < 0)
            goto fail;
    }
    sylva_rng r;
    rng_stream(&r, 7, "bench forest", 0);
    for (uint32_t k = 0; k < n; k++) {
        double p[3] = {10000 * rng_next_double(&r), 10000 * rng_next_double(&r), 0};
        double turn = 360 * rng_next_double(&r), size = 0.6 + 0.8 * rng_next_double(&r);
        xform3x4 xf = plant_transform(p, turn, size);
        if (scene_add_instance(s, (uint32_t)(rng_next_u64(&r) % VARIANTS), &xf, err) < 0) goto fail;
    }
    return s;
fail:
    scene_free(s);
    return NULL;
}

static int bench_export(uint32_t n, int parse, const char *tmp)
{
    err_buf err = {{0}};
    double t0 = progress_now();
    scene *s = forest_scene(n, &err);
    if (!s) {
        fprintf(stderr, "pov_bench: %s\n", err.msg);
        return 4;
    }
    double t1 = progress_now();
    char path[4200];
    snprintf(path, sizeof path, "%s/forest.pov", tmp);
    pov_export_options po = {.width = 320, .height = 180, .spp = 1, .source = "pov_bench forest"};
    pov_export_stats st;
    double t2 = progress_now();
    int rc = pov_export_scene(s, path, &po, &st, &err);
    double t3 = progress_now();
    if (rc) {
        fprintf(stderr, "pov_bench: %s\n", err.msg);
        scene_free(s);
        return 3;
    }
    printf("\n== export of %u plants (forest built in %.2f s) ==\n", n, t1 - t0);
    printf("export time            %.3f s  (goal <= 5 s)  %s\n", t3 - t2, t3 - t2 <= 5.0 ? "met" : "NOT MET");
    printf("plants file            %.1f MB, %.1f bytes per plant  (goal <= 120)  %s\n", st.instance_bytes / 1e6,
           (double)st.instance_bytes / (st.instances ? st.instances : 1),
           (double)st.instance_bytes / (st.instances ? st.instances : 1) <= 120.0 ? "met" : "NOT MET");
    printf("whole export           %u files, %.1f MB; %.2f M plants/s\n", st.files, st.bytes / 1e6,
           n / (t3 - t2) / 1e6);
    if (parse) {
        povray_job job = {.folder = tmp, .scene = "forest.pov", .output = "forest.exr", .log = "forest.log",
                          .width = 32, .height = 18, .spp = 1};
        povray_result pr;
        if (povray_render(&job, &pr, &err)) {
            fprintf(stderr, "pov_bench: %s\n", err.msg);
        } else {
            printf("POV-Ray parse          %.2f s (process %.2f s) for the %u-plant export\n", pr.parse_seconds,
                   pr.wall_seconds, n);
        }
    }
    scene_free(s);
    return 0;
}

static double best(double a, double b)
{
    return a < 0 ? b : b < a ? b : a;
}

static int bench_render(const char *scene_path, uint32_t w, uint32_t h, uint32_t spp, int runs, const char *tmp)
{
    err_buf err = {{0}};
    double t0 = progress_now();
    plugin_registry *reg = plugin_registry_open(&err);
    if (!reg) {
        fprintf(stderr, "pov_bench: %s\n", err.msg);
        return 4;
    }
    double t_registry = progress_now() - t0;
    double load = -1, bvh = -1, render = -1, sylva_total = -1;
    double parse = -1, bounding = -1, trace = -1, pov_total = -1, pov_wall = -1;
    double ratios[64];
    if (runs > 64) runs = 64;
    crosscheck_result *r = malloc(sizeof *r);
    scene *s = NULL;
    scene_file *sf = NULL;
    int rc = 0;
    if (!r) return 4;
    for (int k = 0; k < runs; k++) {
        double a = progress_now();
        build_options bo = {.quiet = 1};
        sf = scene_file_load(scene_path, reg, &err);
        s = sf ? scene_build(sf, reg, &bo, &err) : NULL;
        double b = progress_now();
        if (!s) {
            fprintf(stderr, "%s\n", err.msg);
            rc = 2;
            break;
        }
        crosscheck_options co = {.width = w, .height = h, .spp = spp, .source = scene_path, .quiet = 1};
        crosscheck_default_thresholds(&co.thresholds);
        if (crosscheck_run(s, tmp, &co, r, &err)) {
            fprintf(stderr, "pov_bench: %s\n", err.msg);
            rc = 4;
            break;
        }
        double this_sylva = (b - a) + r->sylva_bvh_seconds + r->sylva_render_seconds;
        double this_pov = r->povray.parse_seconds + r->povray.bounding_seconds + r->povray.trace_seconds;
        printf("run %d: sylva %.3f s (load+build %.3f, BVH %.3f, render %.3f); POV-Ray %.3f s (parse %.3f, "
               "bounding %.3f, trace %.3f; process %.3f)\n",
               k + 1, this_sylva, b - a, r->sylva_bvh_seconds, r->sylva_render_seconds, this_pov,
               r->povray.parse_seconds, r->povray.bounding_seconds, r->povray.trace_seconds, r->povray.wall_seconds);
        ratios[k] = this_pov / this_sylva;
        load = best(load, b - a);
        bvh = best(bvh, r->sylva_bvh_seconds);
        render = best(render, r->sylva_render_seconds);
        sylva_total = best(sylva_total, this_sylva);
        parse = best(parse, r->povray.parse_seconds);
        bounding = best(bounding, r->povray.bounding_seconds);
        trace = best(trace, r->povray.trace_seconds);
        pov_total = best(pov_total, this_pov);
        pov_wall = best(pov_wall, r->povray.wall_seconds);
        scene_free(s);
        scene_file_free(sf);
        s = NULL, sf = NULL;
    }
    if (!rc) {
        printf("\n== %s in verification mode: %ux%u, %u spp (%u camera samples per pixel), best of %d ==\n",
               scene_path, r->width, r->height, r->spp, r->samples, runs);
        printf("sylva                  %.3f s = load+build %.3f + BVH %.3f + render %.3f  (plugin registry %.3f s "
               "more, once per process)\n", sylva_total, load, bvh, render, t_registry);
        printf("POV-Ray                %.3f s = parse %.3f + bounding %.3f + trace %.3f  (whole process %.3f s)\n",
               pov_total, parse, bounding, trace, pov_wall);
        /* the runs' own ratios (each pairs a sylva and a POV-Ray render made back to back, so a
         * busy machine slows both): their median is the figure */
        for (int i = 1; i < runs; i++)
            for (int j = i; j > 0 && ratios[j - 1] > ratios[j]; j--) {
                double x = ratios[j];
                ratios[j] = ratios[j - 1], ratios[j - 1] = x;
            }
        double median = runs % 2 ? ratios[runs / 2] : 0.5 * (ratios[runs / 2 - 1] + ratios[runs / 2]);
        printf("ratio POV-Ray / sylva  %.2f, median of the runs' ratios (lowest %.2f; best times' ratio %.2f)  "
               "(goal >= 3)  %s\n", median, ratios[0], pov_total / sylva_total, median >= 3.0 ? "met" : "NOT MET");
        printf("agreement              %s\n", r->verdict);
        crosscheck_thresholds t;
        crosscheck_default_thresholds(&t);
        printf("                       coverage %.4f %%, MAE %.3g, RMSE %.3g, PSNR %.1f dB, max %.3g, over %.3g: %.4f %%\n",
               100 * r->coverage.agreement, r->overall.mae, r->overall.rmse, r->overall.psnr, r->overall.max_abs,
               t.over_error, 100 * r->overall.over_fraction);
        for (int k = 0; k < PIXEL_CLASS_COUNT; k++)
            if (r->classes[k].pixels)
                printf("  %-8s %7llu px  MAE %.3g  RMSE %.3g  max %.3g  over %.4f %%\n", crosscheck_class_name(k),
                       (unsigned long long)r->classes[k].pixels, r->classes[k].mae, r->classes[k].rmse,
                       r->classes[k].max_abs, 100 * r->classes[k].over_fraction);
    }
    scene_free(s);
    scene_file_free(sf);
    plugin_registry_free(reg);
    free(r);
    return rc;
}

int main(int argc, char **argv)
{
    uint32_t n = 1000000, w = 0, h = 0, spp = 0;
    int runs = 3, parse = 0, do_export = 1, do_render = 1;
    const char *scene_path = SYLVA_SOURCE_DIR "/scenes/default.yaml";
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--parse")) parse = 1;
        else if (!strcmp(a, "--skip-export")) do_export = 0;
        else if (!strcmp(a, "--skip-render")) do_render = 0;
        else if (v && !strcmp(a, "--instances")) n = (uint32_t)strtoul(v, NULL, 10), i++;
        else if (v && !strcmp(a, "--scene")) scene_path = v, i++;
        else if (v && !strcmp(a, "--spp")) spp = (uint32_t)strtoul(v, NULL, 10), i++;
        else if (v && !strcmp(a, "--runs")) runs = atoi(v), i++;
        else if (v && !strcmp(a, "--size") && sscanf(v, "%ux%u", &w, &h) == 2) i++;
        else {
            fprintf(stderr, "usage: pov_bench [--instances N] [--scene PATH] [--size WxH] [--spp N] [--runs K] "
                            "[--parse] [--skip-export] [--skip-render]\n");
            return 1;
        }
    }
    if (runs < 1) runs = 1;
    const char *base = getenv("TMPDIR");
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s/sylva-pov-bench-XXXXXX", base && *base ? base : "/tmp");
    if (!mkdtemp(tmp)) {
        perror("pov_bench: cannot create a temporary folder");
        return 3;
    }
    print_machine();
    int rc = 0;
    if (do_export) rc = bench_export(n, parse, tmp);
    if (!rc && do_render) rc = bench_render(scene_path, w, h, spp, runs, tmp);
    remove_folder(tmp);
    return rc;
}
