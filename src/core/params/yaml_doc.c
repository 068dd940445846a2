/* yaml_doc.c — libyaml's event stream folded into a ynode tree with locations.
 *
 * The tree is built with an explicit stack (no recursion), so nesting depth is bounded by
 * YAML_DOC_MAX_DEPTH and never by the C stack. Children of an open collection gather in a
 * malloc'ed vector that is copied into the arena when the collection closes; the vectors are
 * released on every path out. Duplicate keys are found when a mapping closes, by sorting, so a
 * mapping with many keys costs n log n, not n^2.
 */
#include "params/yaml_doc.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <yaml.h>

#include "util/file_check.h"
#include "util/memory_budget.h"

typedef struct open_collection {
    ynode *node;          /* allocated in the arena when the collection starts */
    void *children;       /* malloc'ed: const ynode * (sequence) or ynode_pair (mapping) */
    uint32_t n, cap;
    int have_key;         /* mapping: a key waits for its value */
    ynode_pair key;       /* mapping: that key */
} open_collection;

typedef struct doc_builder {
    arena *a;
    const char *file;
    const char *text;
    size_t len;
    open_collection stack[YAML_DOC_MAX_DEPTH];
    uint32_t depth;
    const ynode *root;
    int documents;
    err_buf *err;
} doc_builder;

static uint32_t mark_line(yaml_mark_t m) { return (uint32_t)m.line + 1; }
static uint32_t mark_column(yaml_mark_t m) { return (uint32_t)m.column + 1; }

static int grow(open_collection *c, size_t elem)
{
    if (c->n < c->cap) return 0;
    uint32_t cap = c->cap ? c->cap * 2 : 8;
    void *p = realloc(c->children, (size_t)cap * elem);
    if (!p) return -1;
    c->children = p, c->cap = cap;
    return 0;
}

/* Attaches a finished node to the collection on top of the stack, or makes it the root. */
static int attach(doc_builder *b, const ynode *n)
{
    if (b->depth == 0) {
        b->root = n;
        return 0;
    }
    open_collection *c = &b->stack[b->depth - 1];
    if (c->node->kind == YNODE_SEQUENCE) {
        if (grow(c, sizeof(const ynode *)))
            return err_nomem(b->err, "%s: out of memory while reading", b->file);
        ((const ynode **)c->children)[c->n++] = n;
        return 0;
    }
    if (!c->have_key) {
        if (n->kind != YNODE_SCALAR)
            return err_set(b->err,
                           "%s:%u:%u: a mapping key must be a name (a scalar), not %s",
                           b->file, n->line, n->column, ynode_kind_phrase(n));
        c->key.key = n->text;
        c->key.key_line = n->line, c->key.key_column = n->column;
        c->have_key = 1;
        return 0;
    }
    if (grow(c, sizeof(ynode_pair)))
        return err_nomem(b->err, "%s: out of memory while reading", b->file);
    ynode_pair *p = &((ynode_pair *)c->children)[c->n++];
    *p = c->key;
    p->value = n;
    c->have_key = 0;
    return 0;
}

static int pair_order(const void *x, const void *y)
{
    const ynode_pair *a = *(const ynode_pair *const *)x, *b = *(const ynode_pair *const *)y;
    int k = strcmp(a->key, b->key);
    if (k) return k;
    if (a->key_line != b->key_line) return a->key_line < b->key_line ? -1 : 1;
    return a->key_column < b->key_column ? -1 : a->key_column > b->key_column;
}

static int later(const ynode_pair *a, const ynode_pair *b)
{
    return a->key_line != b->key_line ? a->key_line > b->key_line : a->key_column > b->key_column;
}

