/* json_read.c — a JSON text read into a tree of values by recursive descent, its depth bounded
 * (json_read.h). */
#include "util/json_read.h"

#include <stdlib.h>
#include <string.h>

typedef struct reader {
    json_doc *d;
    uint32_t p;          /* the next byte */
    const char *where;   /* message prefix */
    err_buf *err;
} reader;

void json_line_column(const json_doc *d, uint32_t at, uint32_t *line, uint32_t *column)
{
    *line = 1, *column = 1;
    for (uint32_t i = 0; i < at && i < d->n; i++) {
        if (d->text[i] == '\n') (*line)++, *column = 1;
        else (*column)++;
    }
}

/* -1 with err set at byte at: "where:L:C: what". */
static int fail_at(reader *r, err_status status, uint32_t at, const char *what)
{
    uint32_t line, column;
    json_line_column(r->d, at, &line, &column);
    return err_fail(r->err, status, "%s:%u:%u: %s", r->where, line, column, what);
}

static void skip_space(reader *r)
{
    while (r->p < r->d->n && strchr(" \t\r\n", r->d->text[r->p])) r->p++;
}

/* A new value of the kind starting at byte at, its index in *out; -1 with err set. */
static int add(reader *r, json_kind kind, uint32_t at, uint32_t *out)
{
    json_doc *d = r->d;
    if (d->count == JSON_MAX_VALUES)
        return fail_at(r, ERR_LIMIT, at, "more than 8388608 JSON values; sylva reads files of fewer");
    if (d->count == d->cap) {
        uint32_t cap = d->cap ? (d->cap > JSON_MAX_VALUES / 2 ? JSON_MAX_VALUES : d->cap * 2) : 64;
        json_value *v = realloc(d->values, (size_t)cap * sizeof *v);
        if (!v) return err_nomem(r->err, "%s: out of memory reading the JSON (%u values)", r->where, cap);
        d->values = v, d->cap = cap;
    }
    d->values[d->count] = (json_value){.kind = kind, .at = at};
    *out = d->count++;
    return 0;
}

static int is_digit(char c) { return c >= '0' && c <= '9'; }

/* A string from its opening quote at r->p: [*start, *end) its bytes between the quotes. */
static int read_string(reader *r, uint32_t *start, uint32_t *end)
{
    const char *t = r->d->text;
    uint32_t open = r->p++;
    *start = r->p;
    for (;;) {
        if (r->p >= r->d->n) return fail_at(r, ERR_INPUT, open, "a string has no closing quote");
        unsigned char c = (unsigned char)t[r->p];
        if (c == '"') break;
        if (c < 0x20) return fail_at(r, ERR_INPUT, r->p, "a control character in a string; write it as \\u00XX");
        if (c != '\\') {
            r->p++;
            continue;
        }
        if (r->p + 1 >= r->d->n || !strchr("\"\\/bfnrtu", t[r->p + 1]))
            return fail_at(r, ERR_INPUT, r->p, "a bad escape in a string; valid are \\\" \\\\ \\/ \\b \\f \\n \\r "
                           "\\t and \\u followed by four hexadecimal digits");
        if (t[r->p + 1] == 'u') {
            for (uint32_t k = 2; k < 6; k++)
                if (r->p + k >= r->d->n || !strchr("0123456789abcdefABCDEF", t[r->p + k]))
                    return fail_at(r, ERR_INPUT, r->p, "a \\u escape without four hexadecimal digits");
            r->p += 6;
        } else {
            r->p += 2;
        }
    }
    *end = r->p++;
    return 0;
}

static int read_number(reader *r, uint32_t v)
{
    const char *t = r->d->text;
    uint32_t n = r->d->n, p = r->p;
    if (p < n && t[p] == '-') p++;
    if (p < n && t[p] == '0') {
        p++;
    } else if (p < n && is_digit(t[p])) {
        while (p < n && is_digit(t[p])) p++;
    } else {
        return fail_at(r, ERR_INPUT, r->p, "a number without digits");
    }
    if (p < n && t[p] == '.') {
        if (++p >= n || !is_digit(t[p])) return fail_at(r, ERR_INPUT, p, "a number's '.' is not followed by a digit");
        while (p < n && is_digit(t[p])) p++;
    }
    if (p < n && (t[p] == 'e' || t[p] == 'E')) {
        if (++p < n && (t[p] == '+' || t[p] == '-')) p++;
        if (p >= n || !is_digit(t[p])) return fail_at(r, ERR_INPUT, p, "a number's exponent has no digits");
        while (p < n && is_digit(t[p])) p++;
    }
    r->d->values[v].len = p - r->p;
    r->p = p;
    return 0;
}

static int read_value(reader *r, int depth, uint32_t *out);

