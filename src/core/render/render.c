/* render.c — the render setup (acceleration structure and lights), the tile scheduler and the
 * worker threads. */
#include "render/render.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <unistd.h>

#include "render/accel.h"
#include "render/accel_frame.h"
#include "render/crown_calibrate.h"
#include "render/crown_proxy.h"
#include "render/integrator.h"
#include "render/lights_cache.h"
#include "util/interleave.h"
#include "util/progress.h"

#define TILE RENDER_BAND_ROWS /* a row of tiles is a band of a part */

typedef struct render_job {
    const render_ctx *ctx;
    film *film;
    uint32_t tiles_x, tiles_y;     /* tiles_y: the rows of tiles of this part */
    uint32_t part, parts;          /* this part's tile row k is the frame's part + k * parts */
    atomic_uint next_tile;
    atomic_uint_fast64_t samples; /* camera samples taken (fewer than spp per pixel when adaptive) */
    progress *prog;
} render_job;

unsigned render_default_threads(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (unsigned)n : 1;
}

static void render_tile(render_job *job, uint32_t tile)
{
    film *f = job->film;
    uint32_t tx = tile % job->tiles_x, ty = job->part + tile / job->tiles_x * job->parts;
    uint64_t samples = 0;
    for (uint32_t y = ty * TILE; y < (ty + 1) * TILE && y < f->height; y++)
        for (uint32_t x = tx * TILE; x < (tx + 1) * TILE && x < f->width; x++) {
            pixel_result r;
            integrate_pixel(job->ctx, x, y, &r);
            size_t k = (size_t)y * f->width + x;
            f->rgb[k * 3] = r.rgb.x, f->rgb[k * 3 + 1] = r.rgb.y, f->rgb[k * 3 + 2] = r.rgb.z;
            f->depth[k] = r.depth;
            f->normal[k * 3] = r.normal.x, f->normal[k * 3 + 1] = r.normal.y, f->normal[k * 3 + 2] = r.normal.z;
            f->albedo[k * 3] = r.albedo.x, f->albedo[k * 3 + 1] = r.albedo.y, f->albedo[k * 3 + 2] = r.albedo.z;
            f->instance_id[k] = r.instance_id;
            f->species_id[k] = r.species_id;
            f->object_id[k] = r.object_id;
            f->development[k] = r.development;
            f->development_rgb[k * 3] = r.development_rgb.x, f->development_rgb[k * 3 + 1] = r.development_rgb.y;
            f->development_rgb[k * 3 + 2] = r.development_rgb.z;
            f->pixel_class[k] = r.pixel_class;
            f->coverage[k] = r.coverage;
            samples += r.samples;
        }
    atomic_fetch_add(&job->samples, samples);
}

static void *render_worker(void *arg)
{
    render_job *job = arg;
    uint32_t n = job->tiles_x * job->tiles_y;
    for (;;) {
        uint32_t t = atomic_fetch_add(&job->next_tile, 1);
        if (t >= n) break;
        render_tile(job, t);
        progress_advance(job->prog, 1);
    }
    return NULL;
}

struct render_setup {
    const scene *scene;
    accel acc;
    const lights *lt;          /* own_lights, or borrowed from a lights_cache */
    lights own_lights;         /* owned (lights_free) when no cache gives them */
    double build_seconds, bvh_seconds;
};

static unsigned thread_count(const render_options *o)
{
    return o->recorder ? 1 : o->threads ? o->threads : render_default_threads();
}

/* The render context of rs for options o at w x h (its camera, curved rays and masks). */
static void ctx_init(render_ctx *ctx, render_setup *rs, const render_options *o, uint32_t w, uint32_t h)
{
    const scene *s = rs->scene;
    unsigned leave_out = o->leave_out;
    if (leave_out & ACCEL_MASK_PLANT) leave_out |= ACCEL_MASK_FAR_PLANT | ACCEL_MASK_PROXY;
    *ctx = (render_ctx){.accel = &rs->acc, .lights = rs->lt, .spp = o->spp ? o->spp : s->image.spp,
                        .noise_target = (float)s->image.noise_target,
                        .max_depth = s->image.max_depth, .seed = o->seed_set ? o->seed : s->image.seed,
                        .verify = o->verify, .recorder = o->recorder, .ray_mask = ~leave_out & ~ACCEL_MASK_PROXY};
    /* crown proxies stand in for their plants before camera rays alone, never in verification */
    ctx->camera_mask = o->verify ? ctx->ray_mask : ~leave_out & ~ACCEL_MASK_FAR_PLANT;
    camera_init(&ctx->camera, &s->camera, w, h);
    const double *eye = s->camera.position, *frame = rs->acc.frame; /* the eye in the accel's frame */
    ctx->camera.origin = v3((float)(eye[0] - frame[0]), (float)(eye[1] - frame[1]), (float)(eye[2] - frame[2]));
    curved_rays_init(&ctx->curved, o->flat_earth ? NULL : &s->earth, &ctx->camera, rs->acc.bounds_lo,
                     rs->acc.bounds_hi);
}

/* The crown proxies of the plants that look small through the camera at w x h
 * (crown_proxy.h) through camera cam, before the top scene's BVH is built; nothing in
 * verification mode or with image.crown_proxy 0. */
static int attach_proxies(render_setup *rs, const render_options *o, const camera *cam, err_buf *err)
{
    if (o->verify || !(rs->scene->image.crown_proxy > 0)) return 0;
    vec3 sun = rs->lt->summary.sun_on ? rs->lt->summary.sun_dir : v3(0.0f, 0.7071f, 0.7071f);
    return crown_proxies_attach(&rs->acc, cam, sun, rs->scene->image.crown_proxy, thread_count(o), err);
}

