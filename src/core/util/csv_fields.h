/* csv_fields.h — one line of a comma-separated file split into its fields, as the CSV inputs
 * (object layouts, control points) read them: each field trimmed of spaces and tabs (and a
 * line's trailing carriage return), a field in double quotes unquoted, with the 1-based column
 * where it starts for messages. No quoted commas: the inputs never need them, so a quote that
 * does not close before the field ends is an error. A file may start with a UTF-8 byte-order
 * mark, as spreadsheets write it. */
#ifndef SYLVA_CSV_FIELDS_H
#define SYLVA_CSV_FIELDS_H

#include <stddef.h>
#include <stdint.h>

/* The length of the UTF-8 byte-order mark text starts with: 3, or 0 when it has none. */
size_t csv_bom_length(const char *text);

/* Splits line in place; the first max fields go to field[] and column[]. Returns how many
 * fields the line has (more than max when it has too many). *open_quote is the column of the
 * first field whose opening double quote is not closed at the field's end, or 0. */
uint32_t csv_split(char *line, char **field, uint32_t *column, uint32_t max, uint32_t *open_quote);

#endif
