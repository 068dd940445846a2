/* crown_proxy.c — distant plants' crowns as calibrated envelopes for camera rays
 * (crown_proxy.h). */
#include "render/crown_proxy.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/crown_hull.h"
#include "render/accel_errors.h"
#include "render/accel_mesh.h"
#include "scene/mesh.h"
#include "util/rng.h"
#include "util/task_pool.h"

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
    free(p->hull_box);
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

/* Of the rays at elevation asin(rise) over all azimuths, through a disc that covers the whole of
 * prototype k, the share that its leaves and branches block per ray that crosses its envelope
 * (at most 1: a few leaves stick out of the rounded envelope). */
static float blocked_share(const accel *a, uint32_t k, float rise)
{
    const crown_proxies *p = a->proxies;
    float lo[3], hi[3];
    mesh_bounds(p->hull[k], lo, hi);
    vec3 c = v3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    float plo[3], phi_[3]; /* the whole plant's bounds */
    mesh_bounds(a->scene->prototypes[k].mesh, plo, phi_);
    for (int i = 0; i < 3; i++) lo[i] = fminf(lo[i], plo[i]), hi[i] = fmaxf(hi[i], phi_[i]);
    float r = 0.5f * v3_len(v3(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));
    float horiz = sqrtf(fmaxf(0.0f, 1.0f - rise * rise));
    uint32_t crossed = 0, blocked = 0;
    for (uint32_t i = 0; i < CROSSING_RAYS; i++) {
        uint64_t key = rng_combine(rng_combine(0x63726f776eull, k), i);
        float az = 2.0f * (float)M_PI * rng_u01f(rng_combine(key, 1));
        vec3 d = v3(horiz * cosf(az), horiz * sinf(az), rise);
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
    return crossed ? fminf(1.0f, (float)blocked / (float)crossed) : 0.0f;
}

/* A crown whose envelope blocks at least this share of the camera's rays is drawn opaque (its
 * gaps' light goes into the calibrated reflectance); a sparser one lets rays through. */
#define DENSE_CROWN 0.5f

/* A camera ray meets an envelope with probability its opacity, decided once per ray and plant (so
 * it passes both faces or neither) by a hash of the ray's direction and the plant. */
static void hull_camera_filter(const struct RTCFilterFunctionNArguments *args)
{
    const geom_info *g = args->geometryUserPtr;
    const unsigned n = args->N;
    const float *ray = (const float *)args->ray; /* RTCRayN: org xyz, tnear, dir xyz, ... */
    const unsigned *inst = (const unsigned *)args->hit + 7 * (size_t)n;
    for (unsigned i = 0; i < n; i++) {
        if (args->valid[i] != -1) continue;
        uint32_t b[3];
        for (int j = 0; j < 3; j++) memcpy(&b[j], &ray[(size_t)(4 + j) * n + i], sizeof b[j]);
        uint64_t key = rng_combine(rng_combine(((uint64_t)b[0] << 32) | b[1], b[2]), inst[i]);
        if (rng_u01f(key) >= g->opacity) args->valid[i] = 0;
    }
}

typedef struct hull_job {
    accel *a;
    crown_proxies *p;
    const uint8_t *used;
    uint32_t *order;  /* prototypes by falling triangle count: the largest start first */
    err_buf *errs;    /* per prototype */
    int *rc;          /* per prototype */
} hull_job;

/* The envelope of prototype order[i] and its BVH: it writes only that prototype's slots. */
static void build_hull(void *ctx, unsigned worker, uint32_t i)
{
    hull_job *job = ctx;
    accel *a = job->a;
    crown_proxies *p = job->p;
    const scene *s = a->scene;
    uint32_t k = job->order[i];
    err_buf *err = &job->errs[k];
    if (!job->used[k]) return;
    if (crown_hull_build(s, s->prototypes[k].mesh, &p->hull[k], err)) {
        job->rc[k] = -1;
        return;
    }
    if (!p->hull[k]) return;
    if (accel_build_shared(a, p->hull[k], GEOM_PROTOTYPE, &p->hull_scene[k], &p->hull_geom[k * ACCEL_PARTS], err)) {
        job->rc[k] = -1;
        return;
    }
    geom_info *gi = &p->hull_geom[k * ACCEL_PARTS];
    gi->crossing = sqrtf(1.0f - blocked_share(a, k, p->sun.z));
    gi->opacity = blocked_share(a, k, p->view.z);
    if (gi->opacity >= DENSE_CROWN) gi->opacity = 1.0f;
    RTCGeometry g = rtcGetGeometry(p->hull_scene[k], ACCEL_PART_OPAQUE);
    rtcSetGeometryOccludedFilterFunction(g, hull_shadow_filter);
    rtcSetGeometryIntersectFilterFunction(g, hull_camera_filter);
    rtcCommitGeometry(g);
    /* no spatial splits: a triangle met twice would count twice */
    rtcSetSceneBuildQuality(p->hull_scene[k], RTC_BUILD_QUALITY_MEDIUM);
    rtcCommitScene(p->hull_scene[k]);
}

typedef struct proto_size {
    uint32_t triangles, k;
} proto_size;

static int more_triangles(const void *x, const void *y)
{
    const proto_size *a = x, *b = y;
    if (a->triangles != b->triangles) return a->triangles > b->triangles ? -1 : 1;
    return (a->k > b->k) - (a->k < b->k);
}

/* The envelopes of the prototypes that some chosen plant uses, and their BVHs, on up to
 * `threads` threads; each prototype's own slots, so the result is the same for any count. */
static int build_hulls(accel *a, crown_proxies *p, const uint8_t *used, unsigned threads, err_buf *err)
{
    const scene *s = a->scene;
    uint32_t n = s->n_prototypes;
    hull_job job = {.a = a, .p = p, .used = used};
    proto_size *size = calloc(n ? n : 1, sizeof *size); /* owned here */
    job.order = calloc(n ? n : 1, sizeof *job.order);
    job.errs = calloc(n ? n : 1, sizeof *job.errs);
    job.rc = calloc(n ? n : 1, sizeof *job.rc);
    int rc = 0;
    if (!size || !job.order || !job.errs || !job.rc) rc = err_nomem(err, "out of memory for the crown envelopes");
    if (!rc) {
        for (uint32_t k = 0; k < n; k++) size[k] = (proto_size){s->prototypes[k].mesh->nt, k};
        qsort(size, n, sizeof *size, more_triangles);
        for (uint32_t k = 0; k < n; k++) job.order[k] = size[k].k;
        task_pool_run(threads, n, build_hull, &job);
        for (uint32_t k = 0; k < n && !rc; k++)
            if (job.rc[k]) *err = job.errs[k], rc = -1;
    }
    free(size), free(job.order), free(job.errs), free(job.rc);
    return rc;
}

/* --- the envelopes as one geometry of the top scene ---------------------------------------- */

/* The inverse of xf (a plant's placement: turn, uniform scale, translation; any invertible xf). */
static xform3x4 xf_inverse(const xform3x4 *xf)
{
    const float(*m)[4] = xf->m;
    float c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1], c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2],
          c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    float det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02, r = 1.0f / det;
    xform3x4 v;
    v.m[0][0] = c00 * r, v.m[1][0] = c01 * r, v.m[2][0] = c02 * r;
    v.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * r;
    v.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * r;
    v.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * r;
    v.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * r;
    v.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * r;
    v.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * r;
    for (int i = 0; i < 3; i++)
        v.m[i][3] = -(v.m[i][0] * m[0][3] + v.m[i][1] * m[1][3] + v.m[i][2] * m[2][3]);
    return v;
}

