/* test_image_compare.c — comparison metrics on hand-made images with known answers, masks and
 * class maps, luminance, broken pixels, mask agreement and the heatmap colours. */
#include <math.h>
#include <stdint.h>

#include "harness.h"
#include "io/image_compare.h"

/* 2x2 RGB, reference black. Absolute errors per pixel: (0.1, 0, 0), (0, 0.2, 0), (0, 0, 0),
 * (0.3, 0.3, 0). Sum 0.9 over 12 values: MAE 0.075. Squares sum 0.23: RMSE sqrt(0.23/12) =
 * 0.138443731, PSNR 10 log10(12/0.23) = 17.17453 dB. Largest error 0.3. Pixel maxima 0.1, 0.2,
 * 0, 0.3: over 0.15 → 2 of 4, over 0.25 → 1 of 4. */
static const float black4[12] = {0};
static const float known4[12] = {0.1f, 0, 0, 0, 0.2f, 0, 0, 0, 0, 0.3f, -0.3f, 0};

static image_view view(const float *px, uint32_t w, uint32_t h, uint32_t c)
{
    image_view v = {px, w, h, c};
    return v;
}

TEST(known_metrics)
{
    image_view ref = view(black4, 2, 2, 3), test = view(known4, 2, 2, 3);
    image_compare_opts opts = {.threshold = 0.15};
    image_diff_stats s;
    err_buf err = {{0}};
    CHECK_INT(image_compare(&ref, &test, &opts, &s, &err), 0);
    CHECK_INT(s.pixels, 4);
    CHECK_INT(s.values, 3);
    CHECK_NEAR(s.mae, 0.075, 1e-7);
    CHECK_NEAR(s.rmse, 0.138443731, 1e-7);
    CHECK_NEAR(s.psnr, 17.17453, 1e-4);
    CHECK_NEAR(s.max_abs, 0.3, 1e-7);
    CHECK_INT(s.over_pixels, 2);
    CHECK_NEAR(s.over_fraction, 0.5, 0);
    CHECK_INT(s.nonfinite_pixels, 0);

    opts.threshold = 0.25;
    CHECK_INT(image_compare(&ref, &test, &opts, &s, &err), 0);
    CHECK_NEAR(s.over_fraction, 0.25, 0);
    /* swapping the images changes nothing */
    CHECK_INT(image_compare(&test, &ref, &opts, &s, &err), 0);
    CHECK_NEAR(s.mae, 0.075, 1e-7);
    CHECK_NEAR(s.over_fraction, 0.25, 0);
}

TEST(identical_images)
{
    image_view a = view(known4, 2, 2, 3);
    image_diff_stats s;
    err_buf err = {{0}};
    CHECK_INT(image_compare(&a, &a, NULL, &s, &err), 0);
    CHECK(s.mae == 0 && s.rmse == 0 && s.max_abs == 0 && s.over_fraction == 0);
    CHECK(isinf(s.psnr) && s.psnr > 0);
    CHECK_INT(s.pixels, 4);

    /* equal infinities (an HDR sky, say) are no error */
    float inf3[3] = {INFINITY, 1, 2};
    image_view b = view(inf3, 1, 1, 3);
    CHECK_INT(image_compare(&b, &b, NULL, &s, &err), 0);
    CHECK(s.mae == 0 && isinf(s.psnr) && s.nonfinite_pixels == 0);
}

