/* time_to_noise.c — sylva's renders of a scene at a ladder of sample counts, each with the time of
 * its pixel phase, and a reference at many samples, as EXR files for bench_image_rms
 * (bench/cycles_noise.sh compares them with Cycles' renders of the same scene).
 *
 * usage: bench_time_to_noise SCENE WxH OUTDIR REF_SPP [SPP...] [--threads N] [--crown-proxy PX]
 *
 * The scene is built once (ground cover for WxH, as `sylva render` places it); each render is
 * render_setup_run alone, so the times are the pixel phase's: wall and the process's processor
 * time (all threads). The ladder renders with the scene's seed, the reference with seed + 1, so
 * its noise is independent of theirs (REF_SPP 0: no reference). Prints one line per render:
 *   sylva spp N cpu C wall W file PATH
 * --crown-proxy: image.crown_proxy for the renders (0: every plant in full, as another renderer
 * given the plants sees them).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "io/exr_write.h"
#include "render/render.h"
#include "util/phase_times.h"

static int render_one(render_setup *rs, render_options o, const char *dir, const char *tag, err_buf *err)
{
    phase_times t = {{0}};
    phase_mark m = phase_start();
    film *f = render_setup_run(rs, &o, NULL, err);
    phase_stop(&t, PHASE_RENDER, m);
    double cpu = t.cpu[PHASE_RENDER], wall = t.seconds[PHASE_RENDER];
    if (!f) return -1;
    char path[4096];
    snprintf(path, sizeof path, "%s/sylva_%s.exr", dir, tag);
    exr_frame fr = {.width = f->width, .height = f->height, .rgb = f->rgb};
    int rc = exr_write(path, &fr, err);
    film_free(f);
    if (!rc) printf("sylva spp %u cpu %.4f wall %.4f file %s\n", o.spp, cpu, wall, path);
    fflush(stdout);
    return rc;
}

int main(int argc, char **argv)
{
    unsigned threads = 0;
    double proxy = -1;
    int n = 0;
    char *pos[64];
    for (int a = 1; a < argc; a++) {
        if (!strcmp(argv[a], "--threads") && a + 1 < argc) threads = (unsigned)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--crown-proxy") && a + 1 < argc) proxy = atof(argv[++a]);
        else if (n < 64) pos[n++] = argv[a];
    }
    uint32_t w = 0, h = 0;
    if (n < 4 || sscanf(pos[1], "%ux%u", &w, &h) != 2 || !w || !h || atoi(pos[3]) < 0) {
        fprintf(stderr, "usage: %s SCENE WxH OUTDIR REF_SPP [SPP...] [--threads N] [--crown-proxy PX]\n", argv[0]);
        return 1;
    }
    cli_scene c;
    build_options bo = {.quiet = 1, .threads = threads};
    cli_scene_use use = {.view = {.picture = 1, .width = w, .height = h, .quiet = 1}};
    int rc = cli_scene_open(&c, "time-to-noise", pos[0], &use, &bo);
    if (rc) {
        cli_scene_close(&c);
        return rc;
    }
    if (proxy >= 0) c.scene->image.crown_proxy = proxy;
    err_buf err = {{0}};
    render_options ro = {.quiet = 1, .threads = threads, .width = w, .height = h, .seed_set = 1,
                         .seed = c.scene->image.seed};
    render_setup *rs = render_setup_new(c.scene, &ro, &err);
    rc = rs ? 0 : 2;
    for (int k = 4; !rc && k < n; k++) {
        ro.spp = (uint32_t)atoi(pos[k]);
        char tag[32];
        snprintf(tag, sizeof tag, "%u", ro.spp);
        if (render_one(rs, ro, pos[2], tag, &err)) rc = 2;
    }
    if (!rc && atoi(pos[3]) > 0) {
        render_options ref = ro;
        ref.spp = (uint32_t)atoi(pos[3]), ref.seed = ro.seed + 1;
        if (render_one(rs, ref, pos[2], "ref", &err)) rc = 2;
    }
    if (rc) fprintf(stderr, "time-to-noise: %s\n", err.msg);
    render_setup_free(rs);
    cli_scene_close(&c);
    return rc;
}
