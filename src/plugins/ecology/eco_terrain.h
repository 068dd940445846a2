/* eco_terrain.h — the terrain as the ecology sees it: a grid of patches s_{i,k} over the
 * heightfield (004 §4, Fig. 4.3) with each patch's centre height and unit normal, the water
 * patches, and the five static factors of 004 §4.1–4.5, each in [0, 1]: altitude ȳ (4.2),
 * slope (4.3–4.4), humidity (Algorithm 3), windiness (Algorithm 4 as corrected in MODELS.md)
 * and sunniness (Algorithm 5).
 *
 * Frame: sylva's (Z up, x east, y north). Patch (i, k) covers
 * [x0 + i kx, x0 + (i+1) kx] x [y0 + k ky, y0 + (k+1) ky]; arrays are row-major with k the
 * row (row 0 the southern row), index i + k ni.
 *
 * Ownership: an eco_terrain owns its arrays; eco_terrain_free releases them (accepts NULL).
 * Nothing here keeps a pointer to the heightfield it was built from.
 */
#ifndef ECO_TERRAIN_H
#define ECO_TERRAIN_H

#include <stdint.h>

#include "sylva/plugin.h"

/* The factor maps, in the order they are listed and written. */
typedef enum eco_factor {
    ECO_ALTITUDE = 0,
    ECO_SLOPE = 1,
    ECO_HUMIDITY = 2,
    ECO_WINDINESS = 3,
    ECO_SUNNINESS = 4,
    ECO_N_FACTORS = 5
} eco_factor;

extern const char *const eco_factor_names[ECO_N_FACTORS];

/* Parameters of the factor computations (the plugin's scene parameters). */
typedef struct eco_factor_params {
    uint32_t patches;        /* patches along the terrain's longer side */
    double water_altitude;   /* ȳ_w: patches with ȳ below it are water (0: none) (4.5) */
    double rain;             /* m_climate: precipitation every patch receives */
    double water_humidity;   /* m_w: added to water patches (4.5) */
    double runoff;           /* k_m in [0, 1]: runoff strength (4.6) */
    uint32_t humidity_blur;  /* N_mblur: passes of the 5-point average */
    double wind_azimuth_deg; /* where the wind comes from, clockwise from north */
    uint32_t wind_samples;   /* N_w: patches marched upwind */
    double shelter_deg;      /* Θ0: shelter angle at which windiness reaches 0 */
    double latitude_deg;     /* of the terrain; sets the summer sun path (004 appendix B) */
    uint32_t sun_samples;    /* N_l: sun positions along the day, odd */
    double ambient;          /* l_ambient: light share in shadow, (0, 1) */
    unsigned threads;        /* worker threads for the shadow and wind marches (>= 1) */
} eco_factor_params;

typedef struct eco_terrain {
    uint32_t ni, nk;         /* patches along x and y */
    double x0, y0;           /* south-west corner of the grid (the heightfield's first node) */
    double kx, ky;           /* patch size along x and y, metres */
    double k;                /* K = min(kx, ky): the march step and the N_opt unit (4.27) */
    double *cz;              /* centre height c_y of each patch (004's y is sylva's z) */
    double *normal;          /* unit normal per patch, 3 each */
    uint8_t *water;          /* 1: a water patch (ȳ < ȳ_w, or below the heightfield's water) */
    float *water_map;        /* the same as 0 / 1 values, for the "water" map */
    float *factor[ECO_N_FACTORS]; /* ni * nk values each, in [0, 1] */
    /* the heightfield, copied: plants are placed on it and z is read from it */
    uint32_t hnx, hny;
    double hx0, hy0, hdx, hdy;
    float *hz;
    int has_water;
    double water_level;
} eco_terrain;

/* Builds the patch grid over `hf` and computes every factor. Returns 0, or -1 with msg (size n)
 * saying what is wrong (a parameter out of its valid combination, or out of memory). */
int eco_terrain_build(eco_terrain *t, const sylva_heightfield *hf, const eco_factor_params *fp,
                      char *msg, size_t n);
void eco_terrain_free(eco_terrain *t); /* accepts a zeroed struct */

/* Height of the heightfield at (x, y), bilinear, clamped to the grid. */
double eco_height_at(const eco_terrain *t, double x, double y);

/* 1 when (x, y) lies in water: in a water patch, or below the heightfield's water surface. */
int eco_in_water(const eco_terrain *t, double x, double y);

/* Patch index (i + k ni) of a point, or -1 outside the grid. */
int64_t eco_patch_of(const eco_terrain *t, double x, double y);

/* The factor computations, each over an eco_terrain whose grid, cz, normal and water are set
 * (eco_terrain_build calls them in this order). */
void eco_altitude(eco_terrain *t);                               /* (4.2) */
void eco_slope(eco_terrain *t);                                  /* (4.3) */
int eco_humidity(eco_terrain *t, const eco_factor_params *fp);   /* Algorithm 3; -1: no memory */
void eco_windiness(eco_terrain *t, const eco_factor_params *fp); /* Algorithm 4, corrected */
void eco_sunniness(eco_terrain *t, const eco_factor_params *fp); /* Algorithm 5 */

/* The sun path of 004 §4.5 for a latitude: sample n of n_l (odd) as a unit vector toward the
 * sun (4.11–4.13, normalised) and its weight k_l (4.16). */
void eco_sun_sample(double latitude_deg, uint32_t n_l, uint32_t n, double dir[3], double *weight);

/* The largest elevation angle φ (4.9), seen from patch p's centre, of the patch centres met by
 * marching `samples` steps of K from it along the unit vector (ux, uy); 0 when none is higher. */
double eco_shelter_angle(const eco_terrain *t, size_t p, double ux, double uy, uint32_t samples);

/* 1 when a patch met by marching from patch p's centre toward the sun's horizontal direction
 * rises above the sun's elevation; the march ends at the terrain's edge (not shadowed) or once
 * even the highest patch (z_max) could no longer reach the sun's elevation. */
int eco_in_shadow(const eco_terrain *t, double z_max, size_t p, const double sun[3]);

/* Normalises v (n values) to [0, 1] by its minimum and maximum; constant values become 0.5. */
void eco_normalise(double *v, size_t n);

#endif
