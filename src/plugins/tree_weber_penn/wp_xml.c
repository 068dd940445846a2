/* wp_xml.c — the species files' XML subset read into a tree of wp_xml_node (wp_xml.h): a cursor
 * that counts lines and columns, the declaration, comments, elements, attributes and text. */
#include "wp_xml.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct cursor {
    const char *file, *buf;
    size_t len, pos;
    int line, col, nodes;
    plugin_err *err;
} cursor;

static int fail_at(cursor *c, int line, int col, const char *fmt, ...) SYLVA_PRINTF(4, 5);
static int fail_at(cursor *c, int line, int col, const char *fmt, ...)
{
    char what[PLUGIN_ERR_MAX - 128];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return plugin_fail(c->err, SYLVA_ERR_PARAM, "%s:%d:%d: %s", c->file, line, col, what);
}

static int fail_here(cursor *c, const char *what)
{
    return fail_at(c, c->line, c->col, "%s", what);
}

static int at_end(const cursor *c) { return c->pos >= c->len; }
static char peek(const cursor *c) { return at_end(c) ? '\0' : c->buf[c->pos]; }

static int looking_at(const cursor *c, const char *s)
{
    size_t n = strlen(s);
    return c->len - c->pos >= n && memcmp(c->buf + c->pos, s, n) == 0;
}

static void advance(cursor *c, size_t n)
{
    for (size_t i = 0; i < n && !at_end(c); i++, c->pos++) {
        if (c->buf[c->pos] == '\n') c->line++, c->col = 1;
        else c->col++;
    }
}

