/* test_accel.c — the Embree scene: its geometry-id layout (terrain, water, objects, instances;
 * opaque and cut-out parts) seen through real hits, and Embree's errors: recorded by the accel,
 * reported on the calling thread, never written into a caller's buffer by the callback (which
 * may run on any thread); a build holding only the plants that reach a rectangle, or none
 * (accel_build_plants); the frame near the camera that the verification render is built in
 * (render/accel_frame.h). */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "geometry/terrain_mesh.h"
#include "render/accel.h"
#include "render/accel_frame.h"
#include "render/accel_terrain.h"

static void add_quad(mesh *m, float x0, float y0, float x1, float y1, float z, err_buf *err)
{
    const float pos[12] = {x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z};
    const uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    CHECK_INT(mesh_append(m, pos, NULL, NULL, 4, tri, NULL, -1, 2, err), 0);
}

/* A 10 m x 10 m flat terrain at z 0 under water at z 1, two objects (quads at z 5 over
 * x in [1, 2] and [4, 5]) and one plant (a quad at z 3 over x in [7, 8]). */
static scene *small_scene(void)
{
    err_buf err;
    scene *s = scene_new();
    sylva_heightfield *hf = calloc(1, sizeof *hf);
    float *z = calloc(4, sizeof *z);
    mesh *o0 = mesh_new(), *o1 = mesh_new(), *p = mesh_new();
    if (!s || !hf || !z || !o0 || !o1 || !p) {
        scene_free(s), free(hf), free(z), mesh_free(o0), mesh_free(o1), mesh_free(p);
        return NULL;
    }
    *hf = (sylva_heightfield){.nx = 2, .ny = 2, .dx = 10, .dy = 10, .z = z, .has_water = 1, .water_level = 1,
                              .water_material = -1};
    s->terrain = hf;
    add_quad(o0, 1, 4, 2, 6, 5, &err);
    add_quad(o1, 4, 4, 5, 6, 5, &err);
    add_quad(p, -0.5f, -1, 0.5f, 1, 3, &err);
    CHECK_INT(scene_add_object(s, "first", o0, &err), 0);
    CHECK_INT(scene_add_object(s, "second", o1, &err), 1);
    CHECK_INT(scene_add_prototype(s, 0, 0, 1, 3, p, &err), 0);
    xform3x4 xf = {{{1, 0, 0, 7.5f}, {0, 1, 0, 5}, {0, 0, 1, 0}}};
    CHECK_INT(scene_add_instance(s, 0, &xf, &err), 0);
    return s;
}

/* The hit of a vertical ray from (x, y, z0) going down (or up). */
static struct RTCRayHit cast(const accel *a, float x, float y, float z0, float dz)
{
    struct RTCRayHit rh = {.ray = {.org_x = x, .org_y = y, .org_z = z0, .dir_z = dz, .tnear = 0, .tfar = INFINITY,
                                   .mask = 0xffffffffu},
                           .hit = {.geomID = RTC_INVALID_GEOMETRY_ID, .instID = {RTC_INVALID_GEOMETRY_ID}}};
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    rtcIntersect1(a->top, &ic, &rh);
    return rh;
}

