/* lsys_read.c — the reader of L-parser files in the numeric (Lparser 4) and keyword (Lparser 2.1)
 * dialects. It owns the dialect rules (comments, header lines, keywords, rule lines) and the
 * check of every symbol; it knows nothing of derivation or geometry. */
#include "lsys_system.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lsys_symbols.h"

typedef struct reader {
    const char *name;
    const lsys_read_options *opt;
    plugin_err *err;
    lsys_system *sys;
    uint32_t line;                /* 1-based number of the line being read */
    uint32_t axiom_line;          /* 0 until an axiom was read */
} reader;

/* A line of text without its end-of-line bytes. */
typedef struct text_line {
    const unsigned char *s;
    size_t n;
} text_line;

static void reader_warn(reader *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void reader_warn(reader *r, const char *fmt, ...)
{
    if (!r->opt || !r->opt->warn) return;
    char msg[PLUGIN_ERR_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    r->opt->warn(r->opt->warn_ctx, msg);
}

static int is_blank(unsigned char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

/* Prints byte c for a message: the character itself when printable ASCII, else its code. */
static const char *byte_name(unsigned char c, char buf[16])
{
    if (c > 32 && c < 127) snprintf(buf, 16, "'%c'", c);
    else snprintf(buf, 16, "byte 0x%02x", c);
    return buf;
}

static const char symbol_help[] =
    "the language knows the commands F Z f z g . + - & ^ < > | % $ t ~ [ ] { } c \" ' ; : ? ! _, "
    "rule variables (letters, digits, Latin-1 bytes) and arguments written as (number)";

/* Checks and copies the symbols of an axiom or successor. s[i] stands at column cols[i] of the
 * current line. `what` names the string for messages ("the axiom", "rule 'A'"). A successor
 * that is exactly "_" is empty. Returns LSYS_OK with *out (owned by the caller; NULL when
 * empty) and *out_len. */
static int read_symbols(reader *r, const unsigned char *s, const uint32_t *cols, size_t n,
                        const char *what, unsigned char **out, uint32_t *out_len)
{
    *out = NULL, *out_len = 0;
    if (n == 1 && s[0] == '_') return LSYS_OK;
    if (n == 0) return LSYS_OK;
    unsigned char *buf = malloc(n); /* owned here until handed to *out */
    if (!buf) return plugin_fail(r->err, LSYS_ERR_NOMEM, "%s: out of memory reading %s", r->name, what);
    size_t k = 0;
    for (size_t i = 0; i < n;) {
        if (s[i] == '(') {
            size_t g = lsys_arg_group(s + i, n - i, NULL);
            if (g) {
                memcpy(buf + k, s + i, g);
                k += g, i += g;
                continue;
            }
        } else if (lsys_is_command(s[i]) || lsys_is_variable(s[i])) {
            buf[k++] = s[i++];
            continue;
        }
        size_t huge = s[i] == '(' ? lsys_arg_out_of_range(s + i, n - i) : 0;
        if (huge) {
            free(buf);
            return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                             "%s:%u:%u: the argument %.*s in %s is beyond the range of numbers; an "
                             "argument is a finite number of magnitude below 1.8e308, such as (30) or (1e-3)",
                             r->name, r->line, cols[i], (int)huge, (const char *)s + i, what);
        }
        char b[16];
        if (!r->opt || !r->opt->lenient) {
            free(buf);
            if (s[i] == '(')
                return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                                 "%s:%u:%u: '(' in %s does not start an argument: an argument is one "
                                 "number in parentheses, such as (30), (.95), (-2.5) or (+38)",
                                 r->name, r->line, cols[i], what);
            return plugin_fail(r->err, LSYS_ERR_SYNTAX, "%s:%u:%u: unknown symbol %s in %s; %s",
                             r->name, r->line, cols[i], byte_name(s[i], b), what, symbol_help);
        }
        reader_warn(r, "%s:%u:%u: unknown symbol %s in %s is ignored (lenient mode)", r->name, r->line,
                    cols[i], byte_name(s[i], b), what);
        i++;
    }
    if (!k) {
        free(buf);
        return LSYS_OK;
    }
    *out = buf, *out_len = (uint32_t)k;
    return LSYS_OK;
}

/* Copies s[0..n) without blanks, up to a '#' comment, into bytes and columns (col0: column of
 * s[0]). Returns the count kept, or (size_t)-1 when memory runs out. */
static size_t strip_blanks(const unsigned char *s, size_t n, uint32_t col0, unsigned char **bytes,
                           uint32_t **cols)
{
    *bytes = malloc(n ? n : 1);
    *cols = malloc((n ? n : 1) * sizeof **cols);
    if (!*bytes || !*cols) {
        free(*bytes), free(*cols);
        *bytes = NULL, *cols = NULL;
        return (size_t)-1;
    }
    size_t k = 0;
    for (size_t i = 0; i < n && s[i] != '#'; i++) {
        if (is_blank(s[i])) continue;
        (*bytes)[k] = s[i];
        (*cols)[k] = col0 + (uint32_t)i;
        k++;
    }
    return k;
}

/* Parses the whole of token s[0..n) as a number. */
static int token_number(const unsigned char *s, size_t n, double *v)
{
    size_t k = lsys_parse_number(s, n, v);
    return k && k == n && isfinite(*v);
}

static int set_rule(reader *r, unsigned char name, const unsigned char *body, const uint32_t *cols,
                    size_t n, uint32_t name_col)
{
    char b[16], what[48];
    if (!lsys_is_command(name) && !lsys_is_variable(name)) {
        if (!r->opt || !r->opt->lenient)
            return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                             "%s:%u:%u: %s cannot name a rule; a rule is named by a command or a "
                             "variable (letter, digit or Latin-1 byte)",
                             r->name, r->line, name_col, byte_name(name, b));
        reader_warn(r, "%s:%u:%u: rule named %s is ignored (lenient mode)", r->name, r->line, name_col,
                    byte_name(name, b));
        return LSYS_OK;
    }
    lsys_rule *rule = &r->sys->rules[name];
    if (rule->defined) {
        if (!r->opt || !r->opt->lenient)
            return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                             "%s:%u:%u: rule %s is given twice (first at line %u); give each rule once",
                             r->name, r->line, name_col, byte_name(name, b), rule->line);
        reader_warn(r, "%s:%u:%u: second rule %s is ignored; the first, at line %u, applies (lenient mode)",
                    r->name, r->line, name_col, byte_name(name, b), rule->line);
        return LSYS_OK;
    }
    snprintf(what, sizeof what, "rule %s", byte_name(name, b));
    int rc = read_symbols(r, body, cols, n, what, &rule->successor, &rule->length);
    if (rc) return rc;
    rule->defined = 1;
    rule->line = r->line;
    return LSYS_OK;
}

