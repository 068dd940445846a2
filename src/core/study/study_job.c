/* study_job.c — one viewpoint in one frame rendered and written (study_job.h). */
#include "study/study_job.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/scene_view.h"
#include "render/accel.h"
#include "render/camera.h"
#include "render/render_still.h"
#include "render/wireline.h"
#include "render/wireline_trace.h"
#include "scene/scene_mark.h"
#include "scene_build/scene_ground.h"
#include "scene_file/host_schema.h"
#include "sheet/sheet.h"
#include "study/study_frames.h"
#include "util/task_pool.h"

int study_job_path(const study_job *j, int p, const char *ext, char out[STUDY_PATH_MAX], err_buf *err)
{
    int n = snprintf(out, STUDY_PATH_MAX, "%s/%s_%s.%s", j->folder, host_study_products[p],
                     study_frame_of(j->frame)->name, ext);
    return n > 0 && n < STUDY_PATH_MAX ? 0 : err_fail(err, ERR_USAGE, "the path of %s's files is too long", j->folder);
}

/* A camera that cannot be placed, said at the viewpoint (a point of a points file at its row). */
static int view_error(const scene_viewpoint *v, const scene_file *sf, err_buf *err)
{
    char what[ERR_MSG_MAX], file[ERR_FILE_MAX];
    snprintf(what, sizeof what, "%s", err_sentence(err));
    snprintf(file, sizeof file, "%s", v->file ? v->file : err_has_place(err) ? err->file : sf->path);
    uint32_t line = v->file || !err_has_place(err) ? v->line : err->line;
    uint32_t column = v->file || !err_has_place(err) ? v->column : err->column;
    return err_at(err, ERR_INPUT, file, line, column, "viewpoint '%s': %s", v->name, what);
}

const char *study_product_ext(int p)
{
    return p == STUDY_SHEET ? "pdf" : "exr";
}

/* The wireline of the development in `full`, found through the job's camera (wl then owned by the
 * caller: wireline_free). Returns 0, or -1 with err set. */
static int find_wireline(const scene *s, const study_job *j, const film *full, wireline *wl, err_buf *err)
{
    camera cam;
    camera_init(&cam, &s->camera, j->size[0], j->size[1]);
    return wireline_find(wl, full, s, &cam, err);
}

/* The wireline of the development in `full` over the existing view `bg` exposed at ev, as 8-bit
 * sRGB pixels (owned by the caller), or NULL with err set. */
static uint8_t *wireline_pixels(const scene *s, const study_job *j, const film *full, const film *bg, double ev,
                                int inner_edges, err_buf *err)
{
    static const uint8_t red[3] = {255, 0, 0}, yellow[3] = {255, 220, 0};
    wireline wl = {0};
    uint8_t *px = film_tonemap(bg, s->image.tone, ev); /* owned by the caller */
    if (!px) return err_nomem(err, "out of memory tone-mapping the wireline"), NULL;
    if (find_wireline(s, j, full, &wl, err)) {
        free(px);
        return NULL;
    }
    wireline_draw(&wl, px, red, inner_edges ? yellow : NULL);
    wireline_free(&wl);
    return px;
}

static int write_wireline(const scene *s, const study_job *j, const film *full, const film *bg, double ev,
                          int inner_edges, const char *png, const char *exr, err_buf *err)
{
    uint8_t *px = wireline_pixels(s, j, full, bg, ev, inner_edges, err); /* owned here */
    if (!px) return -1;
    film layers = *bg; /* the existing view's layers, borrowed, with the proposed view's development */
    layers.development = full->development, layers.development_rgb = full->development_rgb;
    int rc = film_write_pair_pixels(&layers, &s->site, ev, px, png, exr, err);
    free(px);
    return rc;
}

/* The sheet of j (sheet/sheet.h): its two pictures from the renders, the wireline traced from the
 * proposed render's pixels, its facts from the scene. */
static int write_sheet(const scene *s, const scene_file *sf, const study_job *j, const film *full, const film *bg,
                       double ev, uint32_t spp, const char *png, const char *pdf, err_buf *err)
{
    sheet sh = {.s = s, .sf = sf, .eye = {s->camera.position[0], s->camera.position[1]}, .spp = spp,
                .wider_frames = j->other_frames[0] ? j->other_frames : NULL, .page = j->page};
    sheet_view_of(s, sf, j->view, &s->camera, study_frame_of(j->frame)->name, j->size[0], j->size[1], &sh.view);
    uint8_t *existing = film_tonemap(bg, s->image.tone, ev), *proposed = film_tonemap(full, s->image.tone, ev); /* owned here */
    wireline wl = {0};
    wireline_paths paths = {0}; /* owned here */
    int rc = -1;
    if (!existing || !proposed) err_nomem(err, "out of memory for the sheet's pictures");
    else if (!find_wireline(s, j, full, &wl, err)) {
        rc = wireline_trace(&paths, &wl, sf->study.inner_edges, err);
        wireline_free(&wl);
    }
    if (!rc) {
        sh.existing = (page_picture){j->size[0], j->size[1], existing};
        sh.proposed = (page_picture){j->size[0], j->size[1], proposed};
        sh.wireline = &paths;
        rc = sheet_write(&sh, pdf, png, err);
    }
    wireline_paths_free(&paths);
    free(existing), free(proposed);
    return rc;
}

