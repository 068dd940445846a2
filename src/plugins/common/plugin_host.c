/* plugin_host.c — a plugin model's failure and random streams through the host's API table. */
#include "plugin_host.h"

int plugin_report(const sylva_host_api *api, sylva_host *host, const plugin_err *err)
{
    if (err->param[0]) api->param_error(host, err->where, err->param, "%s", err->msg);
    else api->error(host, "%s", err->msg);
    return err->status ? err->status : SYLVA_ERR_INTERNAL;
}

void plugin_host_stream(void *ctx, sylva_rng *rng, const char *purpose, uint64_t index)
{
    const plugin_host_ref *h = ctx;
    h->api->rng_init(h->host, rng, purpose, index);
}
