/* image_compare.h — how far a rendered image is from a reference: error metrics over colour,
 * agreement of two coverage masks, and a heatmap of the difference for reports. Used by the
 * image-diff tests (tests/image/sylva_imgdiff.c) and the POV-Ray cross-check.
 *
 * Colour channels: the first 3 channels of an image with 3 or more (RGB, RGBA, ...), the first
 * channel of an image with 1 or 2 (grey, grey + alpha). Both images must have the same size and
 * the same number of colour channels. Per value the error is |ref - test|; two equal values
 * (also two equal infinities) differ by 0, a NaN on either side or an infinity on one side
 * differs by +inf, so a broken pixel cannot hide: it makes MAE and RMSE infinite and is
 * counted in nonfinite_pixels. Nothing here allocates except image_diff_heatmap_write. */
#ifndef SYLVA_IMAGE_COMPARE_H
#define SYLVA_IMAGE_COMPARE_H

#include <stddef.h>
#include <stdint.h>

#include "io/image_io.h"
#include "util/err.h"

/* A read-only look at pixels owned elsewhere: width*height*channels floats, row 0 at the top. */
typedef struct image_view {
    const float *pixels;
    uint32_t width, height, channels;
} image_view;

static inline image_view image_view_of(const image_f32 *img)
{
    image_view v = {img->pixels, img->width, img->height, img->channels};
    return v;
}

typedef struct image_compare_opts {
    double threshold;      /* a pixel is "over" when its error exceeds this; >= 0 */
    const uint8_t *labels; /* NULL: every pixel; else width*height labels (a class map) */
    int label;             /* with labels: compare pixels whose label equals this (0..255);
                              -1: pixels whose label is not 0 */
    int luminance;         /* 0: each colour channel; 1: Rec. 709 luminance of RGB */
} image_compare_opts;

typedef struct image_diff_stats {
    double mae;           /* mean |error| over compared pixels and values */
    double rmse;          /* root of the mean squared error */
    double psnr;          /* dB for a peak of 1.0: -20 log10(rmse); +inf when rmse is 0 */
    double max_abs;       /* largest |error| */
    double over_fraction; /* over_pixels / pixels */
    uint64_t pixels;      /* pixels compared (all, or those selected by the labels) */
    uint64_t over_pixels; /* pixels whose largest value error exceeds the threshold */
    uint64_t nonfinite_pixels; /* pixels with an infinite error (see above) */
    uint32_t values;      /* values compared per pixel: 1 (grey or luminance) or 3 */
} image_diff_stats;

/* Compares test against ref. opts may be NULL (threshold 0, every pixel, per channel). When no
 * pixel is selected, pixels is 0, every error metric 0 and psnr +inf. Returns 0, or -1 with err
 * set when the sizes or colour channel counts differ or an option is invalid. */
int image_compare(const image_view *ref, const image_view *test, const image_compare_opts *opts,
                  image_diff_stats *out, err_buf *err);

typedef struct mask_agreement {
    double agreement;     /* (both + neither) / n: the fraction of positions that agree; 1 if n 0 */
    double overlap;       /* both / (both + only_ref + only_test), Jaccard index; 1 if all empty */
    uint64_t both, only_ref, only_test, neither; /* counts of the four cases */
} mask_agreement;

/* Compares two coverage masks of n entries each (nonzero = covered, e.g. foreground). */
void image_mask_agreement(const uint8_t *ref, const uint8_t *test, size_t n,
                          mask_agreement *out);

/* Fills rgb (width*height*3 bytes, caller-owned) with a heatmap of the per-pixel error (the
 * largest value error): black at 0 through red and yellow to white at full_scale and above;
 * magenta where the error is infinite; dark grey where the labels leave the pixel out.
 * Same checks as image_compare; full_scale must be > 0. Returns 0 or -1 with err set. */
int image_diff_heatmap(const image_view *ref, const image_view *test,
                       const image_compare_opts *opts, double full_scale, uint8_t *rgb,
                       err_buf *err);
/* image_diff_heatmap written as an 8-bit RGB image to path (format from the extension). */
int image_diff_heatmap_write(const char *path, const image_view *ref, const image_view *test,
                             const image_compare_opts *opts, double full_scale, err_buf *err);

#endif
