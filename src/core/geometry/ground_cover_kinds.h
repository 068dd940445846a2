/* ground_cover_kinds.h — what covers the ground at a point, as weights of the kinds of ground
 * that decide how much grass and herb grows there.
 *
 * ADAPTER: the terrain materials module (geometry/ground_cover.h, ground_cover_weights) owns
 * these weights once it is part of the build; this file then goes, and ground_cover_place.c
 * asks ground_cover_weights instead. Until then the weights come from the terrain's node
 * classes (the terrain_ifs plugin's materials "terrain_ifs grass", "... dry grass", "... scree",
 * "... rock", "... snow") and the water level: one kind at a time, weight 1. A terrain without
 * those materials (an inline grid in a material of the scene's) has weight 0 everywhere, so no
 * ground cover. Forest floor is not told apart from meadow here. */
#ifndef SYLVA_GROUND_COVER_KINDS_H
#define SYLVA_GROUND_COVER_KINDS_H

#include <stdint.h>

#include "scene/scene.h"

typedef enum cover_kind {
    COVER_MEADOW = 0,
    COVER_FOREST_FLOOR,
    COVER_SOIL,
    COVER_ROCK,
    COVER_SCREE,
    COVER_SNOW,
    COVER_WATER,
    COVER_KINDS
} cover_kind;

/* The kind of each of s's materials (-1: none of them), for cover_kinds_at; owned by the
 * caller (cover_kind_table_free). */
typedef struct cover_kind_table {
    int8_t *of_material; /* n_materials entries */
} cover_kind_table;

int cover_kind_table_new(const scene *s, cover_kind_table *t, err_buf *err);
void cover_kind_table_free(cover_kind_table *t);

/* Weights (summing to 1, or all 0 where nothing is known) of the ground at (x, y) into w. */
void cover_kinds_at(const scene *s, const cover_kind_table *t, double x, double y, float w[COVER_KINDS]);

#endif
