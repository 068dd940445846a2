/* image_compare.c — error metrics, mask agreement and the difference heatmap. Sums are kept
 * in double so that a 4K frame's error is not lost to float rounding. */
#include "io/image_compare.h"

#include <math.h>
#include <stdlib.h>

static uint32_t colour_values(uint32_t channels)
{
    return channels >= 3 ? 3u : 1u;
}

static int compare_check(const image_view *ref, const image_view *test,
                         const image_compare_opts *opts, err_buf *err)
{
    if (!ref || !test || !ref->pixels || !test->pixels)
        return err_set(err, "image comparison needs two images with pixels");
    if (ref->width == 0 || ref->height == 0 || ref->channels == 0 || test->channels == 0)
        return err_set(err, "image comparison needs images with at least one pixel and channel; "
                       "the reference is %ux%u with %u channels, the test image %ux%u with %u",
                       ref->width, ref->height, ref->channels, test->width, test->height,
                       test->channels);
    if (ref->width != test->width || ref->height != test->height)
        return err_set(err, "image sizes differ: the reference is %ux%u, the test image %ux%u",
                       ref->width, ref->height, test->width, test->height);
    if (colour_values(ref->channels) != colour_values(test->channels))
        return err_set(err, "colour channels differ: the reference has %u channels, the test "
                       "image %u; both need 3 or more (RGB) or both 1 or 2 (grey)",
                       ref->channels, test->channels);
    if (opts) {
        if (!(opts->threshold >= 0.0))
            return err_set(err, "comparison threshold %g is invalid; it must be 0 or more",
                           opts->threshold);
        if (opts->labels && (opts->label < -1 || opts->label > 255))
            return err_set(err, "comparison label %d is invalid; use 0..255, or -1 for every "
                           "nonzero label", opts->label);
    }
    return 0;
}

static int pixel_selected(const image_compare_opts *opts, size_t i)
{
    if (!opts || !opts->labels) return 1;
    return opts->label < 0 ? opts->labels[i] != 0 : opts->labels[i] == (uint8_t)opts->label;
}

static double value_error(double a, double b)
{
    if (a == b) return 0.0;
    double d = fabs(a - b);
    return isnan(d) ? INFINITY : d;
}

static double luminance_709(const float *rgb)
{
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

/* The errors of pixel i: fills err_v[0..n) and returns their count n (1 or 3). */
static uint32_t pixel_errors(const image_view *ref, const image_view *test, int luminance,
                             size_t i, double err_v[3])
{
    const float *a = ref->pixels + i * ref->channels;
    const float *b = test->pixels + i * test->channels;
    uint32_t n = colour_values(ref->channels);
    if (luminance && n == 3) {
        err_v[0] = value_error(luminance_709(a), luminance_709(b));
        return 1;
    }
    for (uint32_t c = 0; c < n; c++) err_v[c] = value_error(a[c], b[c]);
    return n;
}

int image_compare(const image_view *ref, const image_view *test, const image_compare_opts *opts,
                  image_diff_stats *out, err_buf *err)
{
    if (!out) return err_set(err, "image_compare needs somewhere to put the result");
    if (compare_check(ref, test, opts, err)) return -1;

    const int luminance = opts && opts->luminance;
    const double threshold = opts ? opts->threshold : 0.0;
    const size_t n_px = (size_t)ref->width * ref->height;
    image_diff_stats s = {0};
    s.values = luminance ? 1u : colour_values(ref->channels);
    double sum_abs = 0.0, sum_sq = 0.0;
    for (size_t i = 0; i < n_px; i++) {
        if (!pixel_selected(opts, i)) continue;
        double e[3];
        uint32_t n = pixel_errors(ref, test, luminance, i, e);
        double worst = 0.0;
        for (uint32_t c = 0; c < n; c++) {
            sum_abs += e[c];
            sum_sq += e[c] * e[c];
            if (e[c] > worst) worst = e[c];
        }
        s.pixels++;
        if (worst > threshold) s.over_pixels++;
        if (isinf(worst)) s.nonfinite_pixels++;
        if (worst > s.max_abs) s.max_abs = worst;
    }
    if (s.pixels > 0) {
        double count = (double)s.pixels * s.values;
        s.mae = sum_abs / count;
        s.rmse = sqrt(sum_sq / count);
        s.over_fraction = (double)s.over_pixels / (double)s.pixels;
    }
    s.psnr = s.rmse > 0.0 ? -20.0 * log10(s.rmse) : INFINITY;
    *out = s;
    return 0;
}

void image_mask_agreement(const uint8_t *ref, const uint8_t *test, size_t n,
                          mask_agreement *out)
{
    mask_agreement m = {0};
    for (size_t i = 0; i < n; i++) {
        int r = ref[i] != 0, t = test[i] != 0;
        if (r && t) m.both++;
        else if (r) m.only_ref++;
        else if (t) m.only_test++;
        else m.neither++;
    }
    m.agreement = n ? (double)(m.both + m.neither) / (double)n : 1.0;
    uint64_t any = m.both + m.only_ref + m.only_test;
    m.overlap = any ? (double)m.both / (double)any : 1.0;
    *out = m;
}

/* black → red → yellow → white over v in [0, 1] */
static void heat_colour(double v, uint8_t rgb[3])
{
    double r = v * 3.0, g = v * 3.0 - 1.0, b = v * 3.0 - 2.0;
    double ch[3] = {r, g, b};
    for (int c = 0; c < 3; c++) {
        double x = ch[c] < 0.0 ? 0.0 : ch[c] > 1.0 ? 1.0 : ch[c];
        rgb[c] = (uint8_t)lrint(x * 255.0);
    }
}

int image_diff_heatmap(const image_view *ref, const image_view *test,
                       const image_compare_opts *opts, double full_scale, uint8_t *rgb,
                       err_buf *err)
{
    if (!rgb) return err_set(err, "image_diff_heatmap needs an output buffer");
    if (!(full_scale > 0.0) || isinf(full_scale))
        return err_set(err, "heatmap full scale %g is invalid; it must be a positive error",
                       full_scale);
    if (compare_check(ref, test, opts, err)) return -1;

    const int luminance = opts && opts->luminance;
    const size_t n_px = (size_t)ref->width * ref->height;
    for (size_t i = 0; i < n_px; i++) {
        uint8_t *px = rgb + 3 * i;
        if (!pixel_selected(opts, i)) {
            px[0] = px[1] = px[2] = 64;
            continue;
        }
        double e[3], worst = 0.0;
        uint32_t n = pixel_errors(ref, test, luminance, i, e);
        for (uint32_t c = 0; c < n; c++)
            if (e[c] > worst) worst = e[c];
        if (isinf(worst)) {
            px[0] = 255, px[1] = 0, px[2] = 255;
            continue;
        }
        heat_colour(worst >= full_scale ? 1.0 : worst / full_scale, px);
    }
    return 0;
}

int image_diff_heatmap_write(const char *path, const image_view *ref, const image_view *test,
                             const image_compare_opts *opts, double full_scale, err_buf *err)
{
    if (!path) return err_set(err, "image_diff_heatmap_write needs an output path");
    if (compare_check(ref, test, opts, err)) return -1;
    size_t n_px = (size_t)ref->width * ref->height;
    uint8_t *rgb = malloc(3 * n_px); /* owned here */
    if (!rgb) return err_nomem(err, "%s: out of memory for a %ux%u heatmap", path, ref->width,
                             ref->height);
    int status = image_diff_heatmap(ref, test, opts, full_scale, rgb, err);
    if (!status) status = image_write_u8(path, ref->width, ref->height, 3, rgb, err);
    free(rgb);
    return status;
}
