/* fuzz_layout_csv.c — libFuzzer target for the layout CSV of an objects entry: each input is
 * the layout.csv that a fixed scene's `objects: - {layout: layout.csv, shape: box}` names, and
 * the scene is read with scene_file_load(), which reads the layout and makes one placement per
 * row. Loading must end in a scene with a placement per row or an error sentence: a crash, a
 * sanitizer report, a leak, a hang or runaway memory is a finding. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_file/scene_file.h"
#include "fuzz_file.h"

#define TARGET "fuzz_layout_csv"

static const char *scene_path, *layout_path; /* in the scratch folder (work_dir.h owns it) */

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static char scene[1200], layout[1200];
    scene_path = fuzz_scratch_path("scene.yaml", scene, sizeof scene);
    layout_path = fuzz_scratch_path("layout.csv", layout, sizeof layout);
    static const char text[] = "camera: {position: [0, -50, 10], look_at: [0, 0, 0]}\n"
                               "objects:\n  - {layout: layout.csv, shape: box, size: [2, 2, 4]}\n";
    fuzz_write_file(TARGET, scene_path, (const uint8_t *)text, strlen(text));
    /* The harness itself checked: a layout of one row gives one object. */
    static const char row[] = "id,x,y\nA,1,2\n";
    fuzz_write_file(TARGET, layout_path, (const uint8_t *)row, strlen(row));
    err_buf err = {{0}};
    scene_file *sf = scene_file_load(scene_path, NULL, &err);
    if (!sf || sf->n_objects != 1) {
        fprintf(stderr, "%s: the fixed scene does not load (%s)\n", TARGET, err.msg);
        exit(2);
    }
    scene_file_free(sf);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_write_file(TARGET, layout_path, data, size);
    err_buf err = {{0}};
    scene_file *sf = scene_file_load(scene_path, NULL, &err); /* owned here */
    if (!sf && !err.msg[0]) fuzz_finding(TARGET, "loading failed without a message");
    for (uint32_t i = 0; sf && i < sf->n_objects; i++) {
        const object_spec *o = &sf->objects[i];
        if (!o->name || !isfinite(o->position[0]) || !isfinite(o->position[1]))
            fuzz_finding(TARGET, "a placement without a name or at a position that is not finite");
    }
    scene_file_free(sf);
    return 0;
}