/* The items or members of the array or object v, whose opening bracket is at r->p. */
static int read_container(reader *r, uint32_t v, int depth)
{
    int object = r->d->values[v].kind == JSON_OBJECT;
    char close = object ? '}' : ']';
    uint32_t last = 0;
    r->p++;
    skip_space(r);
    if (r->p < r->d->n && r->d->text[r->p] == close) {
        r->p++;
        return 0;
    }
    for (;;) {
        uint32_t key = 0, key_end = 0;
        if (object) {
            skip_space(r);
            if (r->p >= r->d->n || r->d->text[r->p] != '"')
                return fail_at(r, ERR_INPUT, r->p, "an object's member must start with its key in quotes");
            if (read_string(r, &key, &key_end)) return -1;
            skip_space(r);
            if (r->p >= r->d->n || r->d->text[r->p] != ':')
                return fail_at(r, ERR_INPUT, r->p, "a key must be followed by ':'");
            r->p++;
        }
        uint32_t item;
        if (read_value(r, depth + 1, &item)) return -1;
        json_value *values = r->d->values;
        values[item].key = key, values[item].key_len = key_end - key;
        if (last) values[last].next = item;
        else values[v].first = item;
        last = item;
        skip_space(r);
        if (r->p < r->d->n && r->d->text[r->p] == ',') {
            r->p++;
            continue;
        }
        if (r->p < r->d->n && r->d->text[r->p] == close) {
            r->p++;
            return 0;
        }
        return fail_at(r, ERR_INPUT, r->p, object ? "expected ',' or '}' after an object's member"
                                                  : "expected ',' or ']' after an array's item");
    }
}

/* One value from r->p (white space before it skipped) as *out; -1 with err set. */
static int read_value(reader *r, int depth, uint32_t *out)
{
    skip_space(r);
    if (depth > JSON_MAX_DEPTH)
        return fail_at(r, ERR_LIMIT, r->p, "arrays and objects nested more than 64 deep; sylva reads files "
                       "nested less");
    if (r->p >= r->d->n) return fail_at(r, ERR_INPUT, r->p, "the text ends where a value was expected");
    const char *t = r->d->text + r->p;
    uint32_t at = r->p, left = r->d->n - r->p, v;
    static const struct { const char *word; json_kind kind; } words[] = {
        {"null", JSON_NULL}, {"true", JSON_BOOL}, {"false", JSON_BOOL}};
    for (size_t k = 0; k < sizeof words / sizeof words[0]; k++) {
        uint32_t len = (uint32_t)strlen(words[k].word);
        if (left >= len && !memcmp(t, words[k].word, len)) {
            if (add(r, words[k].kind, at, &v)) return -1;
            r->d->values[v].len = len;
            r->p += len;
            return *out = v, 0;
        }
    }
    if (*t == '{' || *t == '[') {
        if (add(r, *t == '{' ? JSON_OBJECT : JSON_ARRAY, at, &v) || read_container(r, v, depth)) return -1;
        return *out = v, 0;
    }
    if (*t == '"') {
        uint32_t start, end;
        if (add(r, JSON_STRING, at, &v) || read_string(r, &start, &end)) return -1;
        r->d->values[v].len = end - start;
        return *out = v, 0;
    }
    if (*t == '-' || is_digit(*t)) {
        if (add(r, JSON_NUMBER, at, &v) || read_number(r, v)) return -1;
        return *out = v, 0;
    }
    return fail_at(r, ERR_INPUT, at, "not a JSON value; valid are an object, an array, a string, a number, true, "
                   "false and null");
}

int json_read(json_doc *d, const char *text, size_t n, const char *where, err_buf *err)
{
    *d = (json_doc){.text = text};
    if (n > UINT32_MAX - 1) return err_fail(err, ERR_LIMIT, "%s: the JSON is over 4 GiB; sylva reads less", where);
    const char *nul = memchr(text, 0, n);
    d->n = (uint32_t)(nul ? (size_t)(nul - text) : n);
    reader r = {.d = d, .where = where, .err = err};
    uint32_t root; /* the first value added: index 0 */
    if (read_value(&r, 1, &root)) {
        json_free(d);
        return -1;
    }
    skip_space(&r);
    if (r.p < d->n) {
        fail_at(&r, ERR_INPUT, r.p, "more text after the JSON value; a JSON file holds one value");
        json_free(d);
        return -1;
    }
    return 0;
}

void json_free(json_doc *d)
{
    free(d->values);
    d->values = NULL;
    d->count = d->cap = 0;
}

uint32_t json_member(const json_doc *d, uint32_t o, const char *key)
{
    if (o >= d->count || d->values[o].kind != JSON_OBJECT) return 0;
    size_t len = strlen(key);
    for (uint32_t m = d->values[o].first; m; m = d->values[m].next)
        if (d->values[m].key_len == len && !memcmp(d->text + d->values[m].key, key, len)) return m;
    return 0;
}

int json_whole(const json_doc *d, uint32_t v, uint64_t *out)
{
    if (v >= d->count || d->values[v].kind != JSON_NUMBER) return 0;
    const char *t = d->text + d->values[v].at;
    uint32_t len = d->values[v].len;
    if (len == 0 || len > 16) return 0; /* 2^53 has 16 digits */
    uint64_t x = 0;
    for (uint32_t i = 0; i < len; i++) {
        if (!is_digit(t[i])) return 0;
        x = x * 10 + (uint64_t)(t[i] - '0');
    }
    if (x > (1ull << 53)) return 0;
    *out = x;
    return 1;
}

int json_string_is(const json_doc *d, uint32_t v, const char *s)
{
    if (v >= d->count || d->values[v].kind != JSON_STRING) return 0;
    size_t len = strlen(s);
    return d->values[v].len == len && !memcmp(d->text + d->values[v].at + 1, s, len);
}
