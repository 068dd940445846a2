/* test_surveyed_ground.c — the ground as surveyed, which the analyses read, against the ground a
 * render refines around its camera (scene.surveyed, scene.terrain): through the terrain plugin
 * on a generated DTM refined in levels of detail, a render's surveyed ground and its objects'
 * heights are the same bytes whatever the camera, though the rendered ground is not; an analysis's scene holds the surveyed ground alone; the rendered ground passes through
 * every DTM node with the default detail. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "plugin/plugin_host.h"
#include "scene/heightfield.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "work_dir.h"

/* A 33 x 33 generated DTM 20 m apart (640 m across, 300 m of relief), refined 8 times within
 * 80 m of the camera at `camera_x`, and a box standing on the ground as a development. */
static scene *build(double camera_x, int analysis)
{
    char text[2048];
    snprintf(text, sizeof text,
             "image: {width: 16, height: 16, spp: 1, seed: 3}\n"
             "camera: {position: [%g, -200, 400], look_at: [0, 0, 100]}\n"
             "terrain: {plugin: terrain_ifs, generated: {nodes: [33, 33], relief: 300, smoothness: 0.6},\n"
             "          cell_size: [20], refine: 8, detail_radius: 80}\n"
             "objects:\n"
             "  - {name: mast, shape: box, size: [6, 6, 40], position: [37, -51], development: true}\n",
             camera_x);
    const char *path = work_file("surveyed.yaml", text);
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open(&err);
    scene_file *sf = reg && path ? scene_file_load(path, reg, &err) : NULL;
    build_options bo = {.quiet = 1, .analysis = analysis};
    scene *s = sf ? scene_build(sf, reg, &bo, &err) : NULL;
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    scene_file_free(sf);
    plugin_registry_free(reg);
    return s;
}

static int same_grid(const sylva_heightfield *a, const sylva_heightfield *b)
{
    return a->nx == b->nx && a->ny == b->ny && a->x0 == b->x0 && a->y0 == b->y0 && a->dx == b->dx &&
           a->dy == b->dy && !memcmp(a->z, b->z, (size_t)a->nx * a->ny * sizeof *a->z);
}

TEST(camera_does_not_move_the_surveyed_ground)
{
    scene *a = build(-250, 0), *b = build(250, 0);
    if (!a || !b) goto done;
    CHECK(a->surveyed != a->terrain && b->surveyed != b->terrain);
    CHECK_INT(a->surveyed->nx, 33);
    CHECK_INT(a->surveyed->n_levels, 0);
    CHECK(same_grid(a->surveyed, b->surveyed));
    /* the rendered grounds are refined around their cameras, so they differ */
    CHECK(a->terrain->n_levels > 0 && b->terrain->n_levels > 0);
    const sylva_terrain_level *la = &a->terrain->levels[a->terrain->n_levels - 1];
    const sylva_terrain_level *lb = &b->terrain->levels[b->terrain->n_levels - 1];
    CHECK(la->i0 != lb->i0);
    /* the development stands on the surveyed ground in both */
    CHECK_INT(a->n_objects, 1);
    if (a->n_objects == 1 && b->n_objects == 1) {
        double loa[3] = {INFINITY, INFINITY, INFINITY}, hia[3] = {-INFINITY, -INFINITY, -INFINITY};
        double lob[3] = {INFINITY, INFINITY, INFINITY}, hib[3] = {-INFINITY, -INFINITY, -INFINITY};
        scene_object_bounds(a, 0, loa, hia);
        scene_object_bounds(b, 0, lob, hib);
        CHECK(!memcmp(loa, lob, sizeof loa) && !memcmp(hia, hib, sizeof hia));
    }
done:
    scene_free(a), scene_free(b);
}

/* An analysis's scene: one ground, the DTM's own nodes, no levels, whatever the camera. */
TEST(analysis_scene_has_the_surveyed_ground_alone)
{
    scene *a = build(-250, 1), *b = build(250, 1);
    if (a && b) {
        CHECK(a->terrain == a->surveyed);
        CHECK_INT(a->terrain->nx, 33);
        CHECK_INT(a->terrain->n_levels, 0);
        CHECK(same_grid(a->terrain, b->terrain));
    }
    scene_free(a), scene_free(b);
}

/* With the default detail (alpha from the DTM) the rendered ground passes through every DTM node,
 * on the base grid and on every level, to the float rounding. */
TEST(refinement_never_moves_a_dtm_node)
{
    scene *s = build(0, 0);
    if (!s) return;
    const sylva_heightfield *g = s->surveyed, *t = s->terrain;
    double worst = 0;
    for (uint32_t j = 0; j < g->ny; j++)
        for (uint32_t i = 0; i < g->nx; i++) {
            double x = g->x0 + i * g->dx, y = g->y0 + j * g->dy, z = 0;
            CHECK_INT(heightfield_height(t, x, y, &z), 0);
            worst = fmax(worst, fabs(z - g->z[j * g->nx + i]));
        }
    printf("largest departure of the rendered ground at a DTM node: %g m\n", worst);
    CHECK(worst < 1e-3);
    scene_free(s);
}

TEST_LIST(TEST_CASE(camera_does_not_move_the_surveyed_ground),
          TEST_CASE(analysis_scene_has_the_surveyed_ground_alone), TEST_CASE(refinement_never_moves_a_dtm_node))
