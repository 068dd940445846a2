/* composite.h — the development rendered into a photograph (the plate) by differential
 * rendering with a shadow catcher, in linear light (docs/photomontage.md, "Compositing").
 *
 * Two renders of one scene with one acceleration structure and the same samples: the whole scene
 * (R_full, with the development's own radiance D and its coverage alpha beside it, film.h) and
 * the scene without the development (R_bg). Per pixel and channel:
 *
 *     montage = k D + (1 - alpha) P S,    S = (R_full - D) / ((1 - alpha) R_bg)
 *
 * where k takes the render's radiance to the plate's linear values (1 when the plate is itself a
 * render; for a photograph, the exposure that matches them).
 *
 * D holds only the camera samples whose first hit is on the development, so the terrain and the
 * plants in front of it hide it (holdouts); R_full - D is the rest of the scene as the
 * development changes it (its shadows, the light it reflects), and S its ratio to the scene
 * without it: 1 where the development changes nothing, below 1 in its shadow. The plate is
 * darkened (or brightened) by that ratio, never painted over. Both renders take the same
 * samples, so wherever no path of a pixel meets the development R_full - D and R_bg are the same
 * numbers, S is exactly 1 and the plate passes through unchanged.
 *
 * Guards: S is 1 where (1 - alpha) R_bg is below COMPOSITE_DARK times the mean of R_bg over the
 * frame (no background light to take a ratio of; the pixel wholly development, or black in the
 * render) and is clamped to [0, COMPOSITE_RATIO_MAX] (a ratio beyond it is the noise of a pixel
 * where a sample or two reached past the development's edge, not light it reflects).
 *
 * This module renders and composites; reading the photograph and the command around it live
 * elsewhere. Ownership: composite_render fills a composite_renders whose films the caller frees
 * with composite_renders_free; composite_apply writes into the caller's buffers. */
#ifndef SYLVA_COMPOSITE_H
#define SYLVA_COMPOSITE_H

#include <stdint.h>

#include "io/image_io.h"
#include "render/film.h"
#include "render/render.h"
#include "scene/scene.h"
#include "util/err.h"

#define COMPOSITE_DARK 1e-3f
#define COMPOSITE_RATIO_MAX 4.0f

typedef struct composite_renders {
    film *full;        /* the whole scene: rgb R_full, development_rgb D, development alpha; owned */
    film *background;  /* the scene without its development, same seed and size: rgb R_bg; owned */
} composite_renders;

/* Renders s whole and without its development (opt's size, samples, seed, mode and threads; its
 * leave_out applies to both) with one acceleration structure. Returns 0, or -1 with err set and
 * out zeroed: a scene with no object marked `development: true` is refused, and so are two
 * frames that do not fit the memory budget together (util/memory_budget.h). */
int composite_render(const scene *s, const render_options *opt, composite_renders *out, err_buf *err);
void composite_renders_free(composite_renders *r); /* frees the films; accepts NULL and a zeroed one */

/* The per-pixel layers the formula reads (borrowed), 3 floats per pixel but alpha (1). */
typedef struct composite_layers {
    uint32_t width, height;
    const float *full;        /* R_full */
    const float *development; /* D */
    const float *alpha;       /* the development's coverage */
    const float *background;  /* R_bg */
} composite_layers;

/* The layers of renders made by composite_render. */
composite_layers composite_layers_of(const composite_renders *r);

/* The montage of plate (linear RGB; 1 channel is grey, a 4th channel is ignored) and l, with
 * the development's radiance times gain (k above): montage gets 3 floats per pixel (linear),
 * ratio (may be NULL) the shadow catcher's S, 3 per pixel. shadow_catcher 0 takes S = 1 (the
 * plate kept as it is around the development). Returns 0, or -1 with err set when the plate's
 * size is not the render's or gain is not a positive finite number. */
int composite_apply(const composite_layers *l, const image_f32 *plate, float gain, int shadow_catcher,
                    float *montage, float *ratio, err_buf *err);

/* Linear RGB (3 per pixel) as 8-bit sRGB bytes (the standard transfer function, no tone curve,
 * so the plate's own pixels come back as they were read): a new array the caller frees, or NULL
 * when out of memory. */
uint8_t *composite_srgb8(const float *rgb, size_t pixels);
/* The same, written to a PNG/JPEG/TIFF by its extension. */
int composite_write_srgb(const char *path, uint32_t width, uint32_t height, const float *rgb, err_buf *err);
/* Linear RGB and the development's mask (development.A) as an EXR (FLOAT). */
int composite_write_exr(const char *path, uint32_t width, uint32_t height, const float *rgb, const float *alpha,
                        err_buf *err);
/* The development's mask (its coverage, 0..1) as an 8-bit grey image: 255 where it covers the
 * whole pixel, 0 where it is hidden or absent. */
int composite_write_mask(const char *path, uint32_t width, uint32_t height, const float *alpha, err_buf *err);

#endif
