/* planting_growth.h — a planted species' height against its age: the growth curve its tree
 * model gives, and its inverse, which turns a nursery stock's height into the age the plant is
 * planted at (docs/mitigation.md, "How a plant grows").
 *
 * The curve runs through (0, 0) and, for each of the species' age variants v (built by its tree
 * plugin for normalised age a_v), through (a_v F, h_v), h_v the variant's model height and F the
 * plan's full_grown_age; it is linear between them and level past the full-grown variant. So a
 * plant of age t stands as tall as its species' model built for age t / F would, to within how
 * far that model's height departs from a straight line between two variants. */
#ifndef SYLVA_PLANTING_GROWTH_H
#define SYLVA_PLANTING_GROWTH_H

#include <stdint.h>

#include "scene/scene.h"

/* Height in metres of a plant of species sp_index at `age` years (>= 0), full grown at `full_grown_age`. */
double planting_height_at(const scene *s, uint32_t sp_index, double full_grown_age, double age);

/* The least age in years at which the curve reaches `height`; -1 when the species' model never
 * grows that tall (its tallest variant is lower). */
double planting_age_for_height(const scene *s, uint32_t sp_index, double full_grown_age, double height);

/* The height of the species' tallest variant, metres. */
double planting_tallest(const scene *s, uint32_t sp_index);

#endif
