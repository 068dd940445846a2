/* validate.h — checking a YAML mapping against a parameter schema (sylva_param_spec table) and
 * producing the validated sylva_params a plugin or the scene loader reads.
 *
 * Every key of the mapping must be a parameter of the schema or one of the scope's host keys
 * (keys another schema owns in the same mapping; they are skipped here). Every value must have
 * its parameter's type and lie in its range; required parameters must be present; absent ones
 * take their defaults. The first problem in file order stops validation with
 * "file:line:column: message", naming what was expected ("did you mean 'width'?" for a near
 * miss, the list of valid keys or choices otherwise).
 *
 * Value rules (see docs/scene-file.md): numbers are plain YAML scalars (a quoted "5" is a
 * string, not a number); BOOL takes true/false/yes/no; INT takes integral numbers of magnitude
 * up to 2^53 and sets both .i and .r; REAL sets .r; PATH is resolved against scope->dir to an
 * absolute path (existence is not checked); POLYLINE x values never decrease; GRID rows have
 * one length.
 *
 * Ownership: everything produced lives in the arena passed in.
 */
#ifndef SYLVA_PARAMS_VALIDATE_H
#define SYLVA_PARAMS_VALIDATE_H

#include <stdint.h>

#include "params/yaml_doc.h"
#include "sylva/plugin.h"
#include "util/arena.h"
#include "util/err.h"

#define PARAM_INT_LIMIT 9007199254740992.0 /* 2^53: larger integers are refused */

typedef struct param_scope {
    const char *file;              /* file name for messages and sylva_params.file */
    const char *dir;               /* absolute folder PATH values resolve against */
    const char *where;             /* the block's name in messages: "image", "species.beech" */
    const char *const *host_keys;  /* extra keys allowed in the mapping and skipped */
    uint32_t n_host_keys;
    uint32_t line, column;         /* where the block is named; used when the mapping is absent */
} param_scope;

/* Validates `map` (a mapping node; NULL or a YAML null for an absent or empty block, which
 * gives all defaults) against spec[0..n). On success *out points to a sylva_params in `a` with
 * n values in schema order and returns 0; otherwise returns -1 with err set. */
int params_validate(arena *a, const ynode *map, const sylva_param_spec *spec, uint32_t n,
                    const param_scope *scope, const sylva_params **out, err_buf *err);

/* Reads one value node against one spec (what params_validate does per key). `where` in scope
 * names the enclosing block. Returns 0 or -1 with err set. */
int param_value_read(arena *a, const ynode *node, const sylva_param_spec *spec,
                     const param_scope *scope, sylva_value *out, err_buf *err);

/* The default value of one spec (GROUP: a group of defaults, which fails with err set when the
 * group has required members). Returns 0 or -1. */
int param_value_default(arena *a, const sylva_param_spec *spec, const param_scope *scope,
                        sylva_value *out, err_buf *err);

/* `rel` resolved against the absolute folder `dir`: rel itself when absolute, otherwise
 * dir/rel with leading "./" segments dropped. NULL when out of memory. */
const char *param_resolve_path(arena *a, const char *dir, const char *rel);

/* Writes the range of spec as a phrase (" >= 1", " in [1, 16384]", " in (-1, 1)", or "" when
 * unbounded) into buf. */
void param_range_phrase(const sylva_param_spec *spec, char *buf, size_t size);

/* The candidate nearest to `name` by edit distance when it is close enough to be a likely
 * misspelling (util/edit_distance.h's limit, and fewer edits than the candidate's length), else
 * NULL. Ties go to the earlier candidate; NULL candidates are skipped. */
const char *param_nearest_name(const char *name, const char *const *candidates, size_t n);

#endif