TEST(geometry_id_layout)
{
    scene *s = small_scene();
    CHECK(s != NULL);
    if (!s) return;
    accel a;
    err_buf err;
    CHECK_INT(accel_build(&a, s, 1, &err), 0);
    CHECK_INT(a.n_top_geoms, 3 + 2 * 2);
    CHECK_INT(a.first_instance, 7);
    CHECK_INT(accel_top_object_id(1, ACCEL_PART_CUTOUT), 6);
    hit_info h;
    struct RTCRayHit rh = cast(&a, 1.5f, 5, 10, -1);
    CHECK_INT(rh.hit.geomID, accel_top_object_id(0, ACCEL_PART_OPAQUE));
    accel_shade(&a, &rh, &h);
    CHECK_INT(h.kind, GEOM_OBJECT);
    CHECK_NEAR(h.p.z, 5, 1e-6);
    rh = cast(&a, 4.5f, 5, 10, -1);
    CHECK_INT(rh.hit.geomID, accel_top_object_id(1, ACCEL_PART_OPAQUE));
    rh = cast(&a, 7.5f, 5, 10, -1);
    CHECK_INT(rh.hit.instID[0], a.first_instance);
    CHECK_INT(rh.hit.geomID, ACCEL_PART_OPAQUE);
    accel_shade(&a, &rh, &h);
    CHECK_INT(h.kind, GEOM_PROTOTYPE);
    CHECK_INT(h.instance_id, 1);
    CHECK_NEAR(h.p.z, 3, 1e-6);
    rh = cast(&a, 9, 9, 10, -1);
    CHECK_INT(rh.hit.geomID, ACCEL_TOP_WATER);
    accel_shade(&a, &rh, &h);
    CHECK_INT(h.kind, GEOM_WATER);
    CHECK_NEAR(h.p.z, 1, 1e-6);
    CHECK_INT(h.mat - s->materials, s->water_material);
    rh = cast(&a, 9, 9, 0.5f, -1); /* under the water */
    CHECK_INT(rh.hit.geomID, ACCEL_TOP_TERRAIN + ACCEL_PART_OPAQUE);
    accel_shade(&a, &rh, &h);
    CHECK_INT(h.kind, GEOM_TERRAIN);
    CHECK_INT(accel_device_error(&a, &err), 0);
    accel_free(&a);
    scene_free(s);
}

/* The number of the plant (its instance) that a vertical ray down at (x, y) meets, or -1 when it
 * meets none. */
static int plant_hit(const accel *a, float x, float y)
{
    struct RTCRayHit rh = cast(a, x, y, 10, -1);
    unsigned inst = rh.hit.instID[0];
    return inst == RTC_INVALID_GEOMETRY_ID || inst < a->first_instance ? -1 : (int)(inst - a->first_instance);
}

TEST(plants_held_within_a_rectangle)
{
    scene *s = small_scene(); /* plant 0: a 1 m x 2 m quad centred at (7.5, 5) */
    CHECK(s != NULL);
    if (!s) return;
    err_buf err;
    /* plant 1 reaches the rectangle's east edge by 0.4 m; plant 2, turned a quarter, stops 0.5 m
     * short of it; plant 3 is far off */
    const xform3x4 xf[3] = {{{{1, 0, 0, 9.4f}, {0, 1, 0, 5}, {0, 0, 1, 0}}},
                            {{{0, -1, 0, 10.5f}, {1, 0, 0, 5}, {0, 0, 1, 0}}},
                            {{{1, 0, 0, 20}, {0, 1, 0, 5}, {0, 0, 1, 0}}}};
    for (int k = 0; k < 3; k++) CHECK_INT(scene_add_instance(s, 0, &xf[k], &err), k + 1);
    const accel_plants within = {ACCEL_PLANTS_WITHIN, {6, 4}, {9, 6}}, none = {.kind = ACCEL_PLANTS_NONE};
    accel all, part, bare;
    CHECK_INT(accel_build(&all, s, 1, &err), 0);
    CHECK_INT(accel_build_plants(&part, s, 1, &within, &err), 0);
    CHECK_INT(accel_build_plants(&bare, s, 1, &none, &err), 0);
    CHECK_INT(all.plants_held, 4);
    CHECK_INT(part.plants_held, 2);
    CHECK_INT(bare.plants_held, 0);
    CHECK(bare.proto_scenes[0] == NULL); /* no plant places the prototype: its BVH is not built */
    /* the plants held keep their ids, and rays over the rectangle meet what they meet in all */
    CHECK_INT(plant_hit(&all, 7.5f, 5), 0);
    CHECK_INT(plant_hit(&part, 7.5f, 5), 0);
    CHECK_INT(plant_hit(&all, 9.2f, 5.5f), 1);
    CHECK_INT(plant_hit(&part, 9.2f, 5.5f), 1);
    CHECK_INT(plant_hit(&all, 10.5f, 5), 2);
    CHECK_INT(plant_hit(&part, 10.5f, 5), -1);
    CHECK_INT(plant_hit(&all, 20, 5), 3);
    CHECK_INT(plant_hit(&part, 20, 5), -1);
    CHECK_INT(plant_hit(&bare, 7.5f, 5), -1);
    CHECK_INT(cast(&bare, 4.5f, 5, 10, -1).hit.geomID, accel_top_object_id(1, ACCEL_PART_OPAQUE)); /* objects stay */
    accel_free(&all), accel_free(&part), accel_free(&bare);
    scene_free(s);
}

