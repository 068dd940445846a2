/* json_text.h — a string as a JSON string literal, for the files the core writes by hand
 * (metrics, summaries): quotes and backslashes escaped, control characters as \u00XX, other
 * bytes (UTF-8 included) as they are. */
#ifndef SYLVA_JSON_TEXT_H
#define SYLVA_JSON_TEXT_H

#include <stdio.h>

/* Writes "s" (NULL as "") to f. */
void json_write_string(FILE *f, const char *s);

#endif
