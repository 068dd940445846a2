/* ztv_canopy.c — the canopy surface of a visibility map's canopy mode (ztv_canopy.h). */
#include "ztv/ztv_canopy.h"

#include <math.h>
#include <stdlib.h>

#include "render/accel_terrain.h" /* ACCEL_TERRAIN_TILE: Embree's largest grid */
#include "scene/heightfield.h"
#include "util/memory_budget.h"
#include "ztv/ztv_grid.h"
#include "ztv/ztv_targets.h"

#define CANOPY_BVH_NODE_BYTES 20u /* Embree's grid BVH per node at the peak of its build */

struct ztv_canopy {
    sylva_heightfield surface; /* its z owned */
    float *vertices;           /* the nodes' positions, rows north to south; owned */
    RTCScene scene;            /* owned (released) */
};

/* The surface's heights: the ground the map traces at each node plus the canopy there. */
static void surface_heights(const scene *s, sylva_heightfield *hf)
{
    const sylva_heightfield *surveyed = s->surveyed;
    for (uint32_t j = 0; j < hf->ny; j++)
        for (uint32_t i = 0; i < hf->nx; i++) {
            size_t k = (size_t)j * hf->nx + i;
            double ground;
            if (ztv_ground(s, hf->x0 + i * hf->dx, hf->y0 + j * hf->dy, &ground)) ground = surveyed->z[k];
            hf->z[k] = (float)(ground + canopy_height_or_open(s->canopy, k));
        }
}

/* The grid geometry over the vertices, in tiles of at most ACCEL_TERRAIN_TILE cells a side. */
static int attach_grid(ztv_canopy *c, RTCDevice device)
{
    const sylva_heightfield *hf = &c->surface;
    uint32_t cx = hf->nx - 1, cy = hf->ny - 1, tx = (cx - 1) / ACCEL_TERRAIN_TILE + 1;
    uint32_t n_tiles = tx * ((cy - 1) / ACCEL_TERRAIN_TILE + 1);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_GRID);
    if (!geom) return -1;
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, c->vertices, 0, 3 * sizeof(float),
                               (unsigned)((size_t)hf->nx * hf->ny));
    struct RTCGrid *tiles = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_GRID, 0, RTC_FORMAT_GRID,
                                                    sizeof(struct RTCGrid), n_tiles);
    for (uint32_t t = 0; tiles && t < n_tiles; t++) {
        uint32_t i0 = t % tx * ACCEL_TERRAIN_TILE, j0 = t / tx * ACCEL_TERRAIN_TILE;
        uint32_t w = cx - i0 < ACCEL_TERRAIN_TILE ? cx - i0 : ACCEL_TERRAIN_TILE;
        uint32_t h = cy - j0 < ACCEL_TERRAIN_TILE ? cy - j0 : ACCEL_TERRAIN_TILE;
        uint32_t north_row = hf->ny - 1 - (j0 + h); /* vertex row of the tile's northern nodes */
        tiles[t] = (struct RTCGrid){.startVertexID = (unsigned)((size_t)north_row * hf->nx + i0), .stride = hf->nx,
                                    .width = (unsigned short)(w + 1), .height = (unsigned short)(h + 1)};
    }
    rtcSetGeometryMask(geom, ~0u);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(c->scene, geom);
    rtcReleaseGeometry(geom);
    return tiles ? 0 : -1;
}

/* The vertices of the surface (rows north to south, as the terrain's: Embree's split of each
 * quad is then the terrain's diagonal) and its Embree scene. */
static int build_scene(ztv_canopy *c, const accel *a, err_buf *err)
{
    const sylva_heightfield *hf = &c->surface;
    size_t n = (size_t)hf->nx * hf->ny;
    c->vertices = malloc((n * 3 + 1) * sizeof(float)); /* one more: Embree reads the last with a 16-byte load */
    if (!c->vertices) return err_nomem(err, "out of memory for the canopy surface's %zu vertices", n);
    for (uint32_t r = 0; r < hf->ny; r++)
        for (uint32_t i = 0; i < hf->nx; i++) {
            float *v = c->vertices + ((size_t)r * hf->nx + i) * 3;
            uint32_t j = hf->ny - 1 - r;
            v[0] = (float)(hf->x0 + i * hf->dx), v[1] = (float)(hf->y0 + j * hf->dy), v[2] = hf->z[(size_t)j * hf->nx + i];
        }
    c->vertices[n * 3] = 0.0f;
    c->scene = rtcNewScene(a->device);
    if (c->scene) rtcSetSceneFlags(c->scene, RTC_SCENE_FLAG_ROBUST); /* rays along the cells' edges, as the terrain */
    if (!c->scene || attach_grid(c, a->device)) {
        if (accel_device_error(a, err)) return -1;
        return err_set(err, "Embree could not build the canopy surface");
    }
    rtcCommitScene(c->scene);
    return accel_device_error(a, err);
}

ztv_canopy *ztv_canopy_new(const scene *s, const accel *a, err_buf *err)
{
    const sylva_heightfield *g = s->surveyed;
    if (!s->canopy || !g) {
        err_set(err, "the scene has no canopy heights to screen with (a canopy: section)");
        return NULL;
    }
    if (s->canopy->nx != g->nx || s->canopy->ny != g->ny) {
        err_fail(err, ERR_INTERNAL, "the canopy's %u x %u nodes are not the surveyed ground's %u x %u", s->canopy->nx,
                 s->canopy->ny, g->nx, g->ny);
        return NULL;
    }
    size_t n = (size_t)g->nx * g->ny;
    if (memory_check(n * (4 * sizeof(float) + CANOPY_BVH_NODE_BYTES), "the canopy surface of the visibility map",
                     err))
        return NULL;
    ztv_canopy *c = calloc(1, sizeof *c); /* the caller's: ztv_canopy_free */
    if (c) c->surface = (sylva_heightfield){.size = sizeof(sylva_heightfield), .nx = g->nx, .ny = g->ny, .x0 = g->x0,
                                            .y0 = g->y0, .dx = g->dx, .dy = g->dy, .z = malloc(n * sizeof(float))};
    if (!c || !c->surface.z) {
        ztv_canopy_free(c);
        err_nomem(err, "out of memory for the canopy surface's %zu nodes", n);
        return NULL;
    }
    surface_heights(s, &c->surface);
    if (build_scene(c, a, err)) {
        ztv_canopy_free(c);
        return NULL;
    }
    return c;
}

void ztv_canopy_free(ztv_canopy *c)
{
    if (!c) return;
    if (c->scene) rtcReleaseScene(c->scene);
    free(c->vertices);
    free(c->surface.z);
    free(c);
}

RTCScene ztv_canopy_scene(const ztv_canopy *c) { return c->scene; }

void ztv_canopy_under(const ztv_canopy *c, const ztv_grid *g, uint32_t j, const float *eye_z, uint8_t *under)
{
    for (uint32_t i = 0; i < g->nx; i++) {
        if (under[i] || isnan(eye_z[i])) continue;
        double x, y, top;
        ztv_cell_centre(g, i, j, &x, &y);
        if (!heightfield_surface_height(&c->surface, x, y, &top) && top > eye_z[i]) under[i] = 1;
    }
}