static int set_axiom(reader *r, const unsigned char *s, const uint32_t *cols, size_t n, uint32_t col)
{
    if (r->axiom_line) {
        if (!r->opt || !r->opt->lenient)
            return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                             "%s:%u:%u: a second axiom (the first is at line %u); give one axiom",
                             r->name, r->line, col, r->axiom_line);
        reader_warn(r, "%s:%u:%u: second axiom ignored; the first, at line %u, applies (lenient mode)",
                    r->name, r->line, col, r->axiom_line);
        return LSYS_OK;
    }
    int rc = read_symbols(r, s, cols, n, "the axiom", &r->sys->axiom, &r->sys->axiom_length);
    if (rc) return rc;
    r->axiom_line = r->line;
    return LSYS_OK;
}

static int check_recursion(reader *r, double v, uint32_t col)
{
    if (!(v >= 0 && v <= LSYS_MAX_RECURSION && v == floor(v)))
        return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                         "%s:%u:%u: recursion level %g is refused: it must be a whole number from 0 to %d "
                         "(fractional growth levels are not supported)",
                         r->name, r->line, col, v, LSYS_MAX_RECURSION);
    r->sys->recursion = (uint32_t)v;
    return LSYS_OK;
}

static int check_thickness(reader *r, const char *what, double v, uint32_t col, double *dst)
{
    if (!(v >= 0 && v <= 1e6))
        return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                         "%s:%u:%u: %s %g is refused: it is a percentage of the segment length from 0 "
                         "to 1000000",
                         r->name, r->line, col, what, v);
    *dst = v;
    return LSYS_OK;
}

/* ---- numeric dialect ---------------------------------------------------------------------- */

