/* scene_mark.h — the scene as it stands, marked so that what is added after the mark can be
 * taken out again: a study draws one built scene from many cameras, and each camera's ground
 * cover (geometry/ground_cover_place.h: its materials, species, prototypes and tufts) is added
 * for that camera and taken out before the next, leaving the scene as the build made it.
 *
 * Only appended elements are taken out; a mark says nothing of elements changed in place. */
#ifndef SYLVA_SCENE_MARK_H
#define SYLVA_SCENE_MARK_H

#include <stdint.h>

#include "scene/scene.h"
#include "util/err.h"

typedef struct scene_mark {
    uint32_t materials, textures, species, prototypes, instances, objects, models;
} scene_mark;

/* The counts of s's arrays now. */
scene_mark scene_mark_take(const scene *s);

/* Frees and drops every element added to s after m (a mark of s taken earlier, with nothing
 * taken out since), so that s holds what it held at the mark and adding the same elements again
 * gives them the same indices. Returns 0, or -1 with err set when the material names cannot be
 * indexed again (out of memory; the scene's material lookup is then empty). */
int scene_rewind(scene *s, const scene_mark *m, err_buf *err);

#endif
