/* scene_ground.h — heights given above the ground, resolved once the terrain is built: the
 * camera's eye height (and a look_at on or above the ground), and any point placed by
 * height_above_ground. A point with no terrain under it is an error located where its height
 * was given. */
#ifndef SYLVA_SCENE_GROUND_H
#define SYLVA_SCENE_GROUND_H

#include "scene/scene.h"
#include "scene_file/scene_file.h"

/* Sets p[2] to the terrain height at (p[0], p[1]) plus g->above; nothing unless g->given.
 * `what` names the point in messages ("the camera 'position'"). Returns 0, or -1 with err set
 * at sf's file, g's line and column. */
int scene_ground_point(const scene *s, const scene_file *sf, const char *what, const ground_height *g,
                       double p[3], err_buf *err);

/* Resolves s->camera's heights above ground and then its viewing direction (toward look_at),
 * which must not be zero nor parallel to up. Returns 0 or -1 with err set. */
int scene_ground_camera(scene *s, const scene_file *sf, err_buf *err);

#endif
