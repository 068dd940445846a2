/* test_composite.c — the development composited into a plate (montage/composite.h): a scene
 * rendered whole equals, within noise, the scene without its development rendered with other
 * samples (the "photograph") with the development composited in; without the shadow catcher or
 * without the holdouts it does not. The same bytes for any thread count; the guards of the
 * ratio; the outputs' encodings. With SYLVA_TEST_KEEP=DIR the first test leaves its images
 * there as PNGs to look at (docs/figures/composite_test.png). */
#include <stdint.h>

#include "scene_text.h"
#include "geometry/texture_lookup.h"
#include "montage/composite.h"
#include "render/accel.h"

/* A flat meadow seen from the south; an 8 x 5 x 7 m pale box (the development) lit from the
 * north-north-west, so that its shadow falls toward the camera; four trees (trunk and crown, one
 * taller) stand before it and hide much of it. */
static const char *scene_yaml =
    "image: {width: 160, height: 100, spp: 64, seed: 11, max_depth: 3}\n"
    "camera: {position: [3, -12, 6.5], look_at: [4, 8, 1], fov: 62}\n"
    "sun: {azimuth: 330, elevation: 25}\n"
    "sky: {model: constant, color: [0.12, 0.15, 0.2]}\n"
    "materials:\n"
    "  grass: {albedo: [0.22, 0.3, 0.12]}\n"
    "  concrete: {albedo: [0.7, 0.68, 0.62]}\n"
    "  bark: {albedo: [0.3, 0.2, 0.12]}\n"
    "  foliage: {albedo: [0.1, 0.25, 0.07]}\n"
    "terrain:\n"
    "  origin: [-60, -60]\n"
    "  spacing: [40, 40]\n"
    "  grid: [[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]\n"
    "  material: grass\n"
    "species:\n"
    "  trunk: {shape: box, size: [0.4, 0.4, 3], material: bark}\n"
    "  crown: {shape: sphere, radius: 1.8, subdivisions: 3, material: foliage}\n"
    "plants:\n"
    "  - {species: trunk, position: [-1.5, 3, 0]}\n"
    "  - {species: crown, position: [-1.5, 3, 4]}\n"
    "  - {species: trunk, position: [2.5, 1, 0]}\n"
    "  - {species: crown, position: [2.5, 1, 3.6]}\n"
    "  - {species: trunk, position: [9, 4, 0]}\n"
    "  - {species: crown, position: [9, 4, 4.2]}\n"
    "  - {species: trunk, position: [-1, 8.5, 0], scale: 1.6}\n"
    "  - {species: crown, position: [-1, 8.5, 6.5], scale: 1.3}\n"
    "objects:\n"
    "  - {name: hall, shape: box, size: [8, 5, 7], position: [0, 12, 3.5], material: concrete, development: true}\n";

/* Mean absolute difference over n floats. */
static double mae(const float *a, const float *b, size_t n)
{
    double s = 0.0;
    for (size_t i = 0; i < n; i++) s += fabs((double)a[i] - b[i]);
    return s / (double)n;
}

static image_f32 plate_of(const film *f)
{
    return (image_f32){.width = f->width, .height = f->height, .channels = 3, .pixels = f->rgb};
}

/* Writes linear RGB as sRGB PNG into the work folder (to look at), when SYLVA_TEST_KEEP names a
 * folder to keep it in. */
static void keep_png(const char *name, uint32_t w, uint32_t h, const float *rgb)
{
    const char *dir = getenv("SYLVA_TEST_KEEP");
    if (!dir || !*dir) return;
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    err_buf err = {{0}};
    if (composite_write_srgb(path, w, h, rgb, &err)) fprintf(stderr, "%s\n", err.msg);
}

/* The whole render against the plate (the scene without the development, other samples) with the
 * development composited: MAE <= 0.005 in linear light; with S = 1 (no shadow catcher) or with
 * the development rendered unhidden by the trees (no holdout) the MAE passes that bound. */
