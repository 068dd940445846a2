/* lsys_status.h — the statuses of the L-system model, by the names its code fails with. Each is
 * a sylva_status, so that a failing function returns one and fills a plugin_err (the one error
 * type of the plugins, plugin_err.h) with the sentence; the plugin entry hands the sentence to
 * api->error(). */
#ifndef LSYS_STATUS_H
#define LSYS_STATUS_H

#include "plugin_err.h"

enum {
    LSYS_OK = SYLVA_OK,
    LSYS_ERR_SYNTAX = SYLVA_ERR_PARAM, /* the L-system text is wrong (file:line:column in the sentence) */
    LSYS_ERR_LIMIT = SYLVA_ERR_LIMIT,  /* a documented limit was reached (the sentence names it) */
    LSYS_ERR_NOMEM = SYLVA_ERR_NOMEM,  /* an allocation failed */
    LSYS_ERR_IO = SYLVA_ERR_IO,        /* a file could not be read */
    LSYS_ERR_SINK = SYLVA_ERR_INTERNAL /* the geometry consumer refused (its own sentence is kept) */
};

#endif
