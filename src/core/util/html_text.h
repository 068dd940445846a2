/* html_text.h — text and numbers in the HTML reports the core writes by hand (the cross-check
 * report, the photomontage's verification sheet): markup characters escaped, infinities and
 * missing values spelled out. */
#ifndef SYLVA_HTML_TEXT_H
#define SYLVA_HTML_TEXT_H

#include <stdio.h>

/* Writes s (NULL as nothing) with <, >, & and " escaped. */
void html_text(FILE *f, const char *s);
/* Writes v with the printf format fmt; infinities as the infinity sign, NaN as a dash. */
void html_number(FILE *f, double v, const char *fmt);

#endif
