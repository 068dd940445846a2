/* scene_spring.h — a built scene's plants in spring: the lighter green of new leaves, and the
 * flowers of the species in blossom on the scene's day (docs/seasons.md).
 *
 * Like the rest of the season (scene_season.h) neither changes which plants stand where: fresh
 * leaves are copies of a species' leaf materials, and the flowers are instances of a separate
 * species "blossom <species>" appended after every other instance, so the plants keep their
 * instance indices (and ids) in every season.
 *
 * Ownership: adds materials, species, prototypes and instances to the scene (owned by it). */
#ifndef SYLVA_SCENE_SPRING_H
#define SYLVA_SCENE_SPRING_H

#include <stdint.h>

#include "season/blossom.h"
#include "scene/scene.h"
#include "season/phenology.h"

/* The particle-system parameters of flowering block b (blossom.h): flowers open from b's first
 * day to its last; births fall in the first half or so of that span and each flower lives a
 * quarter to a half of it, so none is left after the last day. *day becomes the scene's day on
 * the particle system's clock (the middle of the day). Returns 1 when the species is in blossom
 * on `day`, else 0 (p and *day untouched). */
int scene_blossom_params(const phenology *ph, uint32_t day, blossom_params *p, double *clock_day);

/* Adds the flowers of species i of s, whose leaves follow ph, when it is in blossom on `day` (a
 * day of the year); name is the species as the scene file names it, for messages. Their crown
 * points are the plants' leaves, so call it before the season drops them (the same flowers
 * before and after leaf_out). Returns 0, or -1 with err set ("file:line:column: species ...":
 * too many petals, out of memory). */
int scene_apply_blossom(scene *s, uint32_t i, const phenology *ph, uint32_t day, const char *name,
                        err_buf *err);

/* Gives species i, when its leaves are still fresh on `day` (phenology_fresh_share > 0), its own
 * copy of each leaf material of its prototypes, albedo moved that share of the way from its
 * summer value toward fresh_color (transmittance keeping its ratio to the albedo). Returns 0, or
 * -1 with err set (out of memory). */
int scene_apply_fresh_leaves(scene *s, uint32_t i, const phenology *p, uint32_t day, err_buf *err);

#endif
