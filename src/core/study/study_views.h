/* study_views.h — the viewpoints a study renders, in rank order: those the command line names
 * (--viewpoints), else the study: section's, else every viewpoint of the scene and then every
 * point of its points file, in file order; kept to --only's names when given; with --rank's
 * names first, in its order. A name is a folder of the output, so it may hold no '/' nor a
 * control character and may not be "." or "..". */
#ifndef SYLVA_STUDY_VIEWS_H
#define SYLVA_STUDY_VIEWS_H

#include <stdint.h>

#include "scene_file/scene_file.h"
#include "util/err.h"

/* Names as the command line gives them: separated by commas or spaces; NULL: not given. */
typedef struct study_view_names {
    const char *viewpoints, *only, *rank;
} study_view_names;

typedef struct study_views {
    const scene_viewpoint **views; /* into sf; the array owned (study_views_free) */
    uint32_t n;
} study_views;

/* Fills out with sf's viewpoints as names picks them. Returns 0, or -1 with err set (ERR_USAGE: a
 * name the scene does not have, a name that cannot be a folder, no viewpoint at all). */
int study_views_pick(const scene_file *sf, const study_view_names *names, study_views *out, err_buf *err);
void study_views_free(study_views *v); /* accepts a zeroed one */

#endif
