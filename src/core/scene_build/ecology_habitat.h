/* ecology_habitat.h — the habitat rows of the ecology request (ABI 1.7, sylva_ecology_request.
 * habitat): for each scene species that a land-cover community names, 1 on the nodes of the
 * ground as surveyed whose class grows that community, so the ecology grows each community where
 * the land cover has it and nowhere else (docs/landcover.md, "Grown by the ecology").
 *
 * Ownership: the rows and the array are the caller's; ecology_habitat_free releases both. */
#ifndef SYLVA_ECOLOGY_HABITAT_H
#define SYLVA_ECOLOGY_HABITAT_H

#include <stdint.h>

#include "scene/scene.h"
#include "scene_file/scene_file.h"

/* The rows, one per scene-file species (NULL for a species no community names), or NULL with
 * err untouched when there is nothing to restrict (no land cover or no communities), NULL with
 * err set when out of memory. */
uint8_t **ecology_habitat_new(const scene *s, const scene_file *sf, err_buf *err);
void ecology_habitat_free(uint8_t **rows, uint32_t n); /* accepts NULL */

#endif