TEST(matches_whole_render)
{
    scene *s = scene_text_build_ok(scene_yaml);
    if (!s) return;
    render_options ro = {.threads = 2, .quiet = 1};
    composite_renders r;
    err_buf err = {{0}};
    int rc = composite_render(s, &ro, &r, &err);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    CHECK_INT(rc, 0);
    render_options po = {.threads = 2, .quiet = 1, .seed_set = 1, .seed = 987654321,
                         .leave_out = ACCEL_MASK_DEVELOPMENT};
    film *plate = render_scene(s, &po, NULL, &err);
    /* the development seen through no plants: what a composite without holdouts would paste */
    render_options uo = {.threads = 2, .quiet = 1, .leave_out = ACCEL_MASK_PLANT};
    film *unheld = render_scene(s, &uo, NULL, &err);
    CHECK(plate && unheld);
    if (rc || !plate || !unheld) goto done;
    uint32_t w = r.full->width, h = r.full->height;
    size_t n = (size_t)w * h;
    float *montage = malloc(n * 3 * sizeof(float)), *ratio = malloc(n * 3 * sizeof(float));
    float *flat = malloc(n * 3 * sizeof(float)), *pasted = malloc(n * 3 * sizeof(float));
    CHECK(montage && ratio && flat && pasted);
    if (!montage || !ratio || !flat || !pasted) goto free_images;

    /* the layers: D never exceeds the whole, equals it where the development covers the pixel */
    uint32_t covered = 0, partial = 0, hidden_by_trees = 0, bad = 0;
    for (size_t i = 0; i < n; i++) {
        float a = r.full->development[i];
        covered += a == 1.0f, partial += a > 0.0f && a < 1.0f;
        hidden_by_trees += unheld->development[i] == 1.0f && a == 0.0f;
        for (int c = 0; c < 3; c++) {
            float d = r.full->development_rgb[3 * i + c], f = r.full->rgb[3 * i + c];
            bad += d > f * (1.0f + 1e-5f) || (a == 0.0f && d != 0.0f) || (a == 1.0f && d != f);
        }
    }
    fprintf(stderr, "development: %u pixels covered, %u partly, %u hidden by the trees\n", covered, partial,
            hidden_by_trees);
    CHECK(covered > 200 && partial > 20 && hidden_by_trees > 50);
    CHECK_INT(bad, 0);

    composite_layers l = composite_layers_of(&r);
    image_f32 p = plate_of(plate);
    CHECK_INT(composite_apply(&l, &p, 1.0f, 1, montage, ratio, &err), 0);
    CHECK_INT(composite_apply(&l, &p, 1.0f, 0, flat, NULL, &err), 0);
    composite_layers u = l;
    u.development = unheld->development_rgb, u.alpha = unheld->development;
    CHECK_INT(composite_apply(&u, &p, 1.0f, 1, pasted, NULL, &err), 0);
    double e = mae(montage, r.full->rgb, 3 * n), e_flat = mae(flat, r.full->rgb, 3 * n);
    double e_pasted = mae(pasted, r.full->rgb, 3 * n), e_plate = mae(plate->rgb, r.full->rgb, 3 * n);
    double e_noise = mae(plate->rgb, r.background->rgb, 3 * n);
    fprintf(stderr, "MAE against the whole render (linear): composite %.5f, without the shadow catcher %.5f, "
                    "without holdouts %.5f, the plate alone %.5f; plate against R_bg (noise) %.5f\n",
            e, e_flat, e_pasted, e_plate, e_noise);
    CHECK(e <= 0.005);
    /* where no path meets the development, the plate passes through to the bit */
    uint32_t untouched = 0, changed = 0;
    for (size_t i = 0; i < n; i++)
        if (!memcmp(r.full->rgb + 3 * i, r.background->rgb + 3 * i, 3 * sizeof(float))) {
            untouched++;
            changed += memcmp(montage + 3 * i, plate->rgb + 3 * i, 3 * sizeof(float)) != 0;
        }
    fprintf(stderr, "%u of %zu pixels untouched by the development\n", untouched, n);
    CHECK(untouched > n / 5);
    CHECK_INT(changed, 0);
    CHECK(e_flat > 0.005);
    CHECK(e_pasted > 0.005);

    /* the shadow: ground pixels (no development, no plant) where the whole render is darker than
     * the scene without the development by a third or more; there the composite is darker than the
     * plate by the ratio of the two renders */
    double sum_m = 0, sum_p = 0, sum_f = 0, sum_b = 0;
    uint32_t shadowed = 0;
    for (size_t i = 0; i < n; i++) {
        if (r.full->development[i] > 0.0f || r.full->pixel_class[i] != PIXEL_TERRAIN) continue;
        double f = r.full->rgb[3 * i + 1], b = r.background->rgb[3 * i + 1];
        if (!(f < 0.67 * b)) continue;
        shadowed++;
        sum_m += montage[3 * i + 1], sum_p += plate->rgb[3 * i + 1], sum_f += f, sum_b += b;
    }
    double got = sum_p > 0 ? sum_m / sum_p : 0, want = sum_b > 0 ? sum_f / sum_b : 0;
    fprintf(stderr, "shadow: %u ground pixels, composite / plate %.4f, whole / without development %.4f\n",
            shadowed, got, want);
    CHECK(shadowed > 100);
    CHECK(want < 0.6);
    CHECK_NEAR(got, want, 0.02 * want);

    keep_png("composite_full.png", w, h, r.full->rgb);
    keep_png("composite_plate.png", w, h, plate->rgb);
    keep_png("composite_montage.png", w, h, montage);
    keep_png("composite_flat.png", w, h, flat);
    keep_png("composite_pasted.png", w, h, pasted);
    const char *dir = getenv("SYLVA_TEST_KEEP");
    if (dir && *dir) {
        char path[1024];
        snprintf(path, sizeof path, "%s/composite_mask.png", dir);
        CHECK_INT(composite_write_mask(path, w, h, r.full->development, &err), 0);
    }
free_images:
    free(montage), free(ratio), free(flat), free(pasted);
done:
    film_free(plate);
    film_free(unheld);
    composite_renders_free(&r);
    scene_free(s);
}

