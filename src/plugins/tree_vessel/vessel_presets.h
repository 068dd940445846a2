/* vessel_presets.h — the named species of the vessel model: beech, spruce and weeping willow
 * with the values of 004 §3.4 (Figs. 3.26–3.28), and maple, which is sylva's own design (not in
 * 004). Textures, colours and the number of cone sides are sylva's choices for every preset. */
#ifndef VESSEL_PRESETS_H
#define VESSEL_PRESETS_H

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

/* Fills *out with the preset's complete parameter set (it passes vessel_params_check).
 * Returns 0, or -1 for an unknown preset. */
int vessel_preset_get(vessel_preset which, vessel_params *out);

#endif
