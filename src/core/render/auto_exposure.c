/* auto_exposure.c — metering a frame's luminance for its exposure (auto_exposure.h). */
#include "render/auto_exposure.h"

#include <math.h>
#include <string.h>

#define LOG_LO (-64.0)
#define LOG_HI 64.0
#define BINS_PER_STOP 32
#define BINS ((int)((LOG_HI - LOG_LO) * BINS_PER_STOP))

/* log2 of pixel k's luminance, or NaN when it is not metered. */
static double pixel_log_luminance(const film *f, size_t k)
{
    const float *c = f->rgb + k * 3;
    double y = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    if (!(y > 0.0) || !isfinite(y)) return NAN;
    double l = log2(y);
    return l < LOG_LO ? LOG_LO : l >= LOG_HI ? LOG_HI - 1e-9 : l;
}

double auto_exposure_stops(const film *f)
{
    static const int n_bins = BINS;
    uint32_t hist[BINS];
    memset(hist, 0, sizeof hist);
    size_t n = (size_t)f->width * f->height;
    uint64_t total = 0;
    for (size_t k = 0; k < n; k++) {
        double l = pixel_log_luminance(f, k);
        if (isnan(l)) continue;
        hist[(int)((l - LOG_LO) * BINS_PER_STOP)]++;
        total++;
    }
    if (!total) return 0.0;
    /* the bins holding the percentiles AUTO_EXPOSURE_CLIP and 1 - AUTO_EXPOSURE_CLIP */
    uint64_t lo_rank = (uint64_t)(AUTO_EXPOSURE_CLIP * (double)total);
    uint64_t hi_rank = total - 1 - lo_rank;
    int lo = -1, hi = -1;
    uint64_t seen = 0;
    for (int b = 0; b < n_bins && hi < 0; b++) {
        seen += hist[b];
        if (lo < 0 && seen > lo_rank) lo = b;
        if (seen > hi_rank) hi = b;
    }
    double sum = 0.0;
    uint64_t used = 0;
    for (size_t k = 0; k < n; k++) {
        double l = pixel_log_luminance(f, k);
        if (isnan(l)) continue;
        int b = (int)((l - LOG_LO) * BINS_PER_STOP);
        if (b < lo || b > hi) continue;
        sum += l;
        used++;
    }
    double mean = sum / (double)used; /* used > 0: the percentile bins themselves hold pixels */
    double ev = log2(AUTO_EXPOSURE_MIDDLE_GREY / M_PI) - mean;
    return ev < -20.0 ? -20.0 : ev > 20.0 ? 20.0 : ev;
}
