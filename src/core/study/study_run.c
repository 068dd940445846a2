/* study_run.c — a study planned, the scene built once, its jobs rendered (study_run.h). */
#include "study/study_run.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/output_folder.h"
#include "render/lights_cache.h"
#include "scene_build/scene_build.h"
#include "scene_file/host_schema.h"
#include "sheet/sheet.h"
#include "study/study_frames.h"
#include "study/study_index.h"
#include "study/study_job.h"
#include "util/name_list.h"
#include "util/progress.h"

/* What the study renders, the section's settings with the command line's over them. */
typedef struct study_plan {
    unsigned products, frames;
    study_sizing sizing;
    uint32_t spp;
    study_views views;
    study_job *jobs;              /* views.n times the frames; owned */
    uint32_t n_jobs, n_todo;      /* n_todo: the jobs with a product to render */
    int ztv, ztv_todo;            /* the visibility map asked for; and to be made */
    study_views ztv_views;        /* the viewpoints it numbers: the study's, --only or not */
    char ztv_dir[STUDY_PATH_MAX];
    char *ztv_record;             /* owned */
} study_plan;

/* The bit mask of `text`'s names among choices (option: --products, --frames). */
static int names_mask(const char *text, const char *const *choices, const char *option, unsigned *mask,
                      err_buf *err)
{
    const char *name;
    *mask = 0;
    for (size_t len; (len = name_list_next(&text, &name));) {
        unsigned k = 0;
        while (choices[k] && (strlen(choices[k]) != len || memcmp(choices[k], name, len))) k++;
        if (!choices[k]) {
            char list[256] = "";
            for (unsigned i = 0, used = 0; choices[i]; i++)
                used += (unsigned)snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "", choices[i]);
            return err_fail(err, ERR_USAGE, "%s names '%.*s'; the names are %s", option, (int)len, name, list);
        }
        *mask |= 1u << k;
    }
    return *mask ? 0 : err_fail(err, ERR_USAGE, "%s names nothing", option);
}

/* The visibility map: asked for by the products, or by the scene's ztv: section when --products
 * does not say; kept when its files and record are there (and no --force). */
static int plan_ztv(const scene_file *sf, const study_options *o, study_plan *p, study_report *rep, err_buf *err)
{
    p->ztv = (p->products >> STUDY_ZTV & 1u) || (sf->ztv.given && !o->products);
    if (!p->ztv) return 0;
    study_view_names all = o->names;
    all.only = NULL;
    int n = snprintf(p->ztv_dir, sizeof p->ztv_dir, "%s/ztv", o->dir);
    if (n < 0 || (size_t)n >= sizeof p->ztv_dir) return err_fail(err, ERR_USAGE, "%s: the path is too long", o->dir);
    if (study_views_pick(sf, &all, &p->ztv_views, err)) return -1;
    if (!(p->ztv_record = malloc(STUDY_ZTV_RECORD_MAX))) return err_nomem(err, "out of memory planning the study");
    if (study_ztv_record(sf, &p->ztv_views, p->ztv_record, err)) return -1;
    p->ztv_todo = o->force && !o->names.only ? 1 : !study_ztv_current(p->ztv_dir, p->ztv_record);
    rep->ztv = p->ztv_todo ? 1 : 2;
    return 0;
}

static int has_development(const scene_file *sf)
{
    int dev = sf->trees.development;
    for (uint32_t i = 0; i < sf->n_objects && !dev; i++) dev = sf->objects[i].development != 0;
    for (uint32_t i = 0; i < sf->n_plants && !dev; i++) dev = sf->plants[i].development;
    return dev;
}

static int plan_settings(const scene_file *sf, const study_options *o, study_plan *p, err_buf *err)
{
    const study_settings *st = &sf->study;
    p->products = st->products, p->frames = st->frames;
    if (o->products && names_mask(o->products, host_study_products, "--products", &p->products, err)) return -1;
    if (o->frames && names_mask(o->frames, host_study_frames, "--frames", &p->frames, err)) return -1;
    int print = o->print_width_mm > 0;
    p->sizing = (study_sizing){.size = {o->size[0], o->size[1]}, .print_width_mm = print ? o->print_width_mm : 0,
                               .dpi = o->dpi > 0 ? o->dpi : st->dpi, .image_width = sf->image.width};
    if (!o->size[0] && !print) {
        p->sizing.size[0] = st->size[0], p->sizing.size[1] = st->size[1];
        p->sizing.print_width_mm = st->print_width_mm;
    }
    p->spp = o->spp ? o->spp : st->spp ? st->spp : sf->image.spp;
    if ((p->products & ~(1u << STUDY_PROPOSED)) && !has_development(sf))
        return err_fail(err, ERR_INPUT, "%s has no development, so its existing view and wireline say nothing: mark "
                        "its new objects (or plants) `development: true`, or render products: proposed", sf->path);
    return 0;
}

