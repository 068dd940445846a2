/* scene_communities.h — the plants of the land cover's communities (landcover: communities:,
 * docs/landcover.md), placed without simulation: the map is read again on a grid of
 * plant_spacing over the plant area, and each node of a class with a community gets that
 * community's density as plants at uniform points of its cell, of species drawn by their shares,
 * with heights spread evenly over the community's range (each plant the age variant nearest its
 * height, scaled to it exactly: scene_build/plant_scale.h). Deterministic from the scene's seed.
 * A species the scene's ecology grows is left to it. */
#ifndef SYLVA_SCENE_COMMUNITIES_H
#define SYLVA_SCENE_COMMUNITIES_H

#include "scene/scene.h"
#include "scene_file/scene_file.h"

/* Places the communities' plants (nothing without communities). Species must be built first.
 * quiet: no summary line. Returns 0, or -1 with err set at the section: more plants than a scene
 * takes, a plant area off the terrain, a map that cannot be read there. */
int scene_build_communities(scene *s, const scene_file *sf, int quiet, err_buf *err);

/* The community of the landcover: section that class c grows: the one of its code, else of its
 * kind, else of its broad kind (forest, wetland); -1 for none. */
int32_t landcover_community_of(const landcover_spec *spec, const land_class *c);

/* 1 when scene species sp is grown by the scene's ecology rather than placed: the scene has an
 * ecology and the species an ecology block. Its community then gives it only its habitat (the
 * ecology request's, scene_build/ecology_habitat.h). */
int community_species_grown(const scene_file *sf, uint32_t sp);

#endif
