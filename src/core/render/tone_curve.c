/* tone_curve.c — the AgX and ACES tone curves (tone_curve.h states them). */
#include "render/tone_curve.h"

#include <math.h>

#include "util/srgb.h"

#define AGX_MIN_EV (-10.0f)
#define AGX_MAX_EV 6.5f
#define AGX_PIVOT_T (10.0f / 16.5f)
#define AGX_PIVOT_Y 0.5f
#define AGX_SLOPE 2.0f
#define AGX_TOE_POWER 3.0f
#define AGX_SHOULDER_POWER 3.25f

/* AgX's inset for linear Rec.709 (sRGB) primaries, by rows; its inverse is the outset. */
static const float agx_inset[3][3] = {{0.842479062f, 0.078433600f, 0.079223745f},
                                      {0.042328242f, 0.878468636f, 0.079166127f},
                                      {0.042375655f, 0.078433600f, 0.879142974f}};

/* z / (1 + z^p)^(1/p) for z >= 0: slope 1 at 0, tends to 1. */
static float soft_limit(float z, float p) { return z / powf(1.0f + powf(z, p), 1.0f / p); }

/* The scale A for which A * soft_limit(k / A) == h: the side of the sigmoid that climbs h over
 * a run of slope k ends exactly there (needs k > h). */
static float side_scale(float k, float h, float p) { return k / powf(powf(k / h, p) - 1.0f, 1.0f / p); }

float tone_agx_sigmoid(float t)
{
    if (!(t > 0.0f)) return 0.0f;
    if (t >= 1.0f) return 1.0f;
    if (t < AGX_PIVOT_T) {
        float a = side_scale(AGX_SLOPE * AGX_PIVOT_T, AGX_PIVOT_Y, AGX_TOE_POWER);
        return AGX_PIVOT_Y - a * soft_limit(AGX_SLOPE * (AGX_PIVOT_T - t) / a, AGX_TOE_POWER);
    }
    float a = side_scale(AGX_SLOPE * (1.0f - AGX_PIVOT_T), 1.0f - AGX_PIVOT_Y, AGX_SHOULDER_POWER);
    return AGX_PIVOT_Y + a * soft_limit(AGX_SLOPE * (t - AGX_PIVOT_T) / a, AGX_SHOULDER_POWER);
}

float tone_aces_value(float x)
{
    if (!(x > 0.0f)) return 0.0f;
    float y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    y = y < 0.0f ? 0.0f : y > 1.0f ? 1.0f : y;
    return srgb_from_linear(y);
}

static void mat3_apply(const float m[3][3], const float in[3], float out[3])
{
    for (int r = 0; r < 3; r++) out[r] = m[r][0] * in[0] + m[r][1] * in[1] + m[r][2] * in[2];
}

/* The inverse of agx_inset from its cofactors, so that no second table can drift from it. */
static void agx_outset(float inv[3][3])
{
    const float(*m)[3] = agx_inset;
    float c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1], c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2],
          c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    float det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    inv[0][0] = c00 / det, inv[1][0] = c01 / det, inv[2][0] = c02 / det;
    inv[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
    inv[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
    inv[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
    inv[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
    inv[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
    inv[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
}

void tone_map_rgb(tone_curve c, const float in[3], float out[3])
{
    if (c == TONE_ACES) {
        for (int k = 0; k < 3; k++) out[k] = tone_aces_value(in[k]);
        return;
    }
    float x[3], y[3], inv[3][3];
    for (int k = 0; k < 3; k++) x[k] = in[k] > 0.0f ? in[k] : 0.0f; /* NaN and negatives as 0 */
    mat3_apply(agx_inset, x, y);
    for (int k = 0; k < 3; k++) {
        float t = y[k] > 0.0f ? (log2f(y[k] / 0.18f) - AGX_MIN_EV) / (AGX_MAX_EV - AGX_MIN_EV) : 0.0f;
        y[k] = srgb_to_linear(tone_agx_sigmoid(t));
    }
    agx_outset(inv);
    mat3_apply(inv, y, x);
    for (int k = 0; k < 3; k++) out[k] = srgb_from_linear(x[k] < 0.0f ? 0.0f : x[k] > 1.0f ? 1.0f : x[k]);
}
