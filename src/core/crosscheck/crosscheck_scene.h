/* crosscheck_scene.h — `sylva crosscheck`'s pipeline on a built scene: the note a curved-Earth
 * scene needs, both renders compared (crosscheck_run) and the failure given its kind. */
#ifndef SYLVA_CROSSCHECK_SCENE_H
#define SYLVA_CROSSCHECK_SCENE_H

#include "crosscheck/crosscheck.h"

/* Compares s's two renders into out_dir. Returns a new result (free() it), or NULL with err set
 * and its kind stated (ERR_OUTPUT: a file or folder not written; ERR_NOMEM; ERR_INTERNAL:
 * POV-Ray missing or failing, anything else). */
crosscheck_result *crosscheck_scene(const scene *s, const char *out_dir, const crosscheck_options *o, err_buf *err);

#endif