/* Calls into Embree that it refuses (an unknown geometry type), from several threads at once. */
#define REFUSERS 4
static void *refuse(void *device)
{
    for (int k = 0; k < 50; k++) CHECK(rtcNewGeometry(device, (enum RTCGeometryType)999) == NULL);
    return NULL;
}

TEST(embree_errors_recorded_and_reported_by_the_caller)
{
    scene *s = small_scene();
    CHECK(s != NULL);
    if (!s) return;
    accel a;
    err_buf build_err = {{0}};
    CHECK_INT(accel_build(&a, s, 2, &build_err), 0);
    build_err.msg[0] = '\0';
    pthread_t t[REFUSERS];
    for (int i = 0; i < REFUSERS; i++) CHECK_INT(pthread_create(&t[i], NULL, refuse, a.device), 0);
    for (int i = 0; i < REFUSERS; i++) pthread_join(t[i], NULL);
    /* the callback wrote into no caller's buffer: not the one accel_build was given */
    CHECK_INT(build_err.msg[0], '\0');
    err_buf err = {{0}};
    CHECK_INT(accel_device_error(&a, &err), -1);
    CHECK(!strncmp(err.msg, "Embree error ", 13)); /* one whole message */
    CHECK_STR_CONTAINS(err.msg, ": invalid geometry type");
    char first[sizeof err.msg];
    memcpy(first, err.msg, sizeof first);
    refuse(a.device); /* a later error does not replace the first */
    CHECK_INT(accel_device_error(&a, &err), -1);
    CHECK(!strcmp(err.msg, first));
    accel_free(&a);
    scene_free(s);
}

/* A rough nx x ny terrain 2 m x 3 m a cell, two materials in a checkerboard of nodes. */
static scene *rough_terrain(uint32_t nx, uint32_t ny)
{
    err_buf err;
    scene *s = scene_new();
    sylva_heightfield *hf = calloc(1, sizeof *hf);
    float *z = malloc((size_t)nx * ny * sizeof *z);
    int32_t *mat = malloc((size_t)nx * ny * sizeof *mat);
    if (!s || !hf || !z || !mat) {
        scene_free(s), free(hf), free(z), free(mat);
        return NULL;
    }
    *hf = (sylva_heightfield){.nx = nx, .ny = ny, .x0 = -7, .y0 = 11, .dx = 2, .dy = 3, .z = z,
                              .material = mat, .water_material = -1};
    for (uint32_t j = 0; j < ny; j++)
        for (uint32_t i = 0; i < nx; i++) {
            z[(size_t)j * nx + i] = (float)(5 * sin(i * 0.7) + 4 * cos(j * 1.3) + ((i * 31 + j * 17) % 7));
            mat[(size_t)j * nx + i] = (int32_t)((i + j) % 2);
        }
    s->terrain = hf;
    sylva_material_desc m = {.size = sizeof m, .name = "a", .bsdf = SYLVA_BSDF_LAMBERT, .texture = -1};
    CHECK(scene_add_material(s, &m, &err) >= 0);
    m.name = "b";
    CHECK(scene_add_material(s, &m, &err) >= 0);
    return s;
}

/* The terrain's grid geometry shows the tessellation every back end draws: a vertical ray
 * through any point hits the height of terrain_mesh's triangle there, with its material and
 * its normal, also past the first grid tile (a terrain wider than ACCEL_TERRAIN_TILE cells). */
