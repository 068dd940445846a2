/* wp_fixture.h — a tree_weber_penn block read in tests as the plugin reads it: YAML text
 * validated against the plugin's schema by the host's own checker, then wp_config_read() through
 * a real host, so every message is the sentence the user sees, with its file:line:column; and
 * the plugin's own create() and generate() on that block, as the host calls them.
 *
 * Ownership: a wp_fixture owns its scene, arena, host and plugin state; wp_fixture_close()
 * frees them (and accepts a fixture that failed to open). */
#ifndef WP_FIXTURE_H
#define WP_FIXTURE_H

#include <stdint.h>

#include "scene/mesh.h"
#include "scene/scene.h"
#include "scene_build/host.h"
#include "util/arena.h"
#include "util/err.h"
#include "wp_config.h"

typedef struct wp_fixture {
    scene *scene;                /* owned */
    arena *arena;                /* owned: the YAML tree and the validated parameters */
    err_buf err;                 /* the last failure sentence (validation or reading) */
    sylva_host host;
    const sylva_params *params;  /* in arena; NULL when validation failed */
    wp_config cfg;               /* what wp_config_read gave */
    void *state;                 /* the plugin's, after wp_fixture_create; NULL before or on failure */
} wp_fixture;

/* Validates `yaml` (the keys beside `plugin:`, as in "model: {levels: 2}\n", read as test.yaml
 * in folder `dir`) and reads it. Returns 0; -1 when the schema refused it; the reading's
 * status otherwise. err holds the sentence. */
int wp_fixture_open(wp_fixture *f, const char *yaml, const char *dir);
/* The same for species `name` of the scene file `path` (its block beside `plugin:` and
 * `variants:`; relative paths in it resolve against the file's folder). */
int wp_fixture_open_species(wp_fixture *f, const char *path, const char *name);
void wp_fixture_close(wp_fixture *f);

/* Runs the plugin's create() on the opened block. Returns its status (err holds the sentence). */
int wp_fixture_create(wp_fixture *f);

/* Runs generate() for variant `variant` of n_variants at `age` into a new mesh (*out, owned by
 * the caller: mesh_free). Returns the plugin's status; *height gets out.height. */
int wp_fixture_generate(wp_fixture *f, double age, uint32_t variant, uint32_t n_variants, mesh **out, double *height);

#endif
