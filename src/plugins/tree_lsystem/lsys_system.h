/* lsys_system.h — an L-system as an L-parser file states it, and the reader for the two
 * dialects found in the wild:
 *
 *  numeric (Lparser 4): three numeric lines (recursion, angle in degrees, thickness in percent of
 *    the segment length), the axiom, one rule `X=successor` per line, a line starting with `@`
 *    (optional here) to end. `#` starts a comment; each line's payload is its first
 *    whitespace-delimited token.
 *  keyword (Lparser 2.1): `recursion`, `angle`, `thickness`, `min_thickness`, `shape`,
 *    `switch_yz`, `no_wait`, `poly_limit`, `mutation`, `color i r g b`, `axiom s` and
 *    `rule X = s` lines in any order; blanks inside axiom and successors are dropped.
 *
 * Every symbol of the axiom and the successors is checked: a byte that is neither a turtle
 * command, a rule variable nor part of an argument group "(number)" is an error naming
 * name:line:column — or, in lenient mode, is dropped with a warning through the callback.
 *
 * Ownership: lsys_read() returns a system the caller frees with lsys_system_free(); the system
 * owns its axiom, successors and name.
 */
#ifndef LSYS_SYSTEM_H
#define LSYS_SYSTEM_H

#include <stddef.h>
#include <stdint.h>

#include "lsys_status.h"

#define LSYS_FILE_MAX_BYTES (16u << 20) /* largest L-system text read */
#define LSYS_MAX_RECURSION 1000         /* largest recursion level accepted */
#define LSYS_MAX_FILE_COLOURS 256       /* colour indices a `color` line may set: 0..255 */

typedef enum lsys_dialect {
    LSYS_DIALECT_NUMERIC = 1, /* Lparser 4: numeric header lines */
    LSYS_DIALECT_KEYWORD = 2  /* Lparser 2.1: keyword lines */
} lsys_dialect;

typedef struct lsys_rule {
    int defined;                /* 1 when the file gives a rule for this byte */
    unsigned char *successor;   /* owned; NULL when empty (`X=_` or `X=`) */
    uint32_t length;            /* bytes of the successor */
    uint32_t line;              /* where the rule stands */
} lsys_rule;

typedef struct lsys_system {
    char *name;                 /* owned: the file name (or label) used in messages */
    lsys_dialect dialect;
    uint32_t recursion;         /* derivation steps */
    double angle_deg;           /* standard turning angle */
    double thickness;           /* first segment's width, percent of its length */
    double min_thickness;       /* lower bound of the width, percent of the length */
    int shape;                  /* -1: not given, 0: blocks (prisms), 1: joined cylinders */
    double base_length;         /* length of F at the start, in the file's units */
    uint32_t poly_limit;        /* polygon limit the file asks for; 0: none */
    unsigned char *axiom;       /* owned */
    uint32_t axiom_length;
    lsys_rule rules[256];       /* indexed by the predecessor byte */
    uint8_t colour_given[LSYS_MAX_FILE_COLOURS]; /* 1 where a `color` line set the index */
    float colour_srgb[LSYS_MAX_FILE_COLOURS][3]; /* 0..1, sRGB-encoded as written (0..255) */
} lsys_system;

typedef struct lsys_read_options {
    int lenient;                /* 1: unknown symbols and unsupported keywords become warnings */
    /* Receives each warning sentence (may be NULL: warnings are dropped). */
    void (*warn)(void *ctx, const char *sentence);
    void *warn_ctx;
} lsys_read_options;

/* Parses `len` bytes of L-system text; `name` labels messages (name:line:column). Returns
 * LSYS_OK with *out set, or a negative status with the sentence in err and *out NULL. */
int lsys_read(const char *text, size_t len, const char *name, const lsys_read_options *opt,
              lsys_system **out, plugin_err *err);

/* Reads the file at `path` (at most LSYS_FILE_MAX_BYTES) and parses it as lsys_read() does,
 * with the path as the name. */
int lsys_read_file(const char *path, const lsys_read_options *opt, lsys_system **out,
                   plugin_err *err);

void lsys_system_free(lsys_system *sys); /* accepts NULL */

#endif
