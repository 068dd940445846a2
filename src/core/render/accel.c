/* accel.c — building Embree scenes from the scene graph and the scene geometry (each mesh by
 * accel_mesh.h), hit shading. */
#include "render/accel.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/texture_lookup.h"
#include "geometry/terrain_apron.h"
#include "geometry/water_surface.h"
#include "render/accel_frame.h"
#include "render/accel_terrain.h"
#include "render/bark_bump.h"
#include "geometry/ground_texture.h"
#include "render/crown_proxy.h"

/* --- what a hit is ---------------------------------------------------------------------- */

uint32_t accel_hit_object(const accel *a, const struct RTCRayHit *rh)
{
    unsigned inst = rh->hit.instID[0];
    unsigned id = inst != RTC_INVALID_GEOMETRY_ID ? inst : rh->hit.geomID;
    if (id == RTC_INVALID_GEOMETRY_ID || id < ACCEL_TOP_FIRST_OBJECT || id >= a->first_instance) return 0;
    return (id - ACCEL_TOP_FIRST_OBJECT) / ACCEL_PARTS + 1;
}

/* --- building ----------------------------------------------------------------------------- */

/* 1 when the box lo .. hi of a prototype, placed by xf, reaches the rectangle of `which`. */
static int box_reaches(const xform3x4 *xf, const float lo[3], const float hi[3], const accel_plants *which)
{
    for (int r = 0; r < 2; r++) {
        double centre = xf->m[r][3], reach = 0;
        for (int k = 0; k < 3; k++) {
            double mid = 0.5 * ((double)lo[k] + hi[k]), half = 0.5 * ((double)hi[k] - lo[k]);
            centre += xf->m[r][k] * mid, reach += fabs(xf->m[r][k]) * half;
        }
        if (centre + reach < which->lo[r] || centre - reach > which->hi[r]) return 0;
    }
    return 1;
}

/* Marks in held (n_instances) the plants a build holds and in used (n_prototypes) the prototypes
 * they place. Returns 0, or -1 when out of memory. */
static int plants_held(const scene *s, const accel_plants *which, uint8_t *held, uint8_t *used)
{
    float (*box)[2][3] = malloc((s->n_prototypes ? s->n_prototypes : 1) * sizeof *box); /* freed below */
    if (!box) return -1;
    for (uint32_t p = 0; p < s->n_prototypes; p++) mesh_bounds(s->prototypes[p].mesh, box[p][0], box[p][1]);
    for (uint32_t i = 0; i < s->n_instances; i++) {
        const instance *in = &s->instances[i];
        held[i] = which->kind == ACCEL_PLANTS_ALL ||
                  (which->kind == ACCEL_PLANTS_WITHIN && box_reaches(&in->xf, box[in->prototype][0],
                                                                     box[in->prototype][1], which));
        if (held[i]) used[in->prototype] = 1;
    }
    free(box);
    return 0;
}

static int build_prototypes(accel *a, const scene *s, const uint8_t *used, err_buf *err)
{
    for (uint32_t p = 0; p < s->n_prototypes; p++)
        if (used[p] && accel_build_shared(a, s->prototypes[p].mesh, GEOM_PROTOTYPE, &a->proto_scenes[p],
                                          &a->proto_geoms[p * ACCEL_PARTS], err))
            return -1;
    for (uint32_t m = 0; m < s->n_models; m++)
        if (accel_build_shared(a, s->models[m].mesh, GEOM_OBJECT, &a->model_scenes[m], &a->model_geoms[m * ACCEL_PARTS],
                         err))
            return -1;
    return 0;
}

