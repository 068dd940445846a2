/* wp_schema.h — the tree_weber_penn parameter schema (wp_schema.c): the block beside
 * `plugin: tree_weber_penn` (the species' file and name, the seed, the look) and its `model`
 * group, one member per Weber–Penn parameter, named as the fields of wp_params. */
#ifndef WP_SCHEMA_H
#define WP_SCHEMA_H

#include "sylva/plugin.h"

#define WP_SCHEMA_COUNT 10u
extern const sylva_param_spec wp_schema[WP_SCHEMA_COUNT];

/* The members of `model`, general parameters first, then the per-level ones (lists of up to
 * WP_LEVELS numbers, level 0 first). */
#define WP_MODEL_SCHEMA_COUNT 44u
extern const sylva_param_spec wp_model_schema[WP_MODEL_SCHEMA_COUNT];

/* wp_model_arbaro[i] is the row of wp_param_table (its name: "Scale", "0BaseSplits",
 * "nLength") that member i of wp_model_schema sets. */
extern const char *const wp_model_arbaro[WP_MODEL_SCHEMA_COUNT];

#endif
