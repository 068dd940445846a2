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

int ztv_labels_fill(ztv_labels *l, const scene_file *sf, ztv_info *info, err_buf *err)
{
    memset(l, 0, sizeof *l);
    today(l->date);
    uint32_t n = sf->n_viewpoints + sf->study.n_points;
    l->names = calloc((size_t)n + 1, sizeof *l->names);
    l->xy = calloc((size_t)n + 1, sizeof *l->xy);
    if (!l->names || !l->xy) {
        ztv_labels_free(l);
        return err_nomem(err, "out of memory for the map's viewpoints");
    }
    for (uint32_t k = 0; k < n; k++) {
        const scene_viewpoint *v = k < sf->n_viewpoints ? &sf->viewpoints[k] : &sf->study.points[k - sf->n_viewpoints];
        l->names[k] = v->name;
        l->xy[k][0] = v->camera.position[0], l->xy[k][1] = v->camera.position[1];
    }
    info->project = base_name(sf->path);
    info->dtm = base_name(scene_file_dtm_path(sf));
    info->date = l->date;
    info->target_heights = sf->ztv.n_targets ? NULL : sf->ztv.target_heights;
    info->n_target_heights = sf->ztv.n_targets ? 0 : sf->ztv.n_target_heights;
    info->n_viewpoints = n;
    info->viewpoint_names = l->names;
    info->viewpoint_xy = (const double(*)[2])l->xy;
    return 0;
}

void ztv_labels_free(ztv_labels *l)
{
    free(l->names);
    free(l->xy);
    l->names = NULL, l->xy = NULL;
}
