/* ztv_labels.h — what a visibility map's page names besides the grid (ztv_map.h): the project
 * (the scene file's name), the DTM's file name, the day the map is made (SOURCE_DATE_EPOCH when
 * set, so a build can make the same bytes; else today, UTC) and the targets' heights. The
 * viewpoints the map marks are info's study_views (ztv_features.h).
 *
 * Ownership: nothing is allocated; the names point into the scene file and into l. */
#ifndef SYLVA_ZTV_LABELS_H
#define SYLVA_ZTV_LABELS_H

#include "scene_file/scene_file.h"
#include "util/err.h"
#include "ztv/ztv_raster.h"

typedef struct ztv_labels {
    char date[16];
} ztv_labels;

/* Fills l from sf and points info's label fields at it (l must outlive info's use). */
void ztv_labels_fill(ztv_labels *l, const scene_file *sf, ztv_info *info);

#endif
