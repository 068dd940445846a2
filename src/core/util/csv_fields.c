/* csv_fields.c — a CSV line split into trimmed, unquoted fields; the byte-order mark. */
#include "util/csv_fields.h"

#include <string.h>

size_t csv_bom_length(const char *text)
{
    return text && !strncmp(text, "\xef\xbb\xbf", 3) ? 3 : 0;
}

uint32_t csv_split(char *line, char **field, uint32_t *column, uint32_t max, uint32_t *open_quote)
{
    uint32_t n = 0;
    *open_quote = 0;
    for (char *p = line;;) {
        char *start = p, *end = strchr(p, ',');
        char *next = end ? end + 1 : NULL;
        if (!end) end = p + strlen(p);
        while (start < end && (*start == ' ' || *start == '\t')) start++;
        while (end > start && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\r')) end--;
        if (end - start >= 2 && *start == '"' && end[-1] == '"') start++, end--;
        else if (end > start && *start == '"' && !*open_quote) *open_quote = (uint32_t)(start - line) + 1;
        *end = 0;
        if (n < max) field[n] = start, column[n] = (uint32_t)(start - line) + 1;
        n++;
        if (!next) break;
        p = next;
    }
    return n;
}
