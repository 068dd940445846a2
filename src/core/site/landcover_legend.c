/* landcover_legend.c — the shipped legends and the keywords that read a class name as a kind
 * (landcover_legend.h). NLCD 2011: the National Land Cover Database's class codes (USGS);
 * CORINE: the CLC raster's grid codes 1-44 of the level-3 classes, with 48 (no data), 49 and 50
 * (unclassified land and water) and 255 (outside the mapped area) as CLC rasters carry them. */
#include "site/landcover_legend.h"

#include <ctype.h>
#include <stddef.h>
#include <string.h>
#include <strings.h>

#define COUNT(a) ((uint32_t)(sizeof(a) / sizeof((a)[0])))

const char *const landcover_legend_choices[] = {"auto", "nlcd2011", "corine", "names", NULL};

const char *landcover_legend_name(landcover_legend l)
{
    return l == LEGEND_NONE ? "none" : landcover_legend_choices[l];
}

static const legend_class nlcd2011[] = {
    {11, "Open Water", LAND_WATER, 0},
    {12, "Perennial Ice/Snow", LAND_SNOW_ICE, 0},
    {21, "Developed, Open Space", LAND_DEVELOPED, 0},
    {22, "Developed, Low Intensity", LAND_DEVELOPED, 0},
    {23, "Developed, Medium Intensity", LAND_DEVELOPED, 0},
    {24, "Developed, High Intensity", LAND_DEVELOPED, 0},
    {31, "Barren Land", LAND_BARREN, 0},
    {41, "Deciduous Forest", LAND_FOREST_DECIDUOUS, 0},
    {42, "Evergreen Forest", LAND_FOREST_EVERGREEN, 0},
    {43, "Mixed Forest", LAND_FOREST_MIXED, 0},
    {51, "Dwarf Scrub", LAND_SHRUB, 0},
    {52, "Shrub/Scrub", LAND_SHRUB, 0},
    {71, "Grassland/Herbaceous", LAND_GRASS, 0},
    {72, "Sedge/Herbaceous", LAND_GRASS, 0},
    {73, "Lichens", LAND_GRASS, 0},
    {74, "Moss", LAND_GRASS, 0},
    {81, "Pasture/Hay", LAND_CULTIVATED, 0},
    {82, "Cultivated Crops", LAND_CULTIVATED, 0},
    {90, "Woody Wetlands", LAND_WETLAND_WOODY, 0},
    {95, "Emergent Herbaceous Wetlands", LAND_WETLAND_HERBACEOUS, 0},
};

static const legend_class corine[] = {
    {1, "Continuous urban fabric", LAND_DEVELOPED, 0},
    {2, "Discontinuous urban fabric", LAND_DEVELOPED, 0},
    {3, "Industrial or commercial units", LAND_DEVELOPED, 0},
    {4, "Road and rail networks and associated land", LAND_DEVELOPED, 0},
    {5, "Port areas", LAND_DEVELOPED, 0},
    {6, "Airports", LAND_DEVELOPED, 0},
    {7, "Mineral extraction sites", LAND_BARREN, 0},
    {8, "Dump sites", LAND_DEVELOPED, 0},
    {9, "Construction sites", LAND_DEVELOPED, 0},
    {10, "Green urban areas", LAND_DEVELOPED, 0},
    {11, "Sport and leisure facilities", LAND_DEVELOPED, 0},
    {12, "Non-irrigated arable land", LAND_CULTIVATED, 0},
    {13, "Permanently irrigated land", LAND_CULTIVATED, 0},
    {14, "Rice fields", LAND_CULTIVATED, 0},
    {15, "Vineyards", LAND_CULTIVATED, 0},
    {16, "Fruit trees and berry plantations", LAND_CULTIVATED, 0},
    {17, "Olive groves", LAND_CULTIVATED, 0},
    {18, "Pastures", LAND_CULTIVATED, 0},
    {19, "Annual crops associated with permanent crops", LAND_CULTIVATED, 0},
    {20, "Complex cultivation patterns", LAND_CULTIVATED, 0},
    {21, "Land principally occupied by agriculture, with significant areas of natural vegetation",
     LAND_CULTIVATED, 0},
    {22, "Agro-forestry areas", LAND_CULTIVATED, 0},
    {23, "Broad-leaved forest", LAND_FOREST_DECIDUOUS, 0},
    {24, "Coniferous forest", LAND_FOREST_EVERGREEN, 0},
    {25, "Mixed forest", LAND_FOREST_MIXED, 0},
    {26, "Natural grasslands", LAND_GRASS, 0},
    {27, "Moors and heathland", LAND_SHRUB, 0},
    {28, "Sclerophyllous vegetation", LAND_SHRUB, 0},
    {29, "Transitional woodland-shrub", LAND_SHRUB, 0},
    {30, "Beaches, dunes, sands", LAND_BARREN, 0},
    {31, "Bare rocks", LAND_BARREN, 0},
    {32, "Sparsely vegetated areas", LAND_BARREN, 0},
    {33, "Burnt areas", LAND_BARREN, 0},
    {34, "Glaciers and perpetual snow", LAND_SNOW_ICE, 0},
    {35, "Inland marshes", LAND_WETLAND_HERBACEOUS, 0},
    {36, "Peat bogs", LAND_WETLAND_HERBACEOUS, 0},
    {37, "Salt marshes", LAND_WETLAND_HERBACEOUS, 0},
    {38, "Salines", LAND_WETLAND_HERBACEOUS, 0},
    {39, "Intertidal flats", LAND_BARREN, 0},
    {40, "Water courses", LAND_WATER, 0},
    {41, "Water bodies", LAND_WATER, 0},
    {42, "Coastal lagoons", LAND_WATER, 0},
    {43, "Estuaries", LAND_WATER, 0},
    {44, "Sea and ocean", LAND_WATER, 0},
    {48, "No data", LAND_UNKNOWN, 1},
    {49, "Unclassified land surface", LAND_UNKNOWN, 0},
    {50, "Unclassified water bodies", LAND_WATER, 0},
    {255, "Unclassified", LAND_UNKNOWN, 1},
};

