/* image_rms.c — the noise of renders against a reference of the same view: the root mean square
 * of the per-pixel difference of Rec. 709 luminance over the whole image, relative to the
 * reference's mean luminance. The same measure for every renderer's files (EXR, R G B).
 *
 * usage: bench_image_rms REF IMAGE...   prints "IMAGE rms X mean M ref_mean R" per image
 */
#include <math.h>
#include <stdio.h>

#include "bench_image.h"

static int luminance_channels(const image_f32 *img, int ch[3], const char *path)
{
    ch[0] = bench_channel(img, "R"), ch[1] = bench_channel(img, "G"), ch[2] = bench_channel(img, "B");
    if (ch[0] < 0 || ch[1] < 0 || ch[2] < 0) {
        fprintf(stderr, "image_rms: %s: no R, G, B channels\n", path);
        return -1;
    }
    return 0;
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
    for (size_t i = 0; !rc && i < n; i++) ref_mean += bench_luminance(&ref, rch, i);
    ref_mean /= (double)n;
    for (int a = 2; !rc && a < argc; a++) {
        image_f32 img = {0};
        int ch[3];
        if (image_read(argv[a], &img, &err)) {
            fprintf(stderr, "image_rms: %s\n", err.msg);
            rc = 2;
            break;
        }
        if (luminance_channels(&img, ch, argv[a])) {
            rc = 2;
        } else if (img.width != ref.width || img.height != ref.height) {
            fprintf(stderr, "image_rms: %s is %ux%u, %s %ux%u\n", argv[a], img.width, img.height, argv[1], ref.width,
                    ref.height);
            rc = 2;
        }
        double se = 0, mean = 0;
        for (size_t i = 0; !rc && i < n; i++) {
            double l = bench_luminance(&img, ch, i), d = l - bench_luminance(&ref, rch, i);
            se += d * d, mean += l;
        }
        if (!rc) printf("%s rms %.6f mean %.6f ref_mean %.6f\n", argv[a], sqrt(se / (double)n) / ref_mean, mean / (double)n, ref_mean);
        image_free(&img);
    }
    image_free(&ref);
    return rc;
}
