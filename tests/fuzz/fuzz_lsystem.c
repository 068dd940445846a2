/* fuzz_lsystem.c — libFuzzer target for the L-system model of tree_lsystem: each input is an
 * L-parser text, read strictly (and leniently when strict reading refuses it), derived, and
 * drawn by the turtle into the mesh builder and the silhouette raster, as the plugin does, with
 * limits small enough that one input takes milliseconds. Every step must end in LSYS_OK or a
 * status with a sentence; the mesh handed over must index only its own vertices, all finite.
 * A crash, a sanitizer report, a leak or a hang is a finding. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "lsys_silhouette.h"
#include "lsys_derive.h"
#include "lsys_mesh.h"
#include "lsys_system.h"
#include "lsys_turtle.h"

#define MAX_STEPS 8                 /* derivation levels tried at most */
#define MAX_STRING (8u << 10)       /* derived bytes */
#define MAX_SEGMENTS 2000
#define MAX_POLYGONS 500
#define MAX_POLYGON_VERTICES 256
#define MAX_DEPTH 512
#define RASTER_LEVEL 7              /* 128 x 128 silhouette */

static void fail(const char *what, const plugin_err *e)
{
    fprintf(stderr, "fuzz_lsystem: %s%s%s\n", what, e ? ": " : "", e ? e->msg : "");
    abort();
}

/* A status other than LSYS_OK must come with a sentence. */
static void check_status(int rc, const plugin_err *e, const char *step)
{
    if (rc != LSYS_OK && !e->msg[0]) fail(step, e);
}

/* A fixed stream for `~`: the same input always draws the same tree. */
static double next_uniform(void *ctx)
{
    uint64_t *x = ctx;
    *x = *x * 6364136223846793005u + 1442695040888963407u;
    return (double)(*x >> 11) * (1.0 / 9007199254740992.0);
}

static int check_chunk(void *ctx, const float *pos, const float *nrm, const float *uv, uint32_t nv, const uint32_t *tri,
                       const int32_t *material_key, uint32_t nt)
{
    for (uint32_t i = 0; i < 3 * nt; i++)
        if (tri[i] >= nv) fail("a triangle indexes past its chunk's vertices", NULL);
    for (uint32_t i = 0; i < 3 * nv; i++)
        if (!isfinite(pos[i]) || !isfinite(nrm[i])) fail("a vertex or normal is not finite", NULL);
    for (uint32_t i = 0; i < 2 * nv; i++)
        if (!isfinite(uv[i])) fail("a texture coordinate is not finite", NULL);
    return 0;
}

static void draw(const lsys_system *sys, const unsigned char *s, size_t n)
{
    uint64_t seed = 1;
    lsys_turtle_config cfg = {.angle_deg = sys->angle_deg, .thickness = sys->thickness,
                              .min_thickness = sys->min_thickness, .base_length = sys->base_length, .colour = 2,
                              .max_segments = MAX_SEGMENTS, .max_polygons = MAX_POLYGONS,
                              .max_polygon_vertices = MAX_POLYGON_VERTICES, .max_depth = MAX_DEPTH,
                              .tube_corners = sys->shape == 0 ? 4 : 8,
                              .random = next_uniform, .random_ctx = &seed};
    if (sys->poly_limit && sys->poly_limit < cfg.max_polygons) cfg.max_polygons = sys->poly_limit;
    plugin_err e = {0};
    lsys_turtle_stats st;
    int rc = lsys_interpret(s, n, &cfg, NULL, 0, &st, &e);
    check_status(rc, &e, "turtle (bounds)");
    if (rc || !st.has_bounds) return;
    /* The plugin's scaling: the model's height (or widest extent) to 10 m, refused beyond 1e7. */
    double ext[3] = {st.hi[0] - st.lo[0], st.hi[1] - st.lo[1], st.hi[2] - st.lo[2]};
    double widest = fmax(ext[0], fmax(ext[1], ext[2]));
    double size = ext[2] > 1e-6 * widest ? ext[2] : widest;
    double scale = 10.0 / size;
    if (!(size > 0) || !isfinite(scale) || !isfinite(widest * scale) || widest * scale > 1e7) return;
    /* A small model far from where the turtle started (`z(1e38)&Z`) passes the extent check but
     * its vertices overflow float; the host refuses them (mesh_append: "vertex 0 is not
     * finite"), so such a model ends in an error, not in a mesh, and is not meshed here. */
    for (int k = 0; k < 3; k++)
        if (!(fabs(st.lo[k] * scale) < FLT_MAX && fabs(st.hi[k] * scale) < FLT_MAX)) return;

    lsys_mesh_config mc = {.sides = sys->shape == 0 ? 4 : 8, .flat = sys->shape == 0, .scale = scale, .bark_tile = 0.5,
                           .max_polygon_vertices = MAX_POLYGON_VERTICES, .flush = check_chunk};
    lsys_mesh *mesh = lsys_mesh_new(&mc, &e); /* owned here */
    if (!mesh) fail("lsys_mesh_new", &e);
    box_raster r = {0};
    double side = fmax(ext[0], ext[2]) * 1.0001;
    int have_raster = st.segments && side > 0 && !box_raster_init(&r, RASTER_LEVEL, st.lo[0], st.lo[2], side);
    lsys_sink sinks[2] = {lsys_mesh_sink(mesh), lsys_silhouette_sink(&r)};
    seed = 1;
    rc = lsys_interpret(s, n, &cfg, sinks, have_raster ? 2 : 1, &st, &e);
    check_status(rc, &e, "turtle (mesh)");
    if (!rc) check_status(lsys_mesh_finish(mesh), &e, "mesh finish");
    if (!rc && have_raster) (void)box_dimension(&r, 0, RASTER_LEVEL);
    box_raster_free(&r);
    lsys_mesh_free(mesh);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    lsys_system *sys = NULL; /* owned here */
    plugin_err e = {0};
    int rc = lsys_read((const char *)data, size, "fuzz.ls", NULL, &sys, &e);
    if (rc == LSYS_ERR_SYNTAX) {
        lsys_read_options lenient = {.lenient = 1};
        e.msg[0] = 0;
        rc = lsys_read((const char *)data, size, "fuzz.ls", &lenient, &sys, &e);
    }
    check_status(rc, &e, "read");
    if (rc) return 0;
    unsigned char *s = NULL; /* owned here */
    size_t n = 0;
    uint32_t steps = sys->recursion < MAX_STEPS ? sys->recursion : MAX_STEPS;
    rc = lsys_derive(sys, steps, MAX_STRING, NULL, NULL, &s, &n, &e);
    check_status(rc, &e, "derive");
    if (!rc) draw(sys, s, n);
    free(s);
    lsys_system_free(sys);
    return 0;
}