/* The products of one job being written, one task each (task_pool.h): each task writes its
 * own files and its own slot of errs and rc. */
typedef struct product_writes {
    const scene *s;
    const scene_file *sf;
    const study_job *j;
    const film *full, *bg;
    uint32_t spp;
    double ev;
    uint32_t n, product[STUDY_PRODUCTS];
    err_buf errs[STUDY_PRODUCTS];
    int rc[STUDY_PRODUCTS];
} product_writes;

/* task_pool task: product w->product[i] written, then its record. */
static void write_product(void *ctx, unsigned worker, uint32_t i)
{
    (void)worker;
    product_writes *w = ctx;
    const scene *s = w->s;
    const study_job *j = w->j;
    int p = (int)w->product[i];
    err_buf *err = &w->errs[i];
    char png[STUDY_PATH_MAX], exr[STUDY_PATH_MAX], record[STUDY_PATH_MAX];
    int rc = study_job_path(j, p, "png", png, err) || study_job_path(j, p, study_product_ext(p), exr, err) ||
             study_job_path(j, p, "manifest", record, err);
    if (!rc)
        rc = p == STUDY_PROPOSED ? film_write_pair(w->full, &s->site, s->image.tone, w->ev, png, exr, err)
             : p == STUDY_EXISTING ? film_write_pair(w->bg, &s->site, s->image.tone, w->ev, png, exr, err)
             : p == STUDY_WIRELINE ? write_wireline(s, j, w->full, w->bg, w->ev, w->sf->study.inner_edges, png, exr, err)
                                   : write_sheet(s, w->sf, j, w->full, w->bg, w->ev, w->spp, png, exr, err);
    if (!rc) rc = study_manifest_write(record, j->record[p], err);
    w->rc[i] = rc ? err_default(err, ERR_OUTPUT) : 0;
}

/* Every product of j written from the renders, each with its record after its files, the
 * products side by side on up to `threads` threads (they share nothing but the renders they
 * read). The first failure in product order is the one told. */
static int write_products(const scene *s, const scene_file *sf, const study_job *j, const film *full, const film *bg,
                          uint32_t spp, unsigned threads, err_buf *err)
{
    product_writes w = {.s = s, .sf = sf, .j = j, .full = full, .bg = bg, .spp = spp,
                        .ev = render_still_exposure(s, full)};
    for (uint32_t p = 0; p < STUDY_PRODUCTS; p++)
        if (j->todo & 1u << p) w.product[w.n++] = p;
    task_pool_run(threads, w.n, write_product, &w);
    for (uint32_t i = 0; i < w.n; i++)
        if (w.rc[i]) return *err = w.errs[i], -1;
    return 0;
}

/* The renders of j on its setup: the whole scene, and without the development when asked. */
static int render_pair(scene *s, const study_job *j, const render_options *ro, phase_times *times, film **full,
                       film **bg, uint32_t *renders, err_buf *err)
{
    render_setup *rs = render_setup_new(s, ro, err);
    if (!rs) return err_default(err, ERR_INTERNAL);
    render_stats st;
    *full = render_setup_run(rs, ro, &st, err);
    if (*full) {
        phase_add(times, PHASE_BVH, st.bvh_seconds);
        phase_add(times, PHASE_RENDER_SETUP, st.build_seconds - st.bvh_seconds);
        phase_add(times, PHASE_RENDER, st.render_seconds);
        ++*renders;
    }
    if (*full && (j->todo & STUDY_NEEDS_PAIR)) {
        render_options without = *ro;
        without.leave_out |= ACCEL_MASK_DEVELOPMENT;
        if ((*bg = render_setup_run(rs, &without, &st, err))) phase_add(times, PHASE_RENDER, st.render_seconds), ++*renders;
    }
    render_setup_free(rs);
    int failed = !*full || (!*bg && (j->todo & STUDY_NEEDS_PAIR));
    return failed ? err_default(err, ERR_INTERNAL) : 0;
}

int study_job_place(scene *s, const scene_file *sf, const study_job *j, err_buf *err)
{
    s->camera = j->camera;
    return scene_ground_camera(s, sf, err) ? view_error(j->view, sf, err) : 0;
}

int study_job_run(scene *s, const scene_file *sf, const study_job *j, const render_options *ro, phase_times *times,
                  uint32_t *renders, err_buf *err)
{
    if (study_job_place(s, sf, j, err)) return -1;
    scene_mark mark = scene_mark_take(s);
    const scene_view view = {.picture = 1, .width = j->size[0], .height = j->size[1], .quiet = 1,
                            .threads = ro->threads};
    film *full = NULL, *bg = NULL;
    int rc = scene_view_prepare(s, &sf->ground_cover, &view, times, err);
    if (!rc) rc = render_pair(s, j, ro, times, &full, &bg, renders, err);
    phase_mark t_out = phase_start();
    if (!rc) rc = write_products(s, sf, j, full, bg, ro->spp, ro->threads, err);
    phase_stop(times, PHASE_OUTPUT, t_out);
    film_free(full);
    film_free(bg);
    err_buf rewind_err = {{0}};
    if (scene_rewind(s, &mark, &rewind_err) && !rc) rc = (*err = rewind_err, -1);
    return rc;
}
