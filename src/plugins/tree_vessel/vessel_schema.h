/* vessel_schema.h — the tree_vessel parameter schema (vessel_schema.c). */
#ifndef VESSEL_SCHEMA_H
#define VESSEL_SCHEMA_H

#include "sylva/plugin.h"

#define VESSEL_SCHEMA_COUNT 34u
extern const sylva_param_spec vessel_schema[VESSEL_SCHEMA_COUNT];

#endif
