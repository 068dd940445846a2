/* plugin_params.h — the one way sylva's plugins read their parameters: a reader over a block
 * (the plugin's own, a GROUP value's ->group, a GROUP_LIST item, a species' ecology block) that
 * asks the host for each name through the checked reader of sylva/plugin.h. A name the schema
 * does not have is the plugin's misspelling: the host's error names it and the parameters the
 * schema has, and the host prints it at the block (file:line:column).
 *
 * The failure is sticky: the first one is kept in `status` (and in every enclosing reader), later
 * reads ask the host nothing and give a value with no elements whose first elements read as 0,
 * so a run of reads goes on without crashing and the caller checks `status` once after it.
 *
 * A reader without a host (api NULL: a block the plugin builds itself, or a model's test) looks
 * the name up alone and keeps the missing name in `missing`; nothing is printed.
 *
 * Lives on the caller's stack; borrows everything it points to. */
#ifndef PLUGIN_PARAMS_H
#define PLUGIN_PARAMS_H

#include <stdint.h>

#include "plugin_err.h"
#include "sylva/plugin.h"

typedef struct plugin_params {
    const sylva_host_api *api;   /* the host's table, or NULL: no host */
    sylva_host *host;
    const sylva_params *block;   /* the block read; NULL reads as a failure */
    int status;                  /* SYLVA_OK, or the first failure's status (SYLVA_ERR_INTERNAL) */
    char missing[64];            /* the first name the schema lacked, or "" */
    struct plugin_params *up;    /* the enclosing block's reader, told of a failure; NULL at the top */
} plugin_params;

/* A reader of `block` through the host of one call (api may be NULL: no host). */
plugin_params plugin_params_open(const sylva_host_api *api, sylva_host *host, const sylva_params *block);

/* A reader of a nested block (a group, a list item, a species block) whose failure is also
 * `outer`'s; outer must outlive it. */
plugin_params plugin_params_in(plugin_params *outer, const sylva_params *block);

/* The value of `name`: never NULL (after a failure, the empty value described above). */
const sylva_value *plugin_param(plugin_params *r, const char *name);

double plugin_param_real(plugin_params *r, const char *name);
int64_t plugin_param_int(plugin_params *r, const char *name);
const char *plugin_param_str(plugin_params *r, const char *name); /* NULL when absent */
int plugin_param_given(plugin_params *r, const char *name);       /* 1: the scene gave it */

/* api->param_error at key `name` of r's block, unless a read through r (or a reader nested in
 * it) has failed: then r's status is returned and nothing is said, so that the first failure's
 * sentence stands. Returns SYLVA_ERR_PARAM otherwise, for `return plugin_params_error(...)`. */
int plugin_params_error(plugin_params *r, const char *name, const char *fmt, ...) SYLVA_PRINTF(3, 4);

/* After a model read through r and filled err: r's failure when it had one (the host has its
 * sentence), else plugin_report() of err. */
int plugin_params_report(const plugin_params *r, const plugin_err *err);

#endif
