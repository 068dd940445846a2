/* test_geometry.c — the shared scene geometry: the terrain's tessellation (counts, positions,
 * the diagonal, materials, normals, uvs), the water surface, the heightfield's bilinear height
 * and normal (at nodes, between nodes, on the last row and column, outside), alpha cut-outs
 * (which materials and triangles, the texel threshold, the split), and the light summary
 * (its sky mean is the path tracer's table's, bit for bit). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "geometry/geometry.h"
#include "render/lights.h"

/* A scene whose terrain is an nx x ny grid from (x0, y0), dx x dy apart, heights z(i, j). */
static scene *scene_with_terrain(uint32_t nx, uint32_t ny, double x0, double y0, double dx, double dy,
                                 double (*z)(uint32_t i, uint32_t j))
{
    scene *s = scene_new();
    sylva_heightfield *hf = calloc(1, sizeof *hf);
    float *h = malloc((size_t)nx * ny * sizeof *h);
    if (!s || !hf || !h) {
        scene_free(s), free(hf), free(h);
        return NULL;
    }
    *hf = (sylva_heightfield){.nx = nx, .ny = ny, .x0 = x0, .y0 = y0, .dx = dx, .dy = dy, .z = h,
                              .water_material = -1};
    for (uint32_t j = 0; j < ny; j++)
        for (uint32_t i = 0; i < nx; i++) h[(size_t)j * nx + i] = (float)z(i, j);
    s->terrain = hf;
    return s;
}

static double plane(uint32_t i, uint32_t j) { return i + 10.0 * j; }
static double bumpy(uint32_t i, uint32_t j) { return (double)((i * 7 + j * 13) % 5) - 1.5; }

/* --- terrain tessellation ------------------------------------------------------------------ */

TEST(terrain_tessellation)
{
    /* 4 x 3 nodes, 2 m x 5 m apart: heights i + 10 j, so dz/dx = 1/2 and dz/dy = 2 everywhere */
    float z[12];
    int32_t mat[12];
    for (uint32_t k = 0; k < 12; k++) z[k] = (float)plane(k % 4, k / 4), mat[k] = -1;
    mat[1] = 3; /* node (1, 0) */
    sylva_heightfield hf = {.nx = 4, .ny = 3, .x0 = -1, .y0 = 2, .dx = 2, .dy = 5, .z = z, .material = mat};
    err_buf err;
    mesh *m = terrain_mesh_build(&hf, 7, &err);
    CHECK(m != NULL);
    if (!m) return;
    CHECK_INT(m->nv, 12);
    CHECK_INT(m->nt, 3 * 2 * 2);
    /* vertex (2, 1) */
    CHECK_NEAR(m->pos[6 * 3], -1 + 2 * 2, 0);
    CHECK_NEAR(m->pos[6 * 3 + 1], 2 + 5 * 1, 0);
    CHECK_NEAR(m->pos[6 * 3 + 2], 12, 0);
    /* cell (1, 0): triangles 2 and 3, split along the diagonal from node 1 to node 6 */
    const uint32_t want[6] = {1, 2, 6, 1, 6, 5};
    for (int k = 0; k < 6; k++) CHECK_INT(m->tri[2 * 3 + k], want[k]);
    CHECK_INT(m->mat[2], 3);
    CHECK_INT(m->mat[3], 3);
    CHECK_INT(m->mat[0], 7);  /* node (0, 0) has none: the fallback */
    CHECK_INT(m->mat[11], 7);
    /* uv 0..1 across the grid */
    CHECK_NEAR(m->uv[0], 0, 0);
    CHECK_NEAR(m->uv[1], 0, 0);
    CHECK_NEAR(m->uv[11 * 2], 1, 0);
    CHECK_NEAR(m->uv[11 * 2 + 1], 1, 0);
    /* every normal is the plane's: (-1/2, -2, 1) normalised, one-sided differences included */
    double l = sqrt(0.25 + 4 + 1);
    for (uint32_t v = 0; v < m->nv; v++) {
        CHECK_NEAR(m->nrm[v * 3], -0.5 / l, 1e-6);
        CHECK_NEAR(m->nrm[v * 3 + 1], -2 / l, 1e-6);
        CHECK_NEAR(m->nrm[v * 3 + 2], 1 / l, 1e-6);
    }
    mesh_free(m);
    /* without a material array every cell takes the fallback */
    hf.material = NULL;
    m = terrain_mesh_build(&hf, 5, &err);
    CHECK(m != NULL);
    for (uint32_t t = 0; m && t < m->nt; t++) CHECK_INT(m->mat[t], 5);
    mesh_free(m);
}

