/* page_text.c — pango layouts on a cairo page in millimetres (page_text.h). */
#include "page/page_text.h"

#include <pango/pangocairo.h>

#define MM_PER_PT (25.4 / 72.0)

/* A layout of text in f on cr, unhinted; the caller frees it (g_object_unref). */
static PangoLayout *layout_of(cairo_t *cr, const page_font *f, const char *text, int markup, double width)
{
    PangoLayout *l = pango_cairo_create_layout(cr); /* owned by the caller */
    PangoContext *pc = pango_layout_get_context(l);
    cairo_font_options_t *fo = cairo_font_options_create(); /* owned here */
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    pango_cairo_context_set_font_options(pc, fo);
    pango_context_set_round_glyph_positions(pc, FALSE); /* the units are millimetres: no rounding to them */
    cairo_font_options_destroy(fo);
    pango_layout_context_changed(l);
    PangoFontDescription *d = pango_font_description_from_string(PAGE_FONT); /* owned here */
    pango_font_description_set_absolute_size(d, f->size_pt * MM_PER_PT * PANGO_SCALE);
    pango_font_description_set_weight(d, f->bold ? PANGO_WEIGHT_BOLD : PANGO_WEIGHT_NORMAL);
    pango_layout_set_font_description(l, d);
    pango_font_description_free(d);
    if (width > 0) {
        pango_layout_set_width(l, (int)(width * PANGO_SCALE));
        pango_layout_set_wrap(l, PANGO_WRAP_WORD_CHAR);
    }
    pango_layout_set_alignment(l, f->align == PAGE_CENTRE ? PANGO_ALIGN_CENTER
                                  : f->align == PAGE_RIGHT ? PANGO_ALIGN_RIGHT : PANGO_ALIGN_LEFT);
    if (markup) pango_layout_set_markup(l, text, -1);
    else pango_layout_set_text(l, text, -1);
    return l;
}

double page_text(cairo_t *cr, double x, double y, double width, const page_font *f, const char *text, int markup)
{
    PangoLayout *l = layout_of(cr, f, text, markup, width); /* owned here */
    int pw, ph;
    pango_layout_get_size(l, &pw, &ph);
    double w = (double)pw / PANGO_SCALE, h = (double)ph / PANGO_SCALE;
    double left = x;
    if (width <= 0) left = f->align == PAGE_CENTRE ? x - w / 2 : f->align == PAGE_RIGHT ? x - w : x;
    cairo_save(cr);
    cairo_move_to(cr, left, y);
    if (f->halo > 0) {
        pango_cairo_layout_path(cr, l);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_set_line_width(cr, 2 * f->halo);
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        cairo_stroke(cr);
        cairo_move_to(cr, left, y);
    }
    cairo_set_source_rgb(cr, f->rgb[0], f->rgb[1], f->rgb[2]);
    pango_cairo_show_layout(cr, l);
    cairo_restore(cr);
    g_object_unref(l);
    return h;
}

double page_text_width(cairo_t *cr, const page_font *f, const char *text)
{
    double w, h;
    page_text_size(cr, f, text, &w, &h);
    return w;
}

void page_text_size(cairo_t *cr, const page_font *f, const char *text, double *w, double *h)
{
    PangoLayout *l = layout_of(cr, f, text, 0, 0); /* owned here */
    int pw, ph;
    pango_layout_get_size(l, &pw, &ph);
    g_object_unref(l);
    *w = (double)pw / PANGO_SCALE, *h = (double)ph / PANGO_SCALE;
}