TEST(size_and_channel_mismatch)
{
    image_view a = view(known4, 2, 2, 3), b = view(known4, 4, 1, 3);
    image_diff_stats s;
    err_buf err = {{0}};
    CHECK_INT(image_compare(&a, &b, NULL, &s, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "image sizes differ: the reference is 2x2, the test image 4x1");
    float grey[4] = {0};
    image_view g = view(grey, 2, 2, 1);
    CHECK_INT(image_compare(&a, &g, NULL, &s, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "colour channels differ");
    image_compare_opts bad = {.threshold = -1};
    CHECK_INT(image_compare(&a, &a, &bad, &s, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "threshold -1 is invalid");
}

TEST(alpha_is_not_compared)
{
    /* RGBA against RGB: alpha differs wildly but only colour counts */
    float rgba[8] = {0.5f, 0.5f, 0.5f, 0.0f, 0.25f, 0.25f, 0.25f, 1.0f};
    float rgb[6] = {0.5f, 0.5f, 0.5f, 0.25f, 0.25f, 0.75f};
    image_view a = view(rgba, 2, 1, 4), b = view(rgb, 2, 1, 3);
    image_diff_stats s;
    err_buf err = {{0}};
    CHECK_INT(image_compare(&a, &b, NULL, &s, &err), 0);
    CHECK_NEAR(s.max_abs, 0.5, 0);
    CHECK_NEAR(s.mae, 0.5 / 6, 1e-9);
    CHECK_NEAR(s.over_fraction, 0.5, 0);
}

TEST(labels_select_pixels)
{
    image_view ref = view(black4, 2, 2, 3), test = view(known4, 2, 2, 3);
    const uint8_t classes[4] = {1, 2, 0, 2};
    image_compare_opts opts = {.threshold = 0.15, .labels = classes, .label = 2};
    image_diff_stats s;
    err_buf err = {{0}};
    /* class 2: pixels 1 and 3 → errors 0.2 and 0.3, 0.3: sum 0.8 over 6 values */
    CHECK_INT(image_compare(&ref, &test, &opts, &s, &err), 0);
    CHECK_INT(s.pixels, 2);
    CHECK_NEAR(s.mae, 0.8 / 6, 1e-7);
    CHECK_NEAR(s.rmse, sqrt(0.22 / 6), 1e-7);
    CHECK_NEAR(s.over_fraction, 1.0, 0);
    /* every nonzero label: pixels 0, 1, 3 */
    opts.label = -1;
    CHECK_INT(image_compare(&ref, &test, &opts, &s, &err), 0);
    CHECK_INT(s.pixels, 3);
    CHECK_NEAR(s.mae, 0.9 / 9, 1e-7);
    CHECK_NEAR(s.over_fraction, 2.0 / 3.0, 1e-12);
    /* a class that is not there: nothing compared */
    opts.label = 7;
    CHECK_INT(image_compare(&ref, &test, &opts, &s, &err), 0);
    CHECK_INT(s.pixels, 0);
    CHECK(s.mae == 0 && isinf(s.psnr));
    opts.label = 300;
    CHECK_INT(image_compare(&ref, &test, &opts, &s, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "label 300 is invalid");
}

TEST(luminance)
{
    /* (+0.1, -0.1, 0): luminance error |0.2126 - 0.7152| * 0.1 = 0.05026;
     * (0.1, 0.1, 0.1): luminance error 0.1 */
    float ref[6] = {0.5f, 0.5f, 0.5f, 0.2f, 0.2f, 0.2f};
    float test[6] = {0.6f, 0.4f, 0.5f, 0.3f, 0.3f, 0.3f};
    image_view a = view(ref, 2, 1, 3), b = view(test, 2, 1, 3);
    image_compare_opts opts = {.threshold = 0.06, .luminance = 1};
    image_diff_stats s;
    err_buf err = {{0}};
    CHECK_INT(image_compare(&a, &b, &opts, &s, &err), 0);
    CHECK_INT(s.values, 1);
    CHECK_NEAR(s.mae, (0.05026 + 0.1) / 2, 1e-6);
    CHECK_NEAR(s.max_abs, 0.1, 1e-6);
    CHECK_NEAR(s.over_fraction, 0.5, 0);
}

TEST(broken_pixels_cannot_hide)
{
    float ref[6] = {0.5f, 0.5f, 0.5f, 0.2f, 0.2f, 0.2f};
    float test[6] = {0.5f, NAN, 0.5f, 0.2f, 0.2f, INFINITY};
    image_view a = view(ref, 2, 1, 3), b = view(test, 2, 1, 3);
    image_compare_opts opts = {.threshold = 1000};
    image_diff_stats s;
    err_buf err = {{0}};
    CHECK_INT(image_compare(&a, &b, &opts, &s, &err), 0);
    CHECK_INT(s.nonfinite_pixels, 2);
    CHECK_INT(s.over_pixels, 2);
    CHECK(isinf(s.mae) && isinf(s.rmse) && isinf(s.max_abs));
    CHECK(isinf(s.psnr) && s.psnr < 0);
}

TEST(mask_agreement_counts)
{
    const uint8_t ref[8] = {1, 1, 0, 0, 1, 0, 255, 0};
    const uint8_t test[8] = {1, 0, 0, 1, 1, 0, 7, 0};
    mask_agreement m;
    image_mask_agreement(ref, test, 8, &m);
    CHECK_INT(m.both, 3);
    CHECK_INT(m.only_ref, 1);
    CHECK_INT(m.only_test, 1);
    CHECK_INT(m.neither, 3);
    CHECK_NEAR(m.agreement, 6.0 / 8.0, 0);
    CHECK_NEAR(m.overlap, 3.0 / 5.0, 0);
    image_mask_agreement(ref, ref, 8, &m);
    CHECK_NEAR(m.agreement, 1.0, 0);
    CHECK_NEAR(m.overlap, 1.0, 0);
    const uint8_t none[3] = {0};
    image_mask_agreement(none, none, 3, &m);
    CHECK_NEAR(m.agreement, 1.0, 0);
    CHECK_NEAR(m.overlap, 1.0, 0);
}

TEST(heatmap_colours)
{
    /* pixel errors 0, 0.05, 0.1 (full scale), inf; scale 0.1 */
    float ref[12] = {0};
    float test[12] = {0, 0, 0, 0.05f, 0, 0, 0, 0.1f, 0, 0, 0, INFINITY};
    image_view a = view(ref, 4, 1, 3), b = view(test, 4, 1, 3);
    uint8_t rgb[12];
    err_buf err = {{0}};
    CHECK_INT(image_diff_heatmap(&a, &b, NULL, 0.1, rgb, &err), 0);
    CHECK(rgb[0] == 0 && rgb[1] == 0 && rgb[2] == 0);         /* no error: black */
    CHECK(rgb[3] == 255 && rgb[4] == 128 && rgb[5] == 0);     /* half scale: orange */
    CHECK(rgb[6] == 255 && rgb[7] == 255 && rgb[8] == 255);   /* full scale: white */
    CHECK(rgb[9] == 255 && rgb[10] == 0 && rgb[11] == 255);   /* infinite: magenta */

    const uint8_t classes[4] = {1, 0, 1, 1};
    image_compare_opts opts = {.labels = classes, .label = 1};
    CHECK_INT(image_diff_heatmap(&a, &b, &opts, 0.1, rgb, &err), 0);
    CHECK(rgb[3] == 64 && rgb[4] == 64 && rgb[5] == 64);      /* left out: grey */
    CHECK_INT(image_diff_heatmap(&a, &b, NULL, 0.0, rgb, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "full scale 0 is invalid");
}

TEST_LIST(TEST_CASE(known_metrics), TEST_CASE(identical_images),
          TEST_CASE(size_and_channel_mismatch), TEST_CASE(alpha_is_not_compared),
          TEST_CASE(labels_select_pixels), TEST_CASE(luminance),
          TEST_CASE(broken_pixels_cannot_hide), TEST_CASE(mask_agreement_counts),
          TEST_CASE(heatmap_colours))
