/* bench_image.h — reading renders for the comparison tools (image_rms, outline_classes): a
 * channel by name and a pixel's Rec. 709 luminance. Header-only, for the benchmark executables. */
#ifndef SYLVA_BENCH_IMAGE_H
#define SYLVA_BENCH_IMAGE_H

#include <string.h>

#include "io/image_io.h"

/* The index of the channel named `name` in img, else -1. */
static inline int bench_channel(const image_f32 *img, const char *name)
{
    for (uint32_t c = 0; c < img->channels; c++)
        if (!strcmp(img->channel_names[c], name)) return (int)c;
    return -1;
}

/* The Rec. 709 luminance of pixel i, from the channels ch[0..2] (R, G, B). */
static inline double bench_luminance(const image_f32 *img, const int ch[3], size_t i)
{
    const float *p = img->pixels + i * img->channels;
    return 0.2126 * p[ch[0]] + 0.7152 * p[ch[1]] + 0.0722 * p[ch[2]];
}

#endif
