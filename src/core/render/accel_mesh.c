/* accel_mesh.c — a mesh's two parts in Embree, the cut-out filter, shared BVHs and their
 * instances (accel_mesh.h). */
#include "render/accel_mesh.h"

#include "render/accel_errors.h"

/* --- the cut-out filter ------------------------------------------------------------------- */

/* Embree's RTCHitN is a structure of arrays, each N long, in this order (rtcore_ray.h); its
 * accessors are C++ only. */
typedef enum hitn_field { HITN_NG_X, HITN_NG_Y, HITN_NG_Z, HITN_U, HITN_V, HITN_PRIM_ID, HITN_GEOM_ID } hitn_field;

static float hitn_float(const struct RTCHitN *hit, unsigned n, unsigned i, hitn_field f)
{
    return ((const float *)hit)[(size_t)f * n + i];
}

static unsigned hitn_uint(const struct RTCHitN *hit, unsigned n, unsigned i, hitn_field f)
{
    return ((const unsigned *)hit)[(size_t)f * n + i];
}

/* Rejects the hits that fall where the cut-out's texture is transparent, by the part's own test
 * (one record per triangle and the textures' coverage masks: cutout.h). */
static void cutout_filter(const struct RTCFilterFunctionNArguments *args)
{
    const geom_info *g = args->geometryUserPtr;
    const unsigned n = args->N;
    for (unsigned i = 0; i < n; i++) {
        if (args->valid[i] != -1) continue;
        if (!cutout_part_point_kept(&g->part, hitn_uint(args->hit, n, i, HITN_PRIM_ID),
                                    hitn_float(args->hit, n, i, HITN_U), hitn_float(args->hit, n, i, HITN_V)))
            args->valid[i] = 0;
    }
}

/* Adds one part of m (its opaque or its cut-out triangles) to rs as geometry `id`. Attaches
 * nothing when the part has no triangles. */
int accel_add_part(accel *a, RTCScene rs, const mesh *m, accel_part part, geom_kind kind, unsigned id,
                    unsigned mask, geom_info *g, err_buf *err)
{
    int cutouts = part == ACCEL_PART_CUTOUT;
    *g = (geom_info){.kind = kind, .mesh = m, .scene = a->scene, .alpha = cutouts};
    if (cutout_part_build(a->scene, m, cutouts, &g->part, err)) return -1;
    if (!g->part.n) return 0;
    RTCGeometry geom = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geom) return accel_device_error(a, err) ? -1 : err_set(err, "Embree could not create a triangle geometry");
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, m->pos, 0,
                               3 * sizeof(float), m->nv);
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, g->part.tri, 0,
                               3 * sizeof(uint32_t), g->part.n);
    rtcSetGeometryUserData(geom, g);
    rtcSetGeometryMask(geom, mask);
    if (cutouts) {
        rtcSetGeometryIntersectFilterFunction(geom, cutout_filter);
        rtcSetGeometryOccludedFilterFunction(geom, cutout_filter);
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(rs, geom, id);
    rtcReleaseGeometry(geom);
    return accel_device_error(a, err);
}

/* Both parts of m at ids first (opaque) and first + 1 (cut-out), into g[0] and g[1]. */
int accel_add_mesh(accel *a, RTCScene rs, const mesh *m, geom_kind kind, unsigned first, unsigned mask,
                    geom_info g[ACCEL_PARTS], err_buf *err)
{
    if (accel_add_part(a, rs, m, ACCEL_PART_OPAQUE, kind, first + ACCEL_PART_OPAQUE, mask, &g[ACCEL_PART_OPAQUE], err))
        return -1;
    return accel_add_part(a, rs, m, ACCEL_PART_CUTOUT, kind, first + ACCEL_PART_CUTOUT, mask, &g[ACCEL_PART_CUTOUT], err);
}

/* One BVH holding mesh m (its two parts in g[0] and g[1]), for instances to share. */
int accel_build_shared(accel *a, const mesh *m, geom_kind kind, RTCScene *out, geom_info g[ACCEL_PARTS],
                       err_buf *err)
{
    RTCScene ps = rtcNewScene(a->device);
    if (!ps) return accel_device_error(a, err) ? -1 : err_set(err, "Embree could not create a scene");
    *out = ps;
    rtcSetSceneBuildQuality(ps, RTC_BUILD_QUALITY_MEDIUM);
    if (accel_add_mesh(a, ps, m, kind, 0, ~0u, g, err)) return -1; /* the instance's mask decides */
    rtcCommitScene(ps);
    return accel_device_error(a, err);
}

int accel_add_instance(accel *a, RTCScene sc, const xform3x4 *xf, unsigned id, unsigned mask, err_buf *err)
{
    RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_INSTANCE);
    if (!g) return accel_device_error(a, err) ? -1 : err_nomem(err, "out of memory building the BVH");
    rtcSetGeometryInstancedScene(g, sc);
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, &xf->m[0][0]);
    rtcSetGeometryMask(g, mask);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(a->top, g, id);
    rtcReleaseGeometry(g);
    return 0;
}
