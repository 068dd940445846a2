/* tone_curve.h — the curves that turn exposed linear RGB (scene-referred, unbounded) into
 * display-encoded sRGB in [0, 1] for PNG. Exposure is applied before (film.h); these see only
 * the exposed values, in which 0.18 is a mid-grey.
 *
 * agx (the default), after Sobotka's AgX image formation:
 *   1. inset: the linear Rec.709 colour is multiplied by AgX's inset matrix (each primary pulled
 *      about 15 % toward the other two; rows sum to 1, so greys are untouched);
 *   2. log encoding per channel: t = (log2(x / 0.18) + 10) / 16.5, clamped to [0, 1]: 10 stops
 *      below mid-grey to 6.5 stops above it;
 *   3. a sigmoid in t through the pivot (10 / 16.5, 0.5) with slope 2 there, a toe of power 3
 *      and a shoulder of power 3.25 that reach (0, 0) and (1, 1) exactly:
 *        y = y_p +/- A * s(2 |t - t_p| / A),  s(z) = z / (1 + z^p)^(1/p),
 *      A chosen per side so the end point is met (tone_curve.c);
 *   4. y is read as an sRGB-encoded value, decoded to linear, multiplied by the inverse of the
 *      inset (the outset, as the minimal AgX of Wrensch 2023 applies) and clamped to [0, 1],
 *      then encoded again.
 * Because each channel passes the sigmoid alone after the inset mixed them, a bright saturated
 * colour runs into the shoulder on all three channels and goes toward white, without the hue
 * skews of a per-channel curve on the raw primaries; colours the curve leaves on its straight
 * part get their saturation back from the outset. Greys, luminance and a colour's largest
 * channel rise with exposure; a minor channel of a saturated colour may dip by a few
 * thousandths in the toe (the outset subtracts a share of the others). Mid-grey 0.18 comes out
 * at 0.5 (128/255).
 *
 * aces: the ACES filmic fit of Narkowicz (2015), y = x (2.51 x + 0.03) / (x (2.43 x + 0.59)
 * + 0.14) per channel, clamped and sRGB-encoded; 0.18 comes out at 0.556 (142/255). */
#ifndef SYLVA_TONE_CURVE_H
#define SYLVA_TONE_CURVE_H

#include "scene/scene_settings.h"

/* The AgX sigmoid alone: log-encoded t in [0, 1] to display-encoded y in [0, 1]. */
float tone_agx_sigmoid(float t);
/* The ACES fit plus sRGB encoding, for one channel. */
float tone_aces_value(float x);
/* Exposed linear RGB to sRGB-encoded RGB in [0, 1] through curve c. */
void tone_map_rgb(tone_curve c, const float in[3], float out[3]);

#endif
