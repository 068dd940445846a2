/* crosscheck.c — both renders, the compositing of POV-Ray's picture over the sky, the metrics,
 * the verdict and the images of the report (see crosscheck.h). */
#include "crosscheck/crosscheck.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "crosscheck/crosscheck_report.h"
#include "geometry/light_summary.h"
#include "io/image_io.h"
#include "pov/pov_write.h"
#include "render/auto_exposure.h"
#include "render/render.h"
#include "util/progress.h"

#define HEATMAP_SCALE_OVER 5.0 /* the heatmap turns white at this many times the over threshold */

/* folder and file name of path ("." when it has no folder). */
static void split_folder(const char *path, char *folder, size_t nf, const char **name)
{
    const char *slash = strrchr(path, '/');
    if (!slash) {
        snprintf(folder, nf, ".");
        *name = path;
    } else if (slash == path) {
        snprintf(folder, nf, "/");
        *name = slash + 1;
    } else {
        snprintf(folder, nf, "%.*s", (int)(slash - path), path);
        *name = slash + 1;
    }
}

/* The export's name: the scene file's name without its extension, or "scene". */
static void export_stem(const char *source, char *out, size_t n)
{
    const char *name = source ? strrchr(source, '/') : NULL;
    name = name ? name + 1 : source;
    if (!name || !*name) {
        snprintf(out, n, "scene");
        return;
    }
    const char *dot = strrchr(name, '.');
    size_t l = dot && dot != name ? (size_t)(dot - name) : strlen(name);
    snprintf(out, n, "%.*s", (int)l, name);
    for (char *p = out; *p; p++)
        if (*p == '"' || *p == '\\' || (unsigned char)*p < 0x20 || *p == 0x7f) *p = '_';
}

static int write_class_map(const char *path, const film *f, err_buf *err)
{
    static const uint8_t colour[PIXEL_CLASS_COUNT][3] = {
        {150, 190, 235}, /* sky */
        {150, 120, 70},  /* terrain */
        {110, 60, 30},   /* bark */
        {60, 160, 50},   /* leaves */
        {200, 200, 210}, /* objects */
    };
    size_t n = (size_t)f->width * f->height;
    uint8_t *px = malloc(n * 3);
    if (!px) return err_nomem(err, "out of memory for the class map");
    for (size_t i = 0; i < n; i++) {
        uint8_t k = f->pixel_class[i] < PIXEL_CLASS_COUNT ? f->pixel_class[i] : 0;
        memcpy(px + i * 3, colour[k], 3);
    }
    int rc = image_write_u8(path, f->width, f->height, 3, px, err);
    free(px);
    return rc;
}

static void append(char *buf, size_t n, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static void append(char *buf, size_t n, const char *fmt, ...)
{
    size_t k = strlen(buf);
    if (k + 1 >= n) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf + k, n - k, fmt, ap);
    va_end(ap);
}