/* The top scene: terrain, water, objects, then the plants held (the id layout in accel.h). */
static int build_top(accel *a, const scene *s, const uint8_t *held, err_buf *err)
{
    a->top = rtcNewScene(a->device);
    /* robust traversal: a ray running exactly along the terrain's cell edges (a camera on a
     * node line looking along it) would otherwise slip between the triangles */
    if (a->top) rtcSetSceneFlags(a->top, RTC_SCENE_FLAG_ROBUST);
    if (!a->top) return accel_device_error(a, err) ? -1 : err_set(err, "Embree could not create a scene");
    if (s->terrain) {
        double eye[3] = {s->camera.position[0], s->camera.position[1], s->camera.position[2]};
        if (accel_terrain_add(a, a->top, ACCEL_TOP_TERRAIN, err) || ground_texture_build(s, &a->ground, err) ||
            water_surface_build(s, &a->water_mesh, err) ||
            terrain_apron_build(s->terrain, s->terrain_material, terrain_apron_reach(s->terrain, eye),
                                &a->apron_mesh, err))
            return -1;
        accel_frame_mesh_in_place(a, a->apron_mesh);
        accel_frame_mesh_in_place(a, a->water_mesh);
        if (a->apron_mesh && accel_add_part(a, a->top, a->apron_mesh, ACCEL_PART_OPAQUE, GEOM_TERRAIN, ACCEL_TOP_APRON,
                                            ACCEL_MASK_GROUND, &a->top_geoms[ACCEL_TOP_APRON], err))
            return -1;
        if (a->water_mesh && accel_add_part(a, a->top, a->water_mesh, ACCEL_PART_OPAQUE, GEOM_WATER, ACCEL_TOP_WATER,
                                            ACCEL_MASK_GROUND, &a->top_geoms[ACCEL_TOP_WATER], err))
            return -1;
    }
    for (uint32_t o = 0; o < s->n_objects; o++) {
        const object *ob = &s->objects[o];
        unsigned id = accel_top_object_id(o, ACCEL_PART_OPAQUE);
        unsigned mask = ob->development ? ACCEL_MASK_DEVELOPMENT : ACCEL_MASK_OBJECT;
        const mesh *m = ob->mesh;
        if (m && a->framed_objects && !(m = a->framed_objects[o] = accel_frame_mesh(a, ob->mesh, err))) return -1;
        xform3x4 xf = accel_frame_xf(a, &ob->xf);
        if (m ? accel_add_mesh(a, a->top, m, GEOM_OBJECT, id, mask, &a->top_geoms[id], err)
              : accel_add_instance(a, a->model_scenes[ob->model], &xf, id, mask, err))
            return -1;
    }
    for (uint32_t i = 0; i < s->n_instances; i++) {
        if (!held[i]) continue;
        a->plants_held++;
        xform3x4 xf = accel_frame_xf(a, &s->instances[i].xf);
        if (accel_add_instance(a, a->proto_scenes[s->instances[i].prototype], &xf, a->first_instance + i,
                               s->instances[i].development ? ACCEL_MASK_DEVELOPMENT : ACCEL_MASK_PLANT, err))
            return -1;
    }
    return accel_device_error(a, err);
}

