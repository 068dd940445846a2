/* ground_departure.h — where the ground a render shows departs from the ground as surveyed that
 * the analyses read (scene.terrain against scene.surveyed): under the camera and under each
 * development object. A departure beyond GROUND_DEPARTURE_TOLERANCE is said with its figure, so
 * that a picture never silently stands on other ground than the study's maps.
 */
#ifndef SYLVA_GROUND_DEPARTURE_H
#define SYLVA_GROUND_DEPARTURE_H

#include <stdio.h>

#include "scene/scene.h"

#define GROUND_DEPARTURE_TOLERANCE 0.5 /* metres */

/* Writes a line to out (NULL: none) for each point whose rendered ground departs from the
 * surveyed by more than the tolerance, and returns the largest departure found, metres (0 when
 * the scene renders the surveyed ground itself). */
double ground_departure_report(const scene *s, FILE *out);

/* How far the rendered ground departs from the surveyed over the rectangle [x0, x1] x [y0, y1],
 * sampled on a GROUND_DEPARTURE_SAMPLES x GROUND_DEPARTURE_SAMPLES lattice: its RMS and largest
 * magnitude, metres (0 and 0 when the scene renders the surveyed ground itself). */
#define GROUND_DEPARTURE_SAMPLES 512u
void ground_departure_over(const scene *s, double x0, double y0, double x1, double y1, double *rms, double *max);

#endif
