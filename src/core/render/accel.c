/* accel.c — building Embree scenes from the scene graph, alpha-mask filters, hit shading. */
#include "render/accel.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/texture_lookup.h"

static void embree_error(void *user, enum RTCError code, const char *str)
{
    err_buf *err = user;
    if (err && !err->msg[0]) err_set(err, "Embree error %d: %s", (int)code, str ? str : "");
}

mesh *terrain_mesh_build(const sylva_heightfield *hf, int32_t fallback, err_buf *err)
{
    uint32_t nx = hf->nx, ny = hf->ny;
    size_t nv = (size_t)nx * ny, nt = (size_t)(nx - 1) * (ny - 1) * 2;
    float *pos = malloc(nv * 3 * sizeof(float)), *nrm = malloc(nv * 3 * sizeof(float));
    float *uv = malloc(nv * 2 * sizeof(float));
    uint32_t *tri = malloc(nt * 3 * sizeof(uint32_t));
    int32_t *mat = malloc(nt * sizeof(int32_t));
    mesh *m = mesh_new();
    if (!pos || !nrm || !uv || !tri || !mat || !m) {
        err_nomem(err, "out of memory tessellating a %u x %u terrain", nx, ny);
        goto fail;
    }
    for (uint32_t j = 0; j < ny; j++)
        for (uint32_t i = 0; i < nx; i++) {
            size_t k = (size_t)j * nx + i;
            pos[k * 3] = (float)(hf->x0 + i * hf->dx);
            pos[k * 3 + 1] = (float)(hf->y0 + j * hf->dy);
            pos[k * 3 + 2] = hf->z[k];
            /* central differences (one-sided at the border) */
            uint32_t i0 = i ? i - 1 : i, i1 = i + 1 < nx ? i + 1 : i;
            uint32_t j0 = j ? j - 1 : j, j1 = j + 1 < ny ? j + 1 : j;
            double dzdx = (hf->z[(size_t)j * nx + i1] - hf->z[(size_t)j * nx + i0]) / ((i1 - i0) * hf->dx);
            double dzdy = (hf->z[(size_t)j1 * nx + i] - hf->z[(size_t)j0 * nx + i]) / ((j1 - j0) * hf->dy);
            double l = sqrt(dzdx * dzdx + dzdy * dzdy + 1.0);
            nrm[k * 3] = (float)(-dzdx / l), nrm[k * 3 + 1] = (float)(-dzdy / l), nrm[k * 3 + 2] = (float)(1.0 / l);
            uv[k * 2] = (float)i / (nx - 1), uv[k * 2 + 1] = (float)j / (ny - 1);
        }
    size_t t = 0;
    for (uint32_t j = 0; j + 1 < ny; j++)
        for (uint32_t i = 0; i + 1 < nx; i++) {
            uint32_t a = j * nx + i, b = a + 1, c = a + nx, d = c + 1;
            int32_t ma = hf->material && hf->material[a] >= 0 ? hf->material[a] : fallback;
            uint32_t q[6] = {a, b, d, a, d, c};
            memcpy(tri + t * 3, q, sizeof q);
            mat[t] = mat[t + 1] = ma;
            t += 2;
        }
    if (mesh_append(m, pos, nrm, uv, (uint32_t)nv, tri, mat, fallback, (uint32_t)nt, err)) goto fail;
    free(pos), free(nrm), free(uv), free(tri), free(mat);
    return m;
fail:
    free(pos), free(nrm), free(uv), free(tri), free(mat);
    mesh_free(m);
    return NULL;
}

static const material *material_of(const scene *s, int32_t id)
{
    return &s->materials[id >= 0 && (uint32_t)id < s->n_materials ? (uint32_t)id : (uint32_t)s->default_material];
}

static int tri_is_masked(const scene *s, const mesh *m, uint32_t t)
{
    return scene_material_cuts_alpha(s, material_of(s, m->mat[t]));
}

