/* eco_sim.h — the ecosystem simulation of 004 ch. 4 (MODELS.md §6): plants of several species
 * on the patch grid, one year at a time by Algorithm 9 — add (reproduction 4.30–4.31,
 * placement by Algorithm 7), grow (4.32) with power (4.18) and dominance (Algorithm 8), remove
 * the dead (age 4.26, domination p_m, unfavourable conditions).
 *
 * Randomness: fifteen streams per species from the caller's eco_random (the plugin file hands
 * in the host's streams), one per purpose — the thirteen of 004 Fig. C.16 and sylva's
 * rotation and edge-band establishment — keyed by purpose and (stream seed, species). A species'
 * draws come from its own streams in a fixed order, and a species' seedlings, growth and deaths
 * touch only its own plants, so the species run on worker threads; the dominance search, also
 * on worker threads, draws nothing. The same seeds therefore give the same forest for any
 * thread count.
 *
 * Failures: functions that can fail return SYLVA_OK or a negative sylva_status with the sentence
 * in a plugin_err; the model never calls the host.
 *
 * Ownership: an eco_sim owns everything in it; eco_sim_free releases it (accepts NULL). It
 * keeps no pointer to the random source, the request or the error.
 */
#ifndef ECO_SIM_H
#define ECO_SIM_H

#include <stdint.h>

#include "plugin_err.h"
#include "plugin_params.h"
#include "eco_species.h"
#include "eco_terrain.h"
#include "sylva/plugin.h"

/* The random streams, each per species. */
typedef enum eco_stream {
    ECO_RNG_NEAR = 0,         /* near a parent or anywhere (p_s) */
    ECO_RNG_PARENT,           /* which parent (Algorithm 7's index list) */
    ECO_RNG_SIDE,             /* which neighbouring patch of the parent's */
    ECO_RNG_ANYWHERE,         /* which patch for a seedling from anywhere */
    ECO_RNG_POSITION_I,       /* where on its patch along x */
    ECO_RNG_POSITION_J,       /* where on its patch along y */
    ECO_RNG_DEATH_DOMINANCE,  /* death of a dominated plant (p_m) */
    ECO_RNG_DEATH_ALTITUDE,   /* death from unfavourable altitude */
    ECO_RNG_DEATH_HUMIDITY,   /* ... humidity */
    ECO_RNG_DEATH_SUNNINESS,  /* ... sunniness */
    ECO_RNG_DEATH_WINDINESS,  /* ... windiness */
    ECO_RNG_DEATH_SLOPE,      /* ... slope */
    ECO_RNG_DEATH_AGE,        /* the death age t_max (4.26) */
    ECO_RNG_ROTATION,         /* sylva's: the plant's turn about the vertical */
    ECO_RNG_ESTABLISH,        /* sylva's: whether a seedling in the edge band takes root */
    ECO_N_STREAMS
} eco_stream;

#define ECO_N_SEEDED_STREAMS 13 /* the thesis's; `stream_seeds` sets these */

extern const char *const eco_stream_purposes[ECO_N_STREAMS];

/* Where the random numbers come from: `stream` starts the stream for (purpose, index) — the
 * host's keyed streams, so that the same scene seed gives the same numbers — and `uniform` draws
 * the next number in [0, 1) from one. Borrowed for the duration of a call. */
typedef struct eco_random {
    void (*stream)(void *ctx, sylva_rng *rng, const char *purpose, uint64_t index);
    double (*uniform)(sylva_rng *rng);
    void *ctx;
} eco_random;

/* One plant (004 §4.6: the factors of its patch are kept with it). */
typedef struct eco_plant {
    double x, y, z;     /* position, metres (z on the terrain) */
    double h;           /* normalised height in [0, 1] */
    double r;           /* ecological radius h R_s, metres (4.33) */
    double power;       /* v h p_r (4.18) */
    double v;           /* vigour (4.20) */
    double t_max;       /* death age, years (4.26) */
    double rotation;    /* radians about +Z */
    float fav[5];       /* favourabilities at its patch, ECO_FAV_* order */
    uint32_t age;       /* years */
    uint32_t patch;     /* index i + k ni of its patch */
    uint32_t planted;   /* a planted cohort's plant: its index there (eco_planted.c); 0 in a run */
    uint32_t set_out_in; /* a planted cohort's plant: the year it was set out (0 at planting); 0 in a run */
    uint8_t dominated;  /* Algorithm 8's flag from the last search */
} eco_plant;

typedef struct eco_population {
    eco_plant *plants;  /* owned; in order of birth */
    uint32_t n, cap;
} eco_population;

/* Everything a run needs besides the terrain and the species blocks. */
typedef struct eco_config {
    eco_factor_params factors;
    uint32_t years;             /* years the scene asks for */
    int64_t area[4];            /* growth rectangle i0, k0, i1, k1 (inclusive); area[0] < 0: none */
    const double *mask;         /* growth mask rows (row 0 south), or NULL; borrowed */
    double edge_fade;           /* metres: the band round the area or mask where seedlings take
                                   root less and less often (eco_edge.c); 0: a hard edge */
    uint32_t mask_rows, mask_cols;
    uint64_t stream_seeds[ECO_N_SEEDED_STREAMS];
    uint64_t max_plants;        /* limit on living plants */
    double min_height;          /* metres: shorter plants are not placed in the scene */
    unsigned threads;           /* >= 1 */
} eco_config;