/* --- water --------------------------------------------------------------------------------- */

TEST(water_surface)
{
    scene *s = scene_with_terrain(3, 5, 10, -20, 4, 2, plane);
    CHECK(s != NULL);
    if (!s) return;
    err_buf err;
    mesh *w = (mesh *)1;
    CHECK_INT(water_surface_build(s, &w, &err), 0); /* no water: no mesh */
    CHECK(w == NULL);

    s->terrain->has_water = 1, s->terrain->water_level = 1.5;
    double lo[3], hi[3];
    water_surface_extent(s->terrain, lo, hi);
    CHECK_NEAR(lo[0], 10, 0); CHECK_NEAR(lo[1], -20, 0); CHECK_NEAR(lo[2], 1.5, 0);
    CHECK_NEAR(hi[0], 10 + 2 * 4, 0); CHECK_NEAR(hi[1], -20 + 4 * 2, 0); CHECK_NEAR(hi[2], 1.5, 0);
    CHECK_INT(water_surface_build(s, &w, &err), 0);
    CHECK(w != NULL);
    if (w) {
        CHECK_INT(w->nv, 4);
        CHECK_INT(w->nt, 2);
        for (uint32_t v = 0; v < 4; v++) {
            CHECK_NEAR(w->pos[v * 3 + 2], 1.5, 0);
            CHECK_NEAR(w->nrm[v * 3 + 2], 1, 1e-6); /* facing up */
        }
        CHECK_NEAR(w->pos[2 * 3], 18, 0); CHECK_NEAR(w->pos[2 * 3 + 1], -12, 0); /* north-east */
        CHECK_INT(w->mat[0], s->water_material); /* the heightfield names none */
        CHECK_INT(w->mat[1], s->water_material);
    }
    mesh_free(w);
    s->terrain->water_material = 0;
    CHECK_INT(water_surface_build(s, &w, &err), 0);
    CHECK(w && w->mat[0] == 0);
    mesh_free(w);
    scene_free(s);
}

/* --- heightfield --------------------------------------------------------------------------- */

