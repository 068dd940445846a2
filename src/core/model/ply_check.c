/* ply_check.c — a PLY file's header parsed and its body walked, to refuse a truncated or
 * malformed file with a sentence before Assimp sees it (see ply_check.h). The format: a header
 * of lines "ply", "format ascii|binary_little_endian|binary_big_endian 1.0", "element NAME
 * COUNT", "property TYPE NAME" or "property list COUNT_TYPE ITEM_TYPE NAME", "comment ...",
 * "obj_info ...", ending with "end_header"; then each element's COUNT items, each holding its
 * properties in order. */
#include "model/ply_check.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PLY_MAX_ELEMENTS 64
#define PLY_MAX_PROPERTIES 64
#define PLY_MAX_BYTES ((uint64_t)1 << 34) /* 16 GiB: far above the triangle limit's files */

typedef struct ply_property {
    int list;                 /* 1: a list */
    int size, count_size;     /* bytes of a value; of the list's count */
    int count_signed;
    int face_indices;         /* 1: the face element's vertex_indices (or vertex_index) list */
} ply_property;

typedef struct ply_element {
    char name[64];
    uint32_t line;  /* of its element line */
    uint64_t count;
    ply_property props[PLY_MAX_PROPERTIES];
    int n_props;
} ply_element;

typedef enum ply_format { PLY_ASCII, PLY_BINARY_LE, PLY_BINARY_BE } ply_format;

/* Bytes of a PLY scalar type name, 0 for an unknown name; *is_signed for the integer types. */
static int type_size(const char *t, int *is_signed)
{
    static const struct { const char *name; int size, is_signed; } types[] = {
        {"char", 1, 1},  {"int8", 1, 1},   {"uchar", 1, 0},  {"uint8", 1, 0},  {"short", 2, 1},
        {"int16", 2, 1}, {"ushort", 2, 0}, {"uint16", 2, 0}, {"int", 4, 1},    {"int32", 4, 1},
        {"uint", 4, 0},  {"uint32", 4, 0}, {"float", 4, 1},  {"float32", 4, 1}, {"double", 8, 1},
        {"float64", 8, 1}};
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (!strcmp(t, types[i].name)) {
            if (is_signed) *is_signed = types[i].is_signed;
            return types[i].size;
        }
    return 0;
}

/* Whether Assimp's reader knows the element name: it reads the count of an element it does not
 * know as 0 (from the name's first characters, which its count follows), and so reads that
 * element's items as the next element's. */
static int assimp_knows(const char *name)
{
    static const char *const known[] = {"vertex", "face", "tristrips", "edge", "material"};
    for (size_t i = 0; i < sizeof known / sizeof known[0]; i++)
        if (!strcmp(name, known[i])) return 1;
    return 0;
}

typedef struct ply_header {
    ply_format format;
    ply_element elements[PLY_MAX_ELEMENTS];
    int n_elements;
    size_t body;     /* offset of the body */
    uint32_t line;   /* line of the body's start */
} ply_header;

static int bad(err_buf *err, const char *path, uint32_t line, const char *what)
{
    return err_at(err, ERR_INPUT, path, line, 1, "%s", what);
}

/* Whether a header line of len bytes reads alike to this walk and to Assimp: Assimp ends a line
 * at \r, \n, \f or NUL and matches its words from the line's first byte, separated by spaces
 * and tabs only, so a line holding another control character or starting with a space would
 * split differently there (an element or end_header seen on one side alone, the binary data read
 * from another place); 1, or 0 with the column in err. A blank line reads alike. */
static int text_as_assimp_reads_it(const char *path, uint32_t line, const char *text, size_t len, err_buf *err)
{
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)text[i];
        if (c < 0x20 && c != '\t')
            return !err_at(err, ERR_INPUT, path, line, (uint32_t)i + 1, "a PLY header line holds the control "
                           "character 0x%02X; header lines hold words separated by spaces", c);
    }
    size_t lead = strspn(text, " \t");
    if (lead && lead < len)
        return !err_at(err, ERR_INPUT, path, line, 1, "a PLY header line starts with a space; header lines "
                       "start with their keyword (ply, format, element, property, comment, end_header)");
    return 1;
}

