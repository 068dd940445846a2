/* crown_calibrate.c — the crown proxies' reflectances, calibrated so the pixels they cover keep
 * the full plants' mean radiance (crown_calibrate.h, crown_proxy.h). */
#include "render/crown_calibrate.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "render/crown_proxy.h"
#include "util/task_pool.h"

/* Camera samples per species region for the calibration: the mean of a region's radiance then
 * carries a relative error of about 0.6 / sqrt(this) (a sample's spread is some 60 % of the
 * mean over a distant forest, less with stratified samples), 0.4 %; but all regions together
 * take at most PROBE_SHARE of the render's own samples (each is traced three times): on a small
 * image that bound decides, and a tenth left a 96 x 64, 16 spp forest 1 % off. */
#define PROBE_SAMPLES 20000.0
#define PROBE_MAX_SPP 64u
#define PROBE_SHARE 0.4

typedef struct probe_job {
    const render_ctx *ctx;       /* the proxies' view */
    render_ctx full;             /* the same with the full plants */
    const uint32_t *region;      /* per pixel: species + 1 of the proxy its centre ray meets, or 0 */
    const uint32_t *spp;         /* per species region */
    uint32_t n_species;
    int with_full;               /* 1: trace the full plants too */
    double *sums;                /* per pixel: (2 + n_species) RGB sums: full, not on a proxy, on species t */
    pthread_mutex_t lock;
    uint32_t next_row;
} probe_job;

/* The species + 1 of the proxy the centre ray of pixel (x, y) meets first, or 0. */
static uint32_t centre_species(const render_ctx *ctx, uint32_t x, uint32_t y)
{
    const accel *a = ctx->accel;
    vec3 d = camera_direction(&ctx->camera, x + 0.5f, y + 0.5f);
    struct RTCRayHit rh = {.ray = {.org_x = ctx->camera.origin.x, .org_y = ctx->camera.origin.y,
                                   .org_z = ctx->camera.origin.z, .dir_x = d.x, .dir_y = d.y, .dir_z = d.z,
                                   .tnear = 0.0f, .tfar = INFINITY, .mask = ctx->camera_mask},
                           .hit = {.geomID = RTC_INVALID_GEOMETRY_ID, .instID = {RTC_INVALID_GEOMETRY_ID}}};
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    rtcIntersect1(a->top, &ic, &rh);
    uint32_t j = crown_proxy_of_hit(a, &rh);
    if (!j) return 0;
    const scene *s = a->scene;
    return s->prototypes[s->instances[a->proxies->plant[j - 1]].prototype].species + 1;
}

/* The centre species of every pixel of a row, one task each (task_pool.h): each row writes its
 * own slots of region. */
typedef struct centre_rows {
    const render_ctx *ctx;
    uint32_t *region;
} centre_rows;

static void centre_row(void *arg, unsigned worker, uint32_t y)
{
    (void)worker;
    const centre_rows *job = arg;
    const uint32_t w = job->ctx->camera.width;
    for (uint32_t x = 0; x < w; x++) job->region[(size_t)y * w + x] = centre_species(job->ctx, x, y);
}

static void probe_row(probe_job *job, uint32_t y)
{
    render_ctx proxies = *job->ctx, full = job->full; /* with the region's samples per pixel */
    const render_ctx *ctx = &proxies;
    const uint32_t w = ctx->camera.width, stride = 3 * (2 + job->n_species);
    for (uint32_t x = 0; x < w; x++) {
        size_t k = (size_t)y * w + x;
        uint32_t r = job->region[k];
        if (!r) continue;
        double *sum = job->sums + k * stride;
        proxies.spp = full.spp = job->spp[r - 1];
        for (uint32_t smp = 0; smp < job->spp[r - 1]; smp++) {
            uint32_t proxy = 0;
            vec3 L;
            if (job->with_full) {
                L = integrate_sample(&full, x, y, smp, NULL);
                sum[0] += L.x, sum[1] += L.y, sum[2] += L.z;
            }
            L = integrate_sample(ctx, x, y, smp, &proxy);
            uint32_t t = proxy ? 2 + ctx->accel->scene->prototypes[ctx->accel->scene->instances
                                     [ctx->accel->proxies->plant[proxy - 1]].prototype].species : 1;
            sum[3 * t] += L.x, sum[3 * t + 1] += L.y, sum[3 * t + 2] += L.z;
        }
    }
}

static void *probe_worker(void *arg)
{
    probe_job *job = arg;
    for (;;) {
        pthread_mutex_lock(&job->lock);
        uint32_t y = job->next_row++;
        pthread_mutex_unlock(&job->lock);
        if (y >= job->ctx->camera.height) break;
        probe_row(job, y);
    }
    return NULL;
}

/* Solves D_s = B_s + sum_t k_t A_st for k in [0, 1], channel by channel (Gauss-Seidel). a is
 * n x n (row s: region s), d and b n long, k n long (in: start; out: solution). */
static void solve_reflectance(uint32_t n, const double *a, const double *d, const double *b, double *k)
{
    for (int it = 0; it < 50; it++)
        for (uint32_t s = 0; s < n; s++) {
            if (!(a[s * n + s] > 0)) continue;
            double r = d[s] - b[s];
            for (uint32_t t = 0; t < n; t++)
                if (t != s) r -= k[t] * a[s * n + t];
            k[s] = fmin(1.0, fmax(0.0, r / a[s * n + s]));
        }
}