static int is_blank(char ch) { return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r'; }

static void skip_blank(cursor *c)
{
    while (!at_end(c) && is_blank(peek(c))) advance(c, 1);
}

static int is_name_char(char ch, int first)
{
    if ((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || ch == '_' || ch == ':') return 1;
    return !first && ((ch >= '0' && ch <= '9') || ch == '-' || ch == '.');
}

static char *copy_range(const char *s, size_t n)
{
    char *out = malloc(n + 1); /* owned by the caller */
    if (!out) return NULL;
    memcpy(out, s, n);
    out[n] = '\0';
    return out;
}

static int no_memory(cursor *c) { return plugin_fail(c->err, SYLVA_ERR_NOMEM, "%s: out of memory reading XML", c->file); }

/* A name at the cursor into *out (owned by the caller). */
static int read_name(cursor *c, const char *what, char **out)
{
    size_t start = c->pos;
    if (!is_name_char(peek(c), 1))
        return fail_at(c, c->line, c->col, "expected %s, a name starting with a letter, '_' or ':'", what);
    while (!at_end(c) && is_name_char(peek(c), 0)) advance(c, 1);
    *out = copy_range(c->buf + start, c->pos - start);
    return *out ? 0 : no_memory(c);
}

/* Skips "<!-- ... -->" at the cursor. */
static int skip_comment(cursor *c)
{
    int line = c->line, col = c->col;
    advance(c, 4);
    while (!at_end(c) && !looking_at(c, "-->")) {
        if (looking_at(c, "--")) return fail_here(c, "'--' inside a comment; a comment ends with '-->'");
        advance(c, 1);
    }
    if (at_end(c)) return fail_at(c, line, col, "comment not closed; end it with '-->'");
    advance(c, 3);
    return 0;
}

/* Skips blanks and comments. */
static int skip_misc(cursor *c)
{
    for (;;) {
        skip_blank(c);
        if (!looking_at(c, "<!--")) return 0;
        int rc = skip_comment(c);
        if (rc) return rc;
    }
}

/* The declaration "<?xml ... ?>", taken without checking its pseudo-attributes. */
static int skip_declaration(cursor *c)
{
    int line = c->line, col = c->col;
    if (!looking_at(c, "<?xml") || is_name_char(c->pos + 5 < c->len ? c->buf[c->pos + 5] : ' ', 0))
        return fail_here(c, "processing instruction not allowed; only '<?xml ...?>' may open the file");
    while (!at_end(c) && !looking_at(c, "?>")) advance(c, 1);
    if (at_end(c)) return fail_at(c, line, col, "the '<?xml' declaration is not closed; end it with '?>'");
    advance(c, 2);
    return 0;
}

/* Appends buf[from..to) to the text *t of length *n, with the five named entities decoded. */
static int append_text(cursor *c, char **t, size_t *n, size_t from, size_t to, int line, int col);

static const struct { const char *name; char ch; } entities[] = {
    { "&lt;", '<' }, { "&gt;", '>' }, { "&amp;", '&' }, { "&quot;", '"' }, { "&apos;", '\'' },
};

/* The entity at s (length `left`): its character and length, or 0. */
static size_t entity_at(const char *s, size_t left, char *ch)
{
    for (size_t i = 0; i < sizeof entities / sizeof entities[0]; i++) {
        size_t k = strlen(entities[i].name);
        if (left >= k && memcmp(s, entities[i].name, k) == 0) {
            *ch = entities[i].ch;
            return k;
        }
    }
    return 0;
}

static int append_text(cursor *c, char **t, size_t *n, size_t from, size_t to, int line, int col)
{
    char *grown = realloc(*t, *n + (to - from) + 1); /* owned by the caller */
    if (!grown) return no_memory(c);
    *t = grown;
    for (size_t i = from; i < to; i++) {
        char ch = c->buf[i];
        if (ch == '&') {
            size_t k = entity_at(c->buf + i, to - i, &ch);
            if (!k) {
                for (size_t j = from; j < i; j++) c->buf[j] == '\n' ? (line++, col = 1) : col++;
                return fail_at(c, line, col, "unknown entity; use &lt; &gt; &amp; &quot; or &apos;");
            }
            i += k - 1;
        }
        (*t)[(*n)++] = ch;
    }
    (*t)[*n] = '\0';
    return 0;
}

static int count_node(cursor *c)
{
    if (++c->nodes <= WP_XML_MAX_NODES) return 0;
    return plugin_fail(c->err, SYLVA_ERR_LIMIT, "%s:%d:%d: more than %d elements and attributes; split the file",
                       c->file, c->line, c->col, WP_XML_MAX_NODES);
}

/* A quoted attribute value at the cursor into a->value. */
static int read_value(cursor *c, wp_xml_attr *a)
{
    char quote = peek(c);
    if (quote != '"' && quote != '\'')
        return fail_here(c, "attribute value must be quoted: name=\"value\" or name='value'");
    advance(c, 1);
    a->value_line = c->line, a->value_col = c->col;
    size_t start = c->pos, n = 0;
    while (!at_end(c) && peek(c) != quote) {
        if (peek(c) == '<') return fail_here(c, "'<' inside an attribute value; write &lt;");
        advance(c, 1);
    }
    if (at_end(c)) return fail_at(c, a->value_line, a->value_col, "attribute value not closed; end it with %c", quote);
    a->value = malloc(1); /* owned by a */
    if (!a->value) return no_memory(c);
    a->value[0] = '\0';
    int rc = append_text(c, &a->value, &n, start, c->pos, a->value_line, a->value_col);
    advance(c, 1);
    return rc;
}

/* One attribute at the cursor, appended to n's list (*tail: where the next goes). */
static int read_attr(cursor *c, wp_xml_node *n, wp_xml_attr ***tail)
{
    int rc = count_node(c);
    if (rc) return rc;
    wp_xml_attr *a = calloc(1, sizeof *a); /* owned by n */
    if (!a) return no_memory(c);
    **tail = a, *tail = &a->next;
    a->line = c->line, a->col = c->col;
    if ((rc = read_name(c, "an attribute", &a->name))) return rc;
    if (wp_xml_attr_find(n, a->name) != a)
        return fail_at(c, a->line, a->col, "attribute '%s' given twice; give it once", a->name);
    skip_blank(c);
    if (peek(c) != '=') return fail_here(c, "expected '=' after the attribute's name: name=\"value\"");
    advance(c, 1);
    skip_blank(c);
    return read_value(c, a);
}

static int read_element(cursor *c, wp_xml_node **out, int depth);

/* The text, comments and children of n up to its end tag. */
static int read_content(cursor *c, wp_xml_node *n, int depth)
{
    size_t text_len = 0;
    wp_xml_node **tail = &n->children;
    int seen_text = 0, rc = 0;
    while (!rc) {
        if (at_end(c)) return fail_at(c, n->line, n->col, "element <%s> not closed; end it with </%s>", n->name, n->name);
        if (looking_at(c, "</")) break;
        if (looking_at(c, "<!--")) rc = skip_comment(c);
        else if (looking_at(c, "<![CDATA[") || looking_at(c, "<!") || looking_at(c, "<?"))
            rc = fail_here(c, "CDATA, DOCTYPE and processing instructions are not read; write plain text or elements");
        else if (peek(c) == '<') {
            rc = read_element(c, tail, depth + 1);
            if (*tail) tail = &(*tail)->next;
        } else {
            size_t start = c->pos;
            int line = c->line, col = c->col;
            while (!at_end(c) && peek(c) != '<') {
                if (!seen_text && !is_blank(peek(c))) seen_text = 1, n->text_line = c->line, n->text_col = c->col;
                advance(c, 1);
            }
            rc = append_text(c, &n->text, &text_len, start, c->pos, line, col);
        }
    }
    return rc;
}

/* The end tag "</name>" of n at the cursor. */
static int read_end_tag(cursor *c, const wp_xml_node *n)
{
    int line = c->line, col = c->col;
    advance(c, 2);
    char *name = NULL;
    int rc = read_name(c, "the end tag's name", &name);
    if (!rc && strcmp(name, n->name) != 0)
        rc = fail_at(c, line, col, "end tag </%s> does not match <%s> at line %d column %d; write </%s>", name, n->name,
                     n->line, n->col, n->name);
    free(name);
    if (rc) return rc;
    skip_blank(c);
    if (peek(c) != '>') return fail_here(c, "expected '>' to close the end tag");
    advance(c, 1);
    return 0;
}

/* The start tag's attributes up to '>' or "/>"; *empty set for the latter. */
static int read_attrs(cursor *c, wp_xml_node *n, int *empty)
{
    wp_xml_attr **tail = &n->attrs;
    for (;;) {
        int blank = is_blank(peek(c));
        skip_blank(c);
        if (at_end(c)) return fail_at(c, n->line, n->col, "start tag <%s not closed; end it with '>' or '/>'", n->name);
        if (looking_at(c, "/>")) return advance(c, 2), *empty = 1, 0;
        if (peek(c) == '>') return advance(c, 1), *empty = 0, 0;
        if (!blank) return fail_here(c, "expected a blank, '>' or '/>' after the name or attribute");
        int rc = read_attr(c, n, &tail);
        if (rc) return rc;
    }
}

static int read_element(cursor *c, wp_xml_node **out, int depth)
{
    if (depth > WP_XML_MAX_DEPTH)
        return plugin_fail(c->err, SYLVA_ERR_LIMIT, "%s:%d:%d: elements nested deeper than %d; flatten the file",
                           c->file, c->line, c->col, WP_XML_MAX_DEPTH);
    int rc = count_node(c);
    if (rc) return rc;
    wp_xml_node *n = calloc(1, sizeof *n); /* owned by the parent's list, or the caller's root */
    if (!n) return no_memory(c);
    *out = n;
    n->line = c->line, n->col = c->col;
    advance(c, 1);
    if ((rc = read_name(c, "an element", &n->name))) return rc;
    n->text = calloc(1, 1); /* owned by n */
    if (!n->text) return no_memory(c);
    int empty = 0;
    if ((rc = read_attrs(c, n, &empty))) return rc;
    n->text_line = c->line, n->text_col = c->col;
    if (empty) return 0;
    if ((rc = read_content(c, n, depth))) return rc;
    return read_end_tag(c, n);
}

/* The prolog (declaration, comments), the root element, then only blanks and comments. */
static int read_document(cursor *c, wp_xml_node **root)
{
    skip_blank(c);
    int rc = looking_at(c, "<?") ? skip_declaration(c) : 0;
    if (!rc) rc = skip_misc(c);
    if (rc) return rc;
    if (looking_at(c, "<!") || looking_at(c, "<?"))
        return fail_here(c, "DOCTYPE and processing instructions are not read; start with the root element");
    if (peek(c) != '<') return fail_here(c, "expected the root element, e.g. <arbaro> or <helios>");
    if ((rc = read_element(c, root, 1))) return rc;
    if ((rc = skip_misc(c))) return rc;
    if (!at_end(c)) return fail_here(c, "text after the root element's end; a file holds one root element");
    return 0;
}

int wp_xml_parse(const char *file, const char *buf, size_t len, wp_xml_node **root, plugin_err *err)
{
    cursor c = { file, buf, len, 0, 1, 1, 0, err };
    *root = NULL;
    if (len > WP_XML_MAX_BYTES)
        return plugin_fail(err, SYLVA_ERR_LIMIT, "%s: %zu bytes, more than the %u a species file may have", file, len,
                           WP_XML_MAX_BYTES);
    if (memchr(buf, '\0', len)) {
        advance(&c, (size_t)((const char *)memchr(buf, '\0', len) - buf));
        return fail_here(&c, "a NUL byte; a species file is text");
    }
    int rc = read_document(&c, root);
    if (rc) {
        wp_xml_free(*root);
        *root = NULL;
    }
    return rc;
}

static void free_attrs(wp_xml_attr *a)
{
    while (a) {
        wp_xml_attr *next = a->next;
        free(a->name);
        free(a->value);
        free(a);
        a = next;
    }
}

void wp_xml_free(wp_xml_node *n)
{
    while (n) {
        wp_xml_node *next = n->next;
        wp_xml_free(n->children); /* as deep as WP_XML_MAX_DEPTH at most */
        free_attrs(n->attrs);
        free(n->name);
        free(n->text);
        free(n);
        n = next;
    }
}

const wp_xml_attr *wp_xml_attr_find(const wp_xml_node *n, const char *name)
{
    for (const wp_xml_attr *a = n->attrs; a; a = a->next)
        if (strcmp(a->name, name) == 0) return a;
    return NULL;
}
