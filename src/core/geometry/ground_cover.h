/* ground_cover.h — what covers the ground at any point of the terrain, as continuous weights of
 * seven kinds (meadow, forest floor, bare soil, rock, scree, snow, water's edge) that sum to one.
 * The weights follow from the slope, the height against the terrain's snow and scree lines, the
 * humidity (the terrain plugin's humidity map where the scene has one), the closeness of the
 * water and the canopy of the scene's plants (a raster of crown cover rasterised from the plant
 * instances when the map is made), each turned into a smooth step whose edge is moved by
 * low-frequency noise so that boundaries wander as they do on the ground. The rules, their
 * defaults for a temperate site and the noise are in docs/models/ground.md.
 *
 * The ground's texture is made from these weights (ground_texture.h: the renderer's terrain
 * shading and the POV-Ray export's ground image), and ground-cover instances are placed by them;
 * all call the same function, so they agree.
 *
 * The procedural ground applies to a terrain whose plugin describes its ground cover (the
 * heightfield's ground rules, sylva_heightfield.has_ground_rules); a terrain drawn from scene
 * materials only (an inline grid) keeps its materials, and ground_cover_map_new returns NULL
 * for it without an error.
 *
 * Ownership: a ground_cover_map owns its canopy raster and borrows the scene's heightfield (the
 * scene must outlive it); ground_cover_map_free releases it (accepts NULL). Queries are
 * read-only and safe from many threads at once.
 */
#ifndef SYLVA_GROUND_COVER_H
#define SYLVA_GROUND_COVER_H

#include "scene/scene.h"
#include "util/err.h"

typedef enum ground_kind {
    GROUND_MEADOW = 0,        /* grass and herbs; dry grass is a tint of it (ground_cover_dryness) */
    GROUND_FOREST_FLOOR = 1,  /* leaf and needle litter under and near crowns */
    GROUND_SOIL = 2,          /* bare earth: banks, trampled and eroded patches */
    GROUND_ROCK = 3,          /* outcrops on steep slopes */
    GROUND_SCREE = 4,         /* loose stones below cliffs and above the scree line */
    GROUND_SNOW = 5,          /* above the snow line */
    GROUND_WATER = 6,         /* wet ground at and below the water's edge */
    GROUND_KINDS = 7
} ground_kind;

/* How far toward cured grass a meadow in its full winter rest turns (its ground and its grass
 * tufts alike): winter grass is a duller, browner green, a third of the way from the growing turf
 * to the straw of a dry summer meadow. */
#define GROUND_MEADOW_REST_SHARE 0.35

typedef struct ground_cover_map ground_cover_map;

/* The map of scene s's terrain: NULL with err untouched when the terrain does not describe its
 * ground (no terrain, or no ground rules), NULL with err set when memory runs out. */
ground_cover_map *ground_cover_map_new(const scene *s, err_buf *err);
void ground_cover_map_free(ground_cover_map *m); /* accepts NULL */

/* The weights of every kind at map point (x, y) (metres, the scene's frame) into w: each in
 * [0, 1], summing to 1, continuous in (x, y). Outside the terrain the nearest edge point's. */
void ground_cover_weights(const ground_cover_map *m, double x, double y, float w[GROUND_KINDS]);

/* How dry the meadow is at (x, y), in [0, 1]: 0 lush, 1 dry grass (from the humidity, and from
 * the season: a resting meadow in autumn and winter, phenology.h meadow_dormancy). */
float ground_cover_dryness(const ground_cover_map *m, double x, double y);

/* Canopy cover at (x, y) in [0, 1]: the share of the ground under the plants' crowns. */
float ground_cover_canopy(const ground_cover_map *m, double x, double y);

/* The kind's name ("meadow", "forest floor", ...). */
const char *ground_kind_name(ground_kind k);

#endif
