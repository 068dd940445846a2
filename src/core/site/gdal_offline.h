/* gdal_offline.h — a GDAL dataset (raster or vector) opened quietly and without network access:
 * the thread's /vsicurl/ sees one impossible file name and every HTTP fetch is refused while the
 * file is open, and GDAL's own messages are kept off stderr (the caller writes its sentence).
 *
 * Ownership: gdal_offline_open returns a dataset that gdal_offline_close closes, putting back
 * the thread's settings; every open is closed on the thread that opened it. */
#ifndef SYLVA_GDAL_OFFLINE_H
#define SYLVA_GDAL_OFFLINE_H

#include <gdal.h>

typedef struct gdal_offline {
    char *saved_allowed; /* the thread's CPL_VSIL_CURL_ALLOWED_FILENAME before the open (CPLFree'd) */
} gdal_offline;

/* Opens path with GDALOpenEx's flags (GDAL_OF_RASTER, GDAL_OF_VECTOR; read-only is added).
 * Returns the dataset or NULL (not a file GDAL reads); either way call gdal_offline_close. */
GDALDatasetH gdal_offline_open(const char *path, unsigned flags, gdal_offline *g);
/* Closes ds (may be NULL) and restores what gdal_offline_open changed. */
void gdal_offline_close(GDALDatasetH ds, gdal_offline *g);

#endif
