/* json_read.h — a JSON text read into a tree of values, for the checks that must see a file's
 * structure before a library reads it (model/gltf_layout.h). RFC 8259 as the JSON readers of
 * the libraries sylva hands files to take it: no comments, no trailing commas, no NaN; the text
 * ends at its first NUL byte, as it does for a reader that parses a NUL-terminated copy in place.
 * Strings are kept as written (escapes undecoded); numbers as their text. Nesting deeper than
 * JSON_MAX_DEPTH and more than JSON_MAX_VALUES values are refused (ERR_LIMIT), so a hostile text
 * can neither exhaust the stack nor ask for more than about 24 bytes a value of it. */
#ifndef SYLVA_JSON_READ_H
#define SYLVA_JSON_READ_H

#include <stddef.h>
#include <stdint.h>

#include "util/err.h"

#define JSON_MAX_DEPTH 64
#define JSON_MAX_VALUES (1u << 23)

typedef enum json_kind { JSON_NULL, JSON_BOOL, JSON_NUMBER, JSON_STRING, JSON_ARRAY, JSON_OBJECT } json_kind;

/* One value. Index 0 is the root, which is nobody's item, so 0 also means "none" below. */
typedef struct json_value {
    uint32_t kind;      /* json_kind */
    uint32_t first;     /* an array's first item or an object's first member; 0 when empty */
    uint32_t next;      /* the next item or member of the enclosing array or object; 0 when last */
    uint32_t key;       /* a member's key: the offset of its first byte after the quote */
    uint32_t key_len;   /* the key's bytes as written */
    uint32_t at;        /* the value's first byte (a string's opening quote) */
    uint32_t len;       /* its bytes: a string's between its quotes, a number's digits and signs */
} json_value;

typedef struct json_doc {
    const char *text;   /* borrowed: the text read, which must outlive the document */
    uint32_t n;         /* its bytes up to the first NUL */
    json_value *values; /* owned (json_free): the tree, values[0] the root */
    uint32_t count, cap;
} json_doc;

/* Reads text[0..n) into d. 0 on success; -1 with err set ("where:L:C: what is wrong", where
 * prefixing every message as given, L and C the line and column in the text; ERR_INPUT, ERR_LIMIT
 * or ERR_NOMEM), d left empty. A text over 4 GiB is refused. */
int json_read(json_doc *d, const char *text, size_t n, const char *where, err_buf *err);
void json_free(json_doc *d);

/* The member of object o whose key is written as key (no escapes compared), the first if the key
 * is repeated; 0 when o is no object or has none. */
uint32_t json_member(const json_doc *d, uint32_t o, const char *key);

/* Whether value v is a whole number written with digits alone (no sign, fraction or exponent) up
 * to 2^53, and then its value in *out. */
int json_whole(const json_doc *d, uint32_t v, uint64_t *out);

/* Whether value v is a string written exactly as s between its quotes. */
int json_string_is(const json_doc *d, uint32_t v, const char *s);

/* The line and column (from 1) of byte at of the text. */
void json_line_column(const json_doc *d, uint32_t at, uint32_t *line, uint32_t *column);

#endif