static void judge(crosscheck_result *r, const crosscheck_thresholds *t)
{
    uint64_t n = (uint64_t)r->width * r->height;
    r->pass_coverage = r->coverage.agreement >= t->min_coverage_agreement;
    r->pass_mae = r->overall.mae <= t->max_mae;
    r->pass_over = r->overall.over_fraction <= t->max_over_fraction;
    r->pass_classes = 1;
    for (int k = 0; k < PIXEL_CLASS_COUNT; k++) {
        r->class_checked[k] = r->classes[k].pixels > 0 && (double)r->classes[k].pixels >= t->min_class_share * (double)n;
        r->class_pass[k] = !r->class_checked[k] || r->classes[k].mae <= t->max_class_mae;
        r->pass_classes &= r->class_pass[k];
    }
    r->pass = r->pass_coverage && r->pass_mae && r->pass_over && r->pass_classes;
    char *v = r->verdict;
    size_t vn = sizeof r->verdict;
    v[0] = '\0';
    if (r->pass) {
        append(v, vn, "agree: coverage %.3f %% (>= %.3g %%), MAE %.3g (<= %.3g), %.3f %% of pixels over %.3g "
                      "(<= %.3g %%), every checked class MAE <= %.3g",
               100 * r->coverage.agreement, 100 * t->min_coverage_agreement, r->overall.mae, t->max_mae,
               100 * r->overall.over_fraction, t->over_error, 100 * t->max_over_fraction, t->max_class_mae);
        return;
    }
    append(v, vn, "disagree:");
    if (!r->pass_coverage)
        append(v, vn, " coverage agreement %.3f %% < %.3g %%;", 100 * r->coverage.agreement, 100 * t->min_coverage_agreement);
    if (!r->pass_mae) append(v, vn, " MAE %.3g > %.3g;", r->overall.mae, t->max_mae);
    if (!r->pass_over)
        append(v, vn, " %.3f %% of pixels differ by more than %.3g (> %.3g %%);", 100 * r->overall.over_fraction,
               t->over_error, 100 * t->max_over_fraction);
    for (int k = 0; k < PIXEL_CLASS_COUNT; k++)
        if (!r->class_pass[k]) append(v, vn, " %s MAE %.3g > %.3g;", crosscheck_class_name(k), r->classes[k].mae, t->max_class_mae);
    size_t len = strlen(v);
    if (len && v[len - 1] == ';') v[len - 1] = '\0';
}

/* POV-Ray's RGBA (alpha 0 where the sky shows, colour premultiplied) over the sky colour:
 * fills rgb (3 per pixel) and alpha (1 per pixel). */
static void composite_over_sky(const image_f32 *img, vec3 sky, float *rgb, float *alpha)
{
    size_t n = (size_t)img->width * img->height;
    const float sk[3] = {sky.x, sky.y, sky.z};
    for (size_t i = 0; i < n; i++) {
        const float *p = img->pixels + i * img->channels;
        float a = p[3] < 0.0f ? 0.0f : p[3] > 1.0f ? 1.0f : p[3];
        alpha[i] = a;
        for (int c = 0; c < 3; c++) rgb[i * 3 + c] = p[c] + (1.0f - a) * sk[c];
    }
}

/* POV-Ray's fog covers the background too and makes it opaque, so with the physical sky's fog
 * POV-Ray's alpha no longer says where the sky shows: a second render without the fog
 * (Sylva_no_air) gives it, and replaces the fogged picture's alpha (whose colours stay). */
static int air_free_alpha(const povray_job *fogged, crosscheck_result *r, const char *image_name,
                          const char *log_name, image_f32 *img, err_buf *err)
{
    char out[600], log[600], path[4300];
    snprintf(out, sizeof out, "%.*s-noair.exr", (int)(strlen(image_name) - 4), image_name);
    snprintf(log, sizeof log, "%.*s-noair.log", (int)(strlen(log_name) - 4), log_name);
    povray_job job = *fogged;
    job.output = out;
    job.log = log;
    job.no_air = 1;
    povray_result *res = &r->povray_coverage;
    if (povray_render(&job, res, err)) return -1;
    snprintf(path, sizeof path, "%s/%s", fogged->folder, out);
    image_f32 bare = {0};
    int rc = image_read(path, &bare, err);
    if (!rc && (bare.width != img->width || bare.height != img->height || bare.channels < 4))
        rc = err_set(err, "%s is not the %ux%u RGBA picture of the fogged render", path, img->width, img->height);
    if (!rc) {
        size_t n = (size_t)img->width * img->height;
        for (size_t i = 0; i < n; i++) img->pixels[i * img->channels + 3] = bare.pixels[i * bare.channels + 3];
        r->povray.wall_seconds += res->wall_seconds;
    }
    image_free(&bare);
    return rc;
}