/* Proxy j's envelope scene and the ray (org, dir) in its frame. */
static RTCScene proxy_local_ray(const accel *a, uint32_t j, float org[3], float dir[3])
{
    const instance *in = &a->scene->instances[a->proxies->plant[j]];
    xform3x4 inv = xf_inverse(&in->xf);
    vec3 o = xf_point(&inv, v3(org[0], org[1], org[2])), d = xf_vector(&inv, v3(dir[0], dir[1], dir[2]));
    org[0] = o.x, org[1] = o.y, org[2] = o.z, dir[0] = d.x, dir[1] = d.y, dir[2] = d.z;
    return a->proxies->hull_scene[in->prototype];
}

/* World bounds of proxy j: its envelope's box, placed. */
static void proxy_bounds(const struct RTCBoundsFunctionArguments *args)
{
    const accel *a = args->geometryUserPtr;
    const instance *in = &a->scene->instances[a->proxies->plant[args->primID]];
    const float *lo = a->proxies->hull_box + 6 * (size_t)in->prototype, *hi = lo + 3;
    float wlo[3] = {INFINITY, INFINITY, INFINITY}, whi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int c = 0; c < 8; c++) {
        vec3 w = xf_point(&in->xf, v3(c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]));
        float f[3] = {w.x, w.y, w.z};
        for (int k = 0; k < 3; k++) wlo[k] = fminf(wlo[k], f[k]), whi[k] = fmaxf(whi[k], f[k]);
    }
    /* a little slack for the rounding of the ray's transform into the envelope's frame */
    float pad = 1e-5f * fmaxf(fmaxf(whi[0] - wlo[0], whi[1] - wlo[1]), whi[2] - wlo[2]);
    *args->bounds_o = (struct RTCBounds){.lower_x = wlo[0] - pad, .lower_y = wlo[1] - pad, .lower_z = wlo[2] - pad,
                                         .upper_x = whi[0] + pad, .upper_y = whi[1] + pad, .upper_z = whi[2] + pad};
}

