/* exr_write.h — writing a rendered frame as a multi-layer OpenEXR file through the OpenEXR Core
 * C API (openexr.h). Channels: R, G, B (linear, HALF or FLOAT), Z (depth, FLOAT), N.X N.Y N.Z
 * (world normal), albedo.R albedo.G albedo.B, id.instance, id.species and id.object (UINT),
 * development.A (the development's coverage, FLOAT 0..1), development.R, development.G,
 * development.B (its radiance premultiplied by that coverage, FLOAT); the site's CRS and origin
 * as header attributes when the scene has a site, and the exposure of its PNG when given. Any
 * layer pointer may be NULL and is then left out. The file is written under a temporary name in the same folder and renamed into place, so
 * a failure never leaves a partial file at `path`. */
#ifndef SYLVA_EXR_WRITE_H
#define SYLVA_EXR_WRITE_H

#include <stdint.h>

#include "io/atomic_file.h"
#include "util/err.h"

typedef struct exr_frame {
    uint32_t width, height;
    const float *rgb;          /* 3 per pixel, row 0 at the top */
    const float *depth;        /* 1 per pixel: distance along the camera axis; +inf for sky */
    const float *normal;       /* 3 per pixel, world space */
    const float *albedo;       /* 3 per pixel */
    const uint32_t *instance_id; /* 1 per pixel: 0 = none, else instance index + 1 */
    const uint32_t *species_id;  /* 1 per pixel: 0 = none, else species index + 1 */
    const uint32_t *object_id;   /* 1 per pixel: 0 = none, else object index + 1 */
    const float *development;    /* 1 per pixel: coverage of the development, 0..1 */
    const float *development_rgb; /* 3 per pixel: the development's radiance times its coverage */
    int rgb_half;              /* 1: store R, G, B as HALF; 0: FLOAT */
    /* Where the image stands on the Earth, as header attributes: siteCrsWkt and siteCrsName
     * (strings), siteOriginEasting, siteOriginNorthing and siteOriginHeight (doubles: the map
     * coordinates of the local frame's origin). Left out when crs_wkt is NULL. */
    const char *crs_wkt;
    const char *crs_name;
    double origin[3];
    /* The exposure in stops the frame's PNG is tone-mapped with: header attribute exposureStops
     * (double), written when has_exposure is 1. */
    int has_exposure;
    double exposure_stops;
} exr_frame;

/* Writes f to path (ZIP compression, scanline). Returns 0 or -1 with err set. */
int exr_write(const char *path, const exr_frame *f, err_buf *err);
/* The same into a temporary the caller opened (atomic_file_open) and commits or aborts itself,
 * for outputs that appear together; messages name out->path. */
int exr_write_into(atomic_file *out, const exr_frame *f, err_buf *err);

#endif