TEST(height_at_nodes_between_and_outside)
{
    scene *s = scene_with_terrain(5, 4, 100, -50, 2, 4, bumpy);
    CHECK(s != NULL);
    if (!s) return;
    const sylva_heightfield *h = s->terrain;
    double z;
    /* at every node, the node's height, the last row and column included */
    for (uint32_t j = 0; j < 4; j++)
        for (uint32_t i = 0; i < 5; i++) {
            CHECK_INT(heightfield_height(h, 100 + 2.0 * i, -50 + 4.0 * j, &z), 0);
            CHECK_NEAR(z, (float)bumpy(i, j), 0);
        }
    /* a cell's centre is its corners' mean; a point on an edge lies between its two nodes */
    CHECK_INT(heightfield_height(h, 100 + 2 * 2.5, -50 + 4 * 1.5, &z), 0);
    CHECK_NEAR(z, (bumpy(2, 1) + bumpy(3, 1) + bumpy(2, 2) + bumpy(3, 2)) / 4, 1e-12);
    CHECK_INT(heightfield_height(h, 100 + 2 * 4, -50 + 4 * 2.25, &z), 0); /* on the last column */
    CHECK_NEAR(z, 0.75 * bumpy(4, 2) + 0.25 * bumpy(4, 3), 1e-12);
    /* a quarter of the way across a cell in x and three quarters in y */
    double want = 0.25 * (0.75 * bumpy(1, 0) + 0.25 * bumpy(2, 0)) + 0.75 * (0.75 * bumpy(1, 1) + 0.25 * bumpy(2, 1));
    CHECK_INT(heightfield_height(h, 100 + 2 * 1.25, -50 + 4 * 0.75, &z), 0);
    CHECK_NEAR(z, want, 1e-12);
    /* outside: -1, z untouched */
    z = 42;
    CHECK_INT(heightfield_height(h, 100 - 1e-9, -50, &z), -1);
    CHECK_INT(heightfield_height(h, 108 + 1e-9, -50, &z), -1);
    CHECK_INT(heightfield_height(h, 104, -50 - 1e-9, &z), -1);
    CHECK_INT(heightfield_height(h, 104, -38 + 1e-9, &z), -1);
    CHECK_INT(heightfield_height(h, NAN, -40, &z), -1);
    CHECK_INT(heightfield_height(h, 104, INFINITY, &z), -1);
    CHECK_NEAR(z, 42, 0);
    /* clamped: the nearest point of the heightfield */
    CHECK_NEAR(heightfield_height_clamped(h, 0, -50 + 4 * 2), (float)bumpy(0, 2), 0);
    CHECK_NEAR(heightfield_height_clamped(h, 1e6, 1e6), (float)bumpy(4, 3), 0);
    CHECK_NEAR(heightfield_height_clamped(h, 100 + 2 * 1.25, -50 + 4 * 0.75), want, 1e-12);
    /* through the scene: the same lookup; no terrain, no height */
    CHECK_INT(scene_terrain_height(s, 100 + 2 * 1.25, -50 + 4 * 0.75, &z), 0);
    CHECK_NEAR(z, want, 0);
    scene_free(s);
    scene *bare = scene_new();
    CHECK(bare && scene_terrain_height(bare, 0, 0, &z) == -1);
    scene_free(bare);
}

TEST(normal_of_a_plane)
{
    scene *s = scene_with_terrain(4, 3, 0, 0, 2, 5, plane); /* dz/dx = 1/2, dz/dy = 2 */
    CHECK(s != NULL);
    if (!s) return;
    double n[3], l = sqrt(0.25 + 4 + 1);
    CHECK_INT(heightfield_normal(s->terrain, 3.3, 7.1, n), 0);
    CHECK_NEAR(n[0], -0.5 / l, 1e-12);
    CHECK_NEAR(n[1], -2 / l, 1e-12);
    CHECK_NEAR(n[2], 1 / l, 1e-12);
    CHECK_INT(heightfield_normal(s->terrain, -0.1, 7.1, n), -1);
    scene_free(s);
}

/* --- cut-outs ------------------------------------------------------------------------------ */

