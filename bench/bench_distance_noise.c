/* bench_distance_noise.c — the noise and mean radiance of a distant plant patch
 * (tests/image/patch_noise.h), and where the noise comes from: renders of a scene at several
 * sample counts and path depths, each measured over the same patch.
 *
 * usage: bench_distance_noise [--patch X0,Y0,X1,Y1] SCENE [WxH] [SEEDS] [SPP...]
 * (the patch: pixels [X0, X1) x [Y0, Y1); default: the plants' bounding box in the first render)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "patch_noise.h"
#include "plugin/plugin_host.h"
#include "scene_build/scene_build.h"

int main(int argc, char **argv)
{
    patch_box b = {0};
    if (argc > 2 && !strcmp(argv[1], "--patch")) {
        sscanf(argv[2], "%u,%u,%u,%u", &b.x0, &b.y0, &b.x1, &b.y1);
        argv += 2, argc -= 2;
    }
    if (argc < 2) {
        fprintf(stderr, "usage: %s SCENE [WxH] [SEEDS] [SPP...]\n", argv[0]);
        return 1;
    }
    unsigned w = 96, h = 64, seeds = 4;
    if (argc > 2) sscanf(argv[2], "%ux%u", &w, &h);
    if (argc > 3) seeds = (unsigned)atoi(argv[3]);
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open(&err);
    if (!reg || plugin_registry_load_all(reg, &err)) goto fail;
    scene_file *sf = scene_file_load(argv[1], reg, &err);
    build_options bo = {.quiet = 1};
    scene *s = sf ? scene_build(sf, reg, &bo, &err) : NULL;
    if (!s) goto fail;
    render_options ro = {.quiet = 1, .width = w, .height = h};
    render_setup *rs = render_setup_new(s, &ro, &err);
    if (!rs) goto fail;
    uint32_t depth0 = s->image.max_depth;
    for (int a = argc > 4 ? 4 : argc; a < (argc > 4 ? argc : argc + 1); a++) {
        ro.spp = a < argc ? (uint32_t)atoi(argv[a]) : 16;
        for (uint32_t d = 1; d <= depth0; d += d < 2 ? 1 : depth0 - 2 > 0 ? depth0 - 2 : 1) {
            ((scene *)s)->image.max_depth = d;
            patch_figures pf;
            if (patch_measure(rs, &ro, seeds, &b, &pf, &err)) goto fail;
            printf("spp %4u depth %u: patch %ux%u at (%u,%u) mean %.5f noise %.4f (plants %.4f, "
                   "ground %.4f) (%.2f s, %.2f s CPU)\n", ro.spp, d, b.x1 - b.x0, b.y1 - b.y0, b.x0, b.y0, pf.mean, pf.noise,
                   pf.noise_plant, pf.noise_ground, pf.seconds, pf.cpu_seconds);
            fflush(stdout);
        }
    }
    render_setup_free(rs);
    scene_free(s);
    scene_file_free(sf);
    plugin_registry_free(reg);
    return 0;
fail:
    fprintf(stderr, "%s\n", err.msg);
    return 2;
}
