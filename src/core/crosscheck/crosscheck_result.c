/* crosscheck_result.c — the pixel classes' names and the default thresholds
 * (crosscheck_result.h). */
#include "crosscheck/crosscheck_result.h"

static const char *const class_names[PIXEL_CLASS_COUNT] = {"sky", "terrain", "bark", "leaves", "objects"};

const char *crosscheck_class_name(int k)
{
    return k >= 0 && k < PIXEL_CLASS_COUNT ? class_names[k] : "unknown";
}

void crosscheck_default_thresholds(crosscheck_thresholds *t)
{
    t->min_coverage_agreement = 0.995;
    t->max_mae = 0.002;
    t->over_error = 0.02;
    t->max_over_fraction = 0.005;
    t->max_class_mae = 0.005;
    t->min_class_share = 0.01;
}