/* Reports the first (in file order) key that repeats an earlier key of the same mapping. */
static int check_duplicate_keys(doc_builder *b, const ynode_pair *pairs, uint32_t n)
{
    if (n < 2) return 0;
    const ynode_pair **sorted = malloc((size_t)n * sizeof *sorted);
    if (!sorted) return err_nomem(b->err, "%s: out of memory while reading", b->file);
    for (uint32_t i = 0; i < n; i++) sorted[i] = &pairs[i];
    qsort(sorted, n, sizeof *sorted, pair_order);
    const ynode_pair *dup = NULL, *first = NULL;
    for (uint32_t i = 1, group = 0; i < n; i++) {
        if (strcmp(sorted[i]->key, sorted[group]->key)) {
            group = i;
            continue;
        }
        if (!dup || later(dup, sorted[i])) dup = sorted[i], first = sorted[group];
    }
    int rc = 0;
    if (dup)
        rc = err_set(b->err,
                     "%s:%u:%u: duplicate key '%s'; it was first given at line %u, column %u",
                     b->file, dup->key_line, dup->key_column, dup->key, first->key_line,
                     first->key_column);
    free(sorted);
    return rc;
}

static int close_collection(doc_builder *b)
{
    open_collection *c = &b->stack[b->depth - 1];
    ynode *n = c->node;
    if (n->kind == YNODE_SEQUENCE) {
        const ynode **items = arena_alloc(b->a, (size_t)c->n * sizeof *items + 1);
        if (!items) return err_nomem(b->err, "%s: out of memory while reading", b->file);
        if (c->n) memcpy(items, c->children, (size_t)c->n * sizeof *items);
        n->items = items, n->n_items = c->n;
    } else {
        ynode_pair *pairs = arena_alloc(b->a, (size_t)c->n * sizeof *pairs + 1);
        if (!pairs) return err_nomem(b->err, "%s: out of memory while reading", b->file);
        if (c->n) memcpy(pairs, c->children, (size_t)c->n * sizeof *pairs);
        n->pairs = pairs, n->n_pairs = c->n;
        if (check_duplicate_keys(b, pairs, c->n)) return -1;
    }
    free(c->children);
    memset(c, 0, sizeof *c);
    b->depth--;
    return attach(b, n);
}

static int open_collection_node(doc_builder *b, ynode_kind kind, yaml_mark_t at)
{
    if (b->depth >= YAML_DOC_MAX_DEPTH)
        return err_set(b->err, "%s:%u:%u: nesting is deeper than the limit of %d levels", b->file,
                       mark_line(at), mark_column(at), YAML_DOC_MAX_DEPTH);
    ynode *n = arena_alloc(b->a, sizeof *n);
    if (!n) return err_nomem(b->err, "%s: out of memory while reading", b->file);
    n->kind = kind, n->line = mark_line(at), n->column = mark_column(at);
    open_collection *c = &b->stack[b->depth++];
    memset(c, 0, sizeof *c);
    c->node = n;
    return 0;
}

static int scalar_node(doc_builder *b, const yaml_event_t *ev)
{
    size_t len = ev->data.scalar.length;
    const char *text = (const char *)ev->data.scalar.value;
    if (len > YAML_DOC_MAX_SCALAR_BYTES)
        return err_set(b->err,
                       "%s:%u:%u: a scalar of %zu bytes is longer than the limit of %zu bytes",
                       b->file, mark_line(ev->start_mark), mark_column(ev->start_mark), len,
                       YAML_DOC_MAX_SCALAR_BYTES);
    if (memchr(text, '\0', len))
        return err_set(b->err, "%s:%u:%u: a scalar contains a NUL character", b->file,
                       mark_line(ev->start_mark), mark_column(ev->start_mark));
    ynode *n = arena_alloc(b->a, sizeof *n);
    char *copy = n ? arena_strndup(b->a, text, len) : NULL;
    if (!copy) return err_nomem(b->err, "%s: out of memory while reading", b->file);
    n->kind = YNODE_SCALAR;
    n->line = mark_line(ev->start_mark), n->column = mark_column(ev->start_mark);
    n->text = copy, n->text_len = len;
    n->quoted = ev->data.scalar.style != YAML_PLAIN_SCALAR_STYLE;
    return attach(b, n);
}

/* Anchors, aliases and explicit tags are refused: the scene format has no use for them, and
 * refusing aliases keeps a small file from expanding into a huge tree. */
static int refuse_extras(doc_builder *b, const yaml_event_t *ev, const yaml_char_t *anchor,
                         const yaml_char_t *tag)
{
    if (anchor)
        return err_set(b->err,
                       "%s:%u:%u: YAML anchors ('&%s') are not supported in scene files; write "
                       "the value out where it is used",
                       b->file, mark_line(ev->start_mark), mark_column(ev->start_mark),
                       (const char *)anchor);
    if (tag)
        return err_set(b->err,
                       "%s:%u:%u: YAML tags ('%s') are not supported in scene files; remove the "
                       "tag (quote a value to make it a string)",
                       b->file, mark_line(ev->start_mark), mark_column(ev->start_mark),
                       (const char *)tag);
    return 0;
}

