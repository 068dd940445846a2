/* verification_sheet.h — the photomontage's verification sheet: what a reviewer needs to check
 * a visualisation, as an HTML page and as one PNG — the viewpoint's map coordinates and height,
 * the camera and lens, the horizontal and vertical fields of view, the distance and bearing to
 * the development, the date, time and sun position used, the control points' residuals, and
 * the wireline and the photomontage side by side.
 *
 * Both are written atomically (io/atomic_file.h). The HTML links to the wireline and montage
 * images by the file names given (beside it); the PNG holds them, scaled to fit. Values not
 * known (NAN, NULL) are shown as a dash. Nothing is kept: the caller owns the sheet's data.
 */
#ifndef SYLVA_VERIFICATION_SHEET_H
#define SYLVA_VERIFICATION_SHEET_H

#include <stdint.h>

#include "util/err.h"

typedef struct sheet_residual {
    const char *id;          /* the control point's name */
    double u, v;             /* its pixel in the photograph */
    double du, dv;           /* the solved camera's projection minus (u, v), pixels */
} sheet_residual;

typedef struct sheet_image {
    uint32_t width, height;
    const uint8_t *rgb;      /* 8-bit sRGB, 3 per pixel, row 0 at the top */
} sheet_image;

typedef struct verification_sheet {
    const char *title;
    const char *photo;                 /* the photograph's file name, or NULL */
    const char *crs_name;              /* NULL: coordinates are local metres */
    double viewpoint[3];               /* easting, northing, height of the camera, metres */
    double eye_above_ground;           /* metres */
    double heading_deg, pitch_deg, roll_deg;
    int cylindrical;                   /* 1: a panorama */
    double hfov_deg, vfov_deg;
    double focal_mm, sensor_width_mm, focal35_mm;
    const char *camera_model;          /* make and model */
    double k1, k2;                     /* radial distortion */
    double development_distance_m;     /* from the camera to the development's centre, horizontal */
    double development_bearing_deg;    /* clockwise from grid north */
    const char *date_time;             /* as the sun was placed for, or NULL */
    double sun_azimuth_deg, sun_elevation_deg;
    const sheet_residual *residuals;
    uint32_t n_residuals;
    double rmse_px;
    sheet_image wireline, montage;
    const char *wireline_file, *montage_file; /* the images' names beside the HTML */
} verification_sheet;

/* Writes the sheet as html_path and png_path (either may be NULL). Returns 0, or -1 with err
 * set (nothing is left behind). */
int verification_sheet_write(const verification_sheet *v, const char *html_path, const char *png_path, err_buf *err);

#endif
