/* crown_proxy.c — distant plants' crowns as calibrated envelopes for camera rays
 * (crown_proxy.h). */
#include "render/crown_proxy.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/crown_hull.h"
#include "scene/mesh.h"
#include "util/rng.h"

void crown_proxies_free(crown_proxies *p)
{
    if (!p) return;
    for (uint32_t i = 0; i < p->n_prototypes; i++) {
        if (p->hull_scene && p->hull_scene[i]) rtcReleaseScene(p->hull_scene[i]);
        if (p->hull_geom)
            for (uint32_t k = 0; k < ACCEL_PARTS; k++) cutout_part_free(&p->hull_geom[i * ACCEL_PARTS + k].part);
        if (p->hull) mesh_free(p->hull[i]);
    }
    free(p->hull);
    free(p->hull_scene);
    free(p->hull_geom);
    free(p->materials);
    free(p->plant);
    free(p);
}

/* The uniform scale of xf (the length of its first column). */
static double xf_scale(const xform3x4 *xf)
{
    return sqrt((double)xf->m[0][0] * xf->m[0][0] + (double)xf->m[1][0] * xf->m[1][0] +
                (double)xf->m[2][0] * xf->m[2][0]);
}

/* A leaf must look smaller than this many pixels for its plant to become a proxy: a plant a few
 * pixels high whose leaves are half a pixel or more (a shrub 200 m away) keeps its detail. */
#define PROXY_LEAF_PIXELS 0.25

/* 1 when plant i looks small through camera c, whose pixels span `pixel` radians: its height is
 * below max_pixels and its leaves (leaf_size m in its model) below PROXY_LEAF_PIXELS. */
static int looks_small(const scene *s, uint32_t i, const camera *c, double pixel, double max_pixels,
                       const double *leaf_size)
{
    const instance *in = &s->instances[i];
    double scale = xf_scale(&in->xf), h = s->prototypes[in->prototype].height * scale;
    vec3 mid = xf_point(&in->xf, v3(0, 0, (float)(s->prototypes[in->prototype].height / 2)));
    double d = v3_len(v3_sub(mid, c->origin)) * pixel;
    return d > 0 && h < max_pixels * d && leaf_size[in->prototype] * scale < PROXY_LEAF_PIXELS * d;
}

/* Shadow rays pass through an envelope, losing its crossing transmittance at each surface; a ray
 * nearly opaque by then stops. The ray must carry a shadow_context. */
static void hull_shadow_filter(const struct RTCFilterFunctionNArguments *args)
{
    const geom_info *g = args->geometryUserPtr;
    shadow_context *sc = (shadow_context *)args->context;
    const unsigned n = args->N;
    const unsigned *prim = (const unsigned *)args->hit + 5 * (size_t)n, *inst = prim + 2 * (size_t)n;
    for (unsigned i = 0; i < n; i++) {
        if (args->valid[i] != -1) continue;
        int seen = 0;
        for (uint32_t k = 0; k < sc->n_seen && k < SHADOW_SEEN; k++)
            seen |= sc->seen_inst[k] == inst[i] && sc->seen_prim[k] == prim[i];
        if (!seen) {
            uint32_t k = sc->n_seen++ % SHADOW_SEEN;
            sc->seen_inst[k] = inst[i], sc->seen_prim[k] = prim[i];
            sc->transmittance *= g->crossing;
        }
        if (sc->transmittance > 1e-3f) args->valid[i] = 0;
    }
}

/* Rays per prototype for the envelope's crossing transmittance. */
#define CROSSING_RAYS 4096u

/* One crossing's transmittance of prototype k's envelope: rays at the sun's elevation over all
 * azimuths, through a disc that covers the whole plant, must lose as much light on average
 * crossing the envelope as they lose to its leaves and branches (some of which the rounded
 * envelope leaves outside): tau^2 = 1 - blocked / crossed. */