/* Parses the header in data[0, size). */
static int parse_header(const char *path, const char *data, size_t size, ply_header *h, err_buf *err)
{
    size_t at = 0;
    uint32_t line = 0;
    int have_format = 0;
    uint32_t info = 0; /* the line of an obj_info inside the last element, 0 when none */
    h->n_elements = 0;
    for (;;) {
        line++;
        const char *nl = memchr(data + at, '\n', size - at);
        if (!nl)
            return bad(err, path, line, "the PLY header has no end_header line (the file is cut short "
                       "or not a PLY file)");
        char text[256];
        size_t len = (size_t)(nl - (data + at));
        int crlf = len && data[at + len - 1] == '\r';
        len -= (size_t)crlf;
        if (len >= sizeof text) return bad(err, path, line, "a PLY header line is longer than 255 characters");
        memcpy(text, data + at, len);
        text[len] = '\0';
        at = (size_t)(nl - data) + 1;
        if (!text_as_assimp_reads_it(path, line, text, len, err)) return -1;
        char w[5][64] = {{0}};
        int n = sscanf(text, "%63s %63s %63s %63s %63s", w[0], w[1], w[2], w[3], w[4]);
        if (line == 1) {
            if (n != 1 || strcmp(w[0], "ply")) return bad(err, path, line, "a PLY file starts with the line 'ply'");
            continue;
        }
        if (n > 0 && !strcmp(w[0], "obj_info") && h->n_elements && !info) info = line;
        if (n <= 0 || !strcmp(w[0], "comment") || !strcmp(w[0], "obj_info")) continue;
        /* the words were read 63 bytes at a time: a longer one would have been split in two */
        for (size_t i = 0, run = 0; i < len; i++)
            if ((run = isspace((unsigned char)text[i]) ? 0 : run + 1) > 63)
                return err_at(err, ERR_INPUT, path, line, (uint32_t)(i - 62), "a word of a PLY header line is longer "
                              "than 63 characters (a name, a type or a count)");
        if (!strcmp(w[0], "end_header")) {
            if (crlf && have_format && h->format != PLY_ASCII)
                return err_at(err, ERR_INPUT, path, line, (uint32_t)len + 1, "the end_header line of a binary "
                              "PLY ends with \\r\\n: Assimp's reader would start the binary data at the \\n; "
                              "end it with \\n alone");
            break;
        }
        if (!strcmp(w[0], "format")) {
            if (n != 3 || strcmp(w[2], "1.0"))
                return bad(err, path, line, "the format line reads 'format ascii|binary_little_endian|"
                           "binary_big_endian 1.0'");
            if (!strcmp(w[1], "ascii")) h->format = PLY_ASCII;
            else if (!strcmp(w[1], "binary_little_endian")) h->format = PLY_BINARY_LE;
            else if (!strcmp(w[1], "binary_big_endian")) h->format = PLY_BINARY_BE;
            else return bad(err, path, line, "unknown PLY format; ascii, binary_little_endian or "
                            "binary_big_endian is valid");
            have_format = 1;
        } else if (!strcmp(w[0], "element")) {
            char *end;
            errno = 0;
            unsigned long long count = n == 3 ? strtoull(w[2], &end, 10) : 0;
            if (n != 3 || *end || errno || w[2][0] == '-')
                return bad(err, path, line, "an element line reads 'element NAME COUNT'");
            if (h->n_elements == PLY_MAX_ELEMENTS)
                return bad(err, path, line, "more than 64 PLY elements");
            /* Assimp reads the count of an element whose name it does not know from the name's
             * first characters: a name of digits stated billions of items to it. */
            if (isdigit((unsigned char)w[1][0]))
                return err_at(err, ERR_INPUT, path, line, 1, "element name '%s' starts with a digit, which "
                              "Assimp reads as the element's count; start the name with a letter", w[1]);
            /* Assimp sizes an element's array by its first declaration and fills it from all of
             * them: a second, longer 'vertex' element was written past the first's array. */
            for (int k = 0; k < h->n_elements; k++)
                if (!strcmp(h->elements[k].name, w[1]))
                    return err_at(err, ERR_INPUT, path, line, 1, "element '%s' is declared again (first "
                                  "on line %u); a PLY declares each element once", w[1], h->elements[k].line);
            ply_element *e = &h->elements[h->n_elements++];
            info = 0;
            memset(e, 0, sizeof *e);
            snprintf(e->name, sizeof e->name, "%s", w[1]);
            e->line = line;
            e->count = count;
        } else if (!strcmp(w[0], "property")) {
            if (!h->n_elements) return bad(err, path, line, "a property comes before any element");
            ply_element *e = &h->elements[h->n_elements - 1];
            /* Assimp's reader ends an element's properties at an obj_info line and passes over
             * the rest of them: the element would lose this one */
            if (info)
                return err_at(err, ERR_INPUT, path, line, 1, "a property of element '%s' follows an obj_info "
                              "line (line %u), after which Assimp's reader drops the element's properties; "
                              "put obj_info lines before the first element", e->name, info);
            if (e->n_props == PLY_MAX_PROPERTIES)
                return bad(err, path, line, "more than 64 properties in one PLY element");
            ply_property *p = &e->props[e->n_props++];
            memset(p, 0, sizeof *p);
            if (!strcmp(w[1], "list")) {
                p->list = 1;
                p->count_size = n == 5 ? type_size(w[2], &p->count_signed) : 0;
                p->size = n == 5 ? type_size(w[3], NULL) : 0;
                if (!p->count_size || !p->size || !strncmp(w[2], "float", 5) || !strcmp(w[2], "double"))
                    return bad(err, path, line, "a list property reads 'property list INTEGER_TYPE TYPE "
                               "NAME' with PLY type names (uchar, int, float, ...)");
                p->face_indices = !strcmp(e->name, "face") &&
                                  (!strcmp(w[4], "vertex_indices") || !strcmp(w[4], "vertex_index"));
            } else {
                p->size = n == 3 ? type_size(w[1], NULL) : 0;
                if (!p->size)
                    return bad(err, path, line, "a property reads 'property TYPE NAME' with a PLY type "
                               "name (char, uchar, short, ushort, int, uint, float, double)");
            }
        } else {
            return bad(err, path, line, "unknown PLY header line; ply, format, element, property, "
                       "comment, obj_info and end_header are valid");
        }
    }
    if (!have_format) return bad(err, path, line, "the PLY header has no format line");
    /* An item of no properties takes no bytes of the body: a binary walk (Assimp's, and this
     * one) would go round 7.7 x 10^10 of them without reading a byte. */
    for (int k = 0; k < h->n_elements; k++)
        if (h->elements[k].count && !h->elements[k].n_props)
            return err_at(err, ERR_INPUT, path, h->elements[k].line, 1, "element '%s' has %llu items but no "
                          "property; an element with items declares at least one property",
                          h->elements[k].name, (unsigned long long)h->elements[k].count);
    for (int k = 0; k < h->n_elements; k++) {
        const ply_element *e = &h->elements[k];
        if (!e->count || assimp_knows(e->name)) continue;
        for (int j = k + 1; j < h->n_elements; j++)
            if (h->elements[j].count && assimp_knows(h->elements[j].name))
                return err_at(err, ERR_INPUT, path, e->line, 1, "element '%s' has %llu item%s, which Assimp's "
                              "reader reads as none, as it does for every element but vertex, face, tristrips, "
                              "edge and material, so it would read element '%s' from the wrong place; leave '%s' "
                              "out or declare it after the elements it knows", e->name,
                              (unsigned long long)e->count, e->count == 1 ? "" : "s", h->elements[j].name, e->name);
    }
    h->body = at;
    h->line = line + 1;
    return 0;
}

