/* ztv_geotiff.h — one GeoTIFF of a visibility map, written a block of rows at a time through
 * GDAL: Float32 bands on the map's grid (the geotransform of ztv_raster.h) and the site's CRS,
 * band descriptions, nodata ZTV_GEOTIFF_NODATA, DEFLATE-compressed strips of one row. Memory
 * stays that of one block of rows whatever the grid's size.
 *
 * The file is written under a new temporary name beside the target (io/atomic_file.h: created
 * with O_EXCL|O_NOFOLLOW, removed on failure and on SIGINT/SIGTERM) and only
 * ztv_geotiff_commit renames it into place; a link planted at the target is replaced, never
 * written through.
 *
 * Ownership: ztv_geotiff_open returns a writer that ztv_geotiff_free releases (removing the
 * temporary unless it was committed); it keeps info, which must outlive it. */
#ifndef SYLVA_ZTV_GEOTIFF_H
#define SYLVA_ZTV_GEOTIFF_H

#include <stdint.h>

#include "util/err.h"
#include "ztv/ztv_raster.h"

#define ZTV_GEOTIFF_NODATA (-1.0f) /* no band of a visibility map holds a negative value */
#define ZTV_GEOTIFF_MAX_BANDS 4u

typedef struct ztv_geotiff ztv_geotiff;

/* Creates the temporary for path with `bands` bands named by descriptions. NULL with err set. */
ztv_geotiff *ztv_geotiff_open(const char *path, const ztv_info *info, uint32_t bands,
                              const char *const *descriptions, err_buf *err);
/* Writes grid rows [j0, j0 + rows): values holds bands planes of rows * nx floats, band after
 * band, row 0 the northernmost. */
int ztv_geotiff_rows(ztv_geotiff *g, uint32_t j0, uint32_t rows, const float *values, err_buf *err);
/* Lets GDAL finish the file, still under its temporary name (every row must have been
 * written). */
int ztv_geotiff_finish(ztv_geotiff *g, err_buf *err);
/* Renames the finished file into place. */
int ztv_geotiff_commit(ztv_geotiff *g, err_buf *err);
void ztv_geotiff_free(ztv_geotiff *g); /* accepts NULL */

#endif
