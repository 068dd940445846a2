/* scene_surveyed.h — a built scene as an analysis sees it: on the ground as surveyed. A scene
 * built for rendering (its terrain refined, `sylva study`) keeps the surveyed ground beside it;
 * this view takes that ground as its terrain and stands the plants the build set on the refined
 * ground (their base at its height) on the surveyed ground instead, where a build for an
 * analysis (build_options.analysis, `sylva ztv`) stands them. Objects already stand on the
 * surveyed ground in either build. So a visibility map of the view is the map of the scene,
 * whatever the rendering refined.
 *
 * Ownership: the view borrows everything of the scene but its instances, a copy that
 * scene_surveyed_free releases; the scene must outlive the view and not change meanwhile. */
#ifndef SYLVA_SCENE_SURVEYED_H
#define SYLVA_SCENE_SURVEYED_H

#include "scene/scene.h"
#include "util/err.h"

#define SCENE_ON_GROUND_TOLERANCE 1e-3 /* metres: a plant's base this near the ground stands on it */

typedef struct scene_surveyed {
    scene view;            /* read only: what an analysis traces */
    instance *instances;   /* owned: the view's instances */
    uint32_t moved;        /* plants moved onto the surveyed ground */
} scene_surveyed;

/* Fills out with s seen on its surveyed ground. Returns 0, or -1 with err set (out of memory). */
int scene_surveyed_view(const scene *s, scene_surveyed *out, err_buf *err);
void scene_surveyed_free(scene_surveyed *v); /* accepts a zeroed one */

#endif