/* A camera ray against proxy j: its envelope's hit reported as an instance's would be (geomID the
 * envelope's part, instID[0] the proxy's top-level id, Ng in the envelope's frame). */
static void proxy_intersect(const struct RTCIntersectFunctionNArguments *args)
{
    const accel *a = args->geometryUserPtr;
    const unsigned n = args->N;
    float *ray = (float *)args->rayhit;
    unsigned *hit = (unsigned *)(ray + 12 * (size_t)n); /* RTCHitN after the 12 fields of RTCRayN */
    for (unsigned i = 0; i < n; i++) {
        if (args->valid[i] != -1) continue;
        struct RTCRayHit rh = {.hit = {.geomID = RTC_INVALID_GEOMETRY_ID, .instID = {RTC_INVALID_GEOMETRY_ID}}};
        float org[3] = {ray[i], ray[n + i], ray[2 * n + i]}, dir[3] = {ray[4 * n + i], ray[5 * n + i], ray[6 * n + i]};
        RTCScene hull = proxy_local_ray(a, args->primID, org, dir);
        rh.ray = (struct RTCRay){.org_x = org[0], .org_y = org[1], .org_z = org[2], .tnear = ray[3 * n + i],
                                 .dir_x = dir[0], .dir_y = dir[1], .dir_z = dir[2], .time = ray[7 * n + i],
                                 .tfar = ray[8 * n + i], .mask = ~0u};
        args->context->instID[0] = a->first_proxy + args->primID;
        rtcIntersect1(hull, args->context, &rh);
        args->context->instID[0] = RTC_INVALID_GEOMETRY_ID;
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
        ray[8 * n + i] = rh.ray.tfar;
        float *fhit = (float *)hit;
        fhit[i] = rh.hit.Ng_x, fhit[n + i] = rh.hit.Ng_y, fhit[2 * n + i] = rh.hit.Ng_z;
        fhit[3 * n + i] = rh.hit.u, fhit[4 * n + i] = rh.hit.v;
        hit[5 * n + i] = rh.hit.primID, hit[6 * n + i] = rh.hit.geomID, hit[7 * n + i] = a->first_proxy + args->primID;
    }
}

/* A shadow ray across proxy j: through its envelope's transmittance filter, which stops the ray
 * (and so this) once it is nearly opaque. */
static void proxy_occluded(const struct RTCOccludedFunctionNArguments *args)
{
    const accel *a = args->geometryUserPtr;
    const unsigned n = args->N;
    float *ray = (float *)args->ray;
    for (unsigned i = 0; i < n; i++) {
        if (args->valid[i] != -1) continue;
        float org[3] = {ray[i], ray[n + i], ray[2 * n + i]}, dir[3] = {ray[4 * n + i], ray[5 * n + i], ray[6 * n + i]};
        RTCScene hull = proxy_local_ray(a, args->primID, org, dir);
        struct RTCRay r = {.org_x = org[0], .org_y = org[1], .org_z = org[2], .tnear = ray[3 * n + i],
                           .dir_x = dir[0], .dir_y = dir[1], .dir_z = dir[2], .time = ray[7 * n + i],
                           .tfar = ray[8 * n + i], .mask = ~0u};
        args->context->instID[0] = a->first_proxy + args->primID;
        rtcOccluded1(hull, args->context, &r);
        args->context->instID[0] = RTC_INVALID_GEOMETRY_ID;
        if (r.tfar < 0.0f) ray[8 * n + i] = -INFINITY;
    }
}