int crown_proxies_calibrate(accel *a, const render_ctx *ctx, unsigned threads, err_buf *err)
{
    crown_proxies *p = a->proxies;
    if (!p || !p->n) return 0;
    const uint32_t w = ctx->camera.width, h = ctx->camera.height, ns = p->n_species;
    const size_t npx = (size_t)w * h, stride = 3 * (2 + (size_t)ns);
    uint32_t *region = calloc(npx, sizeof *region);         /* owned here */
    uint32_t *spp = calloc(ns, sizeof *spp);                 /* owned here */
    double *sums = calloc(npx * stride, sizeof *sums);       /* owned here */
    double *acc = calloc((size_t)ns * (ns + 3) * 3, sizeof *acc); /* owned here: A, D, B, k per channel */
    pthread_t *tids = calloc(threads ? threads : 1, sizeof *tids);
    double *count = NULL; /* per region: its samples; owned here */
    int rc = -1;
    if (!region || !spp || !sums || !acc || !tids) {
        err_nomem(err, "out of memory calibrating the crown proxies");
        goto done;
    }
    centre_rows centres = {.ctx = ctx, .region = region};
    task_pool_run(threads ? threads : 1, h, centre_row, &centres);
    /* pixels within two of a proxy's, whose samples may meet it or its shadow, join its region */
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            size_t k = (size_t)y * w + x;
            for (int dy = -2; dy <= 2 && !region[k]; dy++)
                for (int dx = -2; dx <= 2 && !region[k]; dx++) {
                    int64_t xx = (int64_t)x + dx, yy = (int64_t)y + dy;
                    if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
                    uint32_t r = region[(size_t)yy * w + (size_t)xx];
                    if (r && r <= ns) region[k] = r + ns + 1; /* marked, not yet a member */
                }
        }
    for (size_t k = 0; k < npx; k++)
        if (region[k] > ns) region[k] -= ns + 1;
    for (size_t k = 0; k < npx; k++)
        if (region[k]) spp[region[k] - 1]++;
    double region_px = 0, budget = PROBE_SHARE * (double)npx * ctx->spp, per_region = PROBE_SAMPLES;
    for (uint32_t s = 0; s < ns; s++) region_px += spp[s] > 0;
    if (region_px * per_region > budget) per_region = budget / region_px;
    for (uint32_t s = 0; s < ns; s++) {
        double want = spp[s] ? ceil(per_region / spp[s]) : 0;
        spp[s] = (uint32_t)fmax(fmin(want, PROBE_MAX_SPP), spp[s] ? 1 : 0);
    }
    double *A = acc, *D = acc + (size_t)3 * ns * ns, *B = D + 3 * ns, *K = B + 3 * ns;
    count = calloc(ns, sizeof *count);
    if (!count) {
        err_nomem(err, "out of memory calibrating the crown proxies");
        goto done;
    }
    for (uint32_t i = 0; i < 3 * ns; i++) K[i] = 1.0;
    /* Round 0 traces both views; round 1 again the proxies at the reflectances round 0 found,
     * since a path from one proxy may meet another later (the radiance is then not quite linear). */
    for (int round = 0; round < 2; round++) {
        probe_job job = {.ctx = ctx, .full = *ctx, .region = region, .spp = spp, .n_species = ns, .sums = sums,
                         .with_full = round == 0};
        job.full.camera_mask = ctx->ray_mask;
        for (size_t k = 0; k < npx * stride; k++)
            if (round == 0 || k % stride >= 3) sums[k] = 0;
        pthread_mutex_init(&job.lock, NULL);
        unsigned started = 0;
        for (; started + 1 < threads; started++)
            if (pthread_create(&tids[started], NULL, probe_worker, &job)) break;
        probe_worker(&job);
        for (unsigned i = 0; i < started; i++) pthread_join(tids[i], NULL);
        pthread_mutex_destroy(&job.lock);

        /* Region means, reduced in pixel order so that the result does not depend on threads;
         * a proxy's part divided by its present reflectance is A. */
        memset(A, 0, sizeof *A * 3 * ns * ns);
        memset(B, 0, sizeof *B * 3 * ns);
        if (round == 0) memset(D, 0, sizeof *D * 3 * ns);
        memset(count, 0, sizeof *count * ns);
        for (size_t k = 0; k < npx; k++) {
            if (!region[k]) continue;
            uint32_t r = region[k] - 1;
            const double *sum = sums + k * stride;
            count[r] += spp[r];
            for (int c = 0; c < 3; c++) {
                if (round == 0) D[c * ns + r] += sum[c];
                B[c * ns + r] += sum[3 + c];
                for (uint32_t t = 0; t < ns; t++)
                    A[((size_t)c * ns + r) * ns + t] += sum[3 * (2 + t) + c] / K[c * ns + t];
            }
        }
        for (int c = 0; c < 3; c++) {
            for (uint32_t r = 0; r < ns; r++) {
                double n = count[r] > 0 ? count[r] : 1;
                if (round == 0) D[c * ns + r] /= n;
                B[c * ns + r] /= n;
                for (uint32_t t = 0; t < ns; t++) A[((size_t)c * ns + r) * ns + t] /= n;
            }
            solve_reflectance(ns, A + (size_t)c * ns * ns, D + c * ns, B + c * ns, K + c * ns);
            for (uint32_t r = 0; r < ns; r++) K[c * ns + r] = fmax(K[c * ns + r], 1e-3);
        }
        for (uint32_t r = 0; r < ns; r++)
            p->materials[r].albedo = v3((float)K[r], (float)K[ns + r], (float)K[2 * ns + r]);
    }
    rc = 0;
done:
    free(region);
    free(spp);
    free(sums);
    free(acc);
    free(tids);
    free(count);
    return rc;
}
