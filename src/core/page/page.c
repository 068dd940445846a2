/* page.c — one drawing written as a PDF page and as a PNG (page.h). */
#include "page/page.h"

#include <cairo-pdf.h>
#include <math.h>
#include <stdio.h>

#include "io/atomic_file.h"
#include "io/png_write.h"

#define MM_PER_INCH 25.4
#define PT_PER_MM (72.0 / MM_PER_INCH)

int page_pixels(double mm, double dpi)
{
    long n = lround(mm / MM_PER_INCH * dpi);
    return n < 1 ? 1 : (int)n;
}

static cairo_status_t to_stream(void *closure, const unsigned char *data, unsigned int length)
{
    return fwrite(data, 1, length, (FILE *)closure) == length ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

/* Runs draw on surface s scaled so that one unit is a millimetre; the cairo status checked. */
static int draw_on(cairo_surface_t *s, double units_per_mm, const page_size *size, page_draw_fn draw, void *ctx,
                   const char *what, err_buf *err)
{
    cairo_t *cr = cairo_create(s); /* owned here */
    cairo_scale(cr, units_per_mm, units_per_mm);
    int rc = draw(cr, size, ctx, err);
    if (!rc && cairo_status(cr))
        rc = err_fail(err, ERR_OUTPUT, "drawing the %s page failed: %s", what, cairo_status_to_string(cairo_status(cr)));
    cairo_destroy(cr);
    return rc;
}

static int write_pdf(const page_size *size, page_draw_fn draw, void *ctx, FILE *out, err_buf *err)
{
    cairo_surface_t *s = cairo_pdf_surface_create_for_stream(to_stream, out, size->width_mm * PT_PER_MM,
                                                             size->height_mm * PT_PER_MM); /* owned here */
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATOR, "sylva");
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00Z"); /* deterministic */
    int rc = draw_on(s, PT_PER_MM, size, draw, ctx, "PDF", err);
    cairo_surface_finish(s);
    if (!rc && cairo_surface_status(s))
        rc = err_fail(err, ERR_OUTPUT, "writing the PDF failed: %s", cairo_status_to_string(cairo_surface_status(s)));
    cairo_surface_destroy(s);
    return rc;
}

static int write_png(const page_size *size, page_draw_fn draw, void *ctx, FILE *out, err_buf *err)
{
    int w = page_pixels(size->width_mm, size->dpi), h = page_pixels(size->height_mm, size->dpi);
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h); /* owned here */
    if (cairo_surface_status(s)) {
        cairo_surface_destroy(s);
        return err_nomem(err, "out of memory for a %dx%d page", w, h);
    }
    int rc = draw_on(s, size->dpi / MM_PER_INCH, size, draw, ctx, "PNG", err);
    if (!rc) {
        /* libpng at zlib level 1: several times faster than cairo's own PNG writer on a page */
        cairo_surface_flush(s);
        rc = png_write_xrgb(out, (uint32_t)w, (uint32_t)h, (size_t)cairo_image_surface_get_stride(s),
                            cairo_image_surface_get_data(s), err);
    }
    cairo_surface_destroy(s);
    return rc;
}

int page_write_streams(const page_size *size, page_draw_fn draw, void *ctx, FILE *pdf, FILE *png, err_buf *err)
{
    if (pdf && write_pdf(size, draw, ctx, pdf, err)) return -1;
    return png ? write_png(size, draw, ctx, png, err) : 0;
}

int page_write(const page_size *size, page_draw_fn draw, void *ctx, const char *pdf_path, const char *png_path,
               err_buf *err)
{
    atomic_file af[2] = {{.fd = -1, .slot = -1}, {.fd = -1, .slot = -1}};
    FILE *f[2] = {NULL, NULL};
    int n = 0, rc = 0;
    const char *paths[2] = {pdf_path, png_path};
    for (int k = 0; k < 2 && !rc; k++) {
        if (!paths[k]) continue;
        if (!(f[k] = atomic_file_open_stream(&af[n], paths[k], err))) rc = -1;
        else n++;
    }
    if (!rc) rc = page_write_streams(size, draw, ctx, f[0], f[1], err);
    if (rc) {
        for (int k = 0; k < n; k++) atomic_file_abort(&af[k]);
        return -1;
    }
    return n ? atomic_file_commit_together(af, n, err) : 0;
}