/* A binary list count of `size` bytes at p; -1 when it is negative. */
static int64_t binary_count(const unsigned char *p, int size, int is_signed, int big)
{
    uint64_t v = 0;
    for (int i = 0; i < size; i++) v |= (uint64_t)p[big ? size - 1 - i : i] << (8 * i);
    if (is_signed && size < 8 && (v >> (8 * size - 1)) & 1) return -1;
    return (int64_t)v;
}

static int walk_binary(const char *path, const ply_header *h, const unsigned char *d, size_t size,
                       err_buf *err)
{
    size_t at = h->body;
    int big = h->format == PLY_BINARY_BE;
    for (int e = 0; e < h->n_elements; e++) {
        const ply_element *el = &h->elements[e];
        for (uint64_t i = 0; i < el->count; i++) {
            for (int k = 0; k < el->n_props; k++) {
                const ply_property *p = &el->props[k];
                uint64_t need = p->list ? (uint64_t)p->count_size : (uint64_t)p->size;
                if (need > size - at) goto short_body;
                if (p->list) {
                    int64_t n = binary_count(d + at, p->count_size, p->count_signed, big);
                    at += (size_t)p->count_size;
                    if (n < 0)
                        return err_fail(err, ERR_INPUT, "%s: element '%s' item %llu has a negative list "
                                        "length", path, el->name, (unsigned long long)i);
                    if (n == 0 && p->face_indices) /* Assimp aborts on a face of no vertices */
                        return err_fail(err, ERR_INPUT, "%s: face %llu lists no vertices; a face lists "
                                        "at least one (three for a triangle)", path, (unsigned long long)i + 1);
                    if ((uint64_t)n > (size - at) / (uint64_t)p->size) goto short_body;
                    at += (size_t)n * (size_t)p->size;
                } else {
                    at += (size_t)p->size;
                }
            }
            continue;
        short_body:
            return err_fail(err, ERR_INPUT, "%s: the file ends inside element '%s' (item %llu of %llu); "
                            "the file is cut short", path, el->name, (unsigned long long)i + 1,
                            (unsigned long long)el->count);
        }
    }
    return 0;
}