/* Values of n floats that differ in their bits. */
static size_t differing(const float *a, const float *b, size_t n)
{
    size_t d = 0;
    for (size_t i = 0; i < n; i++) d += memcmp(a + i, b + i, sizeof *a) != 0;
    return d;
}

/* Leaving the development out for every ray renders the scene as if it had none: the same bytes
 * as the scene file without the development's line, at the same seed. */
TEST(leave_out_is_the_scene_without)
{
    scene *s = scene_text_build_ok(scene_yaml);
    char *bare = strdup(scene_yaml);
    char *hall = bare ? strstr(bare, "  - {name: hall") : NULL;
    CHECK(hall != NULL);
    if (hall) *hall = '\0';
    scene *b = hall ? scene_text_build_ok(bare) : NULL;
    free(bare);
    if (s && b) {
        render_options ro = {.threads = 2, .quiet = 1, .width = 64, .height = 40, .spp = 16,
                             .leave_out = ACCEL_MASK_DEVELOPMENT};
        err_buf err = {{0}};
        film *left = render_scene(s, &ro, NULL, &err);
        ro.leave_out = 0;
        film *without = render_scene(b, &ro, NULL, &err), *whole = render_scene(s, &ro, NULL, &err);
        CHECK(left && without && whole);
        if (left && without && whole) {
            size_t n = (size_t)left->width * left->height;
            CHECK_INT(differing(left->rgb, without->rgb, 3 * n), 0);
            CHECK(differing(left->rgb, whole->rgb, 3 * n) > n / 10); /* the development is in view */
            float dev = 0;
            for (size_t i = 0; i < n; i++) dev += left->development[i];
            CHECK_INT(dev, 0);
        }
        film_free(left), film_free(without), film_free(whole);
    }
    scene_free(s);
    scene_free(b);
}

/* The verification mode (POV-Ray's shading) gives the development's radiance too: the whole
 * pixel's where the development covers it, none where it is absent, between 0 and it at edges. */
TEST(verify_mode_layers)
{
    scene *s = scene_text_build_ok(scene_yaml);
    if (!s) return;
    render_options ro = {.threads = 2, .quiet = 1, .verify = 1, .width = 80, .height = 50, .spp = 9};
    err_buf err = {{0}};
    film *f = render_scene(s, &ro, NULL, &err);
    CHECK(f != NULL);
    if (f) {
        uint32_t covered = 0, partial = 0, bad = 0;
        for (size_t i = 0; i < (size_t)f->width * f->height; i++) {
            float a = f->development[i];
            covered += a == 1.0f, partial += a > 0.0f && a < 1.0f;
            for (int c = 0; c < 3; c++) {
                float d = f->development_rgb[3 * i + c], v = f->rgb[3 * i + c];
                bad += (a == 1.0f && d != v) || (a == 0.0f && d != 0.0f) || (a > 0.0f && !(d > 0.0f && d <= v));
            }
        }
        CHECK(covered > 20 && partial > 10);
        CHECK_INT(bad, 0);
    }
    film_free(f);
    scene_free(s);
}