TEST(terrain_grid_matches_the_tessellation)
{
    const uint32_t sizes[2][2] = {{9, 7}, {ACCEL_TERRAIN_TILE + 40, 3}};
    for (int c = 0; c < 2; c++) {
        scene *s = rough_terrain(sizes[c][0], sizes[c][1]);
        if (!s) {
            CHECK(0);
            return;
        }
        const sylva_heightfield *hf = s->terrain;
        accel a;
        err_buf err;
        CHECK_INT(accel_build(&a, s, 1, &err), 0);
        uint32_t misses = 0, wrong = 0;
        uint64_t rng = 12345;
        for (int k = 0; k < 4000; k++) {
            rng = rng * 6364136223846793005ull + 1442695040888963407ull;
            double fu = (double)(rng >> 11) / 9007199254740992.0;
            rng = rng * 6364136223846793005ull + 1442695040888963407ull;
            double fv = (double)(rng >> 11) / 9007199254740992.0;
            /* near the far east end half of the time on the wide terrain */
            double gx = (c && k % 2) ? hf->nx - 1 - 60 * fu : fu * (hf->nx - 1), gy = fv * (hf->ny - 1);
            /* the ray's own (single-precision) position, and the cell it falls in */
            double x = (float)(hf->x0 + gx * hf->dx), y = (float)(hf->y0 + gy * hf->dy);
            gx = (x - hf->x0) / hf->dx, gy = (y - hf->y0) / hf->dy;
            uint32_t i = (uint32_t)gx, j = (uint32_t)gy;
            double fx = gx - i, fy = gy - j;
            if (fabs(fx - fy) < 1e-3 || fx < 1e-3 || fy < 1e-3 || fx > 1 - 1e-3 || fy > 1 - 1e-3)
                continue; /* on a cell's edge or diagonal: either triangle */
            terrain_grid g = terrain_grid_of(hf, 0);
            uint32_t t = terrain_triangle_of_cell(&g, i, j, fy > fx), n[3];
            terrain_triangle_nodes(&g, t, n);
            float p[3][3];
            for (int q = 0; q < 3; q++) terrain_node_vertex(&g, n[q] % hf->nx, n[q] / hf->nx, p[q], NULL, NULL);
            /* the plane through the triangle at (x, y) */
            double e1[3], e2[3];
            for (int q = 0; q < 3; q++) e1[q] = p[1][q] - p[0][q], e2[q] = p[2][q] - p[0][q];
            double nz = e1[0] * e2[1] - e1[1] * e2[0], nxp = e1[1] * e2[2] - e1[2] * e2[1];
            double nyp = e1[2] * e2[0] - e1[0] * e2[2];
            double zt = p[0][2] - (nxp * (x - p[0][0]) + nyp * (y - p[0][1])) / nz;
            struct RTCRayHit rh = cast(&a, (float)x, (float)y, 100, -1);
            if (rh.hit.geomID != ACCEL_TOP_TERRAIN) {
                misses++;
                continue;
            }
            hit_info h;
            accel_shade(&a, &rh, &h);
            uint32_t want = (uint32_t)terrain_triangle_material(&g, t, s->terrain_material);
            if (fabs(h.p.z - zt) > 1e-3 || h.mat != &s->materials[want] || h.kind != GEOM_TERRAIN ||
                fabs(h.ng.z * sqrt(nz * nz + nxp * nxp + nyp * nyp) - nz) > 1e-4 * fabs(nz)) {
                if (wrong++ < 5)
                    fprintf(stderr, "  (%g, %g): z %g, want %g; material %td, want %u\n", x, y, h.p.z, zt,
                            h.mat - s->materials, want);
            }
        }
        CHECK_INT(misses, 0);
        CHECK_INT(wrong, 0);
        accel_free(&a);
        scene_free(s);
    }
}

/* small_scene moved by (dx, dy): the terrain, the objects' own meshes and the plant. */
static scene *small_scene_at(double dx, double dy)
{
    scene *s = small_scene();
    if (!s) return NULL;
    s->terrain->x0 += dx, s->terrain->y0 += dy;
    for (uint32_t o = 0; o < s->n_objects; o++)
        for (uint32_t v = 0; v < s->objects[o].mesh->nv; v++) {
            s->objects[o].mesh->pos[v * 3] = (float)(s->objects[o].mesh->pos[v * 3] + dx);
            s->objects[o].mesh->pos[v * 3 + 1] = (float)(s->objects[o].mesh->pos[v * 3 + 1] + dy);
        }
    s->instances[0].xf.m[0][3] = (float)(s->instances[0].xf.m[0][3] + dx);
    s->instances[0].xf.m[1][3] = (float)(s->instances[0].xf.m[1][3] + dy);
    return s;
}

