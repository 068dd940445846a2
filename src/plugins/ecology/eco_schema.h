/* eco_schema.h — the parameter schemas of the ecology plugin: the keys the scene's `ecology:`
 * block may hold and the keys of each species' `ecology:` block, with their types, defaults,
 * ranges, units and help (docs/models/ecology.md lists them). Static const data. */
#ifndef ECO_SCHEMA_H
#define ECO_SCHEMA_H

#include "sylva/plugin.h"

#define ECO_PARAMS 21 /* entries of eco_params */
extern const sylva_param_spec eco_params[ECO_PARAMS];

#define ECO_SPECIES_KEYS 23 /* entries of eco_species_schema */
extern const sylva_param_spec eco_species_schema[ECO_SPECIES_KEYS];

#endif
