/* test_tone.c — the PNG tone curves (AgX and the ACES fit) and the metered exposure. */
#include "harness.h"

#include <math.h>
#include <stdlib.h>

#include "render/auto_exposure.h"
#include "render/film.h"
#include "render/tone_curve.h"
#include "util/srgb.h"

static float grey_out(tone_curve c, float x)
{
    float in[3] = {x, x, x}, out[3];
    tone_map_rgb(c, in, out);
    CHECK_NEAR(out[0], out[1], 1e-3);
    CHECK_NEAR(out[1], out[2], 1e-3);
    return out[1];
}

/* (max - min) / max of an encoded colour, after decoding to linear. */
static float saturation(const float c[3])
{
    float l[3];
    for (int k = 0; k < 3; k++) l[k] = srgb_to_linear(c[k]);
    float hi = fmaxf(l[0], fmaxf(l[1], l[2])), lo = fminf(l[0], fminf(l[1], l[2]));
    return hi > 0.0f ? (hi - lo) / hi : 0.0f;
}

TEST(sigmoid_ends_pivot_and_monotone)
{
    CHECK_NEAR(tone_agx_sigmoid(0.0f), 0.0, 1e-6);
    CHECK_NEAR(tone_agx_sigmoid(1.0f), 1.0, 1e-5);
    CHECK_NEAR(tone_agx_sigmoid(10.0f / 16.5f), 0.5, 1e-6);
    /* slope 2 at the pivot */
    float h = 1e-3f, t = 10.0f / 16.5f;
    CHECK_NEAR((tone_agx_sigmoid(t + h) - tone_agx_sigmoid(t - h)) / (2 * h), 2.0, 0.01);
    float prev = -1.0f;
    for (int i = 0; i <= 1000; i++) {
        float y = tone_agx_sigmoid(i / 1000.0f);
        CHECK(y > prev || (y == prev && y == 1.0f));
        prev = y;
    }
}

TEST(black_to_black_grey_to_mid)
{
    for (int c = TONE_AGX; c <= TONE_ACES; c++) {
        CHECK_NEAR(grey_out((tone_curve)c, 0.0f), 0.0, 1e-6);
        CHECK_NEAR(grey_out((tone_curve)c, -1.0f), 0.0, 1e-6);
        CHECK_NEAR(grey_out((tone_curve)c, NAN), 0.0, 1e-6);
    }
    /* as tone_curve.h states: 0.18 to 0.5 (AgX) and to 0.556 (ACES) */
    CHECK_NEAR(grey_out(TONE_AGX, 0.18f), 0.5, 1.0 / 255);
    CHECK_NEAR(grey_out(TONE_ACES, 0.18f), 0.556, 1.0 / 255);
    /* 6.5 stops above mid-grey is white; 10 below is black */
    CHECK_NEAR(grey_out(TONE_AGX, 0.18f * 90.6f), 1.0, 1e-3);
    CHECK(grey_out(TONE_AGX, 0.18f / 1024.0f) < 0.5f / 255);
}

/* Greys rise in all channels; a colour's luminance and its largest channel rise with exposure
 * (AgX's outset lets a minor channel dip by a few thousandths in the toe: tone_curve.h). */
TEST(monotone_with_exposure)
{
    for (int c = TONE_AGX; c <= TONE_ACES; c++)
        for (int hue = 0; hue < 4; hue++) {
            const float tint[4][3] = {{1, 1, 1}, {1, 0.2f, 0.05f}, {0.1f, 0.8f, 0.2f}, {0.05f, 0.1f, 1}};
            const int major[4] = {0, 0, 1, 2};
            float prev_y = -1, prev_major = -1;
            for (int i = 0; i <= 400; i++) {
                float x = 0.18f * exp2f(-12.0f + i * 0.05f), in[3], out[3], l[3];
                for (int k = 0; k < 3; k++) in[k] = x * tint[hue][k];
                tone_map_rgb((tone_curve)c, in, out);
                for (int k = 0; k < 3; k++) {
                    CHECK(out[k] >= 0.0f && out[k] <= 1.0f);
                    l[k] = srgb_to_linear(out[k]);
                }
                float y = 0.2126f * l[0] + 0.7152f * l[1] + 0.0722f * l[2];
                CHECK(y >= prev_y - 1e-5f && out[major[hue]] >= prev_major - 1e-5f); /* float rounding */
                if (hue == 0) CHECK(out[0] == out[1] || fabsf(out[0] - out[1]) < 1e-3f);
                prev_y = y, prev_major = out[major[hue]];
            }
        }
}

