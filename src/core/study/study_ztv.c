/* study_ztv.c — the study's visibility map: its record, its check and its making (study_ztv.h). */
#include "study/study_ztv.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "io/atomic_file.h"
#include "io/output_folder.h"
#include "study/study_manifest.h"

/* The files a whole map has, whatever its modes: the bare-earth GeoTIFF and map, the summary and
 * the GeoPackage. */
static const char *const map_files[] = {"ztv_bare.tif", "ztv_bare.png", "ztv_summary.csv", "ztv_layers.gpkg"};

int study_ztv_record(const scene_file *sf, const study_views *views, char *out, err_buf *err)
{
    size_t used = (size_t)snprintf(out, STUDY_ZTV_RECORD_MAX,
                                   "sylva study record 1\nsylva %s\nscene %016llx\nproduct ztv\nseed %llu\n"
                                   "season_day %u\nviewpoints %u\n",
                                   SYLVA_VERSION, (unsigned long long)sf->digest, (unsigned long long)sf->image.seed,
                                   sf->season.day, views->n);
    for (uint32_t k = 0; k < views->n && used < STUDY_ZTV_RECORD_MAX; k++) {
        char camera[STUDY_MANIFEST_MAX];
        study_record r = {.scene_digest = sf->digest, .viewpoint = views->views[k]->name,
                          .camera = &views->views[k]->camera, .product = "ztv", .frame = "map"};
        study_manifest_text(&r, camera);
        const char *own = strstr(camera, "position "); /* the camera's lines alone */
        used += (size_t)snprintf(out + used, STUDY_ZTV_RECORD_MAX - used, "viewpoint %u %s\n%s", k + 1,
                                 views->views[k]->name, own ? own : "");
    }
    if (used >= STUDY_ZTV_RECORD_MAX)
        return err_fail(err, ERR_LIMIT, "the record of the study's visibility map would pass %d bytes: "
                        "fewer viewpoints", STUDY_ZTV_RECORD_MAX);
    return 0;
}

static int record_path(const char *dir, char out[ATOMIC_PATH_MAX])
{
    int n = snprintf(out, ATOMIC_PATH_MAX, "%s/ztv.manifest", dir);
    return n > 0 && n < ATOMIC_PATH_MAX ? 0 : -1;
}

int study_ztv_current(const char *dir, const char *text)
{
    char path[ATOMIC_PATH_MAX];
    struct stat st;
    for (size_t k = 0; k < sizeof map_files / sizeof *map_files; k++) {
        if (snprintf(path, sizeof path, "%s/%s", dir, map_files[k]) >= (int)sizeof path) return 0;
        if (stat(path, &st) || !S_ISREG(st.st_mode)) return 0;
    }
    if (record_path(dir, path)) return 0;
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    char *held = malloc(STUDY_ZTV_RECORD_MAX + 1); /* owned here */
    size_t n = held ? fread(held, 1, STUDY_ZTV_RECORD_MAX + 1, f) : 0;
    fclose(f);
    int same = held && n == strlen(text) && !memcmp(held, text, n);
    free(held);
    return same;
}

int study_ztv_make(const study_ztv *z, const scene_file *sf, const scene *s, const study_views *views,
                   const char *dir, const char *text, const run_parts *parts, phase_times *times, err_buf *err)
{
    if (!z->map) return err_fail(err, ERR_INTERNAL, "this program cannot make the study's visibility map");
    if (!parts->part && output_folder_make(dir, err)) return -1;
    if (z->map(z->user, sf, s, views, dir, parts, times, err)) return -1;
    char path[ATOMIC_PATH_MAX];
    if (parts->part) return 0;
    if (record_path(dir, path)) return err_fail(err, ERR_USAGE, "%s: the path is too long", dir);
    return study_manifest_write(path, text, err);
}
