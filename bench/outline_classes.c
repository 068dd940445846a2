/* outline_classes.c — two renders of the same view compared class by class of pixel, the classes
 * read from the first render's id layers (sylva's EXR): a plant pixel with a ground pixel among
 * its 8 neighbours (outline), a ground pixel with a plant among them (ground beside a plant), the
 * other plant pixels (plant inside) and ground pixels with no plant within 2 pixels (open
 * ground). Ground is terrain, water or an object: any pixel with a finite depth that is not an
 * instance. For each class: the pixel count, the second render's mean Rec. 709 luminance over
 * the first's minus 1, and that difference over its standard error (z, from the per-pixel
 * differences), so a bias confined to plant outlines shows beside the scene-wide one.
 *
 * usage: bench_outline_classes SYLVA.exr OTHER.exr */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_image.h"

enum pixel_class { CLASS_OUTLINE, CLASS_GROUND_BESIDE, CLASS_PLANT_INSIDE, CLASS_OPEN_GROUND, CLASSES, CLASS_NONE };
static const char *const class_names[CLASSES] = {"plant next to ground (outline)", "ground next to a plant",
                                                 "plant inside", "open ground"};

/* 1 plant, 0 ground, -1 sky (no depth). */
static int kind(const image_f32 *img, int inst, int depth, uint32_t x, uint32_t y)
{
    const float *p = img->pixels + ((size_t)y * img->width + x) * img->channels;
    if (p[inst] != 0) return 1;
    return isfinite(p[depth]) && p[depth] > 0 && p[depth] < 1e30f ? 0 : -1;
}

/* Whether a pixel of kind `want` lies within r pixels of (x, y). */
static int near(const image_f32 *img, int inst, int depth, uint32_t x, uint32_t y, int r, int want)
{
    for (int dy = -r; dy <= r; dy++)
        for (int dx = -r; dx <= r; dx++) {
            long nx = (long)x + dx, ny = (long)y + dy;
            if ((dx || dy) && nx >= 0 && ny >= 0 && nx < img->width && ny < img->height &&
                kind(img, inst, depth, (uint32_t)nx, (uint32_t)ny) == want)
                return 1;
        }
    return 0;
}

static enum pixel_class classify(const image_f32 *img, int inst, int depth, uint32_t x, uint32_t y)
{
    int k = kind(img, inst, depth, x, y);
    if (k == 1) return near(img, inst, depth, x, y, 1, 0) ? CLASS_OUTLINE : CLASS_PLANT_INSIDE;
    if (k == 0) {
        if (near(img, inst, depth, x, y, 1, 1)) return CLASS_GROUND_BESIDE;
        return near(img, inst, depth, x, y, 2, 1) ? CLASS_NONE : CLASS_OPEN_GROUND;
    }
    return CLASS_NONE;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: %s SYLVA.exr OTHER.exr\n", argv[0]);
        return 1;
    }
    err_buf err = {{0}};
    image_f32 a = {0}, b = {0};
    if (image_read(argv[1], &a, &err) || image_read(argv[2], &b, &err)) {
        fprintf(stderr, "outline_classes: %s\n", err.msg);
        image_free(&a);
        return 2;
    }
    int ca[3] = {bench_channel(&a, "R"), bench_channel(&a, "G"), bench_channel(&a, "B")};
    int cb[3] = {bench_channel(&b, "R"), bench_channel(&b, "G"), bench_channel(&b, "B")};
    int inst = bench_channel(&a, "id.instance"), depth = bench_channel(&a, "Z");
    int rc = 0;
    if (ca[0] < 0 || ca[1] < 0 || ca[2] < 0 || cb[0] < 0 || cb[1] < 0 || cb[2] < 0 || inst < 0 || depth < 0) {
        fprintf(stderr, "outline_classes: %s needs R, G, B, Z and id.instance; %s R, G, B\n", argv[1], argv[2]);
        rc = 2;
    } else if (a.width != b.width || a.height != b.height) {
        fprintf(stderr, "outline_classes: %s is %ux%u, %s %ux%u\n", argv[1], a.width, a.height, argv[2], b.width,
                b.height);
        rc = 2;
    }
    double sa[CLASSES] = {0}, sb[CLASSES] = {0}, sd2[CLASSES] = {0};
    size_t n[CLASSES] = {0};
    for (uint32_t y = 0; !rc && y < a.height; y++)
        for (uint32_t x = 0; x < a.width; x++) {
            enum pixel_class c = classify(&a, inst, depth, x, y);
            if (c == CLASS_NONE) continue;
            size_t i = (size_t)y * a.width + x;
            double la = bench_luminance(&a, ca, i), lb = bench_luminance(&b, cb, i);
            sa[c] += la, sb[c] += lb, sd2[c] += (lb - la) * (lb - la), n[c]++;
        }
    if (!rc) {
        printf("%-32s %9s %9s %6s  (second over first, %s over %s)\n", "pixels", "count", "diff", "z", argv[2], argv[1]);
        for (int c = 0; c < CLASSES; c++) {
            if (!n[c] || !(sa[c] > 0)) {
                printf("%-32s %9zu %9s %6s\n", class_names[c], n[c], "-", "-");
                continue;
            }
            /* the ratio of sums; its standard error from the spread of the per-pixel differences */
            double mean_d = (sb[c] - sa[c]) / (double)n[c], var = sd2[c] / (double)n[c] - mean_d * mean_d;
            double se = sqrt(var > 0 ? var / (double)n[c] : 0) / (sa[c] / (double)n[c]);
            double diff = sb[c] / sa[c] - 1;
            printf("%-32s %9zu %+8.2f%% %6.1f\n", class_names[c], n[c], 100 * diff, se > 0 ? diff / se : 0.0);
        }
    }
    image_free(&a);
    image_free(&b);
    return rc;
}
