/* render_still.c — a render's pipeline from the built scene to the PNG and EXR (render_still.h). */
#include "render/render_still.h"

#include <stdio.h>

#include "render/auto_exposure.h"
#include "scene/heightfield.h"
#include "util/progress.h"

/* What was built, and the ground the render shows against the one the analyses read. */
static void describe_scene(const scene *sc, double seconds)
{
    fprintf(stderr, "scene: %u species, %u prototypes, %u instances, %u objects (%u shared models)%s (built in "
            "%.2fs)\n", sc->n_species, sc->n_prototypes, sc->n_instances, sc->n_objects, sc->n_models,
            sc->terrain ? ", terrain" : "", seconds);
    if (!sc->terrain) return;
    char shown[192], surveyed[192];
    heightfield_describe(sc->terrain, shown, sizeof shown);
    heightfield_describe(sc->surveyed, surveyed, sizeof surveyed);
    if (sc->terrain == sc->surveyed) fprintf(stderr, "ground: %s, as the analyses read it\n", shown);
    else fprintf(stderr, "ground: rendered %s; the analyses read the DTM as surveyed, %s\n", shown, surveyed);
}

/* Part 0's frame gets the other parts' bands of every layer. */
static int gather_film(const run_parts *parts, film *f, err_buf *err)
{
    film_layer l[FILM_LAYERS];
    run_rows a[FILM_LAYERS];
    film_layers(f, l);
    for (int k = 0; k < FILM_LAYERS; k++) a[k] = (run_rows){l[k].data, l[k].pixel_bytes * f->width};
    return parts->gather_rows(parts->job, a, FILM_LAYERS, 0, f->height, RENDER_BAND_ROWS, err);
}

double render_still_exposure(const scene *sc, const film *f)
{
    return sc->image.exposure_set ? sc->image.exposure : auto_exposure_stops(f);
}

/* Part 0: the exposure metered (or the scene's), the pair written, the closing lines. */
static int write_frame(const scene *sc, const render_still_options *o, const film *f, const render_stats *st,
                       uint64_t samples, int parts, phase_times *times, phase_mark t_out, err_buf *err)
{
    int quiet = o->render.quiet;
    double ev = render_still_exposure(sc, f);
    if (!quiet) fprintf(stderr, "exposure: %+.2f EV (%s)\n", ev, sc->image.exposure_set ? "image.exposure" : "metered");
    if (film_write_pair(f, &sc->site, sc->image.tone, ev, o->png, o->exr, err)) return err_default(err, ERR_OUTPUT);
    phase_stop(times, PHASE_OUTPUT, t_out);
    if (!quiet) {
        char ranks[32] = "";
        if (parts > 1) snprintf(ranks, sizeof ranks, " on %d ranks", parts);
        fprintf(stderr, "rendered %ux%u%s, %llu samples in %.2fs (BVH %.2fs); total %.2fs\n", f->width, f->height,
                ranks, (unsigned long long)samples, st->render_seconds, st->build_seconds,
                progress_now() - o->started);
        phase_times_print(times, stderr);
    }
    return 0;
}

int render_still_run(const scene *sc, const render_still_options *o, const run_parts *parts, phase_times *times,
                     err_buf *err)
{
    if (parts->same_scene(parts->job, sc, err)) return err_default(err, ERR_INPUT);
    if (!o->render.quiet) describe_scene(sc, o->scene_seconds);
    render_options ro = o->render;
    ro.part = (uint32_t)parts->part, ro.parts = (uint32_t)parts->parts;
    render_stats st;
    film *f = render_scene(sc, &ro, &st, err);
    if (!f) return err_default(err, ERR_INTERNAL);
    phase_add(times, PHASE_BVH, st.bvh_seconds);
    phase_add(times, PHASE_RENDER_SETUP, st.build_seconds - st.bvh_seconds);
    phase_add(times, PHASE_RENDER, st.render_seconds);
    phase_mark t_out = phase_start();
    /* the whole frame on part 0; the exposure is metered on it there */
    int rc = gather_film(parts, f, err) ? err_default(err, ERR_INTERNAL) : 0;
    uint64_t samples = st.samples;
    if (!rc) parts->sum(parts->job, &samples, 1);
    if (!rc && !parts->part) rc = write_frame(sc, o, f, &st, samples, parts->parts, times, t_out, err);
    film_free(f);
    return rc;
}