static float crossing_transmittance(const accel *a, uint32_t k, vec3 sun)
{
    const crown_proxies *p = a->proxies;
    float lo[3], hi[3];
    mesh_bounds(p->hull[k], lo, hi);
    vec3 c = v3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    float plo[3], phi_[3]; /* the whole plant's bounds */
    mesh_bounds(a->scene->prototypes[k].mesh, plo, phi_);
    for (int i = 0; i < 3; i++) lo[i] = fminf(lo[i], plo[i]), hi[i] = fmaxf(hi[i], phi_[i]);
    float r = 0.5f * v3_len(v3(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));
    float horiz = sqrtf(fmaxf(0.0f, 1.0f - sun.z * sun.z)), up = sun.z;
    uint32_t crossed = 0, blocked = 0;
    for (uint32_t i = 0; i < CROSSING_RAYS; i++) {
        uint64_t key = rng_combine(rng_combine(0x63726f776eull, k), i);
        float az = 2.0f * (float)M_PI * rng_u01f(rng_combine(key, 1));
        vec3 d = v3(horiz * cosf(az), horiz * sinf(az), up); /* toward the sun */
        vec3 u = v3_norm(v3_cross(d, fabsf(d.z) < 0.9f ? v3(0, 0, 1) : v3(1, 0, 0))), w = v3_cross(d, u);
        float rho = r * sqrtf(rng_u01f(rng_combine(key, 2))), phi = 2.0f * (float)M_PI * rng_u01f(rng_combine(key, 3));
        vec3 o = v3_add(v3_madd(v3_madd(c, u, rho * cosf(phi)), w, rho * sinf(phi)), v3_scale(d, -2.0f * r));
        struct RTCRayHit rh = {.ray = {.org_x = o.x, .org_y = o.y, .org_z = o.z, .dir_x = d.x, .dir_y = d.y,
                                       .dir_z = d.z, .tnear = 0.0f, .tfar = 4.0f * r, .mask = ~0u},
                               .hit = {.geomID = RTC_INVALID_GEOMETRY_ID, .instID = {RTC_INVALID_GEOMETRY_ID}}};
        struct RTCRay ray = rh.ray;
        struct RTCIntersectContext ic;
        rtcInitIntersectContext(&ic);
        rtcIntersect1(p->hull_scene[k], &ic, &rh);
        crossed += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        rtcInitIntersectContext(&ic);
        rtcOccluded1(a->proto_scenes[k], &ic, &ray);
        blocked += ray.tfar < 0.0f;
    }
    return crossed ? sqrtf(fmaxf(0.0f, 1.0f - (float)blocked / (float)crossed)) : 1.0f;
}

/* The envelopes of the prototypes that some chosen plant uses, and their BVHs. */
static int build_hulls(accel *a, crown_proxies *p, const uint8_t *used, err_buf *err)
{
    const scene *s = a->scene;
    for (uint32_t k = 0; k < s->n_prototypes; k++) {
        if (!used[k]) continue;
        if (crown_hull_build(s, s->prototypes[k].mesh, &p->hull[k], err)) return -1;
        if (!p->hull[k]) continue;
        if (accel_build_shared(a, p->hull[k], GEOM_PROTOTYPE, &p->hull_scene[k], &p->hull_geom[k * ACCEL_PARTS],
                               err))
            return -1;
        p->hull_geom[k * ACCEL_PARTS].crossing = crossing_transmittance(a, k, a->proxies->sun);
        RTCGeometry g = rtcGetGeometry(p->hull_scene[k], ACCEL_PART_OPAQUE);
        rtcSetGeometryOccludedFilterFunction(g, hull_shadow_filter);
        rtcCommitGeometry(g);
        /* no spatial splits: a triangle met twice would count twice */
        rtcSetSceneBuildQuality(p->hull_scene[k], RTC_BUILD_QUALITY_MEDIUM);
        rtcCommitScene(p->hull_scene[k]);
    }
    return 0;
}

