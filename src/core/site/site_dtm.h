/* site_dtm.h — what the site needs to know of a DTM file before any plugin reads it: its
 * coordinate reference system and the centre of its footprint, read through GDAL.
 *
 * Only local regular files are read (GDAL's virtual paths and connection strings are refused),
 * and GDAL runs with its network access shut for the calling thread, so naming a DTM never
 * reaches the network. Pixels are not read.
 *
 * Ownership: site_dtm_read fills a site_dtm whose strings site_dtm_release frees. */
#ifndef SYLVA_SITE_DTM_H
#define SYLVA_SITE_DTM_H

#include "util/err.h"

typedef struct site_dtm {
    char *crs_wkt;     /* the DTM's CRS as WKT (malloc'ed), or NULL when the file names none */
    char *crs_name;    /* its name (malloc'ed), or NULL */
    int geographic;    /* 1: the CRS is in degrees (longitude, latitude) */
    double centre[2];  /* centre of the footprint in the DTM's CRS, x then y (GIS order) */
} site_dtm;

/* Reads path's CRS and footprint. Returns 0, or -1 with err set ("the DTM 'path': ..."). */
int site_dtm_read(const char *path, site_dtm *out, err_buf *err);
void site_dtm_release(site_dtm *d); /* accepts a zeroed site_dtm */

/* GDAL quiet (its messages kept for CPLGetLastErrorMsg, none on stderr) and offline (every HTTP
 * fetch refused, /vsicurl/ shut) on the calling thread between begin and end, which restores
 * what was there; every file that site/ reads through GDAL is opened between the two. */
typedef struct gdal_offline {
    char *saved_curl; /* CPLStrdup'ed; freed by end */
} gdal_offline;
void site_gdal_offline_begin(gdal_offline *g);
void site_gdal_offline_end(gdal_offline *g);

#endif
