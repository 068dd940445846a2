/* composite.c — the two renders, the compositing formula with its guards, and the montage's
 * outputs (composite.h). */
#include "montage/composite.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/exr_write.h"
#include "render/accel.h"
#include "util/memory_budget.h"
#include "util/srgb.h"

int composite_render(const scene *s, const render_options *opt, composite_renders *out, err_buf *err)
{
    *out = (composite_renders){0};
    uint32_t dev = 0;
    for (uint32_t o = 0; o < s->n_objects; o++) dev += s->objects[o].development != 0;
    for (uint32_t i = 0; i < s->n_instances && !dev; i++) dev += s->instances[i].development != 0;
    if (!dev)
        return err_set(err, "the scene has no development to composite: mark its objects (or its new "
                       "plants) `development: true`");
    uint32_t w = opt->width ? opt->width : s->image.width, h = opt->height ? opt->height : s->image.height;
    char what[96];
    snprintf(what, sizeof what, "a montage's pair of %ux%u frames", w, h);
    if (memory_check(2 * (uint64_t)w * h * FILM_BYTES_PER_PIXEL, what, err)) {
        size_t used = strlen(err->msg);
        snprintf(err->msg + used, sizeof err->msg - used, "; lower the image size");
        return -1;
    }
    render_setup *rs = render_setup_new(s, opt, err);
    if (!rs) return -1;
    render_options bg = *opt;
    bg.leave_out |= ACCEL_MASK_DEVELOPMENT;
    out->full = render_setup_run(rs, opt, NULL, err);
    if (out->full) out->background = render_setup_run(rs, &bg, NULL, err);
    render_setup_free(rs);
    if (!out->background) {
        composite_renders_free(out);
        return -1;
    }
    return 0;
}

void composite_renders_free(composite_renders *r)
{
    if (!r) return;
    film_free(r->full);
    film_free(r->background);
    *r = (composite_renders){0};
}

composite_layers composite_layers_of(const composite_renders *r)
{
    return (composite_layers){.width = r->full->width, .height = r->full->height, .full = r->full->rgb,
                              .development = r->full->development_rgb, .alpha = r->full->development,
                              .background = r->background->rgb};
}

/* The shadow catcher's ratio for one channel: the background with the development over the
 * background without it, both over the (1 - alpha) of the pixel the development leaves. */
static float shadow_ratio(float full, float development, float keep, float background, float dark)
{
    float lit = full - development, den = keep * background;
    if (!(den > dark)) return 1.0f;
    float s = (lit > 0.0f ? lit : 0.0f) / den;
    return s < COMPOSITE_RATIO_MAX ? s : COMPOSITE_RATIO_MAX;
}

int composite_apply(const composite_layers *l, const image_f32 *plate, float gain, int shadow_catcher,
                    float *montage, float *ratio, err_buf *err)
{
    if (!(gain > 0.0f) || !isfinite(gain))
        return err_set(err, "the development's gain is %g; it must be a positive number (1 for a rendered plate)",
                       (double)gain);
    if (plate->width != l->width || plate->height != l->height)
        return err_set(err, "the plate is %ux%u pixels and the render %ux%u; render at the plate's size",
                       plate->width, plate->height, l->width, l->height);
    if (plate->channels < 1)
        return err_set(err, "the plate has no channels; it needs grey or RGB");
    size_t n = (size_t)l->width * l->height;
    double mean = 0.0;
    for (size_t i = 0; i < 3 * n; i++)
        if (isfinite(l->background[i])) mean += l->background[i];
    float dark = (float)(COMPOSITE_DARK * mean / (3.0 * (double)n));
    for (size_t i = 0; i < n; i++) {
        float a = l->alpha[i], keep = 1.0f - a;
        for (int c = 0; c < 3; c++) {
            size_t k = 3 * i + c;
            float p = plate->pixels[i * plate->channels + (plate->channels >= 3 ? (unsigned)c : 0)];
            float s = shadow_catcher ? shadow_ratio(l->full[k], l->development[k], keep, l->background[k], dark)
                                     : 1.0f;
            montage[k] = gain * l->development[k] + keep * p * s;
            if (ratio) ratio[k] = s;
        }
    }
    return 0;
}

uint8_t *composite_srgb8(const float *rgb, size_t pixels)
{
    uint8_t *px = malloc(pixels ? pixels * 3 : 1); /* the caller's */
    for (size_t i = 0; px && i < pixels * 3; i++) px[i] = srgb8_from_linear(rgb[i]);
    return px;
}

int composite_write_srgb(const char *path, uint32_t width, uint32_t height, const float *rgb, err_buf *err)
{
    uint8_t *px = composite_srgb8(rgb, (size_t)width * height); /* owned here */
    if (!px) return err_nomem(err, "out of memory encoding %s", path);
    int rc = image_write_u8(path, width, height, 3, px, err);
    free(px);
    return rc;
}

int composite_write_exr(const char *path, uint32_t width, uint32_t height, const float *rgb, const float *alpha,
                        err_buf *err)
{
    exr_frame fr = {.width = width, .height = height, .rgb = rgb, .development = alpha};
    return exr_write(path, &fr, err);
}

int composite_write_mask(const char *path, uint32_t width, uint32_t height, const float *alpha, err_buf *err)
{
    size_t n = (size_t)width * height;
    uint8_t *px = malloc(n); /* owned here */
    if (!px) return err_nomem(err, "out of memory encoding %s", path);
    for (size_t i = 0; i < n; i++) {
        float a = alpha[i] > 0.0f ? alpha[i] < 1.0f ? alpha[i] : 1.0f : 0.0f;
        px[i] = (uint8_t)lrintf(a * 255.0f);
    }
    int rc = image_write_u8(path, width, height, 1, px, err);
    free(px);
    return rc;
}
