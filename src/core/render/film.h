/* film.h — the rendered frame: linear RGB and the auxiliary layers, tone mapping to 8-bit sRGB
 * and writing EXR and PNG files.
 *
 * Tone mapping for PNG: multiply by pi * 2^exposure, apply the ACES filmic curve as fitted by
 * Narkowicz (2015), then encode with the sRGB transfer function. The factor pi makes exposure 0
 * a daylight exposure: a white Lambertian surface facing a sun of irradiance 1 (radiance 1/pi)
 * comes out just below white, an 18 % grey in the sun as a mid-tone. The EXR keeps linear
 * values.
 *
 * The class and coverage layers serve comparisons (the POV-Ray cross-check); they are not
 * written to the EXR.
 *
 * Ownership: film_new allocates all layers; film_free releases them. */
#ifndef SYLVA_FILM_H
#define SYLVA_FILM_H

#include <stdint.h>

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
    uint8_t *pixel_class;  /* 1 per pixel: a pixel_class */
    float *coverage;       /* 1 per pixel: share of the camera samples that hit a surface */
} film;

film *film_new(uint32_t width, uint32_t height, err_buf *err);
void film_free(film *f); /* accepts NULL */

/* 8-bit sRGB RGB pixels (3 per pixel) after tone mapping; caller frees. */
uint8_t *film_tonemap(const film *f, double exposure_stops);
float film_tonemap_value(float linear); /* the curve plus sRGB encoding, for one channel */

int film_write_exr(const film *f, const char *path, err_buf *err);
int film_write_png(const film *f, const char *path, double exposure_stops, err_buf *err);

#endif
