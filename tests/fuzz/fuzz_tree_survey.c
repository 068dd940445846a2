/* fuzz_tree_survey.c — libFuzzer target for the tree-survey reader (site/tree_survey.h) of the
 * trees: section: each input is the survey.csv of a request in EPSG:4326 with the columns lon,
 * lat, species, height, crown and age, read with survey_read() into a site in EPSG:32611 (WGS 84
 * / UTM zone 11N). Reading must end in trees at finite map points, each attribute absent or
 * text, or an error sentence: a crash, a sanitizer report, a leak, a hang or runaway memory is a
 * finding, and so is a message of GDAL's or PROJ's own (the reader promises to keep them off
 * stderr). The reader hands attributes back as text: whether a height is a finite number above 0
 * is the section's to judge (scene_file_trees.c), so here an attribute is absent or not empty.
 * PROJ's network is shut as the command line shuts it. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cpl_error.h>

#include "site/proj_network.h"
#include "site/site_frame.h"
#include "site/tree_survey.h"
#include "util/arena.h"
#include "fuzz_file.h"

#define TARGET "fuzz_tree_survey"

static survey_request request; /* its path in the scratch folder (work_dir.h owns it) */
static site_frame *site;       /* owns request.site_wkt; lives as long as the process */

/* Reads the survey as it stands; 0 or -1 with err set. The points live in a. */
static int read_survey(arena *a, survey_points *pts, err_buf *err)
{
    survey_key bad = SURVEY_KEY_FILE;
    return survey_read(a, &request, pts, &bad, err);
}

/* GDAL's handler of last resort: reached only by a message that no quiet handler caught. */
static void gdal_message(CPLErr level, CPLErrorNum number, const char *text)
{
    (void)number;
    if (level == CE_Debug) return;
    fprintf(stderr, "%s: GDAL's own message: %s\n", TARGET, text);
    fuzz_finding(TARGET, "a message of GDAL's or PROJ's own would have reached stderr");
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static char path[1200];
    err_buf err = {{0}};
    proj_network_start();
    CPLSetErrorHandler(gdal_message);
    if (!(site = site_frame_new("EPSG:32611", NULL, &err))) {
        fprintf(stderr, "%s: the site CRS is refused (%s)\n", TARGET, err.msg);
        exit(2);
    }
    request = (survey_request){.path = fuzz_scratch_path("survey.csv", path, sizeof path), .shown = "survey.csv",
                               .crs = "EPSG:4326", .x_field = "lon", .y_field = "lat",
                               .site_wkt = site_frame_wkt(site)};
    request.field[SURVEY_SPECIES] = "species", request.field[SURVEY_HEIGHT] = "height";
    request.field[SURVEY_CROWN] = "crown", request.field[SURVEY_AGE] = "age";
    /* The harness itself checked: one tree of test_tree_survey.c's CSV, at its UTM point, its
     * height read and its empty crown absent. */
    static const char row[] = "lon,lat,species,height,crown,age\n-117.836691786,49.889674948,fir,12.5,,40\n";
    fuzz_write_file(TARGET, request.path, (const uint8_t *)row, strlen(row));
    arena *a = arena_new(); /* freed below */
    survey_points pts;
    int rc = a ? read_survey(a, &pts, &err) : -1;
    const survey_point *p = rc ? NULL : pts.points;
    if (rc || pts.n != 1 || fabs(p->map[0] - 439900) > 0.01 || fabs(p->map[1] - 5526700) > 0.01 ||
        !p->value[SURVEY_HEIGHT] || strcmp(p->value[SURVEY_HEIGHT], "12.5") || p->value[SURVEY_CROWN]) {
        fprintf(stderr, "%s: the fixed survey does not read back (%s)\n", TARGET, err.msg);
        exit(2);
    }
    arena_free(a);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_write_file(TARGET, request.path, data, size);
    arena *a = arena_new(); /* owns the points; freed below */
    if (!a) return 0;
    err_buf err = {{0}};
    survey_points pts;
    if (read_survey(a, &pts, &err)) {
        if (!err.msg[0]) fuzz_finding(TARGET, "reading failed without a message");
        arena_free(a);
        return 0;
    }
    for (uint32_t i = 0; i < pts.n; i++) {
        const survey_point *p = &pts.points[i];
        if (!isfinite(p->map[0]) || !isfinite(p->map[1]))
            fuzz_finding(TARGET, "a tree at a map point that is not finite");
        if (!p->feature || !p->feature[0]) fuzz_finding(TARGET, "a tree that names no line");
        for (int k = 0; k < SURVEY_N_VALUES; k++)
            if (p->value[k] && !p->value[k][0]) fuzz_finding(TARGET, "an attribute that is set but empty");
    }
    arena_free(a);
    return 0;
}
