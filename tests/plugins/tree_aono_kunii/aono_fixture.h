/* aono_fixture.h — drives tree_aono_kunii through the real host in tests and benchmarks: a
 * scene, a sylva_host with its error buffer, the plugin's parameters validated from YAML text
 * against its schema, create() and generate().
 *
 * Ownership: an aono_fixture owns its scene, arena, plugin state and the meshes it generates;
 * aono_fixture_close() frees them all (and accepts a fixture that failed to open).
 */
#ifndef AONO_FIXTURE_H
#define AONO_FIXTURE_H

#include <stdint.h>

#include "aono_config.h"
#include "aono_grow.h"
#include "scene_build/host.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "util/arena.h"
#include "util/err.h"

typedef struct aono_fixture {
    scene *scene;          /* owned */
    arena *arena;          /* owned: YAML tree and validated parameters */
    err_buf err;           /* the last failure sentence (validation, create or generate) */
    sylva_host host;
    const sylva_params *params; /* in arena, NULL when validation failed */
    void *state;           /* the plugin's, NULL when create() failed */
    aono_env env;          /* the model's streams: the host's (ctx: this fixture) */
    plugin_err fail;         /* the model's last failure (aono_fixture_config, aono_fixture_grow) */
} aono_fixture;

/* Validates `yaml` (the plugin block's keys, e.g. "levels: 3\npattern: ternary\n") and runs
 * create() with scene seed `seed`. Returns 0; -1 when validation failed; the plugin's status
 * when create() failed. err holds the sentence. */
int aono_fixture_open(aono_fixture *f, const char *yaml, uint64_t seed);
/* The same for species `name` of the scene file `path` (its block beside `plugin:` and
 * `variants:`). */
int aono_fixture_open_species(aono_fixture *f, const char *path, const char *name, uint64_t seed);
void aono_fixture_close(aono_fixture *f);

/* Runs generate() for `age` into a new mesh (*out, owned by the caller: mesh_free). Returns the
 * plugin's status; *height gets out->height. */
int aono_fixture_generate(aono_fixture *f, double age, mesh **out, double *height);

/* Reads the plugin's validated parameters into *cfg (aono_config_release after); a failure is
 * in f->fail. */
int aono_fixture_config(aono_fixture *f, aono_config *cfg);

/* Grows the skeleton of `levels` levels with the fixture's configuration and f->env. */
int aono_fixture_grow(aono_fixture *f, uint32_t levels, aono_skeleton *skel);

#endif
