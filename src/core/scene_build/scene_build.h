/* scene_build.h — from a validated scene file to a scene graph: textures and materials, the
 * terrain (inline grid or terrain plugin), each species' prototypes (tree plugin or built-in
 * shape, one per age variant), explicit plants and the ecology plugin's plants as instances,
 * and objects. Plugins run here, in that order, each through plugin_call.h. */
#ifndef SYLVA_SCENE_BUILD_H
#define SYLVA_SCENE_BUILD_H

#include "plugin/plugin_host.h"
#include "scene_build/build_options.h"
#include "scene/scene.h"
#include "scene_file/scene_file.h"

/* Returns a new scene (free with scene_free) or NULL with err set. plugins may be NULL when the
 * scene names none. */
scene *scene_build(const scene_file *sf, const plugin_registry *plugins, const build_options *opt,
                   err_buf *err);

/* Turns plants into instances of their species' prototypes: the variant chosen by normalised
 * age (scene_variant_for_age), scaled uniformly from that variant's height to the plant's
 * height (unscaled when height <= 0), turned by the plant's rotation about +Z, and standing on
 * the terrain when snap_to_terrain is set. Returns 0, or -1 with err naming the plant. */
int scene_place_plants(scene *s, const sylva_plant *plants, uint32_t n, err_buf *err);

/* The objects: built-in shapes as meshes in world space, model files and groups' parts as
 * shared models placed by instances (one model per file, scale and up axis, however many
 * objects use it), heights resolved against the terrain (scene_build_objects.c). Returns 0, or
 * -1 with err located at the object. Materials and the terrain must be built first. */
int scene_build_objects(scene *s, const scene_file *sf, err_buf *err);

/* A new mesh (the caller frees it) of a built-in shape in the named material (NULL: the
 * default), or NULL with err placed at file:line:column and naming the kind and name. */
mesh *scene_shape_mesh(const scene *s, const shape_spec *shape, const char *material_name, const char *file,
                       uint32_t line, uint32_t column, const char *kind, const char *name, err_buf *err);

#endif