/* The payload of a numeric-dialect line: its first whitespace-delimited token, cut at '#'.
 * Returns the token length (0: a comment or blank line) and its start column. */
static size_t numeric_token(text_line ln, const unsigned char **tok, uint32_t *col)
{
    size_t i = 0;
    while (i < ln.n && is_blank(ln.s[i])) i++;
    size_t start = i;
    while (i < ln.n && !is_blank(ln.s[i]) && ln.s[i] != '#') i++;
    *tok = ln.s + start;
    *col = (uint32_t)start + 1;
    return i - start;
}

static int read_numeric_line(reader *r, text_line ln, int *stage)
{
    const unsigned char *tok;
    uint32_t col;
    size_t n = numeric_token(ln, &tok, &col);
    if (!n) return LSYS_OK;
    if (*stage == 5) return LSYS_OK; /* after '@' */
    double v = 0;
    switch (*stage) {
    case 0:
        if (!token_number(tok, n, &v))
            return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                             "%s:%u:%u: expected the recursion level (a whole number) on the first line",
                             r->name, r->line, col);
        (*stage)++;
        return check_recursion(r, v, col);
    case 1:
        if (!token_number(tok, n, &v))
            return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                             "%s:%u:%u: expected the standard angle in degrees (a number) on the second line",
                             r->name, r->line, col);
        r->sys->angle_deg = v;
        (*stage)++;
        return LSYS_OK;
    case 2:
        if (!token_number(tok, n, &v))
            return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                             "%s:%u:%u: expected the thickness in percent of the segment length (a "
                             "number) on the third line",
                             r->name, r->line, col);
        (*stage)++;
        return check_thickness(r, "thickness", v, col, &r->sys->thickness);
    default:
        break;
    }
    uint32_t *cols = malloc(n * sizeof *cols); /* owned here */
    if (!cols) return plugin_fail(r->err, LSYS_ERR_NOMEM, "%s: out of memory", r->name);
    for (size_t i = 0; i < n; i++) cols[i] = col + (uint32_t)i;
    int rc = LSYS_OK;
    if (*stage == 3) {
        rc = set_axiom(r, tok, cols, n, col);
        (*stage)++;
    } else if (tok[0] == '@') {
        *stage = 5;
    } else if (n < 2 || tok[1] != '=') {
        rc = plugin_fail(r->err, LSYS_ERR_SYNTAX,
                       "%s:%u:%u: expected a rule written X=successor (one symbol, '=', the successor) "
                       "or '@' to end the rules",
                       r->name, r->line, col);
    } else {
        rc = set_rule(r, tok[0], tok + 2, cols + 2, n - 2, col);
    }
    free(cols);
    return rc;
}

/* ---- keyword dialect ---------------------------------------------------------------------- */

static const char *const keywords[] = {"recursion", "angle", "thickness", "min_thickness", "shape",
                                       "switch_yz", "no_wait", "poly_limit", "mutation", "color",
                                       "axiom", "rule", NULL};

/* Reads up to `max` numbers after the keyword; the rest of the line must be blank or a
 * comment. Returns how many were read, or -1 when something else stands there (*bad_col). */
static int keyword_numbers(text_line ln, size_t i, double *v, int max, uint32_t *cols, uint32_t *bad_col)
{
    int k = 0;
    for (;;) {
        while (i < ln.n && is_blank(ln.s[i])) i++;
        if (i >= ln.n || ln.s[i] == '#') return k;
        size_t start = i;
        while (i < ln.n && !is_blank(ln.s[i]) && ln.s[i] != '#') i++;
        if (k == max || !token_number(ln.s + start, i - start, &v[k])) {
            *bad_col = (uint32_t)start + 1;
            return -1;
        }
        cols[k++] = (uint32_t)start + 1;
    }
}

static int read_keyword_values(reader *r, text_line ln, size_t after, const char *kw, int want,
                               double *v, uint32_t *cols)
{
    uint32_t bad = 0;
    int got = keyword_numbers(ln, after, v, want, cols, &bad);
    if (got == want) return LSYS_OK;
    if (got < 0)
        return plugin_fail(r->err, LSYS_ERR_SYNTAX, "%s:%u:%u: '%s' takes %d number%s; what stands here is not one",
                         r->name, r->line, bad, kw, want, want == 1 ? "" : "s");
    return plugin_fail(r->err, LSYS_ERR_SYNTAX, "%s:%u:%zu: '%s' takes %d number%s, found %d", r->name,
                     r->line, after + 1, kw, want, want == 1 ? "" : "s", got);
}

