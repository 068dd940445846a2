/* study_ztv.h — the study's visibility map (docs/study.md, "The ZTV"): made once, from the scene
 * the study built, into DIR/ztv/ (the GeoTIFFs, maps, summary, GeoPackage and QGIS styles of
 * `sylva ztv`), with the record DIR/ztv/ztv.manifest as every product has: the sylva version,
 * the scene's digest (which holds the ztv: section), the seed, the day of the year, and each
 * viewpoint the GeoPackage numbers, with its camera. A rerun keeps a map whose files and record
 * are there.
 *
 * The map itself is drawn by the caller's function (the command line hands it ztv/'s
 * ztv_study_run), which must trace the ground as surveyed, as `sylva ztv` does, never the
 * study's refined ground: an analysis does not depend on how the views are rendered. */
#ifndef SYLVA_STUDY_ZTV_H
#define SYLVA_STUDY_ZTV_H

#include "scene/scene.h"
#include "scene_file/scene_file.h"
#include "study/study_views.h"
#include "util/err.h"
#include "util/phase_times.h"
#include "util/run_parts.h"

#define STUDY_ZTV_RECORD_MAX 65536

/* Maps the visibility of s's development into dir, the GeoPackage numbering views in order. */
typedef int (*study_ztv_fn)(void *user, const scene_file *sf, const scene *s, const study_views *views,
                            const char *dir, const run_parts *parts, phase_times *times, err_buf *err);

typedef struct study_ztv {
    study_ztv_fn map;   /* NULL: no map can be made (then a study asked for one is refused) */
    void *user;
} study_ztv;

/* The record of the map of sf with views into out (STUDY_ZTV_RECORD_MAX bytes). Returns 0, or
 * -1 with err set when it does not fit (too many viewpoints). */
int study_ztv_record(const scene_file *sf, const study_views *views, char *out, err_buf *err);
/* 1 when folder dir holds the map's files and a record that says text. */
int study_ztv_current(const char *dir, const char *text);
/* Makes the map into dir (created when missing) and, on part 0, its record after it. */
int study_ztv_make(const study_ztv *z, const scene_file *sf, const scene *s, const study_views *views,
                   const char *dir, const char *text, const run_parts *parts, phase_times *times, err_buf *err);

#endif