/* The proxies as one user geometry of the top scene at a->first_proxy, primitive j proxy j: an
 * Embree instance per proxy would cost some 400 bytes each (docs/scale.md); a primitive costs its
 * share of the top BVH. Hits carry the ids an instance of the envelope's scene would. */
static int add_proxy_field(accel *a, err_buf *err)
{
    crown_proxies *p = a->proxies;
    p->hull_box = calloc(6 * (size_t)(p->n_prototypes ? p->n_prototypes : 1), sizeof *p->hull_box);
    if (!p->hull_box) return err_nomem(err, "out of memory for the crown proxies");
    for (uint32_t k = 0; k < p->n_prototypes; k++)
        if (p->hull[k]) mesh_bounds(p->hull[k], p->hull_box + 6 * (size_t)k, p->hull_box + 6 * (size_t)k + 3);
    RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_USER);
    if (!g) return accel_device_error(a, err) ? -1 : err_nomem(err, "out of memory for the crown proxies");
    rtcSetGeometryUserPrimitiveCount(g, a->proxies->n);
    rtcSetGeometryUserData(g, a);
    rtcSetGeometryBoundsFunction(g, proxy_bounds, NULL);
    rtcSetGeometryIntersectFunction(g, proxy_intersect);
    rtcSetGeometryOccludedFunction(g, proxy_occluded);
    rtcSetGeometryMask(g, ACCEL_MASK_PROXY);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(a->top, g, a->first_proxy);
    rtcReleaseGeometry(g);
    return accel_device_error(a, err);
}

int crown_proxies_attach(accel *a, const camera *c, vec3 sun, double max_pixels, unsigned threads, err_buf *err)
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
    p->n_prototypes = s->n_prototypes, p->n_species = s->n_species, p->sun = sun, p->view = c->forward;
    p->hull = calloc(s->n_prototypes ? s->n_prototypes : 1, sizeof *p->hull);
    p->hull_scene = calloc(s->n_prototypes ? s->n_prototypes : 1, sizeof *p->hull_scene);
    p->hull_geom = calloc(s->n_prototypes ? (size_t)s->n_prototypes * ACCEL_PARTS : 1, sizeof *p->hull_geom);
    p->materials = calloc(s->n_species ? s->n_species : 1, sizeof *p->materials);
    if (!p->hull || !p->hull_scene || !p->hull_geom || !p->materials) goto nomem;
    for (uint32_t k = 0; k < s->n_species; k++)
        p->materials[k] = (material){.bsdf = SYLVA_BSDF_LAMBERT, .albedo = v3(1, 1, 1), .texture = -1};
    for (uint32_t i = 0; i < s->n_instances; i++)
        if (!s->instances[i].development && !scene_instance_is_ground_cover(s, i) && looks_small(s, i, c, pixel, max_pixels, leaf))
            far[i] = 1, used[s->instances[i].prototype] = 1;
    if (build_hulls(a, p, used, threads, err)) goto fail;
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->n_instances; i++) n += far[i] && p->hull_scene[s->instances[i].prototype];
    p->plant = calloc(n ? n : 1, sizeof *p->plant);
    if (!p->plant) goto nomem;
    a->first_proxy = a->first_instance + s->n_instances;
    for (uint32_t i = 0; i < s->n_instances; i++) {
        if (!far[i] || !p->hull_scene[s->instances[i].prototype]) continue;
        RTCGeometry g = rtcGetGeometry(a->top, a->first_instance + i);
        rtcSetGeometryMask(g, ACCEL_MASK_FAR_PLANT);
        rtcCommitGeometry(g);
        p->plant[p->n++] = i;
    }
    if (p->n && add_proxy_field(a, err)) goto fail;
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
