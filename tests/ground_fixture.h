/* ground_fixture.h — scenes for the ground-cover tests: a heightfield from a height function,
 * with the ground rules a terrain plugin reports (ABI 1.3), optionally a humidity per node and
 * plants whose crowns make a canopy. */
#ifndef SYLVA_TEST_GROUND_FIXTURE_H
#define SYLVA_TEST_GROUND_FIXTURE_H

#include <math.h>
#include <stdlib.h>

#include "scene/scene.h"

/* The rules of a temperate site with snow from 100 m and scree from 80 m, and the terrain plugin's
 * default albedos. */
static inline sylva_ground_rules fixture_rules(void)
{
    return (sylva_ground_rules){.snow_z = 100, .scree_z = 80, .scree_slope = 30, .rock_slope = 42,
                                .dry_humidity = 0.3, .grass_albedo = {0.07, 0.10, 0.04},
                                .dry_grass_albedo = {0.30, 0.26, 0.12}, .scree_albedo = {0.34, 0.32, 0.29},
                                .rock_albedo = {0.21, 0.19, 0.17}, .snow_albedo = {0.85, 0.87, 0.90}};
}

/* A scene whose terrain has nx x ny nodes d metres apart from (x0, y0), heights height(x, y),
 * with the ground rules set (rules 1) or not (0). NULL when out of memory. */
static inline scene *fixture_scene(uint32_t nx, uint32_t ny, double x0, double y0, double d,
                                   double (*height)(double x, double y), int rules)
{
    scene *s = scene_new();
    sylva_heightfield *hf = calloc(1, sizeof *hf);
    float *z = malloc((size_t)nx * ny * sizeof *z);
    if (!s || !hf || !z) {
        scene_free(s), free(hf), free(z);
        return NULL;
    }
    for (uint32_t j = 0; j < ny; j++)
        for (uint32_t i = 0; i < nx; i++) z[(size_t)j * nx + i] = (float)height(x0 + i * d, y0 + j * d);
    *hf = (sylva_heightfield){.size = sizeof *hf, .nx = nx, .ny = ny, .x0 = x0, .y0 = y0, .dx = d, .dy = d,
                              .z = z, .water_material = -1, .has_ground_rules = rules,
                              .ground = fixture_rules()};
    s->terrain = hf;
    return s;
}

/* Adds a plant at (x, y) whose crown spans 2 r metres, height h. Returns 0 or -1. */
static inline int fixture_plant(scene *s, double x, double y, double r, double h)
{
    err_buf err = {{0}};
    mesh *m = mesh_new();
    if (!m) return -1;
    float pos[] = {(float)-r, (float)-r, (float)h, (float)r, (float)-r, (float)h, (float)r, (float)r, (float)h,
                   (float)-r, (float)r, (float)h};
    uint32_t tri[] = {0, 1, 2, 0, 2, 3};
    if (mesh_append(m, pos, NULL, NULL, 4, tri, NULL, -1, 2, &err)) {
        mesh_free(m);
        return -1;
    }
    int32_t p = scene_add_prototype(s, 0, s->n_prototypes, 1.0, h, m, &err);
    if (p < 0) return -1;
    xform3x4 xf = {{{1, 0, 0, (float)x}, {0, 1, 0, (float)y}, {0, 0, 1, 0}}};
    return scene_add_instance(s, (uint32_t)p, &xf, &err) < 0 ? -1 : 0;
}

#endif
