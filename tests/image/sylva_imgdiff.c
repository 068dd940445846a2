/* sylva_imgdiff.c — compares a test image with a reference for the image-diff tests.
 *
 *   sylva_imgdiff REF TEST [--max-rmse X] [--max-mae X] [--threshold T] [--max-over F]
 *                          [--luminance] [--diff OUT.png] [--diff-scale S]
 *
 * Prints one line on stdout:
 *   mae=... rmse=... psnr=... max=... over(T)=... nonfinite=N
 * where over(T) is the fraction of pixels whose largest channel error exceeds T (default 0:
 * pixels that differ at all). Exit status: 0 when every stated bound holds, 1 when one fails
 * (each failure named on stderr), 2 on an error (bad arguments, unreadable image, sizes
 * differ). --diff writes a heatmap of the error (white at S; S defaults to T when T > 0, else
 * 0.1), also when a bound fails. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/image_compare.h"
#include "io/image_io.h"

static const char usage[] =
    "usage: sylva_imgdiff REF TEST [--max-rmse X] [--max-mae X] [--threshold T] [--max-over F]\n"
    "                     [--luminance] [--diff OUT.png] [--diff-scale S]\n";

typedef struct imgdiff_args {
    const char *ref_path, *test_path, *diff_path;
    double max_rmse, max_mae, threshold, max_over, diff_scale; /* NAN: not stated */
    int luminance;
} imgdiff_args;

static int parse_bound(const char *opt, const char *text, double *out)
{
    char *end = NULL;
    errno = 0;
    double v = text ? strtod(text, &end) : NAN;
    if (!text || end == text || *end != '\0' || errno || !(v >= 0.0) || isinf(v)) {
        fprintf(stderr, "sylva_imgdiff: %s needs a finite number >= 0, got \"%s\"\n", opt,
                text ? text : "(nothing)");
        return -1;
    }
    *out = v;
    return 0;
}

static int parse_args(int argc, char **argv, imgdiff_args *a)
{
    *a = (imgdiff_args){.max_rmse = NAN, .max_mae = NAN, .threshold = NAN, .max_over = NAN,
                        .diff_scale = NAN};
    int positional = 0;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        const char *next = i + 1 < argc ? argv[i + 1] : NULL;
        double *bound = !strcmp(arg, "--max-rmse")     ? &a->max_rmse
                        : !strcmp(arg, "--max-mae")    ? &a->max_mae
                        : !strcmp(arg, "--threshold")  ? &a->threshold
                        : !strcmp(arg, "--max-over")   ? &a->max_over
                        : !strcmp(arg, "--diff-scale") ? &a->diff_scale
                                                       : NULL;
        if (bound) {
            if (parse_bound(arg, next, bound)) return -1;
            i++;
        } else if (!strcmp(arg, "--diff")) {
            if (!next) {
                fprintf(stderr, "sylva_imgdiff: --diff needs an output file name\n");
                return -1;
            }
            a->diff_path = next;
            i++;
        } else if (!strcmp(arg, "--luminance")) {
            a->luminance = 1;
        } else if (arg[0] == '-' && arg[1] == '-') {
            fprintf(stderr, "sylva_imgdiff: unknown option %s\n", arg);
            return -1;
        } else if (positional == 0) {
            a->ref_path = arg, positional++;
        } else if (positional == 1) {
            a->test_path = arg, positional++;
        } else {
            fprintf(stderr, "sylva_imgdiff: one reference and one test image, not \"%s\" too\n",
                    arg);
            return -1;
        }
    }
    if (positional != 2) {
        fprintf(stderr, "sylva_imgdiff: a reference and a test image are needed\n");
        return -1;
    }
    if (!isnan(a->diff_scale) && a->diff_scale == 0.0) {
        fprintf(stderr, "sylva_imgdiff: --diff-scale must be greater than 0\n");
        return -1;
    }
    return 0;
}

/* Reports a failed bound on stderr; returns 1 when the bound is stated and not met. */
static int bound_fails(const char *metric, double value, const char *opt, double bound)
{
    if (isnan(bound) || value <= bound) return 0;
    fprintf(stderr, "sylva_imgdiff: %s %.6g exceeds %s %.6g\n", metric, value, opt, bound);
    return 1;
}

int main(int argc, char **argv)
{
    imgdiff_args a;
    if (parse_args(argc, argv, &a)) {
        fputs(usage, stderr);
        return 2;
    }
    err_buf err = {{0}};
    image_f32 ref = {0}, test = {0}; /* owned here */
    int status = 2;
    if (image_read(a.ref_path, &ref, &err) || image_read(a.test_path, &test, &err)) goto done;

    image_view rv = image_view_of(&ref), tv = image_view_of(&test);
    image_compare_opts opts = {.threshold = isnan(a.threshold) ? 0.0 : a.threshold,
                               .luminance = a.luminance};
    image_diff_stats s;
    if (image_compare(&rv, &tv, &opts, &s, &err)) {
        err_prefix(&err, "%s against %s: ", a.test_path, a.ref_path);
        goto done;
    }
    printf("mae=%.6g rmse=%.6g psnr=%.4f max=%.6g over(%g)=%.6g nonfinite=%llu\n", s.mae, s.rmse,
           s.psnr, s.max_abs, opts.threshold, s.over_fraction,
           (unsigned long long)s.nonfinite_pixels);
    fflush(stdout);

    int failed = bound_fails("rmse", s.rmse, "--max-rmse", a.max_rmse);
    failed |= bound_fails("mae", s.mae, "--max-mae", a.max_mae);
    char over_name[64];
    snprintf(over_name, sizeof over_name, "over(%g)", opts.threshold);
    failed |= bound_fails(over_name, s.over_fraction, "--max-over", a.max_over);

    if (a.diff_path) {
        double scale = !isnan(a.diff_scale) ? a.diff_scale
                       : opts.threshold > 0.0 ? opts.threshold
                                              : 0.1;
        if (image_diff_heatmap_write(a.diff_path, &rv, &tv, &opts, scale, &err)) goto done;
    }
    status = failed ? 1 : 0;

done:
    if (status == 2) fprintf(stderr, "sylva_imgdiff: %s\n", err.msg);
    image_free(&ref);
    image_free(&test);
    return status;
}
