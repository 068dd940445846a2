/* scene_build.h — from a validated scene file to a scene graph: textures and materials, the
 * terrain (inline grid or terrain plugin), each species' prototypes (tree plugin or built-in
 * shape, one per age variant), explicit plants and the ecology plugin's plants as instances,
 * and objects. Plugins run here, in that order, each through the host API. */
#ifndef SYLVA_SCENE_BUILD_H
#define SYLVA_SCENE_BUILD_H

#include "plugin_host.h"
#include "scene/scene.h"
#include "scene/scene_file.h"

typedef struct build_options {
    int verbose;  /* plugin DEBUG logs */
    int quiet;    /* no progress output */
} build_options;

/* Returns a new scene (free with scene_free) or NULL with err set. plugins may be NULL when the
 * scene names none. */
scene *scene_build(const scene_file *sf, const plugin_registry *plugins, const build_options *opt,
                   err_buf *err);

/* The transform of a plant: translate to p, rotate by rot_deg about +Z, scale uniformly. */
xform3x4 plant_transform(const double p[3], double rot_deg, double scale);

#endif