/* The sheet's page and the study's other frames, and their lines in the sheet's record. */
static void plan_sheet(const study_plan *p, int f, study_job *j, char *extra, size_t n)
{
    j->page = sheet_page_size(p->sizing.print_width_mm, p->sizing.dpi);
    size_t used = 0;
    j->other_frames[0] = '\0';
    for (int k = 0; k < (int)STUDY_FRAMES; k++)
        if (k != f && p->frames & 1u << k && used < sizeof j->other_frames)
            used += (size_t)snprintf(j->other_frames + used, sizeof j->other_frames - used, "%s%s", used ? ", " : "",
                                     study_frame_of(k)->name);
    snprintf(extra, n, "page %.17g %.17g %.17g\nframes %s\n", j->page.width_mm, j->page.height_mm, j->page.dpi,
             j->other_frames);
}

/* Job j of viewpoint v in frame f: its camera, size, folder, records, and what is left to render. */
static int plan_job(const scene_file *sf, const study_options *o, const study_plan *p, const scene_viewpoint *v,
                    int f, study_job *j, err_buf *err)
{
    j->view = v, j->frame = f, j->camera = v->camera;
    study_frame_lens(f, &j->camera);
    study_frame_size(f, &p->sizing, j->size);
    if (j->size[0] > HOST_IMAGE_MAX_SIZE || j->size[1] > HOST_IMAGE_MAX_SIZE)
        return err_fail(err, ERR_LIMIT, "the %s frame would be %ux%u pixels; frames are at most %d pixels a side: "
                        "lower print_width or dpi", study_frame_of(f)->name, j->size[0], j->size[1],
                        HOST_IMAGE_MAX_SIZE);
    int n = snprintf(j->folder, sizeof j->folder, "%s/%s", o->dir, v->name);
    if (n < 0 || (size_t)n >= sizeof j->folder) return err_fail(err, ERR_USAGE, "%s: the path is too long", o->dir);
    char sheet_lines[256];
    plan_sheet(p, f, j, sheet_lines, sizeof sheet_lines);
    for (int k = 0; k < (int)STUDY_PRODUCTS; k++) {
        if (!(p->products & 1u << k)) continue;
        study_record r = {.scene_digest = sf->digest, .viewpoint = v->name, .camera = &j->camera,
                          .product = host_study_products[k], .frame = study_frame_of(f)->name, .width = j->size[0],
                          .height = j->size[1], .spp = p->spp, .seed = sf->image.seed,
                          .season_day = sf->season.day, .extra = k == STUDY_SHEET ? sheet_lines : NULL};
        study_manifest_text(&r, j->record[k]);
        if (k == STUDY_WIRELINE || k == STUDY_SHEET) /* what the wireline draws, in the records that draw it */
            snprintf(j->record[k] + strlen(j->record[k]), STUDY_MANIFEST_MAX - strlen(j->record[k]),
                     "inner_edges %d\n", sf->study.inner_edges);
        char png[STUDY_PATH_MAX], exr[STUDY_PATH_MAX], record[STUDY_PATH_MAX];
        if (study_job_path(j, k, "png", png, err) || study_job_path(j, k, study_product_ext(k), exr, err) ||
            study_job_path(j, k, "manifest", record, err))
            return -1;
        if (o->force || !study_manifest_current(record, j->record[k], png, exr)) j->todo |= 1u << k;
    }
    return 0;
}

