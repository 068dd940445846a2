/* ztv_features.h — what the GeoPackage beside a visibility map lists besides its cells
 * (docs/ztv.md, "The GeoPackage"): the study's viewpoints, each with its number, eye height,
 * heading and the ground under it, and the development's structures, each as placed with its
 * name, development and heights. Read from the scene file and the built scene; the ground is
 * the one the map traces (ztv_ground), never a rendering's.
 *
 * Ownership: ztv_features_gather allocates the two arrays; ztv_features_free releases them. The
 * names are borrowed from the scene file, which must outlive the features. */
#ifndef SYLVA_ZTV_FEATURES_H
#define SYLVA_ZTV_FEATURES_H

#include <stdint.h>

#include "scene/scene.h"
#include "util/err.h"
#include "ztv/ztv_raster.h"

struct scene_file; /* scene_file/scene_file.h */
struct viewpoint;  /* scene_file/scene_file_spec.h: a scene_viewpoint */

typedef struct ztv_features {
    ztv_viewpoint *viewpoints;   /* owned */
    uint32_t n_viewpoints;
    ztv_structure *structures;   /* owned */
    uint32_t n_structures;
} ztv_features;

/* The viewpoints views[0..n_views) in that order (NULL: the scene's viewpoints, then its points
 * file's, in file order) and the structures of every development object of s. Returns 0, or -1
 * with err set (out of memory). */
int ztv_features_gather(ztv_features *f, const struct scene_file *sf, const scene *s,
                        const struct viewpoint *const *views, uint32_t n_views, err_buf *err);
void ztv_features_free(ztv_features *f); /* accepts a zeroed one */

#endif
