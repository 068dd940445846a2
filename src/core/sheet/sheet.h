/* sheet.h — a study's sheet for one viewpoint in one frame (docs/study.md, Sheets): one page, A3
 * landscape unless the study gives a print width (then that wide, in A-series proportions),
 * written as a vector PDF and a PNG of the same page (page.h). On it:
 *
 *   a title line: the viewpoint's number and name, the frame, the project (the scene file);
 *   the proposed view large, the existing view and the wireline beside each other under it, each
 *   embedded at the print resolution and captioned with its printed size and the distance to
 *   hold it from;
 *   the location map (sheet_map.h);
 *   the facts of sheet_view.h as a table, with the visualisation Type, the print size and the
 *   verification sylva has (camera-match residuals: none without a photograph; the POV-Ray
 *   cross-check: not run within a study), and a note when the frame does not hold the whole
 *   development, saying what the study did.
 *
 * The page is laid out at A3 (420 x 297 mm) and scaled to the print width. The wireline is drawn
 * as vector strokes over the existing view (sheet_wireline.h): the outline and inner edges that
 * render/wireline.h finds in the rendered pixels, traced into polylines.
 *
 * A photomontage's sheet (sheet.photo set, `sylva montage`) is the same page with the photomontage
 * as the proposed view, the photograph as the existing one and the wireline over the photograph;
 * its title names the photograph and its Type (3 or 4), and its table states the photograph's
 * EXIF and camera match (sheet_table.h). Nothing is kept: the caller owns every field. */
#ifndef SYLVA_SHEET_H
#define SYLVA_SHEET_H

#include "page/page.h"
#include "sheet/sheet_content.h"
#include "util/err.h"

/* The page of a sheet print_width_mm wide (0: A3 landscape) at dpi. */
page_size sheet_page_size(double print_width_mm, double dpi);

/* Writes sh as pdf_path and png_path. Returns 0, or -1 with err set and nothing written. */
int sheet_write(const sheet *sh, const char *pdf_path, const char *png_path, err_buf *err);

#endif
