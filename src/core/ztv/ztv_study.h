/* ztv_study.h — a whole zone-of-theoretical-visibility study of a built scene (docs/ztv.md):
 * the targets, the grid, the sightlines traced on bare earth and screened, the GeoTIFFs, PNG
 * maps and summary written into a folder. Split between the parts of a job (util/run_parts.h),
 * each part traces every N-th row and part 0 writes the files. */
#ifndef SYLVA_ZTV_STUDY_H
#define SYLVA_ZTV_STUDY_H

#include "scene/scene.h"
#include "util/err.h"
#include "util/phase_times.h"
#include "util/run_parts.h"

struct scene_file; /* scene_file/scene_file.h: the ztv: section and the site read here */
struct viewpoint;  /* scene_file/scene_file_spec.h: a scene_viewpoint */

typedef struct ztv_study_options {
    const char *dir;     /* the output folder; created when missing */
    double radius;       /* NAN: the scene's ztv.radius; 0: the whole terrain */
    double cell;         /* NAN: the scene's ztv.cell */
    double eye;          /* NAN: the scene's ztv.observer_height */
    int screening;       /* a ztv_mode, or -1: the scene's */
    int flat_earth;      /* 1: straight sightlines */
    int sightlines;      /* 1: bare earth by sightlines too, not by the sweep (ztv/ztv_job.h) */
    unsigned threads;
    int quiet;           /* no information lines (the warnings still print) */
    const struct viewpoint *const *views; /* the viewpoints the GeoPackage lists, numbered in this
                                           * order; NULL: the scene's, then its points file's */
    uint32_t n_views;
    const char *planting_before; /* a planting plan's year (`--years`): the folder of the map made
                                  * before the plan, for the map of what it hides; NULL otherwise */
    double planting_year;        /* years since planting, with planting_before */
    unsigned products;           /* ZTV_PRODUCT_* bits (ztv/ztv_raster.h): the files written; 0: all */
} ztv_study_options;

/* Runs the study of sc (built from sf with the ground it is to trace), printing its information
 * lines on stderr and adding its phases to times. Returns 0, or -1 with err set (its kind
 * stated), or -1 with err empty when another part failed (parts->agree reported it). */
int ztv_study_run(const struct scene_file *sf, const scene *sc, const ztv_study_options *o, const run_parts *parts,
                  phase_times *times, err_buf *err);

#endif
