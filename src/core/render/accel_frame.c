/* accel_frame.c — the frame of the Embree scene near the camera (accel_frame.h). */
#include "render/accel_frame.h"

#include <math.h>
#include <string.h>

void accel_frame_near(const double eye[3], double frame[3])
{
    for (int k = 0; k < 2; k++) frame[k] = isfinite(eye[k]) ? ACCEL_FRAME_STEP * round(eye[k] / ACCEL_FRAME_STEP) : 0.0;
    frame[2] = 0.0;
}

int accel_framed(const accel *a)
{
    return a->frame[0] != 0.0 || a->frame[1] != 0.0 || a->frame[2] != 0.0;
}

xform3x4 accel_frame_xf(const accel *a, const xform3x4 *xf)
{
    xform3x4 f = *xf;
    for (int r = 0; r < 3; r++) f.m[r][3] = (float)((double)xf->m[r][3] - a->frame[r]);
    return f;
}

void accel_frame_point(const accel *a, float p[3])
{
    for (int k = 0; k < 3; k++) p[k] = (float)((double)p[k] - a->frame[k]);
}

vec3 accel_frame_world(const accel *a, vec3 p)
{
    return v3((float)(p.x + a->frame[0]), (float)(p.y + a->frame[1]), (float)(p.z + a->frame[2]));
}

void accel_frame_mesh_in_place(const accel *a, mesh *m)
{
    if (!m || !accel_framed(a)) return;
    for (uint32_t v = 0; v < m->nv; v++) accel_frame_point(a, m->pos + (size_t)v * 3);
}

mesh *accel_frame_mesh(const accel *a, const mesh *m, err_buf *err)
{
    mesh *f = mesh_new(); /* owned by the caller */
    if (!f || mesh_append(f, m->pos, m->nrm, m->uv, m->nv, m->tri, m->mat, -1, m->nt, err)) {
        mesh_free(f);
        if (!f) err_nomem(err, "out of memory moving a mesh into the render's frame");
        return NULL;
    }
    memcpy(f->nrm, m->nrm, (size_t)m->nv * 3 * sizeof(float)); /* as they are, not normalised again */
    accel_frame_mesh_in_place(a, f);
    return f;
}
