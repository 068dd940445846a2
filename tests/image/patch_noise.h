/* patch_noise.h — the noise and the mean radiance of a plant patch in renders of one scene: the
 * patch is the bounding box of the pixels whose centre ray meets a plant; the noise is the
 * per-pixel standard deviation of the luminance over renders with different seeds (unbiased,
 * averaged as a variance over the patch, square root taken last) relative to the patch's mean
 * luminance. Header-only, for the distance test and its benchmark. */
#ifndef SYLVA_TEST_PATCH_NOISE_H
#define SYLVA_TEST_PATCH_NOISE_H

#include <math.h>
#include <stdlib.h>
#include <time.h>

#include "render/film.h"
#include "render/render.h"

typedef struct patch_box {
    uint32_t x0, y0, x1, y1; /* pixels [x0, x1) x [y0, y1) */
} patch_box;

typedef struct patch_figures {
    double mean;   /* mean luminance over the patch and the renders */
    double noise;  /* per-pixel standard deviation over the renders, relative to mean */
    double noise_plant, noise_ground; /* the same over the patch's pixels whose centre ray meets a
                                       * plant (in the first render), and over the others */
    double seconds; /* render time of all the renders */
    double cpu_seconds; /* the process's processor time over the renders (all threads): the
                         * figure to compare on a machine that other work shares */
} patch_figures;

static inline double patch_clock(clockid_t clock)
{
    struct timespec ts;
    clock_gettime(clock, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static inline double patch_seconds(void) { return patch_clock(CLOCK_MONOTONIC); }

static inline double patch_luminance(const float *rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

/* The bounding box of the pixels of f whose centre ray meets a plant; 0, or -1 when none does. */
static inline int patch_find(const film *f, patch_box *b)
{
    *b = (patch_box){f->width, f->height, 0, 0};
    for (uint32_t y = 0; y < f->height; y++)
        for (uint32_t x = 0; x < f->width; x++)
            if (f->species_id[(size_t)y * f->width + x]) {
                if (x < b->x0) b->x0 = x;
                if (y < b->y0) b->y0 = y;
                if (x + 1 > b->x1) b->x1 = x + 1;
                if (y + 1 > b->y1) b->y1 = y + 1;
            }
    return b->x1 > b->x0 ? 0 : -1;
}

/* Renders rs n_seeds times (seeds 1, 2, ...) at opt's size and samples and measures the patch b
 * (found in the first render when b->x1 is 0). Returns 0, or -1 with err set. */
static inline int patch_measure(render_setup *rs, const render_options *opt, uint32_t n_seeds, patch_box *b,
                                patch_figures *out, err_buf *err)
{
    double *sum = NULL, *sum2 = NULL, t0 = patch_seconds(), c0 = patch_clock(CLOCK_PROCESS_CPUTIME_ID);
    uint8_t *plant = NULL;
    size_t n = 0;
    uint32_t w = 0;
    int rc = -1;
    for (uint32_t k = 0; k < n_seeds; k++) {
        render_options o = *opt;
        o.seed_set = 1, o.seed = k + 1;
        film *f = render_setup_run(rs, &o, NULL, err);
        if (!f) goto done;
        if (!k) {
            n = (size_t)f->width * f->height, w = f->width;
            sum = calloc(n, sizeof *sum), sum2 = calloc(n, sizeof *sum2), plant = calloc(n, 1);
            if (!sum || !sum2 || !plant || (!b->x1 && patch_find(f, b))) {
                film_free(f);
                err_set(err, sum && sum2 && plant ? "no pixel of the render shows a plant" : "out of memory");
                goto done;
            }
            for (size_t i = 0; i < n; i++) plant[i] = f->species_id[i] != 0;
        }
        for (size_t i = 0; i < n; i++) {
            double l = patch_luminance(f->rgb + 3 * i);
            sum[i] += l, sum2[i] += l * l;
        }
        film_free(f);
    }
    double mean = 0, var = 0, m = 0, var_p = 0, m_p = 0;
    for (uint32_t y = b->y0; y < b->y1; y++)
        for (uint32_t x = b->x0; x < b->x1; x++) {
            size_t i = (size_t)y * w + x;
            double mu = sum[i] / n_seeds;
            mean += mu;
            double v = (sum2[i] - n_seeds * mu * mu) / (n_seeds - 1);
            var += v, m++;
            if (plant[i]) var_p += v, m_p++;
        }
    out->mean = mean / m;
    out->noise = sqrt(fmax(var / m, 0)) / out->mean;
    out->noise_plant = m_p > 0 ? sqrt(fmax(var_p / m_p, 0)) / out->mean : 0;
    out->noise_ground = m > m_p ? sqrt(fmax((var - var_p) / (m - m_p), 0)) / out->mean : 0;
    out->seconds = patch_seconds() - t0;
    out->cpu_seconds = patch_clock(CLOCK_PROCESS_CPUTIME_ID) - c0;
    rc = 0;
done:
    free(sum);
    free(sum2);
    free(plant);
    return rc;
}

#endif
