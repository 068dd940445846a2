/* plugin_params.c — a plugin's checked, sticky reading of its parameter blocks (plugin_params.h). */
#include "plugin_params.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "plugin_host.h"

/* What a read gives after a failure: not set, no elements, and a list whose first elements
 * (as many as a VEC3 or a pair is read by) are 0. */
static const double no_elements[4] = {0, 0, 0, 0};
static const sylva_value no_value = {.list = no_elements};

plugin_params plugin_params_open(const sylva_host_api *api, sylva_host *host, const sylva_params *block)
{
    return (plugin_params){.api = api, .host = host, .block = block};
}

plugin_params plugin_params_in(plugin_params *outer, const sylva_params *block)
{
    plugin_params r = plugin_params_open(outer->api, outer->host, block);
    r.up = outer;
    return r;
}

/* The status of the first failure seen by r or a reader it is nested in; SYLVA_OK when none. */
static int failure(const plugin_params *r)
{
    for (; r; r = r->up)
        if (r->status) return r->status;
    return SYLVA_OK;
}

static void fail(plugin_params *r, const char *name)
{
    for (; r; r = r->up) {
        if (r->status) continue;
        r->status = SYLVA_ERR_INTERNAL;
        snprintf(r->missing, sizeof r->missing, "%s", name);
    }
}

/* Without a host: the value of `name` in block, or NULL. */
static const sylva_value *look_up(const sylva_params *block, const char *name)
{
    for (uint32_t k = 0; k < block->n; k++)
        if (!strcmp(block->spec[k].name, name)) return &block->values[k];
    return NULL;
}

const sylva_value *plugin_param(plugin_params *r, const char *name)
{
    if (failure(r)) return &no_value;
    const sylva_value *v = NULL;
    if (!r->block) {
        if (r->api) r->api->error(r->host, "the plugin read parameter '%s' of a block it does not have", name);
    } else {
        v = r->api ? sylva_param_get(r->api, r->host, r->block, name) : look_up(r->block, name);
    }
    if (v) return v;
    fail(r, name);
    return &no_value;
}

double plugin_param_real(plugin_params *r, const char *name) { return plugin_param(r, name)->r; }
int64_t plugin_param_int(plugin_params *r, const char *name) { return plugin_param(r, name)->i; }
const char *plugin_param_str(plugin_params *r, const char *name) { return plugin_param(r, name)->s; }
int plugin_param_given(plugin_params *r, const char *name) { return plugin_param(r, name)->is_set; }

int plugin_params_error(plugin_params *r, const char *name, const char *fmt, ...)
{
    int rc = failure(r);
    if (rc) return rc;
    char msg[2048]; /* the host's own sentence length */
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return r->api->param_error(r->host, r->block, name, "%s", msg);
}

int plugin_params_report(const plugin_params *r, const plugin_err *err)
{
    if (r->status) return r->status;
    return plugin_report(r->api, r->host, err);
}