/* Texture alpha at barycentrics (u, v) of triangle t. */
static float alpha_at(const geom_info *g, uint32_t prim, float bu, float bv)
{
    uint32_t t = g->prim_to_tri ? g->prim_to_tri[prim] : prim;
    const mesh *m = g->mesh;
    const material *mt = material_of(g->scene, m->mat[t]);
    const uint32_t *k = m->tri + (size_t)t * 3;
    float w = 1.0f - bu - bv;
    float u = w * m->uv[k[0] * 2] + bu * m->uv[k[1] * 2] + bv * m->uv[k[2] * 2];
    float v = w * m->uv[k[0] * 2 + 1] + bu * m->uv[k[1] * 2 + 1] + bv * m->uv[k[2] * 2 + 1];
    return texture_alpha(&g->scene->textures[mt->texture], u, v);
}

/* Embree's RTCHitN is a structure of arrays (Ng x, y, z, u, v, primID, ...), each N long; its
 * accessors are C++ only, so the offsets are written out here. */
static void alpha_filter(const struct RTCFilterFunctionNArguments *args)
{
    const geom_info *g = args->geometryUserPtr;
    const unsigned N = args->N;
    const float *hf = (const float *)args->hit;
    const unsigned *hu = (const unsigned *)args->hit;
    for (unsigned i = 0; i < N; i++) {
        if (args->valid[i] != -1) continue;
        if (alpha_at(g, hu[5 * N + i], hf[3 * N + i], hf[4 * N + i]) < 0.5f) args->valid[i] = 0;
    }
}

/* Adds the triangles of m selected by `masked` (0: opaque ones, 1: alpha-masked ones) to rs as
 * geometry id `id`. Leaves g->indices empty (and attaches nothing) when none are selected. */
static int add_mesh_part(accel *a, RTCScene rs, const mesh *m, int masked, geom_kind kind, unsigned id,
                         geom_info *g, err_buf *err)
{
    *g = (geom_info){.kind = kind, .mesh = m, .scene = a->scene, .alpha = masked};
    uint32_t n = 0;
    for (uint32_t t = 0; t < m->nt; t++) n += tri_is_masked(a->scene, m, t) == masked;
    if (!n) return 0;
    g->indices = malloc((size_t)n * 3 * sizeof(uint32_t));
    g->prim_to_tri = malloc((size_t)n * sizeof(uint32_t));
    if (!g->indices || !g->prim_to_tri) return err_nomem(err, "out of memory building the BVH");
    uint32_t k = 0;
    for (uint32_t t = 0; t < m->nt; t++)
        if (tri_is_masked(a->scene, m, t) == masked) {
            memcpy(g->indices + (size_t)k * 3, m->tri + (size_t)t * 3, 3 * sizeof(uint32_t));
            g->prim_to_tri[k++] = t;
        }
    RTCGeometry geom = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geom) return err_set(err, "Embree could not create a triangle geometry");
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, m->pos, 0,
                               3 * sizeof(float), m->nv);
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, g->indices, 0,
                               3 * sizeof(uint32_t), n);
    rtcSetGeometryUserData(geom, g);
    if (masked) {
        rtcSetGeometryIntersectFilterFunction(geom, alpha_filter);
        rtcSetGeometryOccludedFilterFunction(geom, alpha_filter);
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(rs, geom, id);
    rtcReleaseGeometry(geom);
    return 0;
}