/* The proxies' reflectances, once the top scene's BVH is built. */
static int calibrate_proxies(render_setup *rs, const render_options *o, uint32_t w, uint32_t h, err_buf *err)
{
    if (!rs->acc.proxies) return 0;
    render_ctx ctx;
    ctx_init(&ctx, rs, o, w, h);
    return crown_proxies_calibrate(&rs->acc, &ctx, thread_count(o), err);
}

/* The setup's lights: the cache's when opt gives one, else its own. */
static int make_lights(render_setup *rs, const render_options *opt, err_buf *err)
{
    const scene *s = rs->scene;
    if (opt->lights)
        return (rs->lt = lights_cache_get(opt->lights, &s->sun, &s->sky, s->site.origin[2], s->camera.position[2],
                                          thread_count(opt), err)) ? 0 : -1;
    rs->lt = &rs->own_lights;
    return lights_init(&rs->own_lights, &s->sun, &s->sky, s->site.origin[2], s->camera.position[2], thread_count(opt),
                       err);
}

render_setup *render_setup_new(const scene *s, const render_options *opt, err_buf *err)
{
    uint32_t w = opt->width ? opt->width : s->image.width, h = opt->height ? opt->height : s->image.height;
    double t0 = progress_now();
    if (film_check(w, h, opt->spp ? opt->spp : s->image.spp, err)) return NULL; /* before any build */
    render_setup *rs = calloc(1, sizeof *rs);
    if (!rs) {
        err_nomem(err, "out of memory setting up the render");
        return NULL;
    }
    rs->scene = s;
    /* one build of the top scene's BVH, with the crown proxies already in it (a failed build
     * leaves rs->acc zeroed, which render_setup_free accepts); the verification render, which
     * POV-Ray's double-precision trace checks, in a frame near the camera (accel_frame.h) */
    double frame[3];
    accel_frame_near(s->camera.position, frame);
    if (accel_build_open(&rs->acc, s, thread_count(opt), opt->verify ? frame : NULL, err)) goto fail;
    double t_open = progress_now() - t0;
    camera cam; /* the pixel's angle sets how finely the ground's texture is resolved */
    camera_init(&cam, &s->camera, w, h);
    rs->acc.pixel_angle = (float)camera_smallest_pixel_angle(&cam);
    rs->acc.flat_ground = opt->verify;
    rs->acc.bark_relief = !opt->verify; /* POV-Ray, which the verification matches, has none */
    if (make_lights(rs, opt, err) || attach_proxies(rs, opt, &cam, err)) goto fail;
    double t_commit = progress_now();
    if (accel_commit(&rs->acc, err)) goto fail;
    rs->bvh_seconds = t_open + progress_now() - t_commit;
    if (calibrate_proxies(rs, opt, w, h, err)) goto fail;
    rs->build_seconds = progress_now() - t0;
    return rs;
fail:
    render_setup_free(rs);
    return NULL;
}

void render_setup_free(render_setup *rs)
{
    if (!rs) return;
    lights_free(&rs->own_lights);
    accel_free(&rs->acc);
    free(rs);
}

film *render_setup_run(render_setup *rs, const render_options *opt, render_stats *stats, err_buf *err)
{
    const scene *s = rs->scene;
    render_options o = *opt;
    uint32_t w = o.width ? o.width : s->image.width, h = o.height ? o.height : s->image.height;
    unsigned threads = thread_count(&o);
    double t1 = progress_now();
    film *f = film_new(w, h, err);
    if (!f) return NULL;
    render_ctx ctx;
    ctx_init(&ctx, rs, &o, w, h);
    uint32_t parts = o.parts > 1 ? o.parts : 1, part = parts > 1 ? o.part : 0, tile_rows = (h + TILE - 1) / TILE;
    render_job job = {.ctx = &ctx, .film = f, .tiles_x = (w + TILE - 1) / TILE, .part = part, .parts = parts,
                      .tiles_y = interleave_count(tile_rows, part, parts)};
    atomic_init(&job.next_tile, 0);
    atomic_init(&job.samples, 0);
    progress prog;
    progress_begin(&prog, o.verify ? "render (verify)" : "render", (uint64_t)job.tiles_x * job.tiles_y, o.quiet);
    job.prog = &prog;
    pthread_t *tids = calloc(threads, sizeof(pthread_t));
    unsigned started = 0;
    if (tids)
        for (; started + 1 < threads; started++)
            if (pthread_create(&tids[started], NULL, render_worker, &job)) break;
    render_worker(&job);
    for (unsigned i = 0; i < started; i++) pthread_join(tids[i], NULL);
    free(tids);
    progress_end(&prog);
    double t2 = progress_now();
    if (stats) {
        stats->build_seconds = rs->build_seconds;
        stats->bvh_seconds = rs->bvh_seconds;
        stats->render_seconds = t2 - t1;
        stats->samples = atomic_load(&job.samples);
    }
    if (accel_device_error(&rs->acc, err)) {
        film_free(f);
        f = NULL;
    }
    return f;
}

film *render_scene(const scene *s, const render_options *opt, render_stats *stats, err_buf *err)
{
    render_setup *rs = render_setup_new(s, opt, err);
    if (!rs) return NULL;
    film *f = render_setup_run(rs, opt, stats, err);
    render_setup_free(rs);
    return f;
}
