/* scene_planting.h — a planting plan (the planting: section) in the scene at a year: the
 * fellings take out the existing plants that stand in their polygons, and each plant of the
 * plan stands where its layout puts it (planting_layout.h), of the age its stock gives
 * (planting_growth.h) plus the years since planting, as tall as its species' growth curve says
 * at that age, placed as a surveyed tree is (scene_trees.h). docs/mitigation.md gives the rules. */
#ifndef SYLVA_SCENE_PLANTING_H
#define SYLVA_SCENE_PLANTING_H

#include "plugin/plugin_host.h"
#include "scene/scene.h"
#include "scene_build/ecology_session.h"
#include "scene_build/build_options.h"
#include "scene_file/scene_file.h"

/* Checks that every feature of sf->planting lies on the terrain (refused at the feature's place
 * otherwise), then, with opt->planting_shown, fells and plants at opt->planting_years, the
 * blocks' and belts' plants that the scene's ecology lets stand then (planting_ecology.h: through
 * `ecology`, the woodland's session when given, else one of reg's plugin). Species and the
 * existing plants must be built first. Returns 0, or -1 with err set. */
int scene_build_planting(scene *s, const scene_file *sf, const plugin_registry *reg, ecology_session *ecology,
                         const build_options *opt, err_buf *err);

#endif
