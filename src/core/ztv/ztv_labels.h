/* ztv_labels.h — what a visibility map's page names besides the grid (ztv_map.h): the project
 * (the scene file's name), the DTM's file name, the day the map is made (SOURCE_DATE_EPOCH when
 * set, so a build can make the same bytes; else today, UTC), the targets' heights and the scene's
 * viewpoints (its viewpoints: section, then the study's points, numbered from 1 as the study's
 * sheets number them).
 *
 * Ownership: ztv_labels_fill allocates the viewpoints' arrays; ztv_labels_free releases them. The
 * names point into the scene file. */
#ifndef SYLVA_ZTV_LABELS_H
#define SYLVA_ZTV_LABELS_H

#include "scene_file/scene_file.h"
#include "util/err.h"
#include "ztv/ztv_raster.h"

typedef struct ztv_labels {
    char date[16];
    const char **names;     /* owned */
    double (*xy)[2];        /* owned */
} ztv_labels;

/* Fills l from sf and points info's label fields at it (l must outlive info's use). Returns 0, or
 * -1 with err set (out of memory). */
int ztv_labels_fill(ztv_labels *l, const scene_file *sf, ztv_info *info, err_buf *err);
void ztv_labels_free(ztv_labels *l); /* accepts a zeroed one */

#endif
