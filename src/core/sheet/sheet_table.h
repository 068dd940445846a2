/* sheet_table.h — the rows of a sheet's table of facts, as label and text (sheet.h): the
 * viewpoint, grid reference, ground level, eye height, view direction, nearest development with
 * its distance and bearing, date and local time, sun, camera, projection, focal length, sensor
 * width, 35 mm equivalent, fields of view, render size, visualisation Type, print size, each
 * panel's printed size and viewing distance, the development in the frame, Earth curvature, the
 * camera match and the POV-Ray cross-check; with a planting plan, the year since planting and
 * the season the view shows. A photomontage's sheet (sheet_photo) names the photograph and how its
 * camera's position was found in place of the viewpoint, gives the capture time beside the sun's,
 * the EXIF's camera, lens and focal lengths beside the matched ones, its visualisation Type with
 * the reason, and the camera match's residuals. */
#ifndef SYLVA_SHEET_TABLE_H
#define SYLVA_SHEET_TABLE_H

#include <stddef.h>

#include "sheet/sheet_content.h"

#define SHEET_ROWS_MAX 32
#define SHEET_TEXT_MAX 320

typedef struct sheet_row {
    char label[48];
    char text[SHEET_TEXT_MAX];
} sheet_row;

/* The printed panels: the proposed view main_mm wide, the two others side_mm wide. */
typedef struct sheet_panels {
    double main_mm, side_mm, height_main_mm, height_side_mm;
} sheet_panels;

/* The distance in millimetres from which a picture of horizontal field hfov_deg printed width_mm
 * wide shows the view at its true size: planar (width / 2) / tan(hfov / 2); a cylindrical
 * panorama the radius of the cylinder it wraps, width / hfov in radians. */
double sheet_viewing_distance(double width_mm, double hfov_deg, int cylindrical);

/* The planting year and season sh shows ("year 15 after planting (2042), summer") into out;
 * 0 when its scene has no planting plan shown (out ""). */
int sheet_planting_text(const sheet *sh, char *out, size_t n);

/* Fills rows with sh's table for panels p (with the page's scale, millimetres printed per
 * millimetre laid out). Returns the number of rows. */
uint32_t sheet_table(const sheet *sh, const sheet_panels *p, double scale, sheet_row rows[SHEET_ROWS_MAX]);

#endif
