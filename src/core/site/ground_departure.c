/* ground_departure.c — the rendered ground against the surveyed (ground_departure.h). */
#include "site/ground_departure.h"

#include <math.h>

#include "scene/heightfield.h"

/* Rendered minus surveyed height at (x, y); 0 where either has no ground there. */
static double departure(const scene *s, double x, double y)
{
    double shown, surveyed;
    if (heightfield_height(s->terrain, x, y, &shown) || heightfield_height(s->surveyed, x, y, &surveyed)) return 0;
    return shown - surveyed;
}

double ground_departure_report(const scene *s, FILE *out)
{
    if (!s->terrain || !s->surveyed || s->terrain == s->surveyed) return 0;
    double worst = 0, d = departure(s, s->camera.position[0], s->camera.position[1]);
    worst = fabs(d);
    if (out && fabs(d) > GROUND_DEPARTURE_TOLERANCE)
        fprintf(out, "sylva: warning: the rendered ground under the camera stands %.2f m %s the DTM as surveyed (the "
                "refinement's detail; tolerance %.1f m): the eye stands at its height above the rendered ground\n",
                fabs(d), d > 0 ? "above" : "below", GROUND_DEPARTURE_TOLERANCE);
    for (uint32_t o = 0; o < s->n_objects; o++) {
        if (!s->objects[o].development) continue;
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        scene_object_bounds(s, o, lo, hi);
        if (!(lo[0] <= hi[0])) continue;
        d = departure(s, 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]));
        worst = fmax(worst, fabs(d));
        if (out && fabs(d) > GROUND_DEPARTURE_TOLERANCE)
            fprintf(out, "sylva: warning: the rendered ground under development object '%s' stands %.2f m %s the DTM "
                    "as surveyed, on which the object stands (the refinement's detail; tolerance %.1f m)\n",
                    s->objects[o].name, fabs(d), d > 0 ? "above" : "below", GROUND_DEPARTURE_TOLERANCE);
    }
    return worst;
}

void ground_departure_over(const scene *s, double x0, double y0, double x1, double y1, double *rms, double *max)
{
    double sum = 0, top = 0;
    uint64_t n = 0;
    if (s->terrain && s->surveyed && s->terrain != s->surveyed)
        for (uint32_t j = 0; j < GROUND_DEPARTURE_SAMPLES; j++)
            for (uint32_t i = 0; i < GROUND_DEPARTURE_SAMPLES; i++) {
                double x = x0 + (x1 - x0) * (i + 0.5) / GROUND_DEPARTURE_SAMPLES;
                double y = y0 + (y1 - y0) * (j + 0.5) / GROUND_DEPARTURE_SAMPLES, d = departure(s, x, y);
                sum += d * d, top = fmax(top, fabs(d)), n++;
            }
    *rms = n ? sqrt(sum / (double)n) : 0, *max = top;
}