/* The renders and the montage are the same bytes on one thread and on two. */
TEST(same_bytes_any_thread_count)
{
    scene *s = scene_text_build_ok(scene_yaml);
    if (!s) return;
    composite_renders r[2];
    float *m[2] = {NULL, NULL};
    for (unsigned t = 0; t < 2; t++) {
        render_options ro = {.threads = t + 1, .quiet = 1, .width = 80, .height = 50, .spp = 16};
        err_buf err = {{0}};
        CHECK_INT(composite_render(s, &ro, &r[t], &err), 0);
        if (!r[t].full) continue;
        size_t n = (size_t)r[t].full->width * r[t].full->height;
        m[t] = malloc(3 * n * sizeof(float));
        image_f32 plate = plate_of(r[t].background); /* any plate of the right size */
        composite_layers l = composite_layers_of(&r[t]);
        if (m[t]) CHECK_INT(composite_apply(&l, &plate, 1.0f, 1, m[t], NULL, &err), 0);
    }
    if (m[0] && m[1]) {
        size_t n = (size_t)r[0].full->width * r[0].full->height;
        CHECK_INT(differing(r[0].full->rgb, r[1].full->rgb, 3 * n), 0);
        CHECK_INT(differing(r[0].full->development_rgb, r[1].full->development_rgb, 3 * n), 0);
        CHECK_INT(differing(r[0].full->development, r[1].full->development, n), 0);
        CHECK_INT(differing(r[0].background->rgb, r[1].background->rgb, 3 * n), 0);
        CHECK_INT(differing(m[0], m[1], 3 * n), 0);
    }
    for (unsigned t = 0; t < 2; t++) free(m[t]), composite_renders_free(&r[t]);
    scene_free(s);
}

/* The formula on made-up pixels: each guard where it applies. Pixel order: untouched ground,
 * ground in the development's shadow, wholly development, half development over shadowed ground,
 * black background, a ratio beyond the clamp. */
