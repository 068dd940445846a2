/* photo.h — a photograph read as a background plate: its pixels in linear light, turned
 * upright, and what its EXIF says about the camera, the lens, where it stood, where it looked
 * and when (docs/photomontage.md, "The plate and the sun").
 *
 * Pixels: JPEG, PNG and TIFF (whatever OpenImageIO reads) become linear RGB floats. 8- and
 * 16-bit samples are decoded with the sRGB curve (IEC 61966-2-1) unless the file declares
 * itself linear or a plain gamma (OpenImageIO's oiio:ColorSpace "linear" or "GammaX.Y");
 * floating-point samples are taken as linear. An ICC profile other than sRGB (Display P3,
 * Adobe RGB) is not converted: its description is kept in the EXIF record so a caller can say
 * so. Grey images become three equal channels; alpha is dropped.
 *
 * Orientation: the EXIF Orientation (1..8) is honoured: the plate is the image as it is meant
 * to be seen, and width and height are the upright ones.
 *
 * Ownership: photo_read fills a photo whose pixels it allocates; photo_free releases them. */
#ifndef SYLVA_PHOTO_H
#define SYLVA_PHOTO_H

#include <stdint.h>

#include "util/err.h"

/* What the EXIF of a photograph says. A field is meaningful only when its has_ flag is 1. */
typedef struct photo_exif {
    int has_make, has_model, has_lens_model;
    char make[64], model[64], lens_model[128];
    int has_focal_length;
    double focal_length_mm;
    int has_focal_length_35mm;
    double focal_length_35mm;         /* FocalLengthIn35mmFilm, mm */
    int has_focal_plane;              /* both resolutions and a length unit */
    double focal_plane_x_res, focal_plane_y_res; /* pixels per unit, along the stored axes */
    int focal_plane_unit;             /* 2 inch, 3 cm, 4 mm, 5 micrometre (EXIF/TIFF-EP) */
    int has_gps_position;
    double latitude_deg, longitude_deg; /* signed by GPSLatitudeRef/GPSLongitudeRef (N, E +) */
    int has_gps_altitude;
    double altitude_m;                /* signed by GPSAltitudeRef (1: below sea level) */
    int has_gps_direction;
    double direction_deg;             /* GPSImgDirection, clockwise from north */
    int direction_true;               /* 1: true north ("T"), 0: magnetic north ("M") */
    int has_date_time;                /* DateTimeOriginal, local time of the camera */
    int year, month, day, hour, minute, second;
    int has_utc_offset;               /* OffsetTimeOriginal ("+01:00") */
    int utc_offset_min;               /* local = UTC + offset */
    int orientation;                  /* EXIF Orientation as stored, 1 when absent */
    char icc_profile[64];             /* the ICC profile's description, "" when there is none */
} photo_exif;

typedef struct photo {
    uint32_t width, height;   /* upright */
    float *rgb;               /* width*height*3 linear RGB, row 0 at the top; owned (photo_free) */
    uint32_t stored_width, stored_height; /* as in the file, before the orientation */
    int bits;                 /* bits per sample in the file (8, 16, 32) */
    int is_float;             /* samples were floating point (taken as linear) */
    char colour_space[32];    /* OpenImageIO's oiio:ColorSpace, "" when not given */
    int sylva_render;         /* 1: sylva wrote the image (its Software tag, or the EXR's
                                 exposureStops): a render, not a photograph */
    photo_exif exif;
} photo;

/* Reads the photograph at path. Before allocating, the memory it needs is checked against the
 * budget (util/memory_budget.h). Returns 0, or -1 with err set to a sentence naming the file
 * (and what OpenImageIO said) when it is missing, unreadable, not an image, too large, or has
 * an Orientation outside 1..8. */
int photo_read(const char *path, photo *out, err_buf *err);
void photo_free(photo *p); /* accepts a zeroed photo */

/* The capture instant as ISO 8601 with its offset ("2021-04-10T11:44:00+01:00"), the form the
 * scene file's sun: date_time takes, into out. Returns 0, or -1 (out "") when the EXIF lacks
 * DateTimeOriginal or OffsetTimeOriginal: a local time without its offset names no instant. */
int photo_exif_iso8601(const photo_exif *x, char out[32]);

/* Where the width of the plate's image on the sensor came from. */
typedef enum photo_sensor_source {
    PHOTO_SENSOR_UNKNOWN = 0,   /* the caller must give it */
    PHOTO_SENSOR_FOCAL_PLANE,   /* plate width / FocalPlaneXResolution, in its unit */
    PHOTO_SENSOR_35MM,          /* from the 35 mm-equivalent focal length (by the diagonal) */
} photo_sensor_source;

/* The width in millimetres that the plate's horizontal extent covers on the sensor: from the
 * focal-plane resolution when present and plausible (1..100 mm), else from the 35 mm-equivalent
 * focal length (diagonal 43.27 mm x focal / f35, shared out by the plate's aspect), else
 * unknown (*width_mm set to 0). Returns the source used. */
photo_sensor_source photo_sensor_width(const photo *p, double *width_mm);
const char *photo_sensor_source_name(photo_sensor_source s);

/* Copies a stored image of sw x sh pixels with `channels` floats each into dst, turned upright
 * by the EXIF orientation (1..8): dst is sh wide and sw high for 5..8, sw wide otherwise. */
void photo_orient(const float *src, uint32_t sw, uint32_t sh, uint32_t channels, int orientation,
                  float *dst);

#endif
