/* test_distance_noise.c — a forest 2 km away (tests/scenes/distance/forest_2km.yaml, pixels of
 * about 1.8 m there) at 16 samples per pixel: the per-pixel noise over the forest patch is at
 * most a quarter of what the renderer gave before crown proxies and stratified pixel samples,
 * and the patch's mean radiance stays within 1 % of that of the full plants (crown_proxy 0)
 * rendered with many seeds;
 * the calibrated proxies give the same bytes on one thread and on two. */
#include <string.h>

#include "harness.h"
#include "patch_noise.h"
#include "plugin/plugin_host.h"
#include "scene_build/scene_build.h"

#define FOREST SYLVA_TEST_DATA_DIR "/scenes/distance/forest_2km.yaml"

/* The patch: the bounding box of the pixels whose centre ray meets a plant of the full forest at
 * 96 x 64. */
static const patch_box PATCH = {5, 19, 84, 39};
/* Before (the renderer as of commit 278b734: independent pixel positions, full plants for every
 * ray), bench_distance_noise over PATCH at 16 spp, 4 seeds: relative noise 0.1443. */
#define NOISE_BEFORE 0.1443
/* Seeds of the full plants' render whose mean stands for the converged image: 12 x 16 samples
 * per pixel leave the patch's mean a sampling error of about 0.1 %. */
#define FULL_SEEDS 12

static plugin_registry *registry;

static scene *forest(void)
{
    err_buf err = {{0}};
    if (!registry) {
        registry = plugin_registry_open(&err);
        if (registry && plugin_registry_load_all(registry, &err)) fprintf(stderr, "%s\n", err.msg);
    }
    scene_file *sf = registry ? scene_file_load(FOREST, registry, &err) : NULL;
    build_options bo = {.quiet = 1};
    scene *s = sf ? scene_build(sf, registry, &bo, &err) : NULL;
    if (!s) fprintf(stderr, "%s\n", err.msg);
    scene_file_free(sf);
    CHECK(s != NULL);
    return s;
}

TEST(forest_2km_noise)
{
    scene *s = forest();
    if (!s) return;
    err_buf err = {{0}};
    render_options ro = {.quiet = 1, .spp = 16};
    patch_figures pf = {0}, full = {0};
    for (int proxies = 1; proxies >= 0; proxies--) {
        s->image.crown_proxy = proxies ? 24 : 0;
        render_setup *rs = render_setup_new(s, &ro, &err);
        if (!rs) fprintf(stderr, "%s\n", err.msg);
        CHECK(rs != NULL);
        patch_box b = PATCH;
        if (rs) CHECK_INT(patch_measure(rs, &ro, proxies ? 4 : FULL_SEEDS, &b, proxies ? &pf : &full, &err), 0);
        render_setup_free(rs);
    }
    fprintf(stderr, "noise %.4f (before %.4f: %.2fx less; full plants %.4f), mean %.5f (full plants %.5f: %+.2f %%)\n",
            pf.noise, NOISE_BEFORE, NOISE_BEFORE / pf.noise, full.noise, pf.mean, full.mean,
            100 * (pf.mean / full.mean - 1));
    CHECK(pf.noise > 0 && pf.noise <= NOISE_BEFORE / 4);
    CHECK_NEAR(pf.mean / full.mean, 1.0, 0.01);
    scene_free(s);
}

TEST(forest_2km_threads)
{
    scene *s = forest();
    if (!s) return;
    film *f[2] = {NULL, NULL};
    for (unsigned t = 1; t <= 2; t++) {
        err_buf err = {{0}};
        render_options ro = {.quiet = 1, .spp = 4, .threads = t};
        f[t - 1] = render_scene(s, &ro, NULL, &err);
        if (!f[t - 1]) fprintf(stderr, "%s\n", err.msg);
        CHECK(f[t - 1] != NULL);
    }
    if (f[0] && f[1]) {
        size_t n = (size_t)f[0]->width * f[0]->height;
        CHECK(!memcmp(f[0]->rgb, f[1]->rgb, 3 * n * sizeof *f[0]->rgb));
    }
    film_free(f[0]);
    film_free(f[1]);
    scene_free(s);
}

TEST_LIST(TEST_CASE(forest_2km_noise), TEST_CASE(forest_2km_threads))