TEST(cutouts)
{
    CHECK_INT(cutout_texel_kept(0), 0);
    CHECK_INT(cutout_texel_kept(127), 0); /* 127 / 255 is below one half */
    CHECK_INT(cutout_texel_kept(128), 1);
    CHECK_INT(cutout_texel_kept(255), 1);

    scene *s = scene_new();
    CHECK(s != NULL);
    if (!s) return;
    err_buf err;
    /* a 2 x 1 texture: the left texel's alpha 127 (cut), the right one's 128 (kept) */
    const uint8_t texels[8] = {200, 200, 200, 127, 200, 200, 200, 128};
    const uint8_t solid[4] = {200, 200, 200, 255};
    int32_t tex = scene_add_texture(s, "mask", 2, 1, texels, &err);
    int32_t opaque_tex = scene_add_texture(s, "solid", 1, 1, solid, &err);
    sylva_material_desc d = {.size = sizeof d, .name = "leaf", .bsdf = SYLVA_BSDF_LAMBERT, .texture = tex, .alpha_mask = 1};
    int32_t leaf = scene_add_material(s, &d, &err);
    d.alpha_mask = 0, d.name = "unmasked";
    int32_t unmasked = scene_add_material(s, &d, &err);
    d.alpha_mask = 1, d.texture = opaque_tex, d.name = "no alpha";
    int32_t no_alpha = scene_add_material(s, &d, &err);
    CHECK_INT(cutout_material(s, &s->materials[leaf]), 1);
    CHECK_INT(cutout_material(s, &s->materials[unmasked]), 0);
    CHECK_INT(cutout_material(s, &s->materials[no_alpha]), 0); /* its texture has no alpha */
    CHECK_INT(cutout_material(s, &s->materials[s->default_material]), 0);

    /* four triangles: unmasked, leaf (uv on the left texel), default (-1), leaf (right texel) */
    mesh *m = mesh_new();
    const float pos[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    const float uv[8] = {0.25f, 0.5f, 0.25f, 0.5f, 0.75f, 0.5f, 0.75f, 0.5f};
    const uint32_t tri[12] = {0, 1, 2, 0, 1, 2, 1, 3, 2, 2, 3, 3};
    const int32_t mat[4] = {unmasked, leaf, -1, leaf};
    CHECK(m && mesh_append(m, pos, NULL, uv, 4, tri, mat, -1, 4, &err) == 0);
    if (!m) {
        scene_free(s);
        return;
    }
    CHECK_INT(cutout_triangle(s, m, 0), 0);
    CHECK_INT(cutout_triangle(s, m, 1), 1);
    CHECK_INT(cutout_triangle(s, m, 2), 0);
    CHECK_INT(cutout_triangle(s, m, 3), 1);
    CHECK_INT(cutout_point_kept(s, m, 1, 0.2f, 0.2f), 0); /* uv (0.25, 0.5): alpha 127 */
    CHECK_INT(cutout_point_kept(s, m, 3, 0.2f, 0.2f), 1); /* uv (0.75, 0.5): alpha 128 */

    cutout_part cut, solid_part;
    CHECK_INT(cutout_part_build(s, m, 1, &cut, &err), 0);
    CHECK_INT(cutout_part_build(s, m, 0, &solid_part, &err), 0);
    CHECK_INT(cut.n, 2);
    CHECK_INT(solid_part.n, 2);
    if (cut.n == 2 && solid_part.n == 2) {
        CHECK_INT(cut.to_mesh[0], 1); CHECK_INT(cut.to_mesh[1], 3);
        CHECK_INT(solid_part.to_mesh[0], 0); CHECK_INT(solid_part.to_mesh[1], 2);
        CHECK(!memcmp(cut.tri + 3, m->tri + 9, 3 * sizeof(uint32_t)));
        CHECK(!memcmp(solid_part.tri + 3, m->tri + 6, 3 * sizeof(uint32_t)));
        /* the cut-out part's own test: two distinct uvs, one mask, the same decisions */
        CHECK_INT(cut.n_uv, 2);
        CHECK_INT(cut.n_masks, 1);
        CHECK_INT(cut.number_bits, 2);
        CHECK_INT(cutout_part_point_kept(&cut, 0, 0.2f, 0.2f), 0); /* alpha 127 */
        CHECK_INT(cutout_part_point_kept(&cut, 1, 0.2f, 0.2f), 1); /* alpha 128 */
        CHECK(solid_part.corners == NULL && solid_part.masks == NULL); /* an opaque part has no test */
    }
    cutout_part_free(&cut);
    cutout_part_free(&solid_part);
    cutout_part_free(&cut); /* an empty part frees again harmlessly */
    CHECK(cut.tri == NULL && cut.n == 0);
    mesh_free(m);
    scene_free(s);
}

/* --- light summary ------------------------------------------------------------------------- */

/* The mean of the upper half of the path tracer's sky table, as its cells hold it. */
static vec3 table_mean(const sky_table *t)
{
    double sum[3] = {0, 0, 0}, wsum = 0;
    for (uint32_t r = 0; r < t->nt / 2; r++) {
        double w = sin((r + 0.5) * M_PI / t->nt);
        for (uint32_t c = 0; c < t->np; c++)
            for (int k = 0; k < 3; k++) sum[k] += w * t->rgb[((size_t)r * t->np + c) * 3 + k];
        wsum += w * t->np;
    }
    return v3((float)(sum[0] / wsum), (float)(sum[1] / wsum), (float)(sum[2] / wsum));
}

TEST(light_summary)
{
    sun_settings sun = {.enabled = 1, .direction = {0, -3, 4}, .irradiance = 2, .color = {1, 0.5, 0.25},
                        .angular_diameter_deg = 0.53};
    sky_settings sky = {.model = SKY_PREETHAM, .turbidity = 3, .scale = 1, .ground_albedo = 0.2,
                        .ambient = {0.1, 0.2, 0.3}};
    light_summary l;
    err_buf err;
    CHECK_INT(light_summary_init(&l, &sun, &sky, 0, 0, 0, &err), 0);
    CHECK_INT(l.sun_on, 1);
    CHECK_NEAR(l.sun_dir.y, -0.6, 1e-7);
    CHECK_NEAR(l.sun_dir.z, 0.8, 1e-7);
    CHECK_NEAR(l.sun_irradiance.y, 1, 0);
    CHECK_NEAR(l.ambient.z, 0.3f, 0);
    double half = 0.53 * M_PI / 360;
    CHECK_NEAR(l.sun_radiance.x, 2 / (M_PI * sin(half) * sin(half)), 1e-3 * l.sun_radiance.x);
    CHECK(l.sky_mean.x > 0 && l.sky_mean.z > l.sky_mean.x); /* a blue sky */

    /* the exporter's figure is the path tracer's, bit for bit */
    lights lt;
    CHECK_INT(lights_init(&lt, &sun, &sky, 0, 0, 0, &err), 0);
    vec3 tm = table_mean(&lt.table);
    CHECK(tm.x == l.sky_mean.x && tm.y == l.sky_mean.y && tm.z == l.sky_mean.z);
    CHECK(!memcmp(&lt.summary, &l, sizeof l));
    lights_free(&lt);

    /* a constant sky's mean is its colour; no sky, no mean; no irradiance, no sun */
    sky = (sky_settings){.model = SKY_CONSTANT, .scale = 2, .color = {0.25, 0.5, 1}};
    sun.irradiance = 0;
    CHECK_INT(light_summary_init(&l, &sun, &sky, 0, 0, 0, &err), 0);
    CHECK_NEAR(l.sky_mean.x, 0.5, 1e-6);
    CHECK_NEAR(l.sky_mean.z, 2, 1e-6);
    CHECK_INT(l.sun_on, 0);
    sky.model = SKY_NONE;
    CHECK_INT(light_summary_init(&l, &sun, &sky, 0, 0, 0, &err), 0);
    CHECK_NEAR(l.sky_mean.y, 0, 0);
    sky = (sky_settings){.model = SKY_PREETHAM, .turbidity = 12, .scale = 1, .ground_albedo = 0.2};
    CHECK_INT(light_summary_init(&l, &sun, &sky, 0, 0, 0, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "turbidity 12 is outside the Preetham model's range [1.7, 10]");
}

TEST_LIST(TEST_CASE(terrain_tessellation), TEST_CASE(water_surface), TEST_CASE(height_at_nodes_between_and_outside),
          TEST_CASE(normal_of_a_plane), TEST_CASE(cutouts), TEST_CASE(light_summary))
