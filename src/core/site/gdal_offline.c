/* gdal_offline.c — GDAL's C API opened with the network shut for the calling thread
 * (gdal_offline.h). */
#include "site/gdal_offline.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_http.h>

static CPLHTTPResult *refuse_fetch(const char *url, CSLConstList options, GDALProgressFunc progress,
                                   void *progress_arg, CPLHTTPFetchWriteFunc write, void *write_arg,
                                   void *user)
{
    (void)url, (void)options, (void)progress, (void)progress_arg, (void)write, (void)write_arg, (void)user;
    CPLHTTPResult *r = CPLCalloc(1, sizeof *r); /* freed by GDAL */
    r->nStatus = 1;
    r->pszErrBuf = CPLStrdup("sylva reads the site's files without network access");
    return r;
}

GDALDatasetH gdal_offline_open(const char *path, unsigned flags, gdal_offline *g)
{
    GDALAllRegister();
    const char *old = CPLGetThreadLocalConfigOption("CPL_VSIL_CURL_ALLOWED_FILENAME", NULL);
    g->saved_allowed = CPLStrdup(old ? old : "");
    CPLSetThreadLocalConfigOption("CPL_VSIL_CURL_ALLOWED_FILENAME", "sylva-network-is-off:");
    CPLHTTPPushFetchCallback(refuse_fetch, NULL);
    CPLPushErrorHandler(CPLQuietErrorHandler);
    return GDALOpenEx(path, flags | GDAL_OF_READONLY, NULL, NULL, NULL);
}

void gdal_offline_close(GDALDatasetH ds, gdal_offline *g)
{
    if (ds) GDALClose(ds);
    CPLPopErrorHandler();
    CPLHTTPPopFetchCallback();
    const char *saved = g->saved_allowed;
    CPLSetThreadLocalConfigOption("CPL_VSIL_CURL_ALLOWED_FILENAME", saved && saved[0] ? saved : NULL);
    CPLFree(g->saved_allowed);
    g->saved_allowed = NULL;
}
