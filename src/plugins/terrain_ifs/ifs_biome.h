/* ifs_biome.h — the biomes terrain_ifs dresses its ground for: each a preset of class albedos,
 * the colours of the ground's other kinds (soil, litter, lichen) and the slopes from which scree
 * and rock show; how `biome: auto` picks one from the site; and the snow and scree heights of
 * a site's climate by its latitude. The numbers and their sources are in docs/models/ground.md
 * (Biomes) and docs/models/terrain_ifs.md. Static data and pure functions: no state. */
#ifndef IFS_BIOME_H
#define IFS_BIOME_H

typedef enum ifs_biome {
    IFS_BIOME_TEMPERATE = 0,     /* temperate meadow: today's defaults, the Alps' lines */
    IFS_BIOME_MEDITERRANEAN = 1, /* Mediterranean scrub, chaparral, maquis */
    IFS_BIOME_SEMI_ARID = 2,     /* semi-arid shrubland and desert, pinyon-juniper, sandstone */
    IFS_BIOME_PRAIRIE = 3,       /* temperate grassland on dark soils */
    IFS_BIOME_BOREAL = 4,        /* taiga: needle litter, podzols, shield rock */
    IFS_BIOME_ALPINE = 5,        /* above the tree line and the tundra: sedge turf, frost-shattered scree */
    IFS_BIOMES = 6
} ifs_biome;

/* What a biome puts on the ground: linear RGB albedos, slopes in degrees. */
typedef struct ifs_biome_preset {
    const char *name;           /* the scene's spelling */
    double grass[3], dry_grass[3], scree[3], rock[3], snow[3];
    double soil[3], wet_soil[3], litter[3], moss[3], lichen[3];
    double scree_slope, rock_slope; /* slopes from which scree and rock lie */
    int dry;                    /* 1: a dry climate: no snow below the high snow line */
} ifs_biome_preset;

/* The share of each kind of land cover over the site, each in [0, 1] (they need not sum to 1:
 * the rest is what the land cover does not name). */
typedef struct ifs_cover_shares {
    double forest, shrub, grass, cultivated, barren, snow, water;
} ifs_cover_shares;

/* The shares a terrain request carries (SYLVA_COVER_KINDS values, sylva/plugin.h). */
ifs_cover_shares ifs_cover_shares_of(const double *request_shares);

const ifs_biome_preset *ifs_biome_preset_of(ifs_biome b);

/* The biome whose name is `name`, or -1. */
int ifs_biome_by_name(const char *name);

/* `biome: auto`: the biome of a site at latitude_deg (degrees north; NaN: no site) with the
 * land cover's shares (NULL: the scene has no land cover). Without either, temperate.
 * Latitude alone: |latitude| < 30 semi-arid, < 40 Mediterranean, < 55 temperate, < 66.5
 * boreal, else alpine (tundra). With shares: scrub and bare ground decide a dry site below 45
 * degrees, else the largest of forest, shrub and open land (grass, fields) within the
 * latitude's band (docs/models/terrain_ifs.md, Biomes, states the rule in full). */
ifs_biome ifs_biome_choose(double latitude_deg, const ifs_cover_shares *shares);

/* The climatological summer snow line and the tree line (metres above sea level) at a
 * latitude (degrees; the sign is ignored), piecewise linear between tabulated latitudes;
 * NaN gives the Alps' 46 degrees. */
double ifs_snow_line(double latitude_deg);
double ifs_tree_line(double latitude_deg);

/* The default heights of snow and scree for biome b at latitude_deg (NaN: no site, the Alps'
 * 2800 m and 2300 m): the snow line, raised in a dry biome (never below 3000 m there); scree
 * from the top of closed alpine grassland, 300 m above the tree line. */
void ifs_biome_heights(ifs_biome b, double latitude_deg, double *snow_z, double *scree_z);

#endif
