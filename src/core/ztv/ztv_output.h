/* ztv_output.h — the files of a visibility map in its output folder (docs/ztv.md, "Outputs"):
 * per computed mode ztv_MODE.tif and ztv_MODE.png, per screened mode ztv_hidden_MODE.tif and
 * ztv_hidden_MODE.png, with several developments ztv_cumulative_MODE.png, and
 * ztv_summary.csv / ztv_summary.json, the GeoPackage ztv_layers.gpkg (viewpoints, distance rings,
 * structures; ztv_layers.h) and QGIS styles (ztv_qml.h): ztv_viewpoints.qml,
 * ztv_distance_rings.qml, ztv_developments.qml and ztv_MODE.qml beside each ztv_MODE.tif. The tracer hands the blocks of rows over as it makes
 * them; memory stays bounded whatever the grid (GeoTIFFs are streamed, the maps drawn from a
 * reduced copy, the summary counts). Every file is written under a temporary name and renamed
 * into place at the end, so an interrupted or failed run leaves nothing behind.
 *
 * Ownership: ztv_output_open returns an output that ztv_output_free releases. */
#ifndef SYLVA_ZTV_OUTPUT_H
#define SYLVA_ZTV_OUTPUT_H

#include "util/err.h"
#include "ztv/ztv_raster.h"

typedef struct ztv_output ztv_output;
/* Prepares the outputs of a map described by info into folder dir (which must exist): nothing is
 * visible in dir until ztv_output_finish. Returns NULL with err set. info and what it points to
 * must outlive the output. */
ztv_output *ztv_output_open(const char *dir, const ztv_info *info, err_buf *err);
/* Takes the next block of rows (blocks come north to south, each row exactly once). */
int ztv_output_block(ztv_output *o, const ztv_block *b, err_buf *err);
/* Writes what needs every row (maps, summary) and renames every file into place. */
int ztv_output_finish(ztv_output *o, err_buf *err);
void ztv_output_free(ztv_output *o); /* accepts NULL; removes the temporaries of an unfinished output */

#endif
