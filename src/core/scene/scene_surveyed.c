/* scene_surveyed.c — a built scene on its ground as surveyed (scene_surveyed.h). */
#include "scene/scene_surveyed.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/heightfield.h"

int scene_surveyed_view(const scene *s, scene_surveyed *out, err_buf *err)
{
    memset(out, 0, sizeof *out);
    out->view = *s;
    if (!s->surveyed || s->terrain == s->surveyed) return 0;
    out->view.terrain = s->surveyed;
    out->instances = malloc((s->n_instances ? s->n_instances : 1) * sizeof *out->instances);
    if (!out->instances) return err_nomem(err, "out of memory for %u plants on the surveyed ground", s->n_instances);
    memcpy(out->instances, s->instances, s->n_instances * sizeof *out->instances);
    for (uint32_t k = 0; k < s->n_instances; k++) {
        const xform3x4 *xf = &s->instances[k].xf;
        double x = xf->m[0][3], y = xf->m[1][3], rendered, surveyed;
        if (heightfield_height(s->terrain, x, y, &rendered) || heightfield_height(s->surveyed, x, y, &surveyed))
            continue;
        if (fabs(xf->m[2][3] - rendered) > SCENE_ON_GROUND_TOLERANCE) continue;
        out->instances[k].xf.m[2][3] = (float)surveyed;
        out->moved++;
    }
    out->view.instances = out->instances;
    return 0;
}

void scene_surveyed_free(scene_surveyed *v)
{
    free(v->instances);
    memset(v, 0, sizeof *v);
}
