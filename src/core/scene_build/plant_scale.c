/* plant_scale.c — a plant sized to a height and crown (plant_scale.h). */
#include "scene_build/plant_scale.h"

#include <math.h>

/* The crown's horizontal scale stays within these factors of the vertical scale. */
#define CROWN_RATIO_MIN 0.5
#define CROWN_RATIO_MAX 2.0

/* The model's crown width: the mean of its horizontal extents. */
static double model_width(const prototype *pr)
{
    float lo[3], hi[3];
    mesh_bounds(pr->mesh, lo, hi);
    double w = 0.5 * ((double)(hi[0] - lo[0]) + (double)(hi[1] - lo[1]));
    return isfinite(w) && w > 0 ? w : 0;
}

void plant_scales(const prototype *pr, double height, double crown, double *vertical, double *horizontal)
{
    *vertical = height / pr->height;
    *horizontal = *vertical;
    double w = crown > 0 ? model_width(pr) : 0;
    if (w > 0)
        *horizontal = fmin(fmax(crown / w, CROWN_RATIO_MIN * *vertical), CROWN_RATIO_MAX * *vertical);
}
