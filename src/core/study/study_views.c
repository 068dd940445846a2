/* study_views.c — picking and ranking a study's viewpoints (study_views.h). */
#include "study/study_views.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/name_list.h"

/* The viewpoint named (len bytes at name) among the scene's and its points, or NULL. */
static const scene_viewpoint *find(const scene_file *sf, const char *name, size_t len)
{
    for (uint32_t i = 0; i < sf->n_viewpoints + sf->study.n_points; i++) {
        const scene_viewpoint *v = i < sf->n_viewpoints ? &sf->viewpoints[i] : &sf->study.points[i - sf->n_viewpoints];
        if (strlen(v->name) == len && !memcmp(v->name, name, len)) return v;
    }
    return NULL;
}

/* "a, b, c" of every viewpoint the study could render, cut to fit. */
static void all_names(const scene_file *sf, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (uint32_t i = 0; i < sf->n_viewpoints + sf->study.n_points && used + 1 < size; i++) {
        const char *name = i < sf->n_viewpoints ? sf->viewpoints[i].name : sf->study.points[i - sf->n_viewpoints].name;
        used += (size_t)snprintf(buf + used, size - used, "%s%s", i ? ", " : "", name);
    }
}

static int unknown(const scene_file *sf, const char *option, const char *name, size_t len, err_buf *err)
{
    char names[ERR_MSG_MAX / 2];
    all_names(sf, names, sizeof names);
    return err_fail(err, ERR_USAGE, "%s names '%.*s', which is no viewpoint of %s; %s%s", option, (int)len, name,
                    sf->path, names[0] ? "its viewpoints are: " : "it has no viewpoints: section nor study: points",
                    names);
}

/* The viewpoints `text` names appended to out (room for every viewpoint), each once. */
static int add_named(const scene_file *sf, const char *text, const char *option, study_views *out, err_buf *err)
{
    const char *name;
    for (size_t len; (len = name_list_next(&text, &name));) {
        const scene_viewpoint *v = find(sf, name, len);
        if (!v) return unknown(sf, option, name, len, err);
        uint32_t k = 0;
        while (k < out->n && out->views[k] != v) k++;
        if (k == out->n) out->views[out->n++] = v;
    }
    return 0;
}

/* The base list: the command line's, the section's, or all. */
static int base_list(const scene_file *sf, const study_view_names *names, study_views *out, err_buf *err)
{
    if (names->viewpoints) return add_named(sf, names->viewpoints, "--viewpoints", out, err);
    if (sf->study.n_viewpoints) {
        for (uint32_t i = 0; i < sf->study.n_viewpoints; i++) {
            const char *name = sf->study.viewpoints[i];
            if (!(out->views[out->n++] = find(sf, name, strlen(name)))) /* a point --points replaced */
                return unknown(sf, "the study's viewpoints", name, strlen(name), err);
        }
        return 0;
    }
    for (uint32_t i = 0; i < sf->n_viewpoints; i++) out->views[out->n++] = &sf->viewpoints[i];
    for (uint32_t i = 0; i < sf->study.n_points; i++) out->views[out->n++] = &sf->study.points[i];
    return 0;
}

/* out kept to the viewpoints of `text` (each of which must be in it), in out's order. */
static int keep_only(const scene_file *sf, const char *text, study_views *out, err_buf *err)
{
    study_views named = {calloc((size_t)out->n + 1, sizeof *named.views), 0};
    if (!named.views) return err_nomem(err, "out of memory");
    int rc = add_named(sf, text, "--only", &named, err);
    uint32_t kept = 0;
    for (uint32_t i = 0; !rc && i < named.n; i++) {
        uint32_t k = 0;
        while (k < out->n && out->views[k] != named.views[i]) k++;
        if (k == out->n)
            rc = err_fail(err, ERR_USAGE, "--only names '%s', which the study does not render (give it in "
                          "--viewpoints or the study's viewpoints)", named.views[i]->name);
    }
    for (uint32_t i = 0; !rc && i < out->n; i++)
        for (uint32_t k = 0; k < named.n; k++)
            if (out->views[i] == named.views[k]) out->views[kept++] = out->views[i];
    if (!rc) out->n = kept;
    free(named.views);
    return rc;
}

/* The viewpoints of `text` moved to the front of out, in its order. */
static int rank_first(const scene_file *sf, const char *text, study_views *out, err_buf *err)
{
    study_views ranked = {calloc((size_t)out->n + 1, sizeof *ranked.views), 0};
    if (!ranked.views) return err_nomem(err, "out of memory");
    int rc = add_named(sf, text, "--rank", &ranked, err);
    uint32_t n_ranked = 0;
    for (uint32_t i = 0; !rc && i < ranked.n; i++) /* those the study renders */
        for (uint32_t k = 0; k < out->n; k++)
            if (out->views[k] == ranked.views[i]) ranked.views[n_ranked++] = ranked.views[i];
    for (uint32_t i = 0; !rc && i < out->n; i++) {
        uint32_t k = 0;
        while (k < n_ranked && ranked.views[k] != out->views[i]) k++;
        if (k == n_ranked) ranked.views[n_ranked++] = out->views[i];
    }
    if (!rc) memcpy(out->views, ranked.views, (size_t)out->n * sizeof *out->views);
    free(ranked.views);
    return rc;
}

/* A name that can be a folder of the output. */
static int check_folder_name(const scene_viewpoint *v, err_buf *err)
{
    int bad = !v->name[0] || !strcmp(v->name, ".") || !strcmp(v->name, "..") || strchr(v->name, '/');
    for (const char *c = v->name; !bad && *c; c++) bad = (unsigned char)*c < 0x20 || *c == 0x7f;
    if (!bad) return 0;
    return err_fail(err, ERR_USAGE, "viewpoint '%s' cannot name the folder of its files; give it a name without "
                    "'/' or control characters, other than '.' and '..'", v->name);
}

int study_views_pick(const scene_file *sf, const study_view_names *names, study_views *out, err_buf *err)
{
    *out = (study_views){calloc((size_t)sf->n_viewpoints + sf->study.n_points + 1, sizeof *out->views), 0};
    if (!out->views) return err_nomem(err, "out of memory");
    int rc = base_list(sf, names, out, err);
    if (!rc && names->only) rc = keep_only(sf, names->only, out, err);
    if (!rc && names->rank) rc = rank_first(sf, names->rank, out, err);
    for (uint32_t i = 0; !rc && i < out->n; i++) rc = check_folder_name(out->views[i], err);
    if (!rc && !out->n)
        rc = err_fail(err, ERR_USAGE, "%s has no viewpoint to render: give it a viewpoints: section, or study: "
                      "{points: FILE} (docs/study.md)", sf->path);
    if (rc) study_views_free(out);
    return rc;
}

void study_views_free(study_views *v)
{
    free(v->views);
    *v = (study_views){0};
}