typedef struct eco_sim {
    eco_terrain terrain;        /* owned */
    eco_config config;          /* copy; mask is not used after eco_sim_new */
    uint32_t n_species;         /* species taking part */
    eco_species *species;       /* owned, n_species */
    uint32_t *request_index;    /* owned: each one's index into the request's species */
    char **names;               /* owned copies of their names */
    double *model_height;       /* owned: full-grown model height, metres */
    double *p_r;                /* owned: relative power (4.19) */
    eco_population *pop;        /* owned, one per species */
    double *seeds;              /* owned: s_s from the last growth (4.31) */
    double *carry;              /* owned: fractional seedlings carried to the next year */
    sylva_rng *rng;             /* owned: ECO_N_STREAMS per species */
    uint32_t year;
    uint8_t **habitat;          /* owned, one per species: NULL (everywhere) or 1 for a patch
                                   where the land cover lets the species take root (eco_habitat.c) */
    uint8_t *growable;          /* owned: 1 for a patch where plants may grow */
    float *establish;           /* owned: chance a seedling takes root on each patch (1 in the
                                   area, falling across the edge band; eco_edge.c) */
    uint32_t *growable_list;    /* owned: those of the area itself (not the edge band), in index
                                   order: where a seedling from anywhere lands */
    uint32_t n_growable;
    uint32_t *band_list;        /* owned: the edge band's patches (0 < establish < 1, no water) */
    uint32_t n_band;
    double max_r_s;             /* max over species of R_s */
    uint32_t n_opt;             /* (4.27) */
    uint64_t fingerprint;       /* of the terrain factors, growth area and species (save/load) */
    /* scratch of the dominance search, owned */
    uint32_t cells_per_patch;   /* the search grid cuts each patch into this many cells a side */
    uint32_t cells_i, cells_k;  /* cells along x and y */
    uint32_t *cell_start;       /* cells + 1: each cell's first entry */
    double *patch_r_max;        /* per patch: the largest radius of its plants */
    struct eco_cell_entry *cell; /* the plants in cell order, strongest first in a cell */
    uint32_t cell_cap;
} eco_sim;

/* Starts a run at year 0: copies the terrain, computes the factors, reads each species block
 * and the growth area. `only` is a list of species names separated by commas or spaces (NULL or
 * empty: every species of the request); `reader` reads the plugin's block (its block locates
 * messages and may be NULL), and each species block through a reader nested in it. Returns
 * SYLVA_OK; reader->status when the code read a name a schema lacks (the host has the
 * sentence); or another negative status with err set. */
int eco_sim_new(const eco_random *rnd, plugin_params *reader, const eco_config *cfg, const char *only,
                const sylva_ecology_request *req, eco_sim **out, plugin_err *err);
void eco_sim_free(eco_sim *s);

/* One year (Algorithm 9). SYLVA_ERR_LIMIT when the living plants would pass max_plants. */
int eco_sim_step(eco_sim *s, const eco_random *rnd, plugin_err *err);

/* The parts of a year, in the order eco_sim_step runs them. */
int eco_reproduce(eco_sim *s, const eco_random *rnd, plugin_err *err); /* 4.30–4.31, Alg. 7 */
void eco_grow(eco_sim *s);                                            /* 4.32, 4.33, 4.18 */
int eco_find_dominance(eco_sim *s, plugin_err *err);                     /* Algorithm 8 */
void eco_remove_dead(eco_sim *s, const eco_random *rnd);              /* 4.26, p_m, env */

uint32_t eco_sim_count(const eco_sim *s); /* living plants */

/* A new plant of species j on its patch (pl->patch set): its favourabilities there (4.21–4.25),
 * vigour (4.20) and death age (4.26, from j's death-age stream) (eco_reproduce.c). */
void eco_plant_settle(const eco_sim *s, uint32_t j, eco_plant *pl, const eco_random *rnd);

/* Plants set out by hand (eco_planted.c): plants [0, n) grown `years` years among themselves on
 * run's terrain by run's species — growth (4.32), dominance (Algorithm 8), deaths (4.26, p_m,
 * unfavourable conditions) as a run's plants, no seedlings — on streams of their own keyed by
 * seed; died[i] the year plant i died in, 0 when it stands at the end or was taken out first.
 * run is only read. SYLVA_OK, or SYLVA_ERR_NOMEM / SYLVA_ERR_PARAM with err set. */
int eco_planted_fate(const eco_sim *run, const eco_random *rnd, const sylva_ecology_planted *plants, uint32_t n,
                     uint32_t years, uint64_t seed, uint32_t *died, plugin_err *err);

/* The edge band (eco_edge.c): the chance that a seedling takes root at distance d metres
 * outside the area, given the band's width fade and the noise n in [0, 1] there (1 for d <= 0),
 * and that chance for every patch of t, `inside` marking the area's patches; a new array (the
 * caller frees it), or NULL when out of memory. */
double eco_edge_chance(double d, double fade, double noise);
float *eco_edge_establishment(const eco_terrain *t, const uint8_t *inside, double fade, uint64_t seed);

/* The request's habitat rows (ABI 1.7) on the patches: s->habitat[j] for each species taking
 * part, NULL where the request gives none; a patch takes the row's value at the node nearest
 * its centre (eco_habitat.c). SYLVA_OK or SYLVA_ERR_NOMEM with err set. */
int eco_habitat_build(eco_sim *s, const sylva_ecology_request *req, plugin_err *err);

/* Save and load the whole state (eco_state_io.c). save writes the file whole or not at all:
 * through a new temporary file beside it (never an existing name, never through a symbolic
 * link), synced, then renamed over `path`. Failures are SYLVA_ERR_IO (or SYLVA_ERR_PARAM for a
 * state that does not fit the run, SYLVA_ERR_NOMEM) with err set. */
int eco_sim_save(const eco_sim *s, const char *path, plugin_err *err);
int eco_sim_load(eco_sim *s, const char *path, plugin_err *err);

#endif
