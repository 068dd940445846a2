/* ecology_maps.h — top-down maps of an ecology run, written as PNG: one terrain factor on its
 * patch grid (as Zamuda 2006 shows humidity, windiness and sunniness in Figs. 4.5, 4.10 and
 * 4.16), and the plants over the shaded terrain at a year (the population of Figs. 6.1–6.5 seen
 * from above). North is up, east to the right. */
#ifndef SYLVA_ECOLOGY_MAPS_H
#define SYLVA_ECOLOGY_MAPS_H

#include <stdint.h>

#include "sylva/plugin.h"
#include "util/err.h"

/* The factor's values from dark (0) to its colour (1): humidity green, windiness yellow,
 * sunniness red, altitude tan, water blue, anything else grey; each patch a square of pixels,
 * the image at least 512 pixels along its longer side. */
int factor_map_write(const char *path, const sylva_ecology_factor_map *map, err_buf *err);

/* Every plant as a disc of its ecological radius in its species' colour (canvas_series_color),
 * the larger drawn first, over the terrain shaded by height and slope, with water in blue (below
 * the terrain's water surface, and where `water` — a 0/1 patch map, or NULL — is 1), a legend of
 * the species and their counts, and the year; 800 pixels along the longer side. */
int plant_map_write(const char *path, const sylva_heightfield *terrain, const sylva_ecology_factor_map *water,
                    const sylva_ecology_plant_record *plants, uint32_t n_plants, const char *const *names,
                    uint32_t n_species, uint32_t year, err_buf *err);

#endif
