/* sheet_view.h — what a study's sheet says of one viewpoint in one frame (docs/study.md,
 * Sheets): the facts TGN 06/19 and NatureScot's Visual Representation of Wind Farms ask a sheet
 * to state, computed from the built scene and the frame's camera:
 *
 *   the viewpoint's number (its place among the scene's viewpoints, then the points file's) and
 *   name; its grid reference (easting, northing in the site's CRS) and the ground level under
 *   it; the eye height; the view's heading and pitch;
 *   the nearest development structure (an object marked development, by its placement point),
 *   its horizontal distance and grid bearing;
 *   the date and local time of the view with its UTC offset (the sun's date_time), or that the
 *   sun was placed by its azimuth and elevation alone;
 *   the lens: projection, focal length, sensor width, 35 mm equivalent, horizontal and vertical
 *   fields of view;
 *   how much of the development the frame holds, in angles from its centre.
 *
 * Nothing is allocated; the strings point into the scene and the scene file. */
#ifndef SYLVA_SHEET_VIEW_H
#define SYLVA_SHEET_VIEW_H

#include <stdint.h>

#include "scene/scene.h"
#include "scene_file/scene_file.h"

typedef struct sheet_view {
    uint32_t number;              /* 1-based */
    const char *name, *frame;     /* viewpoint, frame name */
    const char *crs_name;         /* NULL: local metres */
    double easting, northing;     /* the eye's map coordinates */
    double ground_level;          /* the surveyed ground under the eye, map height */
    double eye_height;            /* the eye above that ground */
    double heading_deg, pitch_deg;
    const char *nearest;          /* the nearest development structure's name, or NULL: none */
    const char *development;      /* the development it belongs to */
    double distance_m, bearing_deg; /* horizontal, from the eye; bearing clockwise from grid north */
    uint32_t structures;          /* development objects in the scene */
    char local_time[64];          /* "2026-06-21 14:30 (UTC+01:00)", or "" when not given */
    double sun_azimuth_deg, sun_elevation_deg;
    int cylindrical;
    double hfov_deg, vfov_deg;
    double focal_mm, sensor_mm, focal35_mm; /* planar frames; NAN for a cylindrical one */
    uint32_t width, height;       /* the render's pixels */
    double dev_left_deg, dev_right_deg; /* the development's angles right of the view's centre */
    double dev_low_deg, dev_high_deg;   /* and above it (planar: on the image plane's axes) */
    int development_fits;         /* 1: the frame holds every development structure whole */
} sheet_view;

/* The facts of viewpoint v (one of sf's; NULL: a camera of no viewpoint, a photograph's, with
 * number 0 and no name) rendered with camera c (the frame's lens, placed over the ground of s) at
 * width x height pixels in the frame named frame. */
void sheet_view_of(const scene *s, const scene_file *sf, const scene_viewpoint *v, const camera_settings *c,
                   const char *frame, uint32_t width, uint32_t height, sheet_view *out);

/* The local date and time of `given` (ISO 8601 with its offset, as the sun's date_time) as
 * "YYYY-MM-DD hh:mm[:ss] (UTC+hh:mm)" into out; "" when given is empty. */
void sheet_local_time(const char *given, char *out, size_t n);

#endif