/* The frame's origin: whole steps of ACCEL_FRAME_STEP, none for a camera near the origin. */
TEST(frame_near_the_camera)
{
    double f[3];
    accel_frame_near((const double[3]){300, -400, 250}, f);
    CHECK(f[0] == 0 && f[1] == 0 && f[2] == 0);
    accel_frame_near((const double[3]){-5093, -6864, 254}, f);
    CHECK(f[0] == -5120 && f[1] == -7168 && f[2] == 0);
}

/* The same scene 8 km from the origin, built in a frame near it: every geometry is met where it
 * stands, accel_shade's points are in the frame and accel_frame_world takes them back. */
TEST(scene_built_in_a_frame_near_the_camera)
{
    const double dx = 7003, dy = -8001;
    scene *s = small_scene_at(dx, dy);
    CHECK(s != NULL);
    if (!s) return;
    double frame[3];
    accel_frame_near((const double[3]){dx + 5, dy + 5, 10}, frame);
    CHECK(frame[0] == 7168 && frame[1] == -8192);
    accel a;
    err_buf err;
    CHECK_INT(accel_build_open(&a, s, 1, frame, &err), 0);
    CHECK_INT(accel_commit(&a, &err), 0);
    const struct {
        float x, y, z0;
        unsigned geom, inst;
        geom_kind kind;
        float z;
    } rays[] = {{1.5f, 5, 10, accel_top_object_id(0, ACCEL_PART_OPAQUE), RTC_INVALID_GEOMETRY_ID, GEOM_OBJECT, 5},
                {4.5f, 5, 10, accel_top_object_id(1, ACCEL_PART_OPAQUE), RTC_INVALID_GEOMETRY_ID, GEOM_OBJECT, 5},
                {7.5f, 5, 10, ACCEL_PART_OPAQUE, 7, GEOM_PROTOTYPE, 3},
                {9, 9, 10, ACCEL_TOP_WATER, RTC_INVALID_GEOMETRY_ID, GEOM_WATER, 1},
                {9, 9, 0.5f, ACCEL_TOP_TERRAIN, RTC_INVALID_GEOMETRY_ID, GEOM_TERRAIN, 0}};
    for (size_t k = 0; k < sizeof rays / sizeof *rays; k++) {
        double wx = rays[k].x + dx, wy = rays[k].y + dy; /* the world point under the ray */
        struct RTCRayHit rh = cast(&a, (float)(wx - frame[0]), (float)(wy - frame[1]), rays[k].z0, -1);
        CHECK_INT(rh.hit.geomID, rays[k].geom);
        CHECK_INT(rh.hit.instID[0], rays[k].inst);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
        hit_info h;
        accel_shade(&a, &rh, &h);
        CHECK_INT(h.kind, rays[k].kind);
        CHECK_NEAR(h.p.x, wx - frame[0], 1e-4);
        CHECK_NEAR(h.p.y, wy - frame[1], 1e-4);
        CHECK_NEAR(h.p.z, rays[k].z, 1e-5);
        vec3 w = accel_frame_world(&a, h.p);
        CHECK_NEAR(w.x, wx, 1e-3);
        CHECK_NEAR(w.y, wy, 1e-3);
    }
    CHECK_INT(accel_device_error(&a, &err), 0);
    accel_free(&a);
    scene_free(s);
}

TEST_LIST(TEST_CASE(geometry_id_layout), TEST_CASE(plants_held_within_a_rectangle),
          TEST_CASE(embree_errors_recorded_and_reported_by_the_caller),
          TEST_CASE(terrain_grid_matches_the_tessellation), TEST_CASE(frame_near_the_camera),
          TEST_CASE(scene_built_in_a_frame_near_the_camera))
