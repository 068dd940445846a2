/* pov_ground.c — the procedural ground's colour as a planar image map (see pov_ground.h). */
#include "pov/pov_ground.h"

#include <math.h>

#include "pov/pov_number.h"
#include "geometry/ground_texture.h"

int pov_write_ground(pov_file *pf, const scene *s, const char *image_path, const char *image_name,
                     const char *ident, int *written, err_buf *err)
{
    *written = 0;
    ground_texture *g = NULL;
    if (ground_texture_build(s, &g, err)) return -1;
    if (!g) return 0;
    const sylva_heightfield *hf = s->terrain;
    double w = hf->dx * (hf->nx - 1), h = hf->dy * (hf->ny - 1), texel;
    uint32_t iw, ih;
    ground_texture_image_size(hf, &iw, &ih, &texel);
    vec3 beyond = g->beyond;
    int rc = ground_texture_write_image(g, image_path, err);
    ground_texture_free(g);
    if (rc) return -1;
    char rgb[3 * POV_NUMBER_MAX + 8], size[3 * POV_NUMBER_MAX + 8], origin[3 * POV_NUMBER_MAX + 8];
    pov_append_vec3f(rgb, beyond.x, beyond.y, beyond.z, NULL);
    pov_append_vec3f(size, (float)w, (float)h, 1.0f, NULL);
    pov_append_vec3f(origin, (float)hf->x0, (float)hf->y0, 0.0f, NULL);
    pov_printf(pf, "// %s: the ground's colour filtered at %g m texels (%ux%u), laid from above over the\n"
                   "// terrain's footprint, over its mean colour beyond it (finer texture and micro-relief\n"
                   "// are sylva's only).\n"
                   "#declare %s =\n"
                   "  texture { pigment { rgb %s } finish { Sylva_finish } }\n"
                   "  texture { pigment { image_map { png \"%s\" gamma srgb once interpolate 2 }\n"
                   "                      scale %s translate %s } finish { Sylva_finish } }\n\n",
               ident, texel, iw, ih, ident, rgb, image_name, size, origin);
    *written = 1;
    return 0;
}
