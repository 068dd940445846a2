/* ifs_biome_presets.c — the ground of each biome (ifs_biome.h). The temperate preset is
 * terrain_ifs's defaults and the host's temperate colours, value for value; every number's
 * source is in docs/models/ground.md (Biomes). Static const data. */
#include "ifs_biome.h"

static const ifs_biome_preset presets[IFS_BIOMES] = {
    [IFS_BIOME_TEMPERATE] = {.name = "temperate",
                             .grass = {0.07, 0.10, 0.04}, .dry_grass = {0.30, 0.26, 0.12},
                             .scree = {0.34, 0.32, 0.29}, .rock = {0.21, 0.19, 0.17},
                             .snow = {0.85, 0.87, 0.90}, .soil = {0.16, 0.115, 0.08},
                             .wet_soil = {0.075, 0.055, 0.04}, .litter = {0.11, 0.075, 0.045},
                             .moss = {0.05, 0.085, 0.025}, .lichen = {0.26, 0.25, 0.18},
                             .scree_slope = 30, .rock_slope = 42, .dry = 0},
    /* evergreen sclerophyll shrubs over brown granitic soil; the annual grass cured gold */
    [IFS_BIOME_MEDITERRANEAN] = {.name = "mediterranean",
                                 .grass = {0.045, 0.055, 0.03}, .dry_grass = {0.30, 0.23, 0.12},
                                 .scree = {0.24, 0.21, 0.17}, .rock = {0.22, 0.20, 0.17},
                                 .snow = {0.85, 0.87, 0.90}, .soil = {0.21, 0.16, 0.11},
                                 .wet_soil = {0.085, 0.065, 0.045}, .litter = {0.13, 0.10, 0.07},
                                 .moss = {0.08, 0.085, 0.05}, .lichen = {0.24, 0.23, 0.17},
                                 .scree_slope = 40, .rock_slope = 48, .dry = 1},
    /* sparse grey-green shrubs and bunchgrass over red sand; red and cream sandstone */
    [IFS_BIOME_SEMI_ARID] = {.name = "semi_arid",
                             .grass = {0.11, 0.12, 0.08}, .dry_grass = {0.36, 0.30, 0.19},
                             .scree = {0.36, 0.22, 0.13}, .rock = {0.40, 0.22, 0.12},
                             .snow = {0.85, 0.87, 0.90}, .soil = {0.36, 0.18, 0.09},
                             .wet_soil = {0.16, 0.08, 0.045}, .litter = {0.14, 0.10, 0.07},
                             .moss = {0.07, 0.065, 0.05}, .lichen = {0.50, 0.40, 0.28},
                             .scree_slope = 38, .rock_slope = 45, .dry = 1},
    /* tall and short grass on dark mollisols */
    [IFS_BIOME_PRAIRIE] = {.name = "prairie",
                           .grass = {0.065, 0.09, 0.04}, .dry_grass = {0.28, 0.23, 0.13},
                           .scree = {0.30, 0.28, 0.24}, .rock = {0.24, 0.21, 0.17},
                           .snow = {0.85, 0.87, 0.90}, .soil = {0.09, 0.07, 0.05},
                           .wet_soil = {0.045, 0.035, 0.025}, .litter = {0.12, 0.09, 0.055},
                           .moss = {0.05, 0.085, 0.025}, .lichen = {0.26, 0.25, 0.18},
                           .scree_slope = 30, .rock_slope = 42, .dry = 0},
    /* dwarf shrubs and feather moss under conifers, grey podzol, shield granite */
    [IFS_BIOME_BOREAL] = {.name = "boreal",
                          .grass = {0.05, 0.07, 0.035}, .dry_grass = {0.25, 0.22, 0.12},
                          .scree = {0.30, 0.29, 0.27}, .rock = {0.20, 0.19, 0.18},
                          .snow = {0.85, 0.87, 0.90}, .soil = {0.14, 0.13, 0.11},
                          .wet_soil = {0.06, 0.055, 0.045}, .litter = {0.07, 0.065, 0.035},
                          .moss = {0.06, 0.09, 0.03}, .lichen = {0.30, 0.30, 0.24},
                          .scree_slope = 30, .rock_slope = 42, .dry = 0},
    /* sedge turf, thin soil, frost-shattered scree from gentler slopes */
    [IFS_BIOME_ALPINE] = {.name = "alpine",
                          .grass = {0.06, 0.08, 0.04}, .dry_grass = {0.28, 0.25, 0.15},
                          .scree = {0.34, 0.32, 0.29}, .rock = {0.21, 0.19, 0.17},
                          .snow = {0.85, 0.87, 0.90}, .soil = {0.13, 0.11, 0.085},
                          .wet_soil = {0.06, 0.05, 0.04}, .litter = {0.10, 0.08, 0.05},
                          .moss = {0.05, 0.08, 0.03}, .lichen = {0.26, 0.25, 0.18},
                          .scree_slope = 28, .rock_slope = 40, .dry = 0},
};

const ifs_biome_preset *ifs_biome_preset_of(ifs_biome b)
{
    return &presets[(unsigned)b < IFS_BIOMES ? b : IFS_BIOME_TEMPERATE];
}
