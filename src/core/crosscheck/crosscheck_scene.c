/* crosscheck_scene.c — both renders of a built scene compared (crosscheck_scene.h). */
#include "crosscheck/crosscheck_scene.h"

#include <stdio.h>
#include <stdlib.h>

crosscheck_result *crosscheck_scene(const scene *s, const char *out_dir, const crosscheck_options *o, err_buf *err)
{
    crosscheck_result *r = malloc(sizeof *r); /* owned by the caller */
    if (!r) {
        err_nomem(err, "out of memory");
        return NULL;
    }
    if (s->earth.curvature && !o->quiet)
        fprintf(stderr, "sylva crosscheck: note: POV-Ray cannot bend rays for the Earth's curvature "
                        "(earth.curvature is on); both renderers draw this scene on a flat Earth here\n");
    int status = crosscheck_run(s, out_dir, o, r, err);
    if (!status) return r;
    err_default(err, status == CROSSCHECK_NOT_WRITTEN ? ERR_OUTPUT : ERR_INTERNAL);
    free(r);
    return NULL;
}