static int plan_jobs(const scene_file *sf, const study_options *o, study_plan *p, study_report *rep, err_buf *err)
{
    unsigned frames = 0, products = 0;
    for (unsigned k = 0; k < STUDY_FRAMES; k++) frames += (p->frames >> k) & 1u;
    for (unsigned k = 0; k < STUDY_PRODUCTS; k++) products += (p->products >> k) & 1u;
    if (!(p->jobs = calloc((size_t)p->views.n * frames + 1, sizeof *p->jobs)))
        return err_nomem(err, "out of memory planning the study");
    for (uint32_t v = 0; v < p->views.n; v++)
        for (int f = 0; f < (int)STUDY_FRAMES; f++) {
            if (!(p->frames & 1u << f)) continue;
            study_job *j = &p->jobs[p->n_jobs++];
            if (plan_job(sf, o, p, p->views.views[v], f, j, err)) return -1;
            p->n_todo += j->todo != 0;
            for (unsigned k = 0; k < STUDY_PRODUCTS; k++) rep->kept += ((p->products & ~j->todo) >> k) & 1u;
        }
    rep->viewpoints = p->views.n, rep->jobs = p->n_jobs, rep->products = p->n_jobs * products;
    return 0;
}

/* The samples job j traces: its frame's pixels times spp, twice with the existing view or wireline. */
static uint64_t job_work(const study_plan *p, const study_job *j)
{
    int pair = (j->todo & STUDY_NEEDS_PAIR) != 0;
    return (uint64_t)j->size[0] * j->size[1] * p->spp * (pair ? 2u : 1u);
}

/* The names of the products of `todo`, for a progress line. */
static void product_names(unsigned todo, char *out, size_t n)
{
    size_t used = 0;
    out[0] = '\0';
    for (int k = 0; k < (int)STUDY_PRODUCTS && used < n; k++)
        if (todo & 1u << k) used += (size_t)snprintf(out + used, n - used, "%s%s", used ? " " : "", host_study_products[k]);
}

/* The jobs to render shared between the parts: the largest first, each to the part with the
 * least work so far (the lower part on a tie), so that every part computes the same sharing. */
static int share_jobs(study_plan *p, int parts, err_buf *err)
{
    uint64_t *load = calloc((size_t)parts, sizeof *load);
    char *given = calloc((size_t)p->n_jobs + 1, 1);
    if (!load || !given) {
        free(load), free(given);
        return err_nomem(err, "out of memory sharing the study's jobs");
    }
    for (;;) {
        int64_t next = -1;
        for (uint32_t i = 0; i < p->n_jobs; i++)
            if (p->jobs[i].todo && !given[i] && (next < 0 || job_work(p, &p->jobs[i]) > job_work(p, &p->jobs[next])))
                next = i;
        if (next < 0) break;
        int least = 0;
        for (int k = 1; k < parts; k++)
            if (load[k] < load[least]) least = k;
        p->jobs[next].part = least, given[next] = 1;
        load[least] += job_work(p, &p->jobs[next]);
    }
    free(load), free(given);
    return 0;
}

static int render_jobs(scene *s, const scene_file *sf, const study_options *o, study_plan *p,
                       const run_parts *parts, study_report *rep, err_buf *err)
{
    if (share_jobs(p, parts->parts, err)) return -1;
    for (uint32_t i = 0; i < p->n_jobs; i++) /* every viewpoint over the ground before any image */
        if (p->jobs[i].todo && study_job_place(s, sf, &p->jobs[i], err)) return -1;
    uint64_t total = 0;
    uint32_t n_mine = 0;
    for (uint32_t i = 0; i < p->n_jobs; i++)
        if (p->jobs[i].todo && p->jobs[i].part == parts->part) total += job_work(p, &p->jobs[i]), n_mine++;
    progress prog;
    progress_begin(&prog, "study", total, 1); /* its time left, printed with each job's line */
    /* one sun, sky and season for every job: their lights built once for every camera that
     * sees the same sky (render/lights_cache.h) */
    render_options ro = {.threads = o->build.threads, .quiet = 1, .spp = p->spp, .lights = lights_cache_new()};
    int rc = ro.lights ? 0 : err_nomem(err, "out of memory for the study's lights");
    for (uint32_t i = 0, mine = 0; !rc && i < p->n_jobs; i++) {
        const study_job *j = &p->jobs[i];
        if (!j->todo || j->part != parts->part) continue;
        double t0 = progress_now();
        ro.width = j->size[0], ro.height = j->size[1];
        rc = output_folder_make(o->dir, err) || output_folder_make(j->folder, err) ||
             study_job_run(s, sf, j, &ro, &rep->times, &rep->renders, err);
        if (rc) break;
        for (unsigned b = 0; b < STUDY_PRODUCTS; b++) rep->rendered += (j->todo >> b) & 1u;
        progress_advance(&prog, job_work(p, j));
        if (o->build.quiet) continue;
        char names[64], took[32], left[32];
        product_names(j->todo, names, sizeof names);
        progress_format_seconds(took, sizeof took, progress_now() - t0);
        progress_format_seconds(left, sizeof left, progress_eta(&prog));
        fprintf(stderr, "study: [%u/%u] %s %s %ux%u: %s in %s; ETA %s\n", ++mine, n_mine, j->view->name,
                study_frame_of(j->frame)->name, j->size[0], j->size[1], names, took, left);
    }
    progress_end(&prog);
    lights_cache_free(ro.lights);
    return rc;
}