int crown_proxies_attach(accel *a, const camera *c, vec3 sun, double max_pixels, err_buf *err)
{
    const scene *s = a->scene;
    if (!(max_pixels > 0) || !s->n_instances) return 0;
    double pixel = camera_smallest_pixel_angle(c);
    crown_proxies *p = calloc(1, sizeof *p);
    uint8_t *used = calloc(s->n_prototypes ? s->n_prototypes : 1, 1); /* owned here */
    uint8_t *far = calloc(s->n_instances, 1);                          /* owned here */
    double *leaf = calloc(s->n_prototypes ? s->n_prototypes : 1, sizeof *leaf); /* owned here */
    if (!p || !used || !far || !leaf) goto nomem;
    for (uint32_t k = 0; k < s->n_prototypes; k++) leaf[k] = crown_leaf_size(s, s->prototypes[k].mesh);
    a->proxies = p;
    p->n_prototypes = s->n_prototypes, p->n_species = s->n_species, p->sun = sun;
    p->hull = calloc(s->n_prototypes ? s->n_prototypes : 1, sizeof *p->hull);
    p->hull_scene = calloc(s->n_prototypes ? s->n_prototypes : 1, sizeof *p->hull_scene);
    p->hull_geom = calloc(s->n_prototypes ? (size_t)s->n_prototypes * ACCEL_PARTS : 1, sizeof *p->hull_geom);
    p->materials = calloc(s->n_species ? s->n_species : 1, sizeof *p->materials);
    if (!p->hull || !p->hull_scene || !p->hull_geom || !p->materials) goto nomem;
    for (uint32_t k = 0; k < s->n_species; k++)
        p->materials[k] = (material){.bsdf = SYLVA_BSDF_LAMBERT, .albedo = v3(1, 1, 1), .texture = -1};
    for (uint32_t i = 0; i < s->n_instances; i++)
        if (!s->instances[i].development && looks_small(s, i, c, pixel, max_pixels, leaf))
            far[i] = 1, used[s->instances[i].prototype] = 1;
    if (build_hulls(a, p, used, err)) goto fail;
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->n_instances; i++) n += far[i] && p->hull_scene[s->instances[i].prototype];
    p->plant = calloc(n ? n : 1, sizeof *p->plant);
    if (!p->plant) goto nomem;
    a->first_proxy = a->first_instance + s->n_instances;
    for (uint32_t i = 0; i < s->n_instances; i++) {
        RTCScene hull = p->hull_scene[s->instances[i].prototype];
        if (!far[i] || !hull) continue;
        RTCGeometry g = rtcGetGeometry(a->top, a->first_instance + i);
        rtcSetGeometryMask(g, ACCEL_MASK_FAR_PLANT);
        rtcCommitGeometry(g);
        if (accel_add_instance(a, hull, &s->instances[i].xf, a->first_proxy + p->n, ACCEL_MASK_PROXY, err)) goto fail;
        p->plant[p->n++] = i;
    }
    rtcCommitScene(a->top);
    free(used);
    free(far);
    free(leaf);
    return accel_device_error(a, err);
nomem:
    err_nomem(err, "out of memory building the crown proxies of %u plants", s->n_instances);
fail:
    if (!a->proxies) free(p);
    free(used);
    free(far);
    free(leaf);
    return -1;
}

uint32_t crown_proxy_of_hit(const accel *a, const struct RTCRayHit *rh)
{
    unsigned inst = rh->hit.instID[0];
    if (!a->proxies || inst == RTC_INVALID_GEOMETRY_ID || inst < a->first_proxy) return 0;
    return inst - a->first_proxy + 1;
}

/* --- calibration ------------------------------------------------------------------------ */

/* Camera samples per species region for the calibration: the mean of a region's radiance then
 * carries a relative error of about 0.6 / sqrt(this) (a sample's spread is some 60 % of the
 * mean over a distant forest, less with stratified samples), 0.4 %; but all regions together
 * take at most PROBE_SHARE of the render's own samples (each is traced three times). */
#define PROBE_SAMPLES 20000.0
#define PROBE_MAX_SPP 64u
#define PROBE_SHARE 0.1

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
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) region[(size_t)y * w + x] = centre_species(ctx, x, y);
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