static int handle_event(doc_builder *b, const yaml_event_t *ev)
{
    switch (ev->type) {
    case YAML_DOCUMENT_START_EVENT:
        if (++b->documents > 1)
            return err_set(b->err,
                           "%s:%u:%u: a second YAML document starts here; a scene file holds one",
                           b->file, mark_line(ev->start_mark), mark_column(ev->start_mark));
        return 0;
    case YAML_ALIAS_EVENT:
        return err_set(b->err,
                       "%s:%u:%u: YAML aliases ('*%s') are not supported in scene files; write "
                       "the value out where it is used",
                       b->file, mark_line(ev->start_mark), mark_column(ev->start_mark),
                       (const char *)ev->data.alias.anchor);
    case YAML_SCALAR_EVENT:
        if (refuse_extras(b, ev, ev->data.scalar.anchor, ev->data.scalar.tag)) return -1;
        return scalar_node(b, ev);
    case YAML_SEQUENCE_START_EVENT:
        if (refuse_extras(b, ev, ev->data.sequence_start.anchor, ev->data.sequence_start.tag))
            return -1;
        return open_collection_node(b, YNODE_SEQUENCE, ev->start_mark);
    case YAML_MAPPING_START_EVENT:
        if (refuse_extras(b, ev, ev->data.mapping_start.anchor, ev->data.mapping_start.tag))
            return -1;
        return open_collection_node(b, YNODE_MAPPING, ev->start_mark);
    case YAML_SEQUENCE_END_EVENT:
    case YAML_MAPPING_END_EVENT:
        return close_collection(b);
    default:
        return 0;
    }
}

/* Line and column of a byte offset, for reader errors (which carry only an offset). */
static void offset_position(const char *text, size_t len, size_t offset, uint32_t *line,
                            uint32_t *column)
{
    *line = 1, *column = 1;
    for (size_t i = 0; i < offset && i < len; i++) {
        if (text[i] == '\n') (*line)++, *column = 1;
        else if (((unsigned char)text[i] & 0xC0) != 0x80) (*column)++;
    }
}

static int syntax_error(doc_builder *b, const yaml_parser_t *p)
{
    if (p->error == YAML_MEMORY_ERROR)
        return err_nomem(b->err, "%s: out of memory while reading", b->file);
    if (p->error == YAML_READER_ERROR) {
        uint32_t line, column;
        offset_position(b->text, b->len, p->problem_offset, &line, &column);
        return err_set(b->err, "%s:%u:%u: %s (YAML syntax)", b->file, line, column,
                       p->problem ? p->problem : "unreadable text");
    }
    const char *problem = p->problem ? p->problem : "malformed YAML";
    if (p->context)
        return err_set(b->err, "%s:%u:%u: %s, %s that starts at line %u, column %u (YAML syntax)",
                       b->file, mark_line(p->problem_mark), mark_column(p->problem_mark), problem,
                       p->context, mark_line(p->context_mark), mark_column(p->context_mark));
    return err_set(b->err, "%s:%u:%u: %s (YAML syntax)", b->file, mark_line(p->problem_mark),
                   mark_column(p->problem_mark), problem);
}

