/* html_text.c — escaped text and spelled-out numbers for hand-written HTML. */
#include "util/html_text.h"

#include <math.h>

void html_text(FILE *f, const char *s)
{
    for (const char *p = s ? s : ""; *p; p++) {
        switch (*p) {
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '&': fputs("&amp;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*p, f);
        }
    }
}

void html_number(FILE *f, double v, const char *fmt)
{
    if (isinf(v)) fputs(v > 0 ? "&infin;" : "&minus;&infin;", f);
    else if (isnan(v)) fputs("&ndash;", f);
    else fprintf(f, fmt, v);
}
