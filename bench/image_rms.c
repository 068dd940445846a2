/* image_rms.c — the noise of renders against a reference of the same view: the root mean square
 * of the per-pixel difference of Rec. 709 luminance over the whole image, relative to the
 * reference's mean luminance. The same measure for every renderer's files (EXR, R G B).
 *
 * usage: bench_image_rms REF IMAGE...   prints "IMAGE rms X mean M ref_mean R" per image
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io/image_io.h"

/* The channel index named `name` in img, else -1. */
static int channel(const image_f32 *img, const char *name)
{
    for (uint32_t c = 0; c < img->channels; c++)
        if (!strcmp(img->channel_names[c], name)) return (int)c;
    return -1;
}

static int luminance_channels(const image_f32 *img, int ch[3], const char *path)
{
    ch[0] = channel(img, "R"), ch[1] = channel(img, "G"), ch[2] = channel(img, "B");
    if (ch[0] < 0 || ch[1] < 0 || ch[2] < 0) {
        fprintf(stderr, "image_rms: %s: no R, G, B channels\n", path);
        return -1;
    }
    return 0;
}

static double lum(const image_f32 *img, const int ch[3], size_t i)
{
    const float *p = img->pixels + i * img->channels;
    return 0.2126 * p[ch[0]] + 0.7152 * p[ch[1]] + 0.0722 * p[ch[2]];
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: %s REF IMAGE...\n", argv[0]);
        return 1;
    }
    err_buf err = {{0}};
    image_f32 ref = {0};
    int rch[3], rc = 0;
    if (image_read(argv[1], &ref, &err)) {
        fprintf(stderr, "image_rms: %s\n", err.msg);
        return 2;
    }
    if (luminance_channels(&ref, rch, argv[1])) rc = 2;
    size_t n = (size_t)ref.width * ref.height;
    double ref_mean = 0;
    for (size_t i = 0; !rc && i < n; i++) ref_mean += lum(&ref, rch, i);
    ref_mean /= (double)n;
    for (int a = 2; !rc && a < argc; a++) {
        image_f32 img = {0};
        int ch[3];
        if (image_read(argv[a], &img, &err)) {
            fprintf(stderr, "image_rms: %s\n", err.msg);
            rc = 2;
            break;
        }
        if (luminance_channels(&img, ch, argv[a]) || img.width != ref.width || img.height != ref.height) {
            if (!rc && img.width != ref.width) fprintf(stderr, "image_rms: %s: size differs from %s\n", argv[a], argv[1]);
            rc = 2;
        }
        double se = 0, mean = 0;
        for (size_t i = 0; !rc && i < n; i++) {
            double l = lum(&img, ch, i), d = l - lum(&ref, rch, i);
            se += d * d, mean += l;
        }
        if (!rc) printf("%s rms %.6f mean %.6f ref_mean %.6f\n", argv[a], sqrt(se / (double)n) / ref_mean, mean / (double)n, ref_mean);
        image_free(&img);
    }
    image_free(&ref);
    return rc;
}
