/* sylva/ecology_ext.h — the optional interfaces "sylva.ecology.v1", "v2" and "v3" of an ecology
 * plugin: a simulation the host runs year by year, and the fate of plants set out by hand.
 * Part of the plugin ABI (sylva/plugin.h, whose version and rules it follows); plugin.h includes
 * it, so a plugin written against an older header compiles unchanged. */
#ifndef SYLVA_ECOLOGY_EXT_H
#define SYLVA_ECOLOGY_EXT_H

#include "sylva/plugin.h"

#ifdef __cplusplus
extern "C" {
#endif

/* =============================================================================================
 * Optional interface "sylva.ecology.v1": an ecology simulation the host runs year by year.
 *
 * An ecology plugin whose descriptor's extension(SYLVA_ECOLOGY_EXT_V1) returns a
 * sylva_ecology_ext_v1 table lets the host drive the simulation itself (`sylva simulate`,
 * `sylva factors`): start a run from create()'s state and an ecology request, step it a year at
 * a time, read the living plants and the terrain factor maps, save the whole run to a file and
 * load it to continue. A run started from the same state and request and stepped to the scene's
 * year holds the plants generate() places. The layouts below are fixed under this id: a change
 * is a new id.
 *
 * Ownership: a run is the plugin's and is freed by run_free (accepts NULL); it borrows the state
 * create() made, which must outlive it, and copies what it needs from the request. Factor values
 * belong to the run. Functions that can fail return SYLVA_OK or a negative sylva_status and
 * leave a sentence through api->error().
 */
#define SYLVA_ECOLOGY_EXT_V1 "sylva.ecology.v1"

typedef struct sylva_ecology_run sylva_ecology_run; /* opaque: the plugin's */

/* One living plant. */
typedef struct sylva_ecology_plant_record {
    uint32_t species;     /* index into the request's species array */
    double position[3];   /* metres; z on the terrain surface */
    double age;           /* years */
    double height;        /* metres: the normalised height times the species' model_height */
    double radius;        /* ecological radius, metres */
    double vigour;        /* [0, 1] */
} sylva_ecology_plant_record;

/* One terrain factor on the run's patch grid. */
typedef struct sylva_ecology_factor_map {
    const char *name;     /* "altitude", "slope", ...: static in the plugin */
    uint32_t nx, ny;      /* patches along x (west to east) and y (south to north) */
    double x0, y0;        /* south-west corner of patch (0, 0), metres */
    double dx, dy;        /* patch size, metres */
    const float *values;  /* nx * ny values in [0, 1], row 0 the southern row; owned by the run */
} sylva_ecology_factor_map;

#define SYLVA_ECOLOGY_ALL_SPECIES 0xffffffffu

typedef struct sylva_ecology_ext_v1 {
    uint32_t size; /* sizeof(sylva_ecology_ext_v1) as the plugin compiled it */
    /* Starts a run at year 0 on the request's terrain and species. */
    int (*run_new)(void *state, const sylva_host_api *, sylva_host *,
                   const sylva_ecology_request *, sylva_ecology_run **run);
    void (*run_free)(sylva_ecology_run *run);
    uint32_t (*years_wanted)(const sylva_ecology_run *); /* the years the scene asks for */
    uint32_t (*year)(const sylva_ecology_run *);         /* years simulated so far */
    /* Simulates `years` more years. */
    int (*step)(sylva_ecology_run *, const sylva_host_api *, sylva_host *, uint32_t years);
    /* Living plants of one species, or of all with SYLVA_ECOLOGY_ALL_SPECIES. */
    uint32_t (*plant_count)(const sylva_ecology_run *, uint32_t species);
    /* Copies living plants [first, first + count) in the run's order (by species, then in
     * order of birth) into out. */
    int (*plants)(const sylva_ecology_run *, const sylva_host_api *, sylva_host *, uint32_t first,
                  uint32_t count, sylva_ecology_plant_record *out);
    uint32_t (*factor_count)(const sylva_ecology_run *);
    int (*factor)(const sylva_ecology_run *, uint32_t index, sylva_ecology_factor_map *out);
    /* The whole run (plants, year, random streams) to a file (written whole or not at all), and
     * back: load replaces the run's state with the file's, refusing a file from another
     * terrain, species list or parameters. */
    int (*save)(const sylva_ecology_run *, const sylva_host_api *, sylva_host *, const char *path);
    int (*load)(sylva_ecology_run *, const sylva_host_api *, sylva_host *, const char *path);
} sylva_ecology_ext_v1;

/* "sylva.ecology.v2": v1's table, then place(). A plugin offering v2 may answer a request for v1
 * with the same table's v1 part (its size is then v2's). */
#define SYLVA_ECOLOGY_EXT_V2 "sylva.ecology.v2"

typedef struct sylva_ecology_ext_v2 {
    sylva_ecology_ext_v1 v1; /* v1.size = sizeof(sylva_ecology_ext_v2) as the plugin compiled it */
    /* Adds the run's plants with api->plant_add exactly as generate() adds those of a run it
     * simulated to the same year (the same plants, turns, heights and normalised ages, seedlings
     * left out alike), so a run saved and loaded renders as the run itself; *placed gets how
     * many. */
    int (*place)(const sylva_ecology_run *, const sylva_host_api *, sylva_host *, uint32_t *placed);
} sylva_ecology_ext_v2;

/* "sylva.ecology.v3": v2's table, then planted_fate(). A plugin offering v3 may answer a request
 * for v1 or v2 with the same table's part (its size is then v3's). */
#define SYLVA_ECOLOGY_EXT_V3 "sylva.ecology.v3"

/* One plant set out by hand (a planting plan's), as it is at planting. */
typedef struct sylva_ecology_planted {
    uint32_t species;     /* index into the request's species array */
    double position[2];   /* x, y, metres */
    double height;        /* metres at planting */
    double age;           /* years at planting */
    uint32_t taken_out;   /* the year since planting from which management takes it out (it
                           * stands no more from that year on); 0: never */
    uint32_t replaced_until; /* the last year since planting in which, dying, it is replaced in kind
                              * (the same stock set out in its place, its number kept); 0: never */
} sylva_ecology_planted;

typedef struct sylva_ecology_ext_v3 {
    sylva_ecology_ext_v2 v2; /* v2.v1.size = sizeof(sylva_ecology_ext_v3) as the plugin compiled it */
    /* Grows plants [0, n), all set out in year 0, for `years` years among themselves on the
     * run's terrain by the run's species and rules — growth, competition, deaths — with no
     * seedlings, drawing from streams keyed by `seed` alone (the run itself is left as it was).
     * died[i] gets the year (1..years) in which plant i died, or 0 when it stands at the end
     * (or was taken out before dying); one dying in a year up to its replaced_until is set out
     * again as it was at planting and is not counted dead. A plant of a species the run does not simulate takes no
     * part: it neither shades another nor dies. The same plants and seed give the same deaths
     * for any thread count, and fewer years give the same deaths up to their last. */
    int (*planted_fate)(const sylva_ecology_run *, const sylva_host_api *, sylva_host *,
                        const sylva_ecology_planted *plants, uint32_t n, uint32_t years, uint64_t seed,
                        uint32_t *died);
} sylva_ecology_ext_v3;

#ifdef __cplusplus
}
#endif
#endif
