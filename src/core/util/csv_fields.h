/* csv_fields.h — one line of a comma-separated file split into its fields, as the CSV inputs
 * (object layouts, control points) read them: each field trimmed of spaces and tabs (and a
 * line's trailing carriage return), a field in double quotes unquoted, with the 1-based column
 * where it starts for messages. No quoted commas: the inputs never need them. */
#ifndef SYLVA_CSV_FIELDS_H
#define SYLVA_CSV_FIELDS_H

#include <stdint.h>

/* Splits line in place; the first max fields go to field[] and column[]. Returns how many
 * fields the line has (more than max when it has too many). */
uint32_t csv_split(char *line, char **field, uint32_t *column, uint32_t max);

#endif