static int read_switch(reader *r, const char *kw, double v, uint32_t col)
{
    if (v != 0 && v != 1)
        return plugin_fail(r->err, LSYS_ERR_SYNTAX, "%s:%u:%u: '%s' is 0 or 1, got %g", r->name, r->line, col, kw, v);
    return LSYS_OK;
}

static int read_keyword_line(reader *r, text_line ln)
{
    size_t i = 0;
    while (i < ln.n && is_blank(ln.s[i])) i++;
    if (i >= ln.n || ln.s[i] == '#') return LSYS_OK;
    size_t start = i;
    while (i < ln.n && ((ln.s[i] >= 'a' && ln.s[i] <= 'z') || ln.s[i] == '_')) i++;
    size_t kn = i - start;
    uint32_t kcol = (uint32_t)start + 1;
    int which = -1;
    for (int k = 0; keywords[k]; k++)
        if (strlen(keywords[k]) == kn && !memcmp(keywords[k], ln.s + start, kn)) which = k;
    int word_ends = i >= ln.n || is_blank(ln.s[i]) || ln.s[i] == '#';
    if (which < 0 || !word_ends) {
        /* A lower-case word alone is quoted (a misspelt keyword); anything else may be some
         * other file's content and is not repeated. */
        if (word_ends && kn > 0 && kn <= 24)
            return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                             "%s:%u:%u: unknown keyword '%.*s'; a keyword-dialect line starts with "
                             "recursion, angle, thickness, min_thickness, shape, switch_yz, no_wait, "
                             "poly_limit, mutation, color, axiom or rule",
                             r->name, r->line, kcol, (int)kn, (const char *)ln.s + start);
        return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                         "%s:%u:%u: this line does not start with a keyword; is this an L-system file? "
                         "A keyword-dialect line starts with recursion, angle, thickness, min_thickness, "
                         "shape, switch_yz, no_wait, poly_limit, mutation, color, axiom or rule",
                         r->name, r->line, kcol);
    }
    const char *kw = keywords[which];
    double v[4];
    uint32_t cols[4];
    int rc;
    if (!strcmp(kw, "axiom") || !strcmp(kw, "rule")) {
        unsigned char *bytes;
        uint32_t *bcols;
        size_t n = strip_blanks(ln.s + i, ln.n - i, (uint32_t)i + 1, &bytes, &bcols);
        if (n == (size_t)-1) return plugin_fail(r->err, LSYS_ERR_NOMEM, "%s: out of memory", r->name);
        if (!strcmp(kw, "axiom")) {
            rc = n ? set_axiom(r, bytes, bcols, n, kcol)
                   : plugin_fail(r->err, LSYS_ERR_SYNTAX, "%s:%u:%u: 'axiom' needs a string of symbols",
                               r->name, r->line, kcol);
        } else if (n < 2 || bytes[1] != '=') {
            rc = plugin_fail(r->err, LSYS_ERR_SYNTAX,
                           "%s:%u:%u: a rule is written 'rule X = successor' (one symbol, '=', the successor)",
                           r->name, r->line, kcol);
        } else {
            rc = set_rule(r, bytes[0], bytes + 2, bcols + 2, n - 2, bcols[0]);
        }
        free(bytes);
        free(bcols);
        return rc;
    }
    if (!strcmp(kw, "color")) {
        if ((rc = read_keyword_values(r, ln, i, kw, 4, v, cols))) return rc;
        if (!(v[0] >= 0 && v[0] < LSYS_MAX_FILE_COLOURS && v[0] == floor(v[0])))
            return plugin_fail(r->err, LSYS_ERR_SYNTAX, "%s:%u:%u: colour index %g must be a whole number from 0 to %d",
                             r->name, r->line, cols[0], v[0], LSYS_MAX_FILE_COLOURS - 1);
        for (int c = 1; c < 4; c++)
            if (!(v[c] >= 0 && v[c] <= 255))
                return plugin_fail(r->err, LSYS_ERR_SYNTAX, "%s:%u:%u: colour component %g must be from 0 to 255",
                                 r->name, r->line, cols[c], v[c]);
        int idx = (int)v[0];
        r->sys->colour_given[idx] = 1;
        for (int c = 0; c < 3; c++) r->sys->colour_srgb[idx][c] = (float)(v[c + 1] / 255.0);
        return LSYS_OK;
    }
    if ((rc = read_keyword_values(r, ln, i, kw, 1, v, cols))) return rc;
    if (!strcmp(kw, "recursion")) return check_recursion(r, v[0], cols[0]);
    if (!strcmp(kw, "angle")) {
        r->sys->angle_deg = v[0];
        return LSYS_OK;
    }
    if (!strcmp(kw, "thickness")) return check_thickness(r, kw, v[0], cols[0], &r->sys->thickness);
    if (!strcmp(kw, "min_thickness")) return check_thickness(r, kw, v[0], cols[0], &r->sys->min_thickness);
    if (!strcmp(kw, "shape")) {
        if (v[0] != 0 && v[0] != 1) {
            if (!r->opt || !r->opt->lenient)
                return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                                 "%s:%u:%u: 'shape %g' is not one of Lparser 2.1's shapes: 0 (blocks) or 1 "
                                 "(joined cylinders)",
                                 r->name, r->line, cols[0], v[0]);
            reader_warn(r, "%s:%u:%u: 'shape %g' is not 0 (blocks) or 1 (cylinders); cylinders are used (lenient mode)",
                        r->name, r->line, cols[0], v[0]);
            v[0] = 1;
        }
        r->sys->shape = (int)v[0];
        return LSYS_OK;
    }
    if (!strcmp(kw, "switch_yz") || !strcmp(kw, "no_wait")) return read_switch(r, kw, v[0], cols[0]);
    if (!strcmp(kw, "poly_limit")) {
        if (!(v[0] >= 0 && v[0] <= 4e9 && v[0] == floor(v[0])))
            return plugin_fail(r->err, LSYS_ERR_SYNTAX, "%s:%u:%u: poly_limit %g must be a whole number from 0",
                             r->name, r->line, cols[0], v[0]);
        r->sys->poly_limit = (uint32_t)v[0];
        return LSYS_OK;
    }
    /* mutation: random edits of the rules; 0 is the identity. */
    if (v[0] != 0) {
        if (!r->opt || !r->opt->lenient)
            return plugin_fail(r->err, LSYS_ERR_SYNTAX,
                             "%s:%u:%u: 'mutation %g' is not supported: sylva grows the rules as written "
                             "(use mutation 0, or lenient mode to ignore the line)",
                             r->name, r->line, cols[0], v[0]);
        reader_warn(r, "%s:%u:%u: 'mutation %g' ignored; the rules grow as written (lenient mode)", r->name,
                    r->line, cols[0], v[0]);
    }
    return LSYS_OK;
}

