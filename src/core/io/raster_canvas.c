/* raster_canvas.c — pixels, rectangles, discs, lines and 5 x 7 text on an RGB canvas. */
#include "io/raster_canvas.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/image_io.h"

int canvas_init(canvas *c, uint32_t width, uint32_t height, const uint8_t bg[3], err_buf *err)
{
    memset(c, 0, sizeof *c);
    if (!width || !height || width > 16384 || height > 16384)
        return err_set(err, "a canvas of %u x %u pixels; each side must be 1 to 16384", width, height);
    size_t n = (size_t)width * height;
    c->rgb = malloc(n * 3);
    if (!c->rgb) return err_nomem(err, "out of memory for a %u x %u image", width, height);
    c->width = width, c->height = height;
    for (size_t i = 0; i < n; i++) memcpy(c->rgb + 3 * i, bg, 3);
    return 0;
}

void canvas_free(canvas *c)
{
    free(c->rgb);
    memset(c, 0, sizeof *c);
}

void canvas_pixel(canvas *c, int x, int y, const uint8_t rgb[3])
{
    if (x < 0 || y < 0 || (uint32_t)x >= c->width || (uint32_t)y >= c->height) return;
    memcpy(c->rgb + 3 * ((size_t)y * c->width + x), rgb, 3);
}

void canvas_rect(canvas *c, int x0, int y0, int x1, int y1, const uint8_t rgb[3])
{
    if (x0 > x1) { int t = x0; x0 = x1; x1 = t; }
    if (y0 > y1) { int t = y0; y0 = y1; y1 = t; }
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 >= (int)c->width) x1 = (int)c->width - 1;
    if (y1 >= (int)c->height) y1 = (int)c->height - 1;
    for (int y = y0; y <= y1; y++)
        for (int x = x0; x <= x1; x++) memcpy(c->rgb + 3 * ((size_t)y * c->width + x), rgb, 3);
}

void canvas_disc(canvas *c, double cx, double cy, double r, const uint8_t rgb[3])
{
    if (!(r > 0) || !isfinite(cx) || !isfinite(cy)) return;
    int y0 = (int)floor(cy - r), y1 = (int)ceil(cy + r), x0 = (int)floor(cx - r), x1 = (int)ceil(cx + r);
    if (y0 < 0) y0 = 0;
    if (x0 < 0) x0 = 0;
    if (y1 >= (int)c->height) y1 = (int)c->height - 1;
    if (x1 >= (int)c->width) x1 = (int)c->width - 1;
    for (int y = y0; y <= y1; y++)
        for (int x = x0; x <= x1; x++) {
            double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
            if (dx * dx + dy * dy <= r * r) memcpy(c->rgb + 3 * ((size_t)y * c->width + x), rgb, 3);
        }
    if (r < 0.75) canvas_pixel(c, (int)floor(cx), (int)floor(cy), rgb); /* never vanish */
}

void canvas_line(canvas *c, double x0, double y0, double x1, double y1, double width, const uint8_t rgb[3])
{
    double len = hypot(x1 - x0, y1 - y0);
    int steps = (int)ceil(len * 2) + 1;
    if (steps > 1 << 20) steps = 1 << 20;
    for (int i = 0; i <= steps; i++) {
        double t = (double)i / steps;
        canvas_disc(c, x0 + t * (x1 - x0), y0 + t * (y1 - y0), 0.5 * width, rgb);
    }
}

/* 5 x 7 glyphs, one byte a row, bit 4 the leftmost pixel. */
static const struct {
    char ch;
    uint8_t rows[7];
} glyphs[] = {
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}}, {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}}, {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}}, {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}}, {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}}, {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {'A', {0x0E, 0x11, 0x11, 0x11, 0x1F, 0x11, 0x11}}, {'B', {0x1E, 0x11, 0x11, 0x1E, 0x11, 0x11, 0x1E}},
    {'C', {0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E}}, {'D', {0x1C, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1C}},
    {'E', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F}}, {'F', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10}},
    {'G', {0x0E, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0F}}, {'H', {0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11}},
    {'I', {0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}}, {'J', {0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0C}},
    {'K', {0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11}}, {'L', {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F}},
    {'M', {0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11}}, {'N', {0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11}},
    {'O', {0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}}, {'P', {0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10}},
    {'Q', {0x0E, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0D}}, {'R', {0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11}},
    {'S', {0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E}}, {'T', {0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04}},
    {'U', {0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}}, {'V', {0x11, 0x11, 0x11, 0x11, 0x11, 0x0A, 0x04}},
    {'W', {0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0A}}, {'X', {0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11}},
    {'Y', {0x11, 0x11, 0x11, 0x0A, 0x04, 0x04, 0x04}}, {'Z', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1F}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}}, {',', {0x00, 0x00, 0x00, 0x00, 0x0C, 0x04, 0x08}},
    {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}}, {':', {0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x00}},
    {'(', {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02}}, {')', {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08}},
    {'/', {0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x00}}, {'_', {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1F}},
    {'%', {0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03}}, {'+', {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00}},
    {'?', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x00, 0x04}}, {' ', {0, 0, 0, 0, 0, 0, 0}},
};

static const uint8_t *glyph(char ch)
{
    char u = (char)toupper((unsigned char)ch);
    for (size_t i = 0; i < sizeof glyphs / sizeof glyphs[0]; i++)
        if (glyphs[i].ch == u) return glyphs[i].rows;
    return glyph('?');
}

void canvas_text(canvas *c, int x, int y, const char *text, int scale, const uint8_t rgb[3])
{
    for (const char *p = text; *p; p++, x += 6 * scale) {
        const uint8_t *g = glyph(*p);
        for (int r = 0; r < 7; r++)
            for (int b = 0; b < 5; b++)
                if (g[r] & (0x10 >> b))
                    canvas_rect(c, x + b * scale, y + r * scale, x + (b + 1) * scale - 1, y + (r + 1) * scale - 1, rgb);
    }
}

int canvas_text_width(const char *text, int scale)
{
    int n = (int)strlen(text);
    return n ? (6 * n - 1) * scale : 0;
}

int canvas_write_png(const canvas *c, const char *path, err_buf *err)
{
    return image_write_u8(path, c->width, c->height, 3, c->rgb, err);
}

void canvas_series_color(uint32_t i, uint8_t rgb[3])
{
    static const uint8_t palette[8][3] = {{34, 139, 34},  {230, 140, 20}, {20, 70, 110},  {190, 60, 60},
                                          {140, 80, 190}, {0, 150, 150},  {150, 150, 20}, {120, 120, 120}};
    memcpy(rgb, palette[i % 8], 3);
}