static int compare(const film *f, const float *pov_rgb, const float *pov_alpha, const crosscheck_thresholds *t,
                   crosscheck_result *r, err_buf *err)
{
    size_t n = (size_t)f->width * f->height;
    image_view ref = {f->rgb, f->width, f->height, 3}, test = {pov_rgb, f->width, f->height, 3};
    image_compare_opts co = {.threshold = t->over_error};
    if (image_compare(&ref, &test, &co, &r->overall, err)) return -1;
    co.labels = f->pixel_class;
    for (int k = 0; k < PIXEL_CLASS_COUNT; k++) {
        co.label = k;
        if (image_compare(&ref, &test, &co, &r->classes[k], err)) return -1;
    }
    uint8_t *ms = malloc(n), *mp = malloc(n);
    if (!ms || !mp) {
        free(ms), free(mp);
        return err_nomem(err, "out of memory for the coverage masks");
    }
    double sum = 0;
    for (size_t i = 0; i < n; i++) {
        ms[i] = f->coverage[i] >= 0.5f;
        mp[i] = pov_alpha[i] >= 0.5f;
        sum += fabs((double)f->coverage[i] - pov_alpha[i]);
    }
    image_mask_agreement(ms, mp, n, &r->coverage);
    r->coverage_mae = n ? sum / n : 0.0;
    free(ms), free(mp);
    return 0;
}

