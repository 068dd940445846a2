/* auto_exposure.h — the exposure a frame needs, metered from its own linear image the way a
 * camera's meter reads a scene: the mean of log2 luminance (Rec.709 weights) is placed on
 * mid-grey, 0.18 after the film's gain pi * 2^EV (film.h).
 *
 * Every pixel is metered, sky included, as a camera's averaging meter does (metering the land
 * alone overexposes a sunlit meadow by a stop and a half: its shadows pull the mean down). The
 * darkest 5 % and the brightest 5 % are left out (deep shadow, the sun's disk and glints), the
 * mean log taken over the rest. Percentiles come from a histogram of 1/32-stop bins from 2^-64 to 2^64;
 * pixels of zero or non-finite luminance are not metered. No allocation; one thread, in pixel
 * order, so the result is the same for the same film. */
#ifndef SYLVA_AUTO_EXPOSURE_H
#define SYLVA_AUTO_EXPOSURE_H

#include "render/film.h"

#define AUTO_EXPOSURE_MIDDLE_GREY 0.18
#define AUTO_EXPOSURE_CLIP 0.05 /* share left out at each end */

/* The exposure in stops (EV) for film_write_png, clamped to [-20, 20]; 0 for a frame with
 * nothing to meter (all black). */
double auto_exposure_stops(const film *f);

#endif
