/* fuzz_ecology_state.c — libFuzzer target for a saved ecology run read back: each input is the
 * forest.state that a fixed scene's `plants: {file: forest.state}` names, and the scene is built
 * with scene_build(), so the ecology plugin's run is opened (scene_build/ecology_session.h), loads the
 * state (the plugin's eco_sim_load) and places its plants in the scene. The state's
 * fingerprint (bytes 16 to 23) and checksum (its last 8 bytes, FNV-1a of what lies between) are
 * written into every input of at least 32 bytes before it is read, so that mutated states get
 * past both to the species, streams and plants. Building must end in a scene or an error
 * sentence: a crash, a sanitizer report, a leak, a hang or runaway memory is a finding. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plugin/plugin_host.h"
#include "scene_build/ecology_session.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "fuzz_file.h"

#define TARGET "fuzz_ecology_state"
#define HEADER 24u   /* "SYLVAECO", version, byte-order mark, fingerprint */
#define MAX_STATE (1u << 16)

/* Two box species on a 5 x 5 grid, as tests/plugins/ecology/scenes/small_forest.yaml but with
 * boxes (the seeds were saved with its 8 patches), so that a run starts in little time beside
 * reading the state. */
static const char scene_text[] =
    "image: {width: 16, height: 12, spp: 1, seed: 3}\n"
    "camera: {position: [20, -40, 30], look_at: [20, 20, 0]}\n"
    "terrain:\n"
    "  origin: [0, 0]\n"
    "  spacing: [10, 10]\n"
    "  grid:\n"
    "    - [0, 3.87, 5.91, 5.18, 2.01]\n"
    "    - [0.8, 4.19, 5.99, 5.35, 2.56]\n"
    "    - [1.6, 3.69, 4.79, 4.4, 2.69]\n"
    "    - [2.4, 2.67, 2.82, 2.77, 2.54]\n"
    "    - [3.2, 1.59, 0.74, 1.04, 2.36]\n"
    "species:\n"
    "  beech: {shape: box, size: [3, 3, 6]}\n"
    "  shrub: {shape: box, size: [1, 1, 1.5]}\n"
    "ecology: {plugin: ecology, years: 5, patches: 8, species: beech shrub, min_height: 0, max_plants: 2000}\n";

static plugin_registry *registry; /* opened once, freed at exit */
static scene_file *saved_scene;   /* the scene with plants: {file: forest.state}; freed at exit */
static const char *state_path;    /* in the scratch folder (work_dir.h owns it) */
static uint64_t fingerprint;      /* of the scene's terrain and species, as the plugin saves it */
static uint8_t *state;            /* the input with its fingerprint and checksum; owned */

static void release(void)
{
    scene_file_free(saved_scene);
    plugin_registry_free(registry);
    free(state);
}

static scene_file *load(const char *name, const char *extra, err_buf *err)
{
    char path[1200], text[sizeof scene_text + 64];
    snprintf(text, sizeof text, "%s%s", scene_text, extra);
    fuzz_write_file(TARGET, fuzz_scratch_path(name, path, sizeof path), (const uint8_t *)text, strlen(text));
    return scene_file_load(path, registry, err);
}

/* The fingerprint the plugin writes for the scene: a year-0 run saved and its bytes read. */
static int read_fingerprint(err_buf *err)
{
    scene_file *sf = load("run.yaml", "", err); /* owned here */
    build_options opt = {.quiet = 1, .threads = 1, .no_ecology = 1};
    scene *s = sf ? scene_build(sf, registry, &opt, err) : NULL; /* owned here */
    ecology_session *e = s ? ecology_session_open(sf, s, registry, &opt, err) : NULL; /* owned here */
    int rc = !e || ecology_session_save(e, state_path, err);
    FILE *f = rc ? NULL : fopen(state_path, "rb");
    rc = !f || fseek(f, 16, SEEK_SET) || fread(&fingerprint, 8, 1, f) != 1;
    if (f) fclose(f);
    ecology_session_free(e);
    scene_free(s);
    scene_file_free(sf);
    return rc;
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static char path[1200];
    state_path = fuzz_scratch_path("forest.state", path, sizeof path);
    err_buf err = {{0}};
    registry = plugin_registry_open(&err);
    if (registry && plugin_registry_load_all(registry, &err)) {
        plugin_registry_free(registry);
        registry = NULL;
    }
    state = malloc(MAX_STATE);
    if (!registry || !state || read_fingerprint(&err) ||
        !(saved_scene = load("scene.yaml", "plants: {file: forest.state}\n", &err))) {
        fprintf(stderr, "%s: cannot start (%s); build the plugins first\n", TARGET, err.msg);
        exit(2);
    }
    atexit(release);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > MAX_STATE) return 0;
    memcpy(state, data, size);
    if (size >= HEADER + 8) {
        memcpy(state + 16, &fingerprint, 8);
        uint64_t sum = 0xcbf29ce484222325ull;
        for (size_t i = HEADER; i < size - 8; i++) sum = (sum ^ state[i]) * 0x100000001b3ull;
        memcpy(state + size - 8, &sum, 8);
    }
    fuzz_write_file(TARGET, state_path, state, size);
    err_buf err = {{0}};
    build_options opt = {.quiet = 1, .threads = 1};
    scene *s = scene_build(saved_scene, registry, &opt, &err); /* owned here */
    if (!s && !err.msg[0]) fuzz_finding(TARGET, "building failed without a message");
    scene_free(s);
    return 0;
}