const legend_class *landcover_legend_class(landcover_legend l, int64_t code)
{
    const legend_class *t = l == LEGEND_NLCD2011 ? nlcd2011 : l == LEGEND_CORINE ? corine : NULL;
    uint32_t n = l == LEGEND_NLCD2011 ? COUNT(nlcd2011) : l == LEGEND_CORINE ? COUNT(corine) : 0;
    for (uint32_t i = 0; i < n; i++)
        if (t[i].code == code) return &t[i];
    return NULL;
}

int landcover_legend_fits(landcover_legend l, const int64_t *codes, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++)
        if (!landcover_legend_class(l, codes[i])) return 0;
    return n > 0;
}

/* 1 when a word of name begins with `word` (case-insensitive): "ice" is in "Perennial Ice/Snow",
 * not in "Rice fields". */
static int begins_a_word(const char *name, const char *word)
{
    size_t n = strlen(word);
    for (const char *p = name; *p; p++)
        if ((p == name || !isalpha((unsigned char)p[-1])) && !strncasecmp(p, word, n)) return 1;
    return 0;
}

/* 1 when name holds one of the NULL-terminated words at a word's start. */
static int says(const char *name, const char *const *words)
{
    for (; *words; words++)
        if (begins_a_word(name, *words)) return 1;
    return 0;
}

/* Keywords in the order they are tried: a wetland's "herbaceous" is a wetland's, a
 * "woodland-shrub" is shrub, a "mixed forest" is not only forest. */
typedef struct kind_words {
    land_kind kind;
    const char *const *words;
    const char *const *also; /* NULL, or a second word the name must hold too */
} kind_words;

static const char *const w_water[] = {"water", "lake", "river", "sea", "ocean", "estuar", "lagoon", NULL};
static const char *const w_snow[] = {"snow", "ice", "glacier", NULL};
static const char *const w_wet[] = {"wetland", "marsh", "bog", "swamp", "fen", NULL};
static const char *const w_woody[] = {"woody", "wooded", "forest", NULL};
static const char *const w_herb[] = {"herbaceous", "emergent", NULL};
static const char *const w_decid[] = {"deciduous", "broad-leaved", "broadleaved", "broadleaf", NULL};
static const char *const w_ever[] = {"evergreen", "conifer", "needle", NULL};
static const char *const w_mixed[] = {"mixed", NULL};
static const char *const w_forest[] = {"forest", "wood", "tree", NULL};
static const char *const w_shrub[] = {"shrub", "scrub", "heath", "moor", "chaparral", NULL};
static const char *const w_grass[] = {"grass", "herbaceous", "meadow", "prairie", "tundra", NULL};
static const char *const w_crop[] = {"cultivated", "crop", "pasture", "arable", "agricult", "orchard",
                                     "vineyard", "hay", "rice", "field", NULL};
static const char *const w_built[] = {"developed", "urban", "built", "industrial", "road", "settlement",
                                      NULL};
static const char *const w_bare[] = {"barren", "rock", "sand", "bare", "dune", "beach", NULL};

static const kind_words kinds[] = {
    {LAND_WETLAND_WOODY, w_wet, w_woody},
    {LAND_WETLAND_HERBACEOUS, w_wet, w_herb},
    {LAND_WETLAND, w_wet, NULL},
    {LAND_SNOW_ICE, w_snow, NULL},
    {LAND_WATER, w_water, NULL},
    {LAND_FOREST_DECIDUOUS, w_decid, NULL},
    {LAND_FOREST_EVERGREEN, w_ever, NULL},
    {LAND_FOREST_MIXED, w_mixed, w_forest},
    {LAND_SHRUB, w_shrub, NULL},
    {LAND_FOREST, w_forest, NULL},
    {LAND_GRASS, w_grass, NULL},
    {LAND_CULTIVATED, w_crop, NULL},
    {LAND_DEVELOPED, w_built, NULL},
    {LAND_BARREN, w_bare, NULL},
};

/* 1 when the name says the map has nothing there. */
static int says_no_data(const char *name)
{
    while (isspace((unsigned char)*name)) name++;
    static const char *const none[] = {"no data", "nodata", "no_data", "unclassified", NULL};
    return !name[0] || !strcasecmp(name, "NA") || !strcasecmp(name, "N/A") || says(name, none);
}

land_kind landcover_kind_of_name(const char *name, int *no_data)
{
    *no_data = says_no_data(name);
    if (*no_data) return LAND_UNKNOWN;
    for (uint32_t i = 0; i < COUNT(kinds); i++)
        if (says(name, kinds[i].words) && (!kinds[i].also || says(name, kinds[i].also))) return kinds[i].kind;
    return LAND_UNKNOWN;
}
