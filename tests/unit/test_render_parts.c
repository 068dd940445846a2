/* test_render_parts.c — a render split into parts (render_options part/parts, the ranks of an
 * MPI job, docs/mpi.md): each part computes only its bands of 16 rows, band k belonging to part
 * k modulo parts, and the bands put together give every layer of the whole render byte for
 * byte, with the metered exposure of the whole; a part's other rows stay zero, a part with no
 * band renders none, and the parts' samples add up to the whole's. */
#include "harness.h"

#include <string.h>

#include "render/auto_exposure.h"
#include "render/render.h"
#include "scene_text.h"

/* A ball on a floor with a box behind it, lit by sun and sky: every layer varies over the frame. */
static const char *const scene_text =
    "image: {width: 40, height: 70, spp: 4, seed: 11, max_depth: 3}\n"
    "camera: {position: [0, -6, 2.5], look_at: [0, 0, 0.8], fov: 60}\n"
    "sun: {azimuth: 210, elevation: 35, irradiance: 1.0}\n"
    "sky: {model: preetham, turbidity: 3}\n"
    "materials:\n  red: {type: lambert, albedo: [0.7, 0.12, 0.08]}\n"
    "  floor: {type: lambert, albedo: [0.45, 0.45, 0.42]}\n"
    "objects:\n"
    "  - {name: ball, shape: sphere, radius: 1, subdivisions: 3, position: [0, 0, 1], material: red}\n"
    "  - {name: box, shape: box, size: [2, 1, 3], position: [2, 3, 1.5], development: true}\n"
    "  - {name: floor, shape: quad, size: [400, 400], material: floor}\n";

static film *render_part(const scene *s, uint32_t part, uint32_t parts, unsigned threads, uint64_t *samples)
{
    render_options ro = {.threads = threads, .quiet = 1, .part = part, .parts = parts};
    render_stats st;
    err_buf err = {{0}};
    film *f = render_scene(s, &ro, &st, &err);
    if (!f) fprintf(stderr, "%s\n", err.msg);
    CHECK(f != NULL);
    if (f && samples) *samples += st.samples;
    return f;
}

TEST(bands_of_the_parts_make_the_whole)
{
    scene *s = scene_text_build_ok(scene_text);
    if (!s) return;
    uint64_t whole_samples = 0;
    film *whole = render_part(s, 0, 1, 2, &whole_samples);
    CHECK_INT(whole_samples, 40u * 70u * 4u);
    /* 70 rows: bands of 16, 16, 16, 16 and 6 rows; 3 parts, 2 and 5 (each band its own), 8 (three
     * parts with none) */
    const uint32_t counts[] = {3, 2, 5, 8};
    for (size_t c = 0; whole && c < sizeof counts / sizeof *counts; c++) {
        uint32_t parts = counts[c];
        film *joined = film_new(whole->width, whole->height, NULL);
        CHECK(joined != NULL);
        if (!joined) break;
        film_layer wl[FILM_LAYERS], jl[FILM_LAYERS];
        film_layers(whole, wl);
        film_layers(joined, jl);
        uint64_t samples = 0;
        for (uint32_t part = 0; part < parts; part++) {
            film *f = render_part(s, part, parts, 1 + part % 2, &samples);
            if (!f) continue;
            film_layer fl[FILM_LAYERS];
            film_layers(f, fl);
            for (uint32_t y = 0; y < f->height; y++) {
                int mine = y / RENDER_BAND_ROWS % parts == part;
                for (int k = 0; k < FILM_LAYERS; k++) {
                    size_t row = fl[k].pixel_bytes * f->width;
                    const char *from = (const char *)fl[k].data + y * row;
                    if (mine) memcpy((char *)jl[k].data + y * row, from, row);
                    else for (size_t b = 0; b < row; b++) CHECK(from[b] == 0); /* left alone */
                }
            }
            film_free(f);
        }
        for (int k = 0; k < FILM_LAYERS; k++)
            CHECK(!memcmp(wl[k].data, jl[k].data, wl[k].pixel_bytes * whole->width * whole->height));
        CHECK(auto_exposure_stops(joined) == auto_exposure_stops(whole));
        CHECK_INT(samples, whole_samples);
        film_free(joined);
    }
    film_free(whole);
    scene_free(s);
}

TEST_LIST(TEST_CASE(bands_of_the_parts_make_the_whole))
