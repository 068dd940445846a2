/* ztv_labels.c — the names on a visibility map's page (ztv_labels.h). */
#include "ztv/ztv_labels.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

static void today(char out[16])
{
    const char *epoch = getenv("SOURCE_DATE_EPOCH");
    time_t t = epoch && *epoch ? (time_t)strtoll(epoch, NULL, 10) : time(NULL);
    struct tm tm;
    gmtime_r(&t, &tm);
    strftime(out, 16, "%Y-%m-%d", &tm);
}

static const char *base_name(const char *path)
{
    const char *slash = path ? strrchr(path, '/') : NULL;
    return slash ? slash + 1 : path;
}

void ztv_labels_fill(ztv_labels *l, const scene_file *sf, ztv_info *info)
{
    memset(l, 0, sizeof *l);
    today(l->date);
    info->project = base_name(sf->path);
    info->dtm = base_name(scene_file_dtm_path(sf));
    info->date = l->date;
    info->target_heights = sf->ztv.n_targets ? NULL : sf->ztv.target_heights;
    info->n_target_heights = sf->ztv.n_targets ? 0 : sf->ztv.n_target_heights;
}