/* The next whitespace-separated token at *at as a number; -1 at the end of the data or when it
 * is not a number. *line follows the newlines passed. */
/* The next number on the current line into *v: 0; -1 at the line's end (or the file's); -2
 * when the word there is not a number. */
static int ascii_number(const char *d, size_t size, size_t *at, double *v)
{
    while (*at < size && (d[*at] == ' ' || d[*at] == '\t' || d[*at] == '\r')) (*at)++;
    if (*at >= size || d[*at] == '\n') return -1;
    char tok[64];
    size_t n = 0;
    while (*at < size && !(d[*at] == ' ' || d[*at] == '\t' || d[*at] == '\r' || d[*at] == '\n')) {
        if (n + 1 < sizeof tok) tok[n++] = d[*at];
        (*at)++;
    }
    tok[n] = '\0';
    char *end;
    *v = strtod(tok, &end);
    return *end || end == tok ? -2 : 0;
}

/* The numbers of one item, all on its line; 0, or -1 when the line ends early, -2 on a word that
 * is not a number (or a list length that is not a whole number up to 10^9), -3 on a face of no
 * vertices. */
static int ascii_item(const ply_element *el, const char *d, size_t size, size_t *at)
{
    for (int k = 0; k < el->n_props; k++) {
        const ply_property *p = &el->props[k];
        double v;
        int rc = ascii_number(d, size, at, &v);
        if (rc) return rc;
        if (!p->list) continue;
        if (!(v >= 0 && v <= 1e9) || v != floor(v)) return -2; /* in range before it is converted */
        if (p->face_indices && v == 0) return -3;
        double index;
        for (uint64_t j = 0, n = (uint64_t)v; j < n; j++)
            if ((rc = ascii_number(d, size, at, &index))) return rc;
    }
    return 0;
}

