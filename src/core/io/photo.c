/* photo.c — a photograph as a plate: the stored pixels (read with their EXIF through the
 * OpenImageIO shim) decoded to linear RGB and turned upright in one pass, and the sensor width
 * the plate covers. */
#include "io/photo.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "io/image_io.h"
#include "util/srgb.h"

/* The stored pixel shown at (x, y) of the upright image, for an EXIF orientation: 1 as stored,
 * 2 mirrored left-right, 3 turned half round, 4 mirrored top-bottom, 5 transposed, 6 turned a
 * quarter clockwise, 7 transversed, 8 turned a quarter anticlockwise. */
static size_t stored_index(uint32_t x, uint32_t y, uint32_t sw, uint32_t sh, int orientation)
{
    uint32_t sx, sy;
    switch (orientation) {
    case 2: sx = sw - 1 - x, sy = y; break;
    case 3: sx = sw - 1 - x, sy = sh - 1 - y; break;
    case 4: sx = x, sy = sh - 1 - y; break;
    case 5: sx = y, sy = x; break;
    case 6: sx = y, sy = sh - 1 - x; break;
    case 7: sx = sw - 1 - y, sy = sh - 1 - x; break;
    case 8: sx = sw - 1 - y, sy = x; break;
    default: sx = x, sy = y; break;
    }
    return (size_t)sy * sw + sx;
}

static int transposes(int orientation) { return orientation >= 5 && orientation <= 8; }

void photo_orient(const float *src, uint32_t sw, uint32_t sh, uint32_t channels, int orientation,
                  float *dst)
{
    uint32_t w = transposes(orientation) ? sh : sw, h = transposes(orientation) ? sw : sh;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            const float *s = src + stored_index(x, y, sw, sh, orientation) * channels;
            memcpy(dst + ((size_t)y * w + x) * channels, s, channels * sizeof(float));
        }
}

typedef enum transfer { TRANSFER_SRGB, TRANSFER_LINEAR, TRANSFER_GAMMA } transfer;

/* How the file's samples encode light: floats and files declared linear are linear, a file
 * declaring "GammaX.Y" (a PNG gAMA chunk) follows that power, everything else is sRGB. */
static transfer transfer_of(const photo *p, float *gamma)
{
    const char *cs = p->colour_space;
    if (p->is_float || !strcasecmp(cs, "linear") || !strcasecmp(cs, "scene_linear") ||
        !strcasecmp(cs, "lin_srgb"))
        return TRANSFER_LINEAR;
    if (!strncasecmp(cs, "gamma", 5)) {
        float g = strtof(cs + 5, NULL);
        if (g > 0.2f && g < 5.0f) {
            *gamma = g;
            return fabsf(g - 1.0f) < 1e-3f ? TRANSFER_LINEAR : TRANSFER_GAMMA;
        }
    }
    return TRANSFER_SRGB;
}

static float decode(float v, transfer t, float gamma)
{
    if (t == TRANSFER_LINEAR) return v;
    v = fmaxf(0.0f, fminf(v, 1.0f));
    return t == TRANSFER_GAMMA ? powf(v, gamma) : srgb_to_linear(v);
}

