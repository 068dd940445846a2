/* film.h — the rendered frame: linear RGB and the auxiliary layers, tone mapping to 8-bit sRGB
 * and writing EXR and PNG files.
 *
 * Tone mapping for PNG: multiply by pi * 2^exposure, then apply a tone curve (render/tone_curve.h:
 * AgX or the ACES fit), which ends in sRGB encoding. The factor pi makes exposure 0 a daylight
 * exposure: an 18 % grey Lambertian surface facing a sun of irradiance 1 (radiance 0.18/pi)
 * comes out as mid-grey. The exposure is chosen by the caller: the scene's, or metered from the
 * frame (render/auto_exposure.h). The EXR keeps linear values and records the exposure.
 *
 * The class and coverage layers serve comparisons (the POV-Ray cross-check); they are not
 * written to the EXR. The development layers are: the antialiased coverage of the objects marked
 * as the development (alpha) and their radiance premultiplied by it (the camera samples whose
 * first hit lies on the development, summed and divided by all samples), for compositing them
 * over a photograph (montage/composite.h).
 *
 * Ownership: film_new allocates all layers; film_free releases them. */
#ifndef SYLVA_FILM_H
#define SYLVA_FILM_H

#include <stddef.h>
#include <stdint.h>

#include "scene/scene_settings.h"
#include "util/err.h"

/* What a pixel's centre ray sees first. Plant surfaces are leaves when their material is a leaf
 * material and bark otherwise; the water surface counts as terrain. */
typedef enum pixel_class {
    PIXEL_SKY = 0, PIXEL_TERRAIN = 1, PIXEL_BARK = 2, PIXEL_LEAVES = 3, PIXEL_OBJECT = 4
} pixel_class;
#define PIXEL_CLASS_COUNT 5

typedef struct film {
    uint32_t width, height;
    float *rgb;            /* 3 per pixel */
    float *depth;          /* 1 per pixel */
    float *normal;         /* 3 per pixel */
    float *albedo;         /* 3 per pixel */
    uint32_t *instance_id; /* 1 per pixel */
    uint32_t *species_id;  /* 1 per pixel */
    uint32_t *object_id;   /* 1 per pixel: object index + 1, 0 for none */
    float *development;    /* 1 per pixel: share of the camera samples that hit the development */
    float *development_rgb; /* 3 per pixel: radiance of those samples over all samples (part of rgb) */
    uint8_t *pixel_class;  /* 1 per pixel: a pixel_class */
    float *coverage;       /* 1 per pixel: share of the camera samples that hit a surface */
} film;

/* The layers above as arrays of bytes, in a fixed order, for whatever moves a frame's rows
 * elsewhere whole (the ranks of an MPI job gather their bands, docs/mpi.md). A layer added to
 * the film is added here too. */
#define FILM_LAYERS 11
typedef struct film_layer {
    void *data;            /* the film's array */
    size_t pixel_bytes;    /* bytes per pixel (width * height of them, row by row) */
} film_layer;
void film_layers(film *f, film_layer out[FILM_LAYERS]);

/* Bytes a frame needs per pixel: the layers above, the 8-bit copy for PNG and the EXR writer's
 * half-float and line buffers (estimated from above). */
#define FILM_BYTES_PER_PIXEL 92u
/* Camera samples (width x height x spp) beyond which a render is refused as absurd work: 1e13
 * samples are weeks of tracing on a workstation. */
#define FILM_MAX_SAMPLES 1e13

/* Refuses, with a sentence saying what to lower, a frame whose layers do not fit the memory
 * budget (util/memory_budget.h) or whose sample count passes FILM_MAX_SAMPLES; 0 when it can be
 * rendered. Called before the scene's acceleration structure is built. */
int film_check(uint32_t width, uint32_t height, uint32_t spp, err_buf *err);
/* Allocates the layers (after the same memory check); NULL with err set on failure. */
film *film_new(uint32_t width, uint32_t height, err_buf *err);
void film_free(film *f); /* accepts NULL */

/* 8-bit sRGB RGB pixels (3 per pixel) after tone mapping; caller frees. */
uint8_t *film_tonemap(const film *f, tone_curve tone, double exposure_stops);

/* The EXR carries the site's CRS and origin in its header when site is not NULL and has a CRS,
 * and the exposure a PNG of it takes (attribute exposureStops) when exposure_stops is finite. */
int film_write_exr(const film *f, const site_settings *site, double exposure_stops, const char *path,
                   err_buf *err);
int film_write_png(const film *f, const char *path, tone_curve tone, double exposure_stops, err_buf *err);
/* film_write_png and film_write_exr as one set (atomic_file_commit_together): both files are
 * written under temporary names and renamed into place together under the lock beside them, so
 * that runs writing the same pair at once leave the PNG and the EXR of one run. */
int film_write_pair(const film *f, const site_settings *site, tone_curve tone, double exposure_stops,
                    const char *png_path, const char *exr_path, err_buf *err);
/* The same pair with the PNG's 8-bit pixels given (3 per pixel, the frame's size: a tone-mapped
 * frame drawn over, as a wireline), the EXR from f's layers. */
int film_write_pair_pixels(const film *f, const site_settings *site, double exposure_stops, const uint8_t *png_pixels,
                           const char *png_path, const char *exr_path, err_buf *err);

#endif
