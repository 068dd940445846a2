/* study_frames.c — the frames' lenses and sizes (study_frames.h). */
#include "study/study_frames.h"

#include <math.h>

#define DEG (M_PI / 180.0)
#define SENSOR_MM 36.0 /* a full-frame sensor's width */

const study_frame_def *study_frame_of(int f)
{
    static const study_frame_def frames[] = {
        {"single", 0, 50.0, 0, 24.0 / 36.0},
        {"planar_53", 0, 0, 53.5, 260.0 / 820.0},
        {"cylindrical_90", 1, 0, 90.0, 260.0 / 820.0},
    };
    return &frames[f];
}

void study_frame_size(int f, const study_sizing *z, uint32_t out[2])
{
    if (z->size[0] && z->size[1]) {
        out[0] = z->size[0], out[1] = z->size[1];
        return;
    }
    double w = z->size[0] ? z->size[0] : z->print_width_mm > 0 ? round(z->print_width_mm / 25.4 * z->dpi)
                                                               : z->image_width;
    if (w < 1) w = 1;
    double h = round(w * study_frame_of(f)->aspect);
    out[0] = (uint32_t)w, out[1] = h < 1 ? 1 : (uint32_t)h;
}

void study_frame_lens(int f, camera_settings *c)
{
    const study_frame_def *d = study_frame_of(f);
    c->cylindrical = d->cylindrical;
    c->sensor_width_mm = SENSOR_MM;
    c->focal_length_mm = d->focal_length_mm;
    /* as the scene file reads a camera's focal_length (scene_file_settings.c), to the bit */
    c->fov_deg = d->focal_length_mm > 0 ? 2.0 * atan(SENSOR_MM / (2.0 * d->focal_length_mm)) / DEG : d->fov_deg;
}