TEST(saturated_highlights_go_to_white)
{
    /* A saturated red: its saturation in the output falls steadily as it is exposed up, and
     * at +10 stops it is white; at mid-grey it keeps most of its saturation. */
    float in[3], out[3], s_prev = 2.0f;
    for (int ev = 0; ev <= 10; ev += 2) {
        float x = 0.18f * exp2f((float)ev);
        in[0] = x, in[1] = 0.1f * x, in[2] = 0.05f * x;
        tone_map_rgb(TONE_AGX, in, out);
        float s = saturation(out);
        if (ev == 0) CHECK(s > 0.6f);
        CHECK(s < s_prev);
        s_prev = s;
    }
    CHECK(s_prev < 0.02f);
    CHECK(out[0] > 0.99f && out[1] > 0.99f && out[2] > 0.99f);
    /* the hue does not skew: at every exposure red stays the largest, blue the smallest */
    for (int ev = -4; ev <= 8; ev++) {
        float x = 0.18f * exp2f((float)ev);
        in[0] = x, in[1] = 0.3f * x, in[2] = 0.1f * x;
        tone_map_rgb(TONE_AGX, in, out);
        CHECK(out[0] >= out[1] && out[1] >= out[2]);
    }
}

/* A film whose every pixel has luminance y. */
static film *flat_film(uint32_t w, uint32_t h, float y)
{
    err_buf err = {{0}};
    film *f = film_new(w, h, &err);
    CHECK(f != NULL);
    for (size_t k = 0; k < (size_t)w * h; k++) {
        f->rgb[k * 3] = f->rgb[k * 3 + 1] = f->rgb[k * 3 + 2] = y;
    }
    return f;
}

TEST(auto_exposure_puts_the_scene_on_mid_grey)
{
    film *f = flat_film(64, 32, 0.05f);
    double ev = auto_exposure_stops(f);
    CHECK_NEAR(M_PI * exp2(ev) * 0.05, 0.18, 1e-6);
    /* a sun disk (a few pixels 1e5 times brighter) and deep shadows do not move it */
    for (int k = 0; k < 40; k++) f->rgb[k * 3] = f->rgb[k * 3 + 1] = f->rgb[k * 3 + 2] = 5e3f;
    for (int k = 40; k < 80; k++) f->rgb[k * 3] = f->rgb[k * 3 + 1] = f->rgb[k * 3 + 2] = 1e-6f;
    CHECK_NEAR(auto_exposure_stops(f), ev, 1e-9);
    film_free(f);
    /* black: nothing to meter */
    f = flat_film(8, 8, 0.0f);
    CHECK_NEAR(auto_exposure_stops(f), 0.0, 0.0);
    film_free(f);
}

TEST(auto_exposure_log_average)
{
    /* half the pixels at 0.01, half at 0.16: the log-average is 0.04 */
    film *f = flat_film(40, 40, 0.01f);
    for (size_t k = 800; k < 1600; k++) f->rgb[k * 3] = f->rgb[k * 3 + 1] = f->rgb[k * 3 + 2] = 0.16f;
    CHECK_NEAR(auto_exposure_stops(f), log2(0.18 / (M_PI * 0.04)), 1e-6);
    film_free(f);
}

TEST_LIST(TEST_CASE(sigmoid_ends_pivot_and_monotone), TEST_CASE(black_to_black_grey_to_mid),
          TEST_CASE(monotone_with_exposure), TEST_CASE(saturated_highlights_go_to_white),
          TEST_CASE(auto_exposure_puts_the_scene_on_mid_grey), TEST_CASE(auto_exposure_log_average))