/* accel_build_open holding the plants `which` says (NULL: all). */
static int build_open(accel *a, const scene *s, unsigned threads, const double frame[3], const accel_plants *which,
                      err_buf *err)
{
    static const accel_plants all = {ACCEL_PLANTS_ALL, {0, 0}, {0, 0}};
    uint8_t *held = NULL, *used = NULL; /* freed below */
    memset(a, 0, sizeof *a);
    a->scene = s;
    if (frame) memcpy(a->frame, frame, sizeof a->frame);
    a->errors = accel_errors_new();
    if (!a->errors) return err_nomem(err, "out of memory building the BVH");
    char config[64];
    snprintf(config, sizeof config, "threads=%u", threads);
    a->device = rtcNewDevice(config);
    if (!a->device) {
        int code = (int)rtcGetDeviceError(NULL);
        accel_free(a);
        return err_set(err, "Embree could not create a device (error %d)", code);
    }
    accel_errors_watch(a->errors, a->device);

    a->proto_scenes = calloc(s->n_prototypes ? s->n_prototypes : 1, sizeof(RTCScene));
    a->proto_geoms = calloc(s->n_prototypes ? (size_t)s->n_prototypes * ACCEL_PARTS : 1, sizeof(geom_info));
    a->model_scenes = calloc(s->n_models ? s->n_models : 1, sizeof(RTCScene));
    a->model_geoms = calloc(s->n_models ? (size_t)s->n_models * ACCEL_PARTS : 1, sizeof(geom_info));
    a->n_top_geoms = accel_top_object_id(s->n_objects, ACCEL_PART_OPAQUE);
    a->first_instance = a->n_top_geoms;
    a->top_geoms = calloc(a->n_top_geoms, sizeof(geom_info));
    if (accel_framed(a)) a->framed_objects = calloc(s->n_objects ? s->n_objects : 1, sizeof(mesh *));
    held = malloc(s->n_instances ? s->n_instances : 1), used = calloc(s->n_prototypes ? s->n_prototypes : 1, 1);
    if (!a->proto_scenes || !a->proto_geoms || !a->model_scenes || !a->model_geoms || !a->top_geoms ||
        (accel_framed(a) && !a->framed_objects) || !held || !used || plants_held(s, which ? which : &all, held, used)) {
        err_nomem(err, "out of memory building the BVH");
        goto fail;
    }
    if (build_prototypes(a, s, used, err) || build_top(a, s, held, err)) goto fail;
    free(held), free(used);
    return 0;
fail:
    free(held), free(used);
    accel_free(a);
    return -1;
}

int accel_build_open(accel *a, const scene *s, unsigned threads, const double frame[3], err_buf *err)
{
    return build_open(a, s, threads, frame, NULL, err);
}

int accel_commit(accel *a, err_buf *err)
{
    rtcCommitScene(a->top);
    if (accel_device_error(a, err)) {
        accel_free(a);
        return -1;
    }
    struct RTCBounds b;
    rtcGetSceneBounds(a->top, &b);
    a->bounds_lo[0] = b.lower_x, a->bounds_lo[1] = b.lower_y, a->bounds_lo[2] = b.lower_z;
    a->bounds_hi[0] = b.upper_x, a->bounds_hi[1] = b.upper_y, a->bounds_hi[2] = b.upper_z;
    return 0;
}

int accel_build(accel *a, const scene *s, unsigned threads, err_buf *err)
{
    return accel_build_plants(a, s, threads, NULL, err);
}

int accel_build_plants(accel *a, const scene *s, unsigned threads, const accel_plants *which, err_buf *err)
{
    return build_open(a, s, threads, NULL, which, err) || accel_commit(a, err) ? -1 : 0;
}

void accel_free(accel *a)
{
    const scene *s = a->scene;
    if (a->top) rtcReleaseScene(a->top);
    for (uint32_t p = 0; a->proto_scenes && p < s->n_prototypes; p++)
        if (a->proto_scenes[p]) rtcReleaseScene(a->proto_scenes[p]);
    for (uint32_t g = 0; a->proto_geoms && g < ACCEL_PARTS * s->n_prototypes; g++)
        cutout_part_free(&a->proto_geoms[g].part);
    for (uint32_t m = 0; a->model_scenes && m < s->n_models; m++)
        if (a->model_scenes[m]) rtcReleaseScene(a->model_scenes[m]);
    for (uint32_t g = 0; a->model_geoms && g < ACCEL_PARTS * s->n_models; g++)
        cutout_part_free(&a->model_geoms[g].part);
    for (uint32_t g = 0; a->top_geoms && g < a->n_top_geoms; g++) cutout_part_free(&a->top_geoms[g].part);
    free(a->proto_scenes);
    free(a->proto_geoms);
    free(a->model_scenes);
    free(a->model_geoms);
    free(a->top_geoms);
    crown_proxies_free(a->proxies);
    accel_terrain_free(a->terrain);
    ground_texture_free(a->ground);
    mesh_free(a->water_mesh);
    mesh_free(a->apron_mesh);
    for (uint32_t o = 0; a->framed_objects && o < s->n_objects; o++) mesh_free(a->framed_objects[o]);
    free(a->framed_objects);
    if (a->device) rtcReleaseDevice(a->device);
    accel_errors_free(a->errors);
    memset(a, 0, sizeof *a);
}