TEST(formula_and_guards)
{
    enum { N = 6 };
    const float full[N * 3] = {0.2f, 0.2f, 0.2f, 0.05f, 0.05f, 0.05f, 0.3f, 0.3f, 0.3f,
                               0.175f, 0.175f, 0.175f, 0.1f, 0.0f, 0.1f, 0.1f, 0.1f, 0.1f};
    const float dev[N * 3] = {0, 0, 0, 0, 0, 0, 0.3f, 0.3f, 0.3f, 0.15f, 0.15f, 0.15f, 0, 0, 0, 0, 0, 0};
    const float alpha[N] = {0, 0, 1, 0.5f, 0, 0};
    const float bg[N * 3] = {0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f,
                             0.2f, 0.2f, 0.2f, 0.1f, 0.0f, 0.1f, 0.01f, 0.01f, 0.01f};
    float plate_px[N * 3];
    for (int i = 0; i < N * 3; i++) plate_px[i] = 0.5f;
    image_f32 plate = {.width = N, .height = 1, .channels = 3, .pixels = plate_px};
    composite_layers l = {.width = N, .height = 1, .full = full, .development = dev, .alpha = alpha, .background = bg};
    float out[N * 3], s[N * 3];
    err_buf err = {{0}};
    CHECK_INT(composite_apply(&l, &plate, 2.0f, 1, out, s, &err), 0);
    CHECK_NEAR(out[0], 0.5, 1e-6);              /* S = 1: the plate as it was */
    CHECK_NEAR(s[3], 0.25, 1e-6);               /* shadow: 0.05 / 0.2 */
    CHECK_NEAR(out[3], 0.125, 1e-6);
    CHECK_NEAR(out[6], 0.6, 1e-6);              /* gain 2 times D, no plate */
    CHECK_NEAR(s[6], 1.0, 0);                   /* no background left: S = 1 */
    CHECK_NEAR(s[9], 0.25, 1e-6);               /* (0.175 - 0.15) / (0.5 * 0.2) */
    CHECK_NEAR(out[9], 0.3 + 0.5 * 0.5 * 0.25, 1e-6);
    CHECK_NEAR(s[13], 1.0, 0);                  /* black background channel: S = 1 */
    CHECK_NEAR(s[12], 1.0, 1e-6);
    CHECK_NEAR(s[15], COMPOSITE_RATIO_MAX, 0);  /* 10 clamped */
    CHECK_INT(composite_apply(&l, &plate, 1.0f, 0, out, s, &err), 0);
    for (int i = 0; i < N * 3; i++) CHECK_NEAR(s[i], 1.0, 0);
    CHECK_NEAR(out[3], 0.5, 1e-6);

    plate.width = 5;
    CHECK_INT(composite_apply(&l, &plate, 1.0f, 1, out, s, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "the plate is 5x1 pixels and the render 6x1");
    plate.width = N;
    CHECK_INT(composite_apply(&l, &plate, 0.0f, 1, out, s, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "it must be a positive number");
}

/* A scene without a development is refused with a sentence saying how to mark one. */
TEST(no_development_refused)
{
    scene *s = scene_text_build_ok("image: {width: 8, height: 8, spp: 1}\n"
                                   "camera: {position: [0, -5, 2], look_at: [0, 0, 0]}\n"
                                   "objects:\n  - {name: shed, shape: box, size: [1, 1, 1]}\n");
    if (!s) return;
    composite_renders r;
    render_options ro = {.threads = 1, .quiet = 1};
    err_buf err = {{0}};
    CHECK_INT(composite_render(s, &ro, &r, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "no development to composite");
    CHECK(r.full == NULL && r.background == NULL);
    scene_free(s);
}

/* Two frames that fit the memory budget one by one but not together are refused before any
 * build, with the size to lower. */
TEST(two_frames_beyond_memory)
{
    scene *s = scene_text_build_ok(scene_yaml);
    if (!s) return;
    setenv("SYLVA_MEMORY_LIMIT", "100M", 1);
    composite_renders r;
    render_options ro = {.threads = 1, .quiet = 1, .width = 1000, .height = 1000, .spp = 1};
    err_buf err = {{0}};
    CHECK_INT(film_check(1000, 1000, 1, &err), 0); /* one frame fits */
    CHECK_INT(composite_render(s, &ro, &r, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "a montage's pair of 1000x1000 frames needs about 175 MiB");
    CHECK_STR_CONTAINS(err.msg, "; lower the image size");
    CHECK(r.full == NULL);
    unsetenv("SYLVA_MEMORY_LIMIT");
    scene_free(s);
}

/* The 8-bit output encodes with the sRGB transfer function only: every byte of a photograph,
 * decoded as the plate is, comes back as itself; the mask is the coverage times 255. */
TEST(outputs_round_trip)
{
    float rgb[256 * 3], alpha[256];
    for (int v = 0; v < 256; v++) {
        rgb[3 * v] = rgb[3 * v + 1] = rgb[3 * v + 2] = texture_srgb_to_linear((uint8_t)v);
        alpha[v] = (float)v / 255.0f;
    }
    err_buf err = {{0}};
    const char *dir = work_dir();
    char png[1024], mask[1024], exr[1024];
    snprintf(png, sizeof png, "%s/montage.png", dir);
    snprintf(mask, sizeof mask, "%s/mask.png", dir);
    snprintf(exr, sizeof exr, "%s/montage.exr", dir);
    CHECK_INT(composite_write_srgb(png, 16, 16, rgb, &err), 0);
    CHECK_INT(composite_write_mask(mask, 16, 16, alpha, &err), 0);
    CHECK_INT(composite_write_exr(exr, 16, 16, rgb, alpha, &err), 0);
    image_f32 a = {0}, b = {0}, c = {0};
    CHECK_INT(image_read(png, &a, &err), 0);
    CHECK_INT(image_read(mask, &b, &err), 0);
    CHECK_INT(image_read(exr, &c, &err), 0);
    if (a.pixels && b.pixels && c.pixels) {
        CHECK_INT(a.channels, 3);
        CHECK_INT(b.channels, 1);
        uint32_t wrong = 0;
        for (int v = 0; v < 256; v++)
            wrong += lrintf(a.pixels[3 * v] * 255.0f) != v || lrintf(b.pixels[v] * 255.0f) != v;
        CHECK_INT(wrong, 0);
        CHECK_INT(c.channels, 4); /* R G B development.A */
    }
    image_free(&a), image_free(&b), image_free(&c);
}

TEST_LIST(TEST_CASE(matches_whole_render), TEST_CASE(leave_out_is_the_scene_without), TEST_CASE(verify_mode_layers),
          TEST_CASE(same_bytes_any_thread_count), TEST_CASE(formula_and_guards), TEST_CASE(no_development_refused),
          TEST_CASE(two_frames_beyond_memory), TEST_CASE(outputs_round_trip))
