/* pov_ground.h — the procedural ground (geometry/ground_texture.h) as POV-Ray can show it:
 * POV-Ray cannot evaluate sylva's noise, so the export writes the ground's image (its colour
 * filtered at a texel: the cover weights and every octave wider than a texel, finer ones at
 * their mean) as a PNG laid over the terrain's footprint from above (a planar image map), over a
 * plain layer of the image's mean colour (ground_texture.beyond) that shows beyond the
 * footprint (the apron). What it leaves out: the octaves finer than a texel and the
 * micro-relief, which sylva's verification mode leaves out too (render/accel_terrain.h), so the
 * cross-check compares the same ground.
 *
 * Ownership: nothing is kept; the image is written beside the other export files. */
#ifndef SYLVA_POV_GROUND_H
#define SYLVA_POV_GROUND_H

#include "pov/pov_file.h"
#include "scene/scene.h"
#include "util/err.h"

/* When scene s has a procedural ground: writes its image to image_path (referred to from the
 * .pov files as image_name), declares texture `ident` into pf and sets *written to 1. Otherwise
 * writes nothing and sets *written to 0. Returns 0, or -1 with err set. */
int pov_write_ground(pov_file *pf, const scene *s, const char *image_path, const char *image_name,
                     const char *ident, int *written, err_buf *err);

#endif
