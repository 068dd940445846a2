/* page_image.c — a picture resampled to its print pixels and painted (page_image.h). */
#include "page/page_image.h"

#include <math.h>
#include <stdlib.h>

#include "page/page.h"

/* The weights of source pixels [*first, *first + n) under destination pixel d of dn along a side of
 * sn source pixels: the overlap of [d, d+1) * sn / dn with each. */
static int footprint(int d, int dn, int sn, int *first, double w[], int max)
{
    double a = (double)d * sn / dn, b = (double)(d + 1) * sn / dn;
    int i0 = (int)floor(a), n = 0;
    for (int i = i0; i < b && n < max; i++, n++) w[n] = fmin(b, i + 1.0) - fmax(a, (double)i);
    if (n == 0) w[n++] = 1;
    *first = i0 < sn ? i0 : sn - 1;
    return n;
}

#define FOOTPRINT_MAX 64 /* source pixels along a side under one destination pixel (more are left out) */

/* One channel-interleaved row of the destination from the source, into an xRGB cairo row. */
static void resample_row(const page_picture *p, int dw, int dh, int y, uint32_t *row)
{
    double wy[FOOTPRINT_MAX], wx[FOOTPRINT_MAX];
    int y0, ny = footprint(y, dh, (int)p->height, &y0, wy, FOOTPRINT_MAX);
    for (int x = 0; x < dw; x++) {
        int x0, nx = footprint(x, dw, (int)p->width, &x0, wx, FOOTPRINT_MAX);
        double sum[3] = {0, 0, 0}, total = 0;
        for (int j = 0; j < ny; j++) {
            int sy = y0 + j < (int)p->height ? y0 + j : (int)p->height - 1;
            for (int i = 0; i < nx; i++) {
                int sx = x0 + i < (int)p->width ? x0 + i : (int)p->width - 1;
                const uint8_t *s = p->rgb + ((size_t)sy * p->width + (size_t)sx) * 3;
                double w = wy[j] * wx[i];
                sum[0] += w * s[0], sum[1] += w * s[1], sum[2] += w * s[2], total += w;
            }
        }
        uint32_t r = (uint32_t)lround(sum[0] / total), g = (uint32_t)lround(sum[1] / total),
                 b = (uint32_t)lround(sum[2] / total);
        row[x] = 0xff000000u | r << 16 | g << 8 | b;
    }
}

cairo_surface_t *page_surface_rgb(const uint8_t *rgb, int w, int h)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h); /* owned by the caller */
    if (cairo_surface_status(s)) {
        cairo_surface_destroy(s);
        return NULL;
    }
    cairo_surface_flush(s);
    unsigned char *data = cairo_image_surface_get_data(s);
    int stride = cairo_image_surface_get_stride(s);
    for (int v = 0; rgb && v < h; v++) {
        uint32_t *row = (uint32_t *)(void *)(data + (size_t)v * stride);
        for (int u = 0; u < w; u++) {
            const uint8_t *p = rgb + 3 * ((size_t)v * w + u);
            row[u] = 0xff000000u | (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
        }
    }
    cairo_surface_mark_dirty(s);
    return s;
}

void page_paint(cairo_t *cr, cairo_surface_t *s, double x, double y, double w, double h, cairo_filter_t filter)
{
    cairo_save(cr);
    cairo_rectangle(cr, x, y, w, h);
    cairo_clip(cr);
    cairo_translate(cr, x, y);
    cairo_scale(cr, w / cairo_image_surface_get_width(s), h / cairo_image_surface_get_height(s));
    cairo_set_source_surface(cr, s, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), filter);
    cairo_paint(cr);
    cairo_restore(cr);
}

int page_image(cairo_t *cr, const page_picture *p, double x, double y, double w, double h, double dpi, err_buf *err)
{
    int dw = page_pixels(w, dpi), dh = page_pixels(h, dpi);
    cairo_surface_t *s = page_surface_rgb(NULL, dw, dh); /* owned here */
    if (!s) return err_nomem(err, "out of memory for a %dx%d picture on the page", dw, dh);
    cairo_surface_flush(s);
    unsigned char *data = cairo_image_surface_get_data(s);
    int stride = cairo_image_surface_get_stride(s);
    for (int r = 0; r < dh; r++) resample_row(p, dw, dh, r, (uint32_t *)(void *)(data + (size_t)r * stride));
    cairo_surface_mark_dirty(s);
    page_paint(cr, s, x, y, w, h, CAIRO_FILTER_GOOD);
    cairo_surface_destroy(s);
    return 0;
}