int accel_build(accel *a, const scene *s, unsigned threads, err_buf *err)
{
    memset(a, 0, sizeof *a);
    a->scene = s;
    char config[64];
    snprintf(config, sizeof config, "threads=%u", threads);
    a->device = rtcNewDevice(config);
    if (!a->device) return err_set(err, "Embree could not create a device (error %d)", (int)rtcGetDeviceError(NULL));
    err_clear(err);
    rtcSetDeviceErrorFunction(a->device, embree_error, err);

    /* prototypes */
    a->proto_scenes = calloc(s->n_prototypes ? s->n_prototypes : 1, sizeof(RTCScene));
    a->proto_geoms = calloc(s->n_prototypes ? (size_t)s->n_prototypes * 2 : 1, sizeof(geom_info));
    if (!a->proto_scenes || !a->proto_geoms) goto oom;
    for (uint32_t p = 0; p < s->n_prototypes; p++) {
        RTCScene ps = rtcNewScene(a->device);
        a->proto_scenes[p] = ps;
        rtcSetSceneBuildQuality(ps, RTC_BUILD_QUALITY_HIGH);
        const mesh *m = s->prototypes[p].mesh;
        if (add_mesh_part(a, ps, m, 0, GEOM_PROTOTYPE, 0, &a->proto_geoms[p * 2], err) ||
            add_mesh_part(a, ps, m, 1, GEOM_PROTOTYPE, 1, &a->proto_geoms[p * 2 + 1], err))
            goto fail;
        rtcCommitScene(ps);
    }

    /* top level: terrain (opaque, masked), water, objects (opaque, masked), then instances */
    a->top = rtcNewScene(a->device);
    a->n_top_geoms = 3 + 2 * s->n_objects;
    a->top_geoms = calloc(a->n_top_geoms, sizeof(geom_info));
    if (!a->top_geoms) goto oom;
    if (s->terrain) {
        a->terrain_mesh = terrain_mesh_build(s->terrain, s->terrain_material, err);
        if (!a->terrain_mesh) goto fail;
        if (add_mesh_part(a, a->top, a->terrain_mesh, 0, GEOM_TERRAIN, 0, &a->top_geoms[0], err) ||
            add_mesh_part(a, a->top, a->terrain_mesh, 1, GEOM_TERRAIN, 1, &a->top_geoms[1], err))
            goto fail;
        if (s->terrain->has_water) {
            const sylva_heightfield *hf = s->terrain;
            float x0 = (float)hf->x0, y0 = (float)hf->y0, z = (float)hf->water_level;
            float x1 = (float)(hf->x0 + (hf->nx - 1) * hf->dx), y1 = (float)(hf->y0 + (hf->ny - 1) * hf->dy);
            float pos[12] = {x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z};
            float uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
            uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
            int32_t wm = hf->water_material >= 0 ? hf->water_material : s->water_material;
            a->water_mesh = mesh_new();
            if (!a->water_mesh) goto oom;
            if (mesh_append(a->water_mesh, pos, NULL, uv, 4, tri, NULL, wm, 2, err)) goto fail;
            if (add_mesh_part(a, a->top, a->water_mesh, 0, GEOM_WATER, 2, &a->top_geoms[2], err)) goto fail;
        }
    }
    for (uint32_t o = 0; o < s->n_objects; o++) {
        const mesh *m = s->objects[o].mesh;
        if (add_mesh_part(a, a->top, m, 0, GEOM_OBJECT, 3 + 2 * o, &a->top_geoms[3 + 2 * o], err) ||
            add_mesh_part(a, a->top, m, 1, GEOM_OBJECT, 4 + 2 * o, &a->top_geoms[4 + 2 * o], err))
            goto fail;
    }
    a->first_instance = a->n_top_geoms;
    for (uint32_t i = 0; i < s->n_instances; i++) {
        RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_INSTANCE);
        if (!g) goto oom;
        rtcSetGeometryInstancedScene(g, a->proto_scenes[s->instances[i].prototype]);
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, &s->instances[i].xf.m[0][0]);
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(a->top, g, a->first_instance + i);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(a->top);
    if (err && err->msg[0]) goto fail;
    struct RTCBounds b;
    rtcGetSceneBounds(a->top, &b);
    a->bounds_lo[0] = b.lower_x, a->bounds_lo[1] = b.lower_y, a->bounds_lo[2] = b.lower_z;
    a->bounds_hi[0] = b.upper_x, a->bounds_hi[1] = b.upper_y, a->bounds_hi[2] = b.upper_z;
    return 0;
oom:
    err_nomem(err, "out of memory building the BVH");
fail:
    accel_free(a);
    return -1;
}

