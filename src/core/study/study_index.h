/* study_index.h — the study's index, DIR/index.html (docs/study.md, "The index"): one page that
 * needs no network (no script, font or style sheet from elsewhere; its style inline), holding
 * the study's visibility map with each viewpoint a numbered, clickable mark at its place, and a
 * table of the viewpoints: number, name, easting and northing, distance and bearing to the
 * nearest structure of the development, and a link to each of its files there is (sheets
 * sheet_FRAME.pdf and .png, images PRODUCT_FRAME.png). It lists what is on disk when it is
 * written, so it is written last, by every run; a file that already says the same is left as is.
 *
 * The marks stand on the map page's picture DIR/ztv/ztv_MODE.png (the screened mode's, else bare
 * earth's) where its world file ztv_MODE.pgw (the map coordinates of its pixels, written by the
 * map beside it, ztv/ztv_map.h) places them, each a ring round the page's own numbered dot, the
 * page's PNG and PDF linked under it; without one, on a key map of the viewpoints and structures
 * the page draws itself (SVG). */
#ifndef SYLVA_STUDY_INDEX_H
#define SYLVA_STUDY_INDEX_H

#include "scene_file/scene_file.h"
#include "study/study_views.h"
#include "util/err.h"

/* Writes dir/index.html for the viewpoints views of sf (numbered in their order). Returns 0, or -1
 * with err set. */
int study_index_write(const scene_file *sf, const study_views *views, const char *dir, err_buf *err);

#endif