/* The scene built once for every job, its ground refined around the development. */
static scene *build_once(const scene_file *sf, const plugin_registry *reg, const study_options *o,
                         study_report *rep, err_buf *err)
{
    build_options bo = o->build;
    bo.analysis = 0, bo.detail_at_development = 1, bo.times = &rep->times;
    double t0 = progress_now();
    scene *s = scene_build(sf, reg, &bo, err);
    rep->build_seconds = progress_now() - t0;
    if (!s) return err_default(err, ERR_INPUT), NULL;
    rep->builds++;
    if (!o->build.quiet)
        fprintf(stderr, "study: the scene built once in %.2fs (%u instances, %u objects) for %u viewpoint%s\n",
                rep->build_seconds, s->n_instances, s->n_objects, rep->viewpoints, rep->viewpoints == 1 ? "" : "s");
    return s;
}

/* DIR/index.html over the whole study's viewpoints (--only or not), numbered as the ZTV numbers them. */
static int write_index(const scene_file *sf, const study_options *o, const study_plan *p, err_buf *err)
{
    if (p->ztv) return study_index_write(sf, &p->ztv_views, o->dir, err);
    study_view_names all = o->names;
    all.only = NULL;
    study_views views = {0};
    int rc = study_views_pick(sf, &all, &views, err) || study_index_write(sf, &views, o->dir, err) ? -1 : 0;
    study_views_free(&views);
    return rc;
}

static void say_plan(const study_options *o, const study_plan *p, const study_report *rep)
{
    if (o->build.quiet) return;
    fprintf(stderr, "study: %u viewpoint%s, %u frame%s each: %u products in %s; %u to render, %u up to date%s\n",
            rep->viewpoints, rep->viewpoints == 1 ? "" : "s", p->views.n ? rep->jobs / p->views.n : 0,
            rep->jobs == p->views.n ? "" : "s", rep->products, o->dir, rep->products - rep->kept, rep->kept,
            !p->ztv ? "" : p->ztv_todo ? "; the ZTV to map" : "; the ZTV up to date");
}

int study_run(scene_file *sf, const plugin_registry *reg, const study_options *o, const run_parts *parts,
              study_report *rep, err_buf *err)
{
    memset(rep, 0, sizeof *rep);
    double t0 = progress_now();
    study_plan p = {0};
    int rc = plan_settings(sf, o, &p, err) || study_views_pick(sf, &o->names, &p.views, err) ||
             plan_jobs(sf, o, &p, rep, err) || plan_ztv(sf, o, &p, rep, err) ? -1 : 0;
    if (parts->agree(parts->job, rc, err)) rc = -1; /* every part has looked before any writes */
    if (!rc) say_plan(o, &p, rep);
    scene *s = NULL;
    if (!rc && (p.n_todo || p.ztv_todo) && !(s = build_once(sf, reg, o, rep, err))) rc = -1;
    if (!rc && s && parts->same_scene(parts->job, s, err)) rc = err_default(err, ERR_INPUT);
    camera_settings built = s ? s->camera : (camera_settings){0}; /* each job moves it */
    if (!rc && s) rc = render_jobs(s, sf, o, &p, parts, rep, err);
    if (s) s->camera = built; /* the scene as built on every part again, for the map */
    if (p.ztv_todo && parts->agree(parts->job, rc, err)) rc = -1; /* every part maps, or none */
    if (!rc && p.ztv_todo)
        rc = study_ztv_make(&o->ztv, sf, s, &p.ztv_views, p.ztv_dir, p.ztv_record, parts, &rep->times, err);
    if (parts->agree(parts->job, rc, err)) rc = -1; /* every part's files are there before the index */
    if (!rc && !parts->part) rc = output_folder_make(o->dir, err) || write_index(sf, o, &p, err) ? -1 : 0;
    scene_free(s);
    free(p.jobs);
    free(p.ztv_record);
    study_views_free(&p.views);
    study_views_free(&p.ztv_views);
    rep->seconds = progress_now() - t0;
    return rc;
}
