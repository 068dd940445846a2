/* yaml_doc.h — a YAML file read into a small tree of nodes (scalar, sequence, mapping), each
 * with its 1-based line and column, for the scene loader to validate with exact locations.
 *
 * What it accepts: one YAML document whose mapping keys are plain or quoted scalars. What it
 * refuses, with "file:line:column: message": libyaml's syntax problems (suffixed
 * "(YAML syntax)"), a key given twice in one mapping, anchors and aliases, explicit tags, a
 * second document, and the limits below. It does not interpret scalars: "5", "true" and "~" are
 * all text here; the validator decides what they mean.
 *
 * Ownership: every node and string lives in the arena the caller passes in.
 */
#ifndef SYLVA_YAML_DOC_H
#define SYLVA_YAML_DOC_H

#include <stddef.h>
#include <stdint.h>

#include "util/arena.h"
#include "util/err.h"

#define YAML_DOC_MAX_FILE_BYTES ((size_t)64 << 20) /* larger files are refused */
#define YAML_DOC_BYTES_PER_BYTE 60u /* memory to load a file, per byte of it (estimate) */
#define YAML_DOC_MAX_DEPTH 64                      /* nested sequences/mappings */
#define YAML_DOC_MAX_SCALAR_BYTES ((size_t)1 << 16) /* one scalar's text */

typedef enum ynode_kind { YNODE_SCALAR = 1, YNODE_SEQUENCE = 2, YNODE_MAPPING = 3 } ynode_kind;

typedef struct ynode ynode;

typedef struct ynode_pair {
    const char *key;
    uint32_t key_line, key_column;
    const ynode *value;
} ynode_pair;

struct ynode {
    ynode_kind kind;
    uint32_t line, column;     /* where the node starts, 1-based */
    /* YNODE_SCALAR */
    const char *text;          /* NUL-terminated; may hold no NUL inside (refused on reading) */
    size_t text_len;
    int quoted;                /* 1: quoted or block scalar (always a string); 0: plain */
    /* YNODE_SEQUENCE */
    const ynode *const *items;
    uint32_t n_items;
    /* YNODE_MAPPING, keys in file order, unique */
    const ynode_pair *pairs;
    uint32_t n_pairs;
};

typedef struct yaml_doc {
    const char *file;          /* the name used in messages (as the caller gave it) */
    const ynode *root;         /* NULL when the file holds no document (empty or comments) */
} yaml_doc;

#define YAML_DOC_UNREADABLE (-2) /* yaml_doc_load: the file could not be opened or read */

/* Reads `path` and builds its tree in `a`. `file_label` names the file in messages (NULL: the
 * path). Returns 0 and fills *doc; YAML_DOC_UNREADABLE with err "file: reason" when the file
 * cannot be opened, is not a regular file, is too large or fails to read; or -1 with err
 * "file:line:column: message" for a problem in its text. */
int yaml_doc_load(arena *a, const char *path, const char *file_label, yaml_doc *doc,
                  err_buf *err);
/* The same for text already in memory (len bytes). */
int yaml_doc_parse(arena *a, const char *text, size_t len, const char *file_label, yaml_doc *doc,
                   err_buf *err);

/* The value under `key` in a mapping, or NULL (also when map is NULL or not a mapping). */
const ynode *ynode_get(const ynode *map, const char *key);
/* The pair under `key`, or NULL. */
const ynode_pair *ynode_get_pair(const ynode *map, const char *key);
/* 1 when the node is a plain scalar that YAML reads as null: empty, "~", "null", "Null", "NULL". */
int ynode_is_null(const ynode *n);
/* "a mapping", "a sequence", "a string", "nothing" — for messages. */
const char *ynode_kind_phrase(const ynode *n);

#endif
