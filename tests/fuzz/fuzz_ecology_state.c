/* fuzz_ecology_state.c — libFuzzer target for a saved ecology run read back: each input is a
 * forest.state given to the ecology plugin's load (its eco_sim_load) on a run opened once, as
 * `sylva simulate --load` and a scene's `plants: {file: forest.state}` open it
 * (scene_build/ecology_session.h), and a state the plugin takes is then placed (its place(),
 * the plants the host receives as a scene's). The state's fingerprint (bytes 16 to 23) and
 * checksum (its last 8 bytes, FNV-1a of what lies between) are written into every input of at
 * least 32 bytes before it is read, so that mutated states get past both to the species,
 * streams and plants. A refused state leaves the run as it was, a taken one replaces all of it,
 * so each input's outcome is its own. Loading must end in placed plants of finite positions and
 * sizes or an error sentence: a crash, a sanitizer report, a leak, a hang or runaway memory is a
 * finding. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plugin/plugin_host.h"
#include "scene_build/ecology_session.h"
#include "scene_build/host.h"
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
static scene_file *run_scene;     /* the scene the run grows on; freed at exit */
static scene *built;              /* run_scene built without its ecology; freed at exit */
static ecology_session *session;  /* the run every input is loaded into; freed at exit */
static const char *state_path;    /* in the scratch folder (work_dir.h owns it) */
static uint64_t fingerprint;      /* of the scene's terrain and species, as the plugin saves it */
static uint8_t *state;            /* the input with its fingerprint and checksum; owned */

static void release(void)
{
    ecology_session_free(session);
    scene_free(built);
    scene_file_free(run_scene);
    plugin_registry_free(registry);
    free(state);
}

/* Opens the run at year 0 and reads the fingerprint it saves. */
static int open_run(err_buf *err)
{
    char path[1200];
    fuzz_write_file(TARGET, fuzz_scratch_path("run.yaml", path, sizeof path), (const uint8_t *)scene_text,
                    strlen(scene_text));
    build_options opt = {.quiet = 1, .threads = 1, .no_ecology = 1};
    run_scene = scene_file_load(path, registry, err);
    built = run_scene ? scene_build(run_scene, registry, &opt, err) : NULL;
    session = built ? ecology_session_open(run_scene, built, registry, &opt, err) : NULL;
    int rc = !session || ecology_session_save(session, state_path, err);
    FILE *f = rc ? NULL : fopen(state_path, "rb");
    rc = !f || fseek(f, 16, SEEK_SET) || fread(&fingerprint, 8, 1, f) != 1;
    if (f) fclose(f);
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
    if (!registry || !state || open_run(&err)) {
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
    uint32_t placed = 0;
    struct sylva_host *host = &session->call.host;
    if (ecology_session_load(session, state_path, &err) || ecology_session_place(session, &placed, &err)) {
        if (!err.msg[0]) fuzz_finding(TARGET, "loading failed without a message");
    } else if (placed != host->n_plants) {
        fuzz_finding(TARGET, "the plants placed are not the plants the host holds");
    }
    for (uint32_t i = 0; i < host->n_plants; i++) {
        const sylva_plant *p = &host->plants[i];
        if (!isfinite(p->position[0]) || !isfinite(p->position[1]) || !isfinite(p->height) || !isfinite(p->age) ||
            !isfinite(p->rotation))
            fuzz_finding(TARGET, "a placed plant is not finite");
    }
    host->n_plants = 0; /* the next input's plants start afresh (the host keeps the array) */
    return 0;
}