void accel_free(accel *a)
{
    if (!a->device) return;
    if (a->top) rtcReleaseScene(a->top);
    const scene *s = a->scene;
    for (uint32_t p = 0; a->proto_scenes && p < s->n_prototypes; p++)
        if (a->proto_scenes[p]) rtcReleaseScene(a->proto_scenes[p]);
    for (uint32_t g = 0; a->proto_geoms && g < 2 * s->n_prototypes; g++)
        free(a->proto_geoms[g].indices), free(a->proto_geoms[g].prim_to_tri);
    for (uint32_t g = 0; a->top_geoms && g < a->n_top_geoms; g++)
        free(a->top_geoms[g].indices), free(a->top_geoms[g].prim_to_tri);
    free(a->proto_scenes);
    free(a->proto_geoms);
    free(a->top_geoms);
    mesh_free(a->terrain_mesh);
    mesh_free(a->water_mesh);
    rtcReleaseDevice(a->device);
    memset(a, 0, sizeof *a);
}

void accel_shade(const accel *a, const struct RTCRayHit *rh, hit_info *h)
{
    const scene *s = a->scene;
    const geom_info *g;
    const xform3x4 *xf = NULL;
    unsigned inst = rh->hit.instID[0];
    h->instance_id = 0, h->species_id = 0;
    if (inst != RTC_INVALID_GEOMETRY_ID) {
        uint32_t i = inst - a->first_instance;
        uint32_t p = s->instances[i].prototype;
        g = &a->proto_geoms[p * 2 + rh->hit.geomID];
        xf = &s->instances[i].xf;
        h->instance_id = i + 1;
        h->species_id = s->prototypes[p].species + 1;
    } else {
        g = &a->top_geoms[rh->hit.geomID];
    }
    const mesh *m = g->mesh;
    uint32_t t = g->prim_to_tri ? g->prim_to_tri[rh->hit.primID] : rh->hit.primID;
    const uint32_t *k = m->tri + (size_t)t * 3;
    float bu = rh->hit.u, bv = rh->hit.v, bw = 1.0f - bu - bv;
    vec3 p0 = v3(m->pos[k[0] * 3], m->pos[k[0] * 3 + 1], m->pos[k[0] * 3 + 2]);
    vec3 p1 = v3(m->pos[k[1] * 3], m->pos[k[1] * 3 + 1], m->pos[k[1] * 3 + 2]);
    vec3 p2 = v3(m->pos[k[2] * 3], m->pos[k[2] * 3 + 1], m->pos[k[2] * 3 + 2]);
    vec3 ng = v3_cross(v3_sub(p1, p0), v3_sub(p2, p0));
    vec3 ns = v3_add(v3_add(v3_scale(v3(m->nrm[k[0] * 3], m->nrm[k[0] * 3 + 1], m->nrm[k[0] * 3 + 2]), bw),
                            v3_scale(v3(m->nrm[k[1] * 3], m->nrm[k[1] * 3 + 1], m->nrm[k[1] * 3 + 2]), bu)),
                     v3_scale(v3(m->nrm[k[2] * 3], m->nrm[k[2] * 3 + 1], m->nrm[k[2] * 3 + 2]), bv));
    if (xf) {
        ng = xf_normal(xf, ng);
        ns = xf_normal(xf, ns);
    }
    h->ng = v3_norm(ng);
    h->ns = v3_norm(ns);
    if (!(v3_dot(h->ns, h->ns) > 0.5f)) h->ns = h->ng;
    h->t = rh->ray.tfar;
    /* The point from the barycentrics rather than origin + t direction: it lies on the triangle
     * to within the rounding of its coordinates, whereas t carries an error proportional to the
     * distance from the camera, which would force a far larger shadow-ray offset. */
    vec3 p = v3_add(v3_add(v3_scale(p0, bw), v3_scale(p1, bu)), v3_scale(p2, bv));
    h->p = xf ? xf_point(xf, p) : p;
    h->u = bw * m->uv[k[0] * 2] + bu * m->uv[k[1] * 2] + bv * m->uv[k[2] * 2];
    h->v = bw * m->uv[k[0] * 2 + 1] + bu * m->uv[k[1] * 2 + 1] + bv * m->uv[k[2] * 2 + 1];
    h->mat = material_of(s, m->mat[t]);
    h->albedo = h->mat->albedo;
    if (h->mat->texture >= 0) {
        float rgba[4];
        texture_sample(&s->textures[h->mat->texture], h->u, h->v, rgba);
        h->albedo = v3_mul(h->albedo, v3(rgba[0], rgba[1], rgba[2]));
    }
    h->kind = g->kind;
}