void accel_shade(const accel *a, const struct RTCRayHit *rh, hit_info *h)
{
    const scene *s = a->scene;
    const geom_info *g;
    const xform3x4 *xf = NULL;
    const material *proxy = NULL; /* the material of a crown proxy (crown_proxy.h) */
    unsigned inst = rh->hit.instID[0];
    h->instance_id = 0, h->species_id = 0, h->object_id = accel_hit_object(a, rh);
    if (h->object_id && inst != RTC_INVALID_GEOMETRY_ID) {
        const object *ob = &s->objects[h->object_id - 1];
        g = &a->model_geoms[(uint32_t)ob->model * ACCEL_PARTS + rh->hit.geomID];
        xf = &ob->xf;
    } else if (a->proxies && inst != RTC_INVALID_GEOMETRY_ID && inst >= a->first_proxy) {
        uint32_t i = a->proxies->plant[inst - a->first_proxy], p = s->instances[i].prototype;
        g = &a->proxies->hull_geom[p * ACCEL_PARTS + rh->hit.geomID];
        xf = &s->instances[i].xf;
        h->instance_id = i + 1;
        h->species_id = s->prototypes[p].species + 1;
        proxy = &a->proxies->materials[s->prototypes[p].species];
    } else if (inst != RTC_INVALID_GEOMETRY_ID) {
        uint32_t i = inst - a->first_instance;
        uint32_t p = s->instances[i].prototype;
        g = &a->proto_geoms[p * ACCEL_PARTS + rh->hit.geomID];
        xf = &s->instances[i].xf;
        h->instance_id = i + 1;
        h->species_id = s->prototypes[p].species + 1;
    } else {
        g = &a->top_geoms[rh->hit.geomID];
        if (g->terrain) {
            accel_terrain_shade(a, rh, h);
            return;
        }
    }
    const mesh *m = g->mesh;
    uint32_t t = g->part.to_mesh[rh->hit.primID];
    const uint32_t *k = g->part.tri + (size_t)rh->hit.primID * 3; /* m's triangle t, read beside to_mesh */
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
    h->one_normal = !memcmp(m->nrm + k[0] * 3, m->nrm + k[1] * 3, 3 * sizeof(float)) &&
                    !memcmp(m->nrm + k[0] * 3, m->nrm + k[2] * 3, 3 * sizeof(float));
    if (!(v3_dot(h->ns, h->ns) > 0.5f)) h->ns = h->ng;
    h->t = rh->ray.tfar;
    /* The point from the barycentrics rather than origin + t direction: it lies on the triangle
     * to within the rounding of its coordinates, whereas t carries an error proportional to the
     * distance from the camera, which would force a far larger shadow-ray offset. */
    vec3 p = v3_add(v3_add(v3_scale(p0, bw), v3_scale(p1, bu)), v3_scale(p2, bv));
    if (xf) {
        xform3x4 framed = accel_frame_xf(a, xf); /* into the frame before rounding, not after */
        p = xf_point(&framed, p);
    }
    h->p = p;
    h->u = bw * m->uv[k[0] * 2] + bu * m->uv[k[1] * 2] + bv * m->uv[k[2] * 2];
    h->v = bw * m->uv[k[0] * 2 + 1] + bu * m->uv[k[1] * 2 + 1] + bv * m->uv[k[2] * 2 + 1];
    h->mat = proxy ? proxy : &s->materials[scene_triangle_material(s, m, t)];
    h->albedo = h->mat->albedo;
    if (h->mat->texture >= 0) {
        float rgba[4];
        texture_sample(&s->textures[h->mat->texture], h->u, h->v, rgba);
        h->albedo = v3_mul(h->albedo, v3(rgba[0], rgba[1], rgba[2]));
    }
    h->kind = g->kind;
    if (a->bark_relief) bark_bump(s, m, t, xf, h);
    if (g->kind == GEOM_TERRAIN) accel_terrain_ground(a, rh, h); /* the apron */
}
