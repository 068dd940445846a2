/* film.c — frame buffers, tone mapping (through render/tone_curve.h) and output. */
#include "render/film.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/exr_write.h"
#include "io/image_io.h"
#include "util/memory_budget.h"
#include "render/tone_curve.h"

static int film_memory_check(uint32_t w, uint32_t h, err_buf *err)
{
    char what[96];
    snprintf(what, sizeof what, "a %ux%u frame", w, h);
    if (memory_check((uint64_t)w * h * FILM_BYTES_PER_PIXEL, what, err)) {
        size_t n = strlen(err->msg);
        snprintf(err->msg + n, sizeof err->msg - n, "; lower the image size");
        return -1;
    }
    return 0;
}

int film_check(uint32_t w, uint32_t h, uint32_t spp, err_buf *err)
{
    if (film_memory_check(w, h, err)) return -1;
    double samples = (double)w * h * spp;
    if (samples > FILM_MAX_SAMPLES)
        return err_set(err, "%ux%u pixels at %u samples per pixel is %.3g camera samples, more "
                       "than the %.0e a render may take (weeks of tracing); lower spp or the "
                       "image size", w, h, spp, samples, FILM_MAX_SAMPLES);
    return 0;
}

film *film_new(uint32_t w, uint32_t h, err_buf *err)
{
    if (film_memory_check(w, h, err)) return NULL;
    size_t n = (size_t)w * h;
    film *f = calloc(1, sizeof *f);
    if (f) {
        f->width = w, f->height = h;
        f->rgb = calloc(n * 3, sizeof(float));
        f->depth = calloc(n, sizeof(float));
        f->normal = calloc(n * 3, sizeof(float));
        f->albedo = calloc(n * 3, sizeof(float));
        f->instance_id = calloc(n, sizeof(uint32_t));
        f->species_id = calloc(n, sizeof(uint32_t));
        f->object_id = calloc(n, sizeof(uint32_t));
        f->development = calloc(n, sizeof(float));
        f->development_rgb = calloc(n * 3, sizeof(float));
        f->pixel_class = calloc(n, 1);
        f->coverage = calloc(n, sizeof(float));
    }
    if (!f || !f->rgb || !f->depth || !f->normal || !f->albedo || !f->instance_id || !f->species_id ||
        !f->object_id || !f->development || !f->development_rgb ||
        !f->pixel_class || !f->coverage) {
        film_free(f);
        err_nomem(err, "out of memory for a %ux%u frame", w, h);
        return NULL;
    }
    return f;
}

void film_layers(film *f, film_layer out[FILM_LAYERS])
{
    const film_layer l[FILM_LAYERS] = {
        {f->rgb, 3 * sizeof(float)},         {f->depth, sizeof(float)},       {f->normal, 3 * sizeof(float)},
        {f->albedo, 3 * sizeof(float)},      {f->instance_id, sizeof(uint32_t)},
        {f->species_id, sizeof(uint32_t)},   {f->object_id, sizeof(uint32_t)},
        {f->development, sizeof(float)},     {f->development_rgb, 3 * sizeof(float)},
        {f->pixel_class, 1},                 {f->coverage, sizeof(float)}};
    memcpy(out, l, sizeof l);
}

void film_free(film *f)
{
    if (!f) return;
    free(f->rgb), free(f->depth), free(f->normal), free(f->albedo), free(f->instance_id), free(f->species_id);
    free(f->object_id), free(f->development), free(f->development_rgb), free(f->pixel_class), free(f->coverage);
    free(f);
}

uint8_t *film_tonemap(const film *f, tone_curve tone, double exposure_stops)
{
    size_t n = (size_t)f->width * f->height;
    uint8_t *out = malloc(n * 3);
    if (!out) return NULL;
    float gain = (float)(M_PI * exp2(exposure_stops));
    for (size_t i = 0; i < n; i++) {
        float x[3] = {f->rgb[i * 3] * gain, f->rgb[i * 3 + 1] * gain, f->rgb[i * 3 + 2] * gain}, y[3];
        tone_map_rgb(tone, x, y);
        for (int k = 0; k < 3; k++) out[i * 3 + k] = (uint8_t)lrintf(y[k] * 255.0f);
    }
    return out;
}

/* The frame's EXR layers, with the site and the exposure as header attributes. */
static exr_frame film_exr_frame(const film *f, const site_settings *site, double exposure_stops)
{
    exr_frame fr = {.width = f->width, .height = f->height, .rgb = f->rgb, .depth = f->depth, .normal = f->normal,
                    .albedo = f->albedo, .instance_id = f->instance_id, .species_id = f->species_id,
                    .object_id = f->object_id, .development = f->development, .development_rgb = f->development_rgb,
                    .rgb_half = 0, .has_exposure = isfinite(exposure_stops),
                    .exposure_stops = exposure_stops};
    if (site && site->crs_wkt) {
        fr.crs_wkt = site->crs_wkt, fr.crs_name = site->crs_name;
        for (int k = 0; k < 3; k++) fr.origin[k] = site->origin[k];
    }
    return fr;
}

int film_write_exr(const film *f, const site_settings *site, double exposure_stops, const char *path,
                   err_buf *err)
{
    exr_frame fr = film_exr_frame(f, site, exposure_stops);
    return exr_write(path, &fr, err);
}

int film_write_pair_pixels(const film *f, const site_settings *site, double exposure_stops, const uint8_t *px,
                           const char *png_path, const char *exr_path, err_buf *err)
{
    exr_frame fr = film_exr_frame(f, site, exposure_stops);
    atomic_file out[2]; /* the EXR, then the PNG */
    memset(out, 0, sizeof out);
    out[0].fd = out[1].fd = -1;
    int rc = atomic_file_open(&out[0], exr_path, err) || exr_write_into(&out[0], &fr, err) ||
             !atomic_file_open_stream(&out[1], png_path, err) ||
             image_write_u8_into(&out[1], f->width, f->height, 3, px, err)
                 ? -1 : atomic_file_commit_together(out, 2, err);
    if (rc) atomic_file_abort(&out[0]), atomic_file_abort(&out[1]);
    return rc;
}

int film_write_pair(const film *f, const site_settings *site, tone_curve tone, double exposure_stops,
                    const char *png_path, const char *exr_path, err_buf *err)
{
    uint8_t *px = film_tonemap(f, tone, exposure_stops); /* owned here */
    if (!px) return err_nomem(err, "out of memory tone-mapping the image");
    int rc = film_write_pair_pixels(f, site, exposure_stops, px, png_path, exr_path, err);
    free(px);
    return rc;
}

int film_write_png(const film *f, const char *path, tone_curve tone, double exposure_stops, err_buf *err)
{
    uint8_t *px = film_tonemap(f, tone, exposure_stops);
    if (!px) return err_nomem(err, "out of memory tone-mapping the image");
    int rc = image_write_u8(path, f->width, f->height, 3, px, err);
    free(px);
    return rc;
}
