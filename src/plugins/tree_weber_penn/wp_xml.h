/* wp_xml.h — the small subset of XML that species files use, read into a tree: elements,
 * attributes in single or double quotes, text (the five named entities decoded), comments, and
 * a leading <?xml ...?> declaration taken as it comes (Helios writes `<?xml version=1.0?>`).
 * DOCTYPE, CDATA and other processing instructions are refused. Every node keeps its line and
 * column; malformed input is refused with `file:line:column: what is wrong, what would be
 * valid`; the input's size, the nesting depth and the node count are limited. */
#ifndef WP_XML_H
#define WP_XML_H

#include <stddef.h>

#include "plugin_err.h"

#define WP_XML_MAX_BYTES (4u << 20) /* input size */
#define WP_XML_MAX_DEPTH 32         /* elements inside elements */
#define WP_XML_MAX_NODES 100000     /* elements and attributes together */

typedef struct wp_xml_attr {
    char *name, *value;          /* owned */
    int line, col;               /* of the name */
    int value_line, value_col;   /* of the value's first character */
    struct wp_xml_attr *next;    /* owned */
} wp_xml_attr;

typedef struct wp_xml_node {
    char *name;                  /* owned */
    int line, col;               /* of the '<' */
    wp_xml_attr *attrs;          /* owned list, in file order */
    char *text;                  /* owned: the element's own text, pieces joined; "" when none */
    int text_line, text_col;     /* of the first non-blank text character (else of the '>') */
    struct wp_xml_node *children, *next; /* owned list, in file order */
} wp_xml_node;

/* Reads buf[0..len) (named `file` in messages) into *root. Returns 0, or a negative
 * sylva_status with err's sentence set and *root NULL. */
int wp_xml_parse(const char *file, const char *buf, size_t len, wp_xml_node **root, plugin_err *err);

/* Frees a tree from wp_xml_parse (NULL: nothing). */
void wp_xml_free(wp_xml_node *root);

/* The attribute `name` of n, or NULL. */
const wp_xml_attr *wp_xml_attr_find(const wp_xml_node *n, const char *name);

#endif
