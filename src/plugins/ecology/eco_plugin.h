/* eco_plugin.h — the `ecology` plugin's state between create() and destroy(): the run
 * configuration read from the scene's `ecology:` block, and where each of its keys stands in the
 * scene file, so that a problem found once the terrain is known (a growth area outside it) is
 * still reported at its key. The operations and the "sylva.ecology.v1" interface use it.
 *
 * Ownership: the state owns every pointer in it (copies of the scene's values); eco_state_free
 * releases it and accepts NULL.
 */
#ifndef ECO_PLUGIN_H
#define ECO_PLUGIN_H

#include "eco_sim.h"
#include "sylva/plugin.h"

typedef struct eco_plugin_state {
    eco_config cfg;         /* cfg.mask points at mask */
    double *mask;           /* owned copy of growth_mask, or NULL */
    char *only;             /* owned copy of `species`, or NULL */
    char *file;             /* owned copy of the scene file's path, or NULL */
    sylva_value *where;     /* owned: per parameter, only is_set, line and column */
    sylva_params located;   /* the plugin's schema with `where`: for api->param_error */
} eco_plugin_state;

extern const sylva_param_spec eco_params[];
extern const uint32_t eco_params_count;

/* The descriptor (ecology.c); ecology_entry.c exports it. */
extern const sylva_plugin eco_descriptor;

/* create(), generate(), destroy() (ecology.c). */
int eco_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params, void **state);
int eco_generate(void *state, const sylva_host_api *api, sylva_host *host, const void *request, void *out);
void eco_destroy(void *state);

/* The "sylva.ecology.v1" table (eco_run.c). */
extern const sylva_ecology_ext_v1 eco_extension_v1;

/* Starts a run for the plugin state and request (shared by generate() and run_new). */
int eco_run_start(const eco_plugin_state *st, const sylva_host_api *api, sylva_host *host,
                  const sylva_ecology_request *req, eco_sim **out);

/* Simulates `years` more years with progress reports. */
int eco_run_years(eco_sim *sim, const sylva_host_api *api, sylva_host *host, uint32_t years);

#endif