/* ---- both ----------------------------------------------------------------------------------- */

/* The dialect from the first line that is neither blank nor a comment: a number starts the
 * numeric header, a lower-case word the keyword dialect. */
static int detect_dialect(const unsigned char *s, size_t n, lsys_dialect *d)
{
    size_t i = 0;
    while (i < n) {
        size_t e = i;
        while (e < n && s[e] != '\n') e++;
        size_t j = i;
        while (j < e && (is_blank(s[j]) || s[j] == '\r')) j++;
        if (j < e && s[j] != '#') {
            unsigned char c = s[j];
            if ((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+') *d = LSYS_DIALECT_NUMERIC;
            else *d = LSYS_DIALECT_KEYWORD;
            return 1;
        }
        i = e + 1;
    }
    return 0;
}

int lsys_read(const char *text, size_t len, const char *name, const lsys_read_options *opt,
              lsys_system **out, plugin_err *err)
{
    *out = NULL;
    if (!name) name = "L-system";
    if (len > LSYS_FILE_MAX_BYTES)
        return plugin_fail(err, LSYS_ERR_LIMIT, "%s: %zu bytes is more than the %u bytes an L-system may have",
                         name, len, LSYS_FILE_MAX_BYTES);
    const char *nul = memchr(text, '\0', len);
    if (nul)
        return plugin_fail(err, LSYS_ERR_SYNTAX, "%s: not a text file (byte %zu is a NUL); an L-system is a text file",
                         name, (size_t)(nul - text) + 1);
    lsys_system *sys = calloc(1, sizeof *sys); /* owned here until handed to *out */
    if (!sys || !(sys->name = strdup(name))) {
        free(sys);
        return plugin_fail(err, LSYS_ERR_NOMEM, "%s: out of memory", name);
    }
    sys->shape = -1;
    const unsigned char *s = (const unsigned char *)text;
    if (!detect_dialect(s, len, &sys->dialect)) {
        lsys_system_free(sys);
        return plugin_fail(err, LSYS_ERR_SYNTAX,
                         "%s: no L-system found: the text is empty or only comments; expected three numeric "
                         "lines (recursion, angle, thickness), an axiom and rules, or keyword lines",
                         name);
    }
    if (sys->dialect == LSYS_DIALECT_NUMERIC) {
        sys->base_length = 100.0;
    } else {
        sys->recursion = 1, sys->angle_deg = 45.0, sys->thickness = 100.0;
        sys->base_length = 1.0;
    }
    reader r = {.name = name, .opt = opt, .err = err, .sys = sys};
    int stage = 0, rc = LSYS_OK;
    for (size_t i = 0; i <= len && !rc;) {
        size_t e = i;
        while (e < len && s[e] != '\n') e++;
        text_line ln = {s + i, e - i};
        while (ln.n && ln.s[ln.n - 1] == '\r') ln.n--;
        r.line++;
        rc = sys->dialect == LSYS_DIALECT_NUMERIC ? read_numeric_line(&r, ln, &stage) : read_keyword_line(&r, ln);
        i = e + 1;
    }
    if (!rc && sys->dialect == LSYS_DIALECT_NUMERIC && stage < 4) {
        static const char *const missing[] = {"the recursion level", "the standard angle", "the thickness",
                                              "the axiom"};
        rc = plugin_fail(err, LSYS_ERR_SYNTAX,
                       "%s:%u: the text ends before %s; a numeric L-system gives the recursion level, the "
                       "angle, the thickness and the axiom on its first four lines",
                       name, r.line, missing[stage]);
    }
    if (!rc && sys->dialect == LSYS_DIALECT_KEYWORD && !r.axiom_line)
        rc = plugin_fail(err, LSYS_ERR_SYNTAX, "%s: no 'axiom' line; the keyword dialect needs 'axiom <symbols>'",
                       name);
    if (rc) {
        lsys_system_free(sys);
        return rc;
    }
    *out = sys;
    return LSYS_OK;
}

int lsys_read_file(const char *path, const lsys_read_options *opt, lsys_system **out, plugin_err *err)
{
    *out = NULL;
    FILE *f = fopen(path, "rb");
    if (!f) return plugin_fail(err, LSYS_ERR_IO, "%s: cannot open the L-system file: %s", path, strerror(errno));
    long size = fseek(f, 0, SEEK_END) ? -1 : ftell(f);
    if (size < 0 || fseek(f, 0, SEEK_SET)) {
        fclose(f);
        return plugin_fail(err, LSYS_ERR_IO, "%s: cannot read the L-system file (not a regular file?)", path);
    }
    if ((unsigned long)size > LSYS_FILE_MAX_BYTES) {
        fclose(f);
        return plugin_fail(err, LSYS_ERR_LIMIT, "%s: %ld bytes is more than the %u bytes an L-system file may have",
                         path, size, LSYS_FILE_MAX_BYTES);
    }
    char *buf = malloc((size_t)size + 1u); /* owned here */
    if (!buf) {
        fclose(f);
        return plugin_fail(err, LSYS_ERR_NOMEM, "%s: out of memory reading the file", path);
    }
    size_t n = fread(buf, 1, (size_t)size, f);
    int bad = ferror(f) || n != (size_t)size;
    fclose(f);
    int rc = bad ? plugin_fail(err, LSYS_ERR_IO, "%s: read error", path) : lsys_read(buf, n, path, opt, out, err);
    free(buf);
    return rc;
}

void lsys_system_free(lsys_system *sys)
{
    if (!sys) return;
    for (int i = 0; i < 256; i++) free(sys->rules[i].successor);
    free(sys->axiom);
    free(sys->name);
    free(sys);
}
