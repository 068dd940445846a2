/* vessel_presets.h — the named species of the vessel model: beech, spruce and weeping willow
 * with the values of 004 §3.4 (Figs. 3.26–3.28), and maple, which is sylva's own design (not in
 * 004). Textures, colours and the number of cone sides are sylva's choices for every preset.
 *
 * A preset is a table of scene-file values (sylva_preset, ABI 1.1): the descriptor hands the
 * same tables to the host, so `sylva plugins --describe tree_vessel` prints the values the
 * plugin starts from. A key a preset does not set keeps the schema's default. */
#ifndef VESSEL_PRESETS_H
#define VESSEL_PRESETS_H

#include "sylva/plugin.h"
#include "vessel_params.h"

typedef enum vessel_preset {
    VESSEL_PRESET_BEECH = 0,
    VESSEL_PRESET_SPRUCE,
    VESSEL_PRESET_WEEPING_WILLOW,
    VESSEL_PRESET_MAPLE,
    VESSEL_PRESETS
} vessel_preset;

/* "beech", "spruce", "weeping_willow", "maple", then NULL (an enum's choices). */
extern const char *const vessel_preset_names[VESSEL_PRESETS + 1];

/* The presets' values, in vessel_preset order (static data). */
extern const sylva_preset vessel_presets[VESSEL_PRESETS];

/* Fills *out with the preset's complete parameter set: the schema's defaults, then the preset's
 * values (it passes vessel_params_check). Returns 0, or -1 for an unknown preset. Defined with
 * the schema in vessel_config.c. */
int vessel_preset_get(vessel_preset which, vessel_params *out);

#endif