int crosscheck_run(const scene *s, const char *out_dir, const crosscheck_options *o, crosscheck_result *r,
                   err_buf *err)
{
    memset(r, 0, sizeof *r);
    const crosscheck_thresholds *t = &o->thresholds;
    r->width = o->width ? o->width : s->image.width;
    r->height = o->height ? o->height : s->image.height;
    r->spp = o->spp ? o->spp : s->image.spp;
    uint32_t grid = 1;
    while ((grid + 1) * (grid + 1) <= r->spp) grid++;
    r->samples = grid > 1 ? grid * grid + 1 : 1;
    if (mkdir(out_dir, 0777) && errno != EEXIST) {
        err_set(err, "%s: cannot create the output folder: %s", out_dir, strerror(errno));
        return CROSSCHECK_NOT_WRITTEN;
    }

    int rc = CROSSCHECK_FAILED;
    film *f = NULL;
    image_f32 img = {0};
    float *pov_rgb = NULL, *pov_alpha = NULL;
    char path[4300];

    /* sylva's verification render */
    r->flat_earth = s->earth.curvature;
    render_options ro = {.threads = o->threads, .verify = 1, .quiet = o->quiet, .spp = r->spp, .width = r->width,
                         .height = r->height, .flat_earth = 1};
    render_stats rs;
    f = render_scene(s, &ro, &rs, err);
    if (!f) goto done;
    r->sylva_bvh_seconds = rs.build_seconds;
    r->sylva_render_seconds = rs.render_seconds;

    /* the POV-Ray scene */
    char folder[4200];
    const char *name;
    if (o->pov_scene) {
        snprintf(r->pov_scene, sizeof r->pov_scene, "%s", o->pov_scene);
    } else {
        char stem[256];
        export_stem(o->source, stem, sizeof stem);
        snprintf(r->pov_scene, sizeof r->pov_scene, "%s/%s.pov", out_dir, stem);
        pov_export_options po = {.width = r->width, .height = r->height, .spp = r->spp, .source = o->source};
        double t0 = progress_now();
        if (pov_export_scene(s, r->pov_scene, &po, NULL, err)) {
            rc = CROSSCHECK_NOT_WRITTEN;
            goto done;
        }
        r->export_seconds = progress_now() - t0;
    }
    split_folder(r->pov_scene, folder, sizeof folder, &name);
    char image_name[512], log_name[512];
    size_t nl = strlen(name);
    int ext = nl > 4 && !strcmp(name + nl - 4, ".pov");
    snprintf(image_name, sizeof image_name, "%.*s-povray.exr", (int)(ext ? nl - 4 : nl), name);
    snprintf(log_name, sizeof log_name, "%.*s-povray.log", (int)(ext ? nl - 4 : nl), name);
    snprintf(r->pov_image, sizeof r->pov_image, "%s/%s", folder, image_name);
    snprintf(r->pov_log, sizeof r->pov_log, "%s/%s", folder, log_name);

    /* POV-Ray's render */
    if (!o->quiet) fprintf(stderr, "povray: rendering %s at %ux%u, %u samples per pixel\n", r->pov_scene, r->width,
                           r->height, r->samples);
    povray_job job = {.folder = folder, .scene = name, .output = image_name, .log = log_name,
                      .executable = o->povray, .width = r->width, .height = r->height, .spp = r->spp,
                      .threads = o->threads};
    if (povray_render(&job, &r->povray, err)) goto done;
    if (!o->quiet) fprintf(stderr, "povray: done in %.2fs (parse %.3fs, trace %.3fs)\n", r->povray.wall_seconds,
                           r->povray.parse_seconds, r->povray.trace_seconds);

    /* POV-Ray's picture over the sky */
    if (image_read(r->pov_image, &img, err)) goto done;
    if (img.width != r->width || img.height != r->height) {
        err_set(err, "%s is %ux%u, but sylva rendered %ux%u: was %s exported for another size?", r->pov_image,
                img.width, img.height, r->width, r->height, r->pov_scene);
        goto done;
    }
    if (img.channels < 4) {
        err_set(err, "%s has %u channels; the cross-check needs POV-Ray's alpha (RGBA)", r->pov_image, img.channels);
        goto done;
    }
    light_summary l;
    if (light_summary_init(&l, &s->sun, &s->sky, s->site.origin[2], s->camera.position[2], 0, err)) goto done;
    if (l.fog_distance > 0.0 && air_free_alpha(&job, r, image_name, log_name, &img, err)) goto done;
    size_t n = (size_t)r->width * r->height;
    pov_rgb = malloc(n * 3 * sizeof(float));
    pov_alpha = malloc(n * sizeof(float));
    if (!pov_rgb || !pov_alpha) {
        err_nomem(err, "out of memory for POV-Ray's picture");
        goto done;
    }
    /* with fog the fogged picture is whole (its background is the fog colour, as sylva's misses) */
    composite_over_sky(&img, l.fog_distance > 0.0 ? v3(0, 0, 0) : l.sky_mean, pov_rgb, pov_alpha);

    if (compare(f, pov_rgb, pov_alpha, t, r, err)) goto done;
    judge(r, t);

    /* images and the report */
    rc = CROSSCHECK_NOT_WRITTEN;
    /* The verification formula has no 1/pi: a given exposure shows both pictures as bright as a
     * path-traced render of the scene would be; a metered one is taken from sylva's picture and
     * used for both. */
    double exposure = s->image.exposure_set ? s->image.exposure - log2(M_PI) : auto_exposure_stops(f);
    snprintf(path, sizeof path, "%s/sylva.exr", out_dir);
    if (film_write_exr(f, &s->site, exposure, path, err)) goto done;
    snprintf(path, sizeof path, "%s/sylva.png", out_dir);
    if (film_write_png(f, path, s->image.tone, exposure, err)) goto done;
    film pf = {.width = r->width, .height = r->height, .rgb = pov_rgb};
    snprintf(path, sizeof path, "%s/povray.png", out_dir);
    if (film_write_png(&pf, path, s->image.tone, exposure, err)) goto done;
    image_view ref = {f->rgb, f->width, f->height, 3}, test = {pov_rgb, f->width, f->height, 3};
    snprintf(path, sizeof path, "%s/difference.png", out_dir);
    if (image_diff_heatmap_write(path, &ref, &test, NULL, HEATMAP_SCALE_OVER * t->over_error, err)) goto done;
    snprintf(path, sizeof path, "%s/classes.png", out_dir);
    if (write_class_map(path, f, err)) goto done;
    if (crosscheck_write_report(out_dir, r, o, HEATMAP_SCALE_OVER * t->over_error, err)) goto done;
    rc = 0;
done:
    free(pov_rgb);
    free(pov_alpha);
    image_free(&img);
    film_free(f);
    return rc;
}