int photo_read(const char *path, photo *out, err_buf *err)
{
    photo p = {0};
    image_f32 stored = {0};
    if (image_read_photo(path, &stored, &p, err)) return -1;
    int o = p.exif.orientation;
    p.width = transposes(o) ? stored.height : stored.width;
    p.height = transposes(o) ? stored.width : stored.height;
    size_t n_px = (size_t)p.width * p.height;
    p.rgb = malloc(n_px * 3 * sizeof(float)); /* owned by the photo; counted in the check */
    if (!p.rgb) {
        image_free(&stored);
        return err_nomem(err, "%s: out of memory for the linear plate (%ux%u)", path, p.width,
                         p.height);
    }
    float gamma = 1.0f;
    transfer t = transfer_of(&p, &gamma);
    /* 8-bit samples arrive as k / 255: one table instead of a power per sample */
    float table[256];
    int use_table = p.bits == 8 && !p.is_float;
    for (int k = 0; use_table && k < 256; k++) table[k] = decode(k / 255.0f, t, gamma);
    /* grey (and grey + alpha) give three equal channels; alpha and extra channels are dropped */
    uint32_t c = stored.channels, step[3] = {0, c >= 3 ? 1u : 0u, c >= 3 ? 2u : 0u};
    for (uint32_t y = 0; y < p.height; y++)
        for (uint32_t x = 0; x < p.width; x++) {
            const float *s = stored.pixels + stored_index(x, y, stored.width, stored.height, o) * c;
            float *d = p.rgb + ((size_t)y * p.width + x) * 3;
            for (int k = 0; k < 3; k++) {
                float v = s[step[k]];
                d[k] = use_table ? table[(int)lrintf(fmaxf(0.0f, fminf(v, 1.0f)) * 255.0f)]
                                 : decode(v, t, gamma);
            }
        }
    image_free(&stored);
    *out = p;
    return 0;
}

int photo_exif_iso8601(const photo_exif *x, char out[32])
{
    out[0] = 0;
    if (!x->has_date_time || !x->has_utc_offset) return -1;
    int off = x->utc_offset_min < 0 ? -x->utc_offset_min : x->utc_offset_min;
    snprintf(out, 32, "%04d-%02d-%02dT%02d:%02d:%02d%c%02d:%02d", x->year, x->month, x->day,
             x->hour, x->minute, x->second, x->utc_offset_min < 0 ? '-' : '+', off / 60, off % 60);
    return 0;
}

void photo_free(photo *p)
{
    if (!p) return;
    free(p->rgb);
    *p = (photo){0};
}

/* Millimetres per focal-plane resolution unit: 2 inch, 3 cm, 4 mm, 5 micrometre. */
static double unit_mm(int unit)
{
    switch (unit) {
    case 2: return 25.4;
    case 3: return 10.0;
    case 4: return 1.0;
    case 5: return 0.001;
    default: return 0.0;
    }
}

#define DIAGONAL_35MM 43.2666 /* mm: the diagonal of the 36 x 24 mm frame */

photo_sensor_source photo_sensor_width(const photo *p, double *width_mm)
{
    const photo_exif *x = &p->exif;
    *width_mm = 0.0;
    if (x->has_focal_plane && unit_mm(x->focal_plane_unit) > 0.0) {
        /* the resolutions count pixels along the stored axes; an upright plate turned a quarter
         * spans the stored height */
        double w = transposes(x->orientation)
                       ? p->stored_height / x->focal_plane_y_res * unit_mm(x->focal_plane_unit)
                       : p->stored_width / x->focal_plane_x_res * unit_mm(x->focal_plane_unit);
        if (w >= 1.0 && w <= 100.0) {
            *width_mm = w;
            return PHOTO_SENSOR_FOCAL_PLANE;
        }
    }
    if (x->has_focal_length && x->has_focal_length_35mm && p->width && p->height) {
        /* the equivalent focal length scales the frame's diagonal (CIPA DC-004) */
        double diagonal = DIAGONAL_35MM * x->focal_length_mm / x->focal_length_35mm;
        double w = diagonal * p->width / hypot((double)p->width, (double)p->height);
        if (w >= 1.0 && w <= 100.0) {
            *width_mm = w;
            return PHOTO_SENSOR_35MM;
        }
    }
    return PHOTO_SENSOR_UNKNOWN;
}

const char *photo_sensor_source_name(photo_sensor_source s)
{
    switch (s) {
    case PHOTO_SENSOR_FOCAL_PLANE: return "the EXIF focal-plane resolution";
    case PHOTO_SENSOR_35MM: return "the EXIF 35 mm-equivalent focal length";
    default: return "nowhere: the EXIF gives neither the focal-plane resolution nor the 35 mm "
                    "equivalent; give the sensor width";
    }
}