int yaml_doc_parse(arena *a, const char *text, size_t len, const char *file_label, yaml_doc *doc,
                   err_buf *err)
{
    const char *file = file_label ? file_label : "(text)";
    memset(doc, 0, sizeof *doc);
    doc->file = arena_strdup(a, file);
    if (!doc->file) return err_nomem(err, "%s: out of memory while reading", file);
    if (len > YAML_DOC_MAX_FILE_BYTES)
        return err_set(err, "%s: the file is %zu bytes, larger than the limit of %zu MiB", file,
                       len, YAML_DOC_MAX_FILE_BYTES >> 20);

    yaml_parser_t parser;
    if (!yaml_parser_initialize(&parser))
        return err_nomem(err, "%s: out of memory while reading", file);
    yaml_parser_set_input_string(&parser, (const unsigned char *)text, len);

    doc_builder b = {.a = a, .file = doc->file, .text = text, .len = len, .err = err};
    int rc = 0;
    for (int done = 0; !done && rc == 0;) {
        yaml_event_t ev;
        if (!yaml_parser_parse(&parser, &ev)) {
            rc = syntax_error(&b, &parser);
            break;
        }
        done = ev.type == YAML_STREAM_END_EVENT;
        rc = handle_event(&b, &ev);
        yaml_event_delete(&ev);
    }
    for (uint32_t i = 0; i < b.depth; i++) free(b.stack[i].children);
    yaml_parser_delete(&parser);
    if (rc) return -1;
    doc->root = b.root;
    return 0;
}

static int unreadable(err_buf *err, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int unreadable(err_buf *err, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    err_vset(err, fmt, ap);
    va_end(ap);
    return YAML_DOC_UNREADABLE;
}

int yaml_doc_load(arena *a, const char *path, const char *file_label, yaml_doc *doc, err_buf *err)
{
    const char *file = file_label ? file_label : path;
    int fd = file_open_regular(path, file, err); /* a FIFO or device would block or never end */
    if (fd < 0) {
        err_buf why = *err;
        return unreadable(err, "%s", why.msg);
    }
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        close(fd);
        return unreadable(err, "%s: cannot open: %s", file, strerror(errno));
    }
    struct stat st;
    if (fstat(fileno(f), &st) != 0) {
        fclose(f);
        return unreadable(err, "%s: cannot open: %s", file, strerror(errno));
    }
    if ((unsigned long long)st.st_size > YAML_DOC_MAX_FILE_BYTES) {
        fclose(f);
        return unreadable(err, "%s: the file is %lld bytes, larger than the limit of %zu MiB", file,
                       (long long)st.st_size, YAML_DOC_MAX_FILE_BYTES >> 20);
    }
    size_t size = (size_t)st.st_size;
    /* the node tree takes up to YAML_DOC_BYTES_PER_BYTE times the text (measured on lists of
     * small mappings and numbers); a file that cannot fit is refused before it is read */
    char what[64];
    snprintf(what, sizeof what, "reading this %.1f MiB file", (double)size / (1024.0 * 1024.0));
    if (memory_check((uint64_t)size * YAML_DOC_BYTES_PER_BYTE, what, err)) {
        fclose(f);
        err_buf why = *err;
        return unreadable(err, "%s: %s", file, why.msg);
    }
    char *text = malloc(size + 1); /* owned here; freed below */
    if (!text) {
        fclose(f);
        err_nomem(err, "%s: out of memory while reading", file);
        return YAML_DOC_UNREADABLE;
    }
    size_t got = fread(text, 1, size, f);
    int read_failed = ferror(f);
    fclose(f);
    if (read_failed || got != size) {
        free(text);
        return unreadable(err, "%s: read error", file);
    }
    text[size] = '\0';
    int rc = yaml_doc_parse(a, text, size, file, doc, err);
    free(text);
    return rc;
}

const ynode_pair *ynode_get_pair(const ynode *map, const char *key)
{
    if (!map || map->kind != YNODE_MAPPING) return NULL;
    for (uint32_t i = 0; i < map->n_pairs; i++)
        if (!strcmp(map->pairs[i].key, key)) return &map->pairs[i];
    return NULL;
}

const ynode *ynode_get(const ynode *map, const char *key)
{
    const ynode_pair *p = ynode_get_pair(map, key);
    return p ? p->value : NULL;
}

int ynode_is_null(const ynode *n)
{
    if (!n || n->kind != YNODE_SCALAR || n->quoted) return 0;
    const char *t = n->text;
    return !t[0] || !strcmp(t, "~") || !strcmp(t, "null") || !strcmp(t, "Null") ||
           !strcmp(t, "NULL");
}

const char *ynode_kind_phrase(const ynode *n)
{
    if (!n || ynode_is_null(n)) return "nothing";
    switch (n->kind) {
    case YNODE_SEQUENCE: return "a sequence";
    case YNODE_MAPPING: return "a mapping";
    default: return "a scalar";
    }
}
