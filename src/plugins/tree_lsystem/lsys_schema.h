/* lsys_schema.h — the parameter schema of the tree_lsystem plugin (lsys_schema.c). */
#ifndef LSYS_SCHEMA_H
#define LSYS_SCHEMA_H

#include "sylva/plugin.h"

#define LSYS_SCHEMA_COUNT 25 /* entries of lsys_schema */
extern const sylva_param_spec lsys_schema[LSYS_SCHEMA_COUNT];

#endif