/* Assimp reads an ASCII body a line per item, so an item that runs onto the next line, or a line
 * with more numbers than its item, would be read out of step (a face's length taken from a
 * vertex's coordinate): each item must hold exactly its own line. */
static int walk_ascii(const char *path, const ply_header *h, const char *d, size_t size, err_buf *err)
{
    size_t at = h->body;
    uint32_t line = h->line;
    for (int e = 0; e < h->n_elements; e++) {
        const ply_element *el = &h->elements[e];
        for (uint64_t i = 0; i < el->count; i++, line++) {
            unsigned long long item = (unsigned long long)i + 1, count = (unsigned long long)el->count;
            if (at >= size)
                return err_at(err, ERR_INPUT, path, line, 1, "the file ends before item %llu of %llu of "
                              "element '%s'; the file is cut short", item, count, el->name);
            size_t from = at;
            int rc = ascii_item(el, d, size, &at);
            double extra;
            if (!rc && ascii_number(d, size, &at, &extra) != -1) rc = -4;
            uint32_t col = (uint32_t)(at - from) + 1;
            if (rc == -1)
                return err_at(err, ERR_INPUT, path, line, col, "item %llu of element '%s' ends before all its "
                              "numbers; each item of an ASCII PLY holds one whole line", item, el->name);
            if (rc == -2)
                return err_at(err, ERR_INPUT, path, line, col, "item %llu of element '%s' holds something "
                              "that is not a number (or a list length that is not a whole number up to "
                              "10^9)", item, el->name);
            if (rc == -3)
                return err_at(err, ERR_INPUT, path, line, 1, "face %llu lists no vertices; a face lists at "
                              "least one (three for a triangle)", item);
            if (rc == -4)
                return err_at(err, ERR_INPUT, path, line, col, "item %llu of element '%s' is followed by more "
                              "numbers on its line; each item of an ASCII PLY holds one whole line", item,
                              el->name);
            if (at < size) at++; /* past the line's '\n' */
        }
    }
    return 0;
}

int ply_check(const char *path, err_buf *err)
{
    FILE *f = fopen(path, "rb");
    if (!f) return err_fail(err, ERR_INPUT, "%s: cannot read the model: %s", path, strerror(errno));
    char *data = NULL;
    int rc = -1;
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (size < 0 || fseek(f, 0, SEEK_SET) != 0) {
        err_fail(err, ERR_INPUT, "%s: cannot read the model: %s", path, strerror(errno));
    } else if ((uint64_t)size > PLY_MAX_BYTES) {
        err_fail(err, ERR_LIMIT, "%s: the PLY file is %ld bytes; at most %llu are read", path, size,
                 (unsigned long long)PLY_MAX_BYTES);
    } else if (!(data = malloc((size_t)size + 1))) {
        err_nomem(err, "%s: out of memory reading %ld bytes", path, size);
    } else if (fread(data, 1, (size_t)size, f) != (size_t)size) {
        err_fail(err, ERR_INPUT, "%s: cannot read the model: a read error", path);
    } else {
        ply_header *h = malloc(sizeof *h);
        if (!h) err_nomem(err, "%s: out of memory for the PLY header", path);
        else if (!parse_header(path, data, (size_t)size, h, err))
            rc = h->format == PLY_ASCII ? walk_ascii(path, h, data, (size_t)size, err)
                                        : walk_binary(path, h, (const unsigned char *)data, (size_t)size, err);
        free(h);
    }
    free(data);
    fclose(f);
    return rc;
}
