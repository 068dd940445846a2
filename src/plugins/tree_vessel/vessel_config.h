/* vessel_config.h — the scene-file face of the vessel model: the parameter schema of the
 * tree_vessel plugin (vessel_schema.h) and the reading of a validated block into a vessel_params.
 *
 * A block starts from its `preset` (beech when not given) and every key the scene gives
 * (sylva_value.is_set) replaces that preset's value; keys not given keep the preset's. The
 * schema's defaults are the beech preset's values, so `sylva plugins --describe tree_vessel`
 * shows a complete species. */
#ifndef VESSEL_CONFIG_H
#define VESSEL_CONFIG_H

#include <stdint.h>

#include "sylva/plugin.h"
#include "plugin_err.h"
#include "plugin_params.h"
#include "vessel_params.h"

#include "vessel_schema.h"

/* Reads a block validated against vessel_schema through `params` (its reader) into *out and
 * checks it (vessel_params_check plus the orders of the polylines). Returns 0; or params->status
 * when the code read a name the schema lacks (the host has the sentence); or a sylva_status with
 * err set, err->param naming the key whose place in the scene file the message belongs to. */
int vessel_config_read(plugin_params *params, vessel_params *out, plugin_err *err);

#endif
