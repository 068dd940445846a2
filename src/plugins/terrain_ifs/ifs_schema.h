/* ifs_schema.h — the parameter schema of the terrain_ifs plugin: the keys a scene's
 * `terrain:` block may hold next to `plugin: terrain_ifs`, with their types, defaults, ranges,
 * units and help (docs/models/terrain_ifs.md lists them). Static const data. */
#ifndef IFS_SCHEMA_H
#define IFS_SCHEMA_H

#include <stdint.h>

#include "sylva/plugin.h"

#define TERRAIN_IFS_N_PARAMS 46u
extern const sylva_param_spec terrain_ifs_params[TERRAIN_IFS_N_PARAMS];

/* Defaults the plugin needs beside the schema. */
#define TERRAIN_IFS_DEFAULT_CELL 25.0          /* m: node spacing of inline and generated DTMs */
#define TERRAIN_IFS_DEFAULT_SNOW_ALTITUDE 2800.0  /* m */
#define TERRAIN_IFS_DEFAULT_SCREE_ALTITUDE 2300.0 /* m */
#define TERRAIN_IFS_UNIFORM_NODES 16785409u /* 4097 x 4097: larger refines in levels of detail */
#define TERRAIN_IFS_LOD_CELLS 1024u          /* automatic finest window: half-width in its cells */
#define TERRAIN_IFS_MAX_OUTPUT_NODES (1u << 28) /* the host's largest heightfield */

#endif
