/* geometry.h — the scene geometry every back end draws the same way, built from the scene graph
 * and shared by the path tracer, the POV-Ray export and the commands that map or composite a
 * scene (a back end never reaches into another's internals for it):
 *
 *   terrain_mesh.h    the terrain heightfield as triangles, normals, uvs and materials
 *   terrain_apron.h   the terrain continued beyond its edge, flat, to the horizon
 *   water_surface.h   the water over the terrain: its rectangle and its mesh
 *   cutout.h          alpha cut-outs: which materials and triangles, the alpha test, the split
 *                     of a mesh into opaque and cut-out triangles
 *   cutout_outline.h  a cut-out texture's leaf as one opaque polygon, laid over its triangles
 *                     (the cross-check's leaves drawn as outlines)
 *   texture_lookup.h  the nearest texel of a texture, sRGB decoding
 *   light_summary.h   the sun and the sky, with the ambient term and the sky's mean radiance
 *   sky_preetham.h    the Preetham daylight sky model the light summary evaluates
 *   atmosphere.h      the physical sky and aerial perspective (single scattering over a
 *                     spherical Earth) the light summary uses with the physical sky
 *   camera_frame.h    the camera's forward, right and up vectors, turned by its roll
 *   camera_project.h  the camera as a photograph sees it: a world point to a pixel and back,
 *                     with radial lens distortion
 *   crown_hull.h      the envelope of a plant's crown, for plants a few pixels across
 *   ground_cover.h    what covers the ground at any point: continuous weights of seven kinds
 *   ground_texture.h  the ground's albedo and micro-relief from those weights, filtered
 *   ground_cover_place.h  grass and herbs near the camera (with ground_cover_models.h, the
 *                     tufts' meshes)
 *   scene_view.h      the steps a built scene takes before it is drawn from its camera (the
 *                     ground cover for the picture's size)
 *
 * The height and normal of the terrain at any point are the scene's (scene/heightfield.h), since
 * the plugin host answers those queries below this layer. Including this header includes them
 * all; each part's header says what it owns.
 */
#ifndef SYLVA_GEOMETRY_H
#define SYLVA_GEOMETRY_H

#include "geometry/atmosphere.h"
#include "geometry/camera_frame.h"
#include "geometry/camera_project.h"
#include "geometry/crown_hull.h"
#include "geometry/cutout.h"
#include "geometry/cutout_outline.h"
#include "geometry/ground_cover.h"
#include "geometry/ground_cover_models.h"
#include "geometry/ground_cover_place.h"
#include "geometry/ground_texture.h"
#include "geometry/light_summary.h"
#include "geometry/scene_view.h"
#include "geometry/sky_preetham.h"
#include "geometry/terrain_apron.h"
#include "geometry/terrain_mesh.h"
#include "geometry/texture_lookup.h"
#include "geometry/water_surface.h"
#include "scene/heightfield.h"

#endif
