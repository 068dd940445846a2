/* planting_ecology.h — which of a planting plan's plants the scene's ecology lets stand at a
 * year: the blocks' and belts' plants grown from planting, year by year, among themselves by
 * the ecology plugin's own rules (competition, Algorithm 8; deaths, §4.7.1) through its
 * "sylva.ecology.v3" interface, from the plan's seed. Single trees take no part. The history
 * does not depend on the year asked: a plant gone at a year is gone at every later one
 * (docs/mitigation.md, "Which plants stand"; docs/models/ecology.md, "Planted plants").
 *
 * Ownership: planting_ecology_fates hands the caller a malloc'ed array (*died) to free(). */
#ifndef SYLVA_PLANTING_ECOLOGY_H
#define SYLVA_PLANTING_ECOLOGY_H

#include <stdint.h>

#include "plugin/plugin_host.h"
#include "scene/scene.h"
#include "scene_build/build_options.h"
#include "scene_build/ecology_session.h"
#include "scene_build/planting_layout.h"
#include "scene_file/scene_file.h"
#include "util/err.h"

/* 1 when sf's plan, shown as opt asks, has blocks or belts for the scene's ecology to grow (the
 * plan's `ecology: true`, an ecology section, the ecology not left out). */
int planting_ecology_wanted(const scene_file *sf, const build_options *opt);

/* For plants [0, n) of sf's plan, the year since planting in which each died by the ecology
 * ((*died)[i], 0: stands through `years`), in a new array; *died stays NULL, with 0 returned,
 * when the ecology does not act on the plan (the plan says `ecology: false`, the scene has no
 * ecology, or the plan has no block or belt), and *why then says so in a few words (static
 * text). The plants are grown through `ecology` (borrowed) when given, else through a session of
 * reg's plugin opened here. Returns 0, or -1 with err set (the plugin cannot grow planted
 * plants, or failed). */
int planting_ecology_fates(scene *s, const scene_file *sf, const plugin_registry *reg, ecology_session *ecology,
                           const build_options *opt, const planted_plant *plants, uint32_t n, double years,
                           uint32_t **died, const char **why, err_buf *err);

#endif
