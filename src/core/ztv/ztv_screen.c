/* ztv_screen.c — the screening geometry without the ground (ztv/ztv_screen.h). */
#include "ztv/ztv_screen.h"

/* Attaches the top scene's geometry id to own. */
static void share(const accel *a, RTCScene own, unsigned id)
{
    RTCGeometry g = rtcGetGeometry(a->top, id);
    if (g) rtcAttachGeometryByID(own, g, id);
}

/* A scene of a's plant instances and objects whose mask meets mask; NULL with err set. */
static RTCScene own_scene(const accel *a, unsigned mask, err_buf *err)
{
    const scene *s = a->scene;
    RTCScene own = rtcNewScene(a->device); /* the caller's */
    if (!own) return accel_device_error(a, err) ? NULL : (err_set(err, "Embree could not create a scene"), NULL);
    rtcSetSceneFlags(own, RTC_SCENE_FLAG_ROBUST); /* as the top scene */
    for (uint32_t o = 0; o < s->n_objects; o++) {
        unsigned kind = s->objects[o].development ? ACCEL_MASK_DEVELOPMENT : ACCEL_MASK_OBJECT;
        if (!(kind & mask)) continue;
        for (int part = 0; part < ACCEL_PARTS; part++) {
            unsigned id = accel_top_object_id(o, (accel_part)part);
            /* an object of its own mesh has a geometry per part with triangles; a placed model,
             * one instance at the opaque part's id */
            int exists = s->objects[o].mesh ? a->top_geoms[id].part.n > 0 : part == ACCEL_PART_OPAQUE;
            if (exists) share(a, own, id);
        }
    }
    for (uint32_t i = 0; i < s->n_instances; i++) {
        unsigned kind = s->instances[i].development ? ACCEL_MASK_DEVELOPMENT : ACCEL_MASK_PLANT;
        if (kind & mask) share(a, own, a->first_instance + i);
    }
    rtcCommitScene(own);
    if (accel_device_error(a, err)) {
        rtcReleaseScene(own);
        return NULL;
    }
    return own;
}

int ztv_screen_open(ztv_screen *s, const accel *a, unsigned mask, uint64_t pairs, err_buf *err)
{
    mask &= ~(unsigned)ACCEL_MASK_GROUND;
    *s = (ztv_screen){.scene = a->top, .mask = mask};
    uint64_t geometries = (uint64_t)a->plants_held + a->scene->n_objects;
    if (pairs < ZTV_SCREEN_PAIRS_PER_PLANT * geometries) return 0;
    if (!(s->own = own_scene(a, mask, err))) return -1;
    s->scene = s->own, s->mask = ~0u;
    return 0;
}

void ztv_screen_close(ztv_screen *s)
{
    if (s->own) rtcReleaseScene(s->own);
    *s = (ztv_screen){0};
}
