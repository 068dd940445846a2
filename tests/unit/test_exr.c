/* test_exr.c — the EXR writer: every layer written and read back through OpenImageIO with
 * its channel names and values, the half conversion on known values, and failures that leave
 * no file behind. */
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <sys/stat.h>
#include <unistd.h>

#include "harness.h"
#include "work_dir.h"
#include "io/exr_write.h"
#include "io/half_float.h"
#include "io/image_io.h"

enum { W = 7, H = 5, N = W * H };

static int count_entries(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) n++;
    closedir(d);
    return n;
}

/* Distinctive layers: no two channels share a value at the same pixel. */
typedef struct test_layers {
    float rgb[3 * N], depth[N], normal[3 * N], albedo[3 * N];
    uint32_t instance[N], species[N], object[N];
    float development[N], development_rgb[3 * N];
} test_layers;

static void fill_layers(test_layers *l)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int i = y * W + x;
            for (int c = 0; c < 3; c++) {
                l->rgb[3 * i + c] = 0.013f * (float)i + 0.31f * (float)c + 0.007f;
                l->normal[3 * i + c] = (c == 2 ? 0.8f : -0.6f) + 0.001f * (float)(i + c);
                l->albedo[3 * i + c] = 0.05f + 0.02f * (float)c + 0.0037f * (float)i;
                l->development_rgb[3 * i + c] = 0.011f * (float)i + 0.23f * (float)c + 0.003f;
            }
            /* the top row and the right column see the sky */
            l->depth[i] = (y == 0 || x == W - 1) ? INFINITY : 10.25f + 3.5f * (float)i;
            l->instance[i] = x == W - 1 ? 0u : 1000u + (uint32_t)i;
            l->species[i] = (uint32_t)(i % 4);
            l->object[i] = (uint32_t)(i % 3);
            l->development[i] = (float)(i % 5) * 0.25f;
        }
    l->rgb[3 * 5] = 70000.0f; /* beyond the half range: stored as +inf when half */
    l->rgb[3 * 6 + 1] = 1e-8f; /* below the smallest half subnormal: stored as 0 */
}

static int channel_index(const image_f32 *img, const char *name)
{
    for (uint32_t c = 0; c < img->channels; c++)
        if (img->channel_names[c] && !strcmp(img->channel_names[c], name)) return (int)c;
    fprintf(stderr, "channel %s not found\n", name);
    return -1;
}

/* Checks one channel of img against src (stride floats apart) exactly, or as half when asked. */
static void check_float_channel(const image_f32 *img, const char *name, const float *src,
                                int stride, int as_half)
{
    int c = channel_index(img, name);
    CHECK(c >= 0);
    if (c < 0) return;
    int bad = 0;
    for (int i = 0; i < N && bad < 3; i++) {
        float want = as_half ? half_to_float(half_from_float(src[i * stride])) : src[i * stride];
        float got = img->pixels[(size_t)i * img->channels + (size_t)c];
        if (!(got == want)) {
            fprintf(stderr, "%s[%d] = %.9g, expected %.9g\n", name, i, got, want);
            bad++;
        }
    }
    CHECK_INT(bad, 0);
}

static void check_id_channel(const image_f32 *img, const char *name, const uint32_t *src)
{
    int c = channel_index(img, name);
    CHECK(c >= 0);
    if (c < 0) return;
    int bad = 0;
    for (int i = 0; i < N; i++)
        if (img->pixels[(size_t)i * img->channels + (size_t)c] != (float)src[i]) bad++;
    CHECK_INT(bad, 0);
}

static void round_trip(int rgb_half)
{
    static test_layers l;
    fill_layers(&l);
    exr_frame f = {.width = W, .height = H, .rgb = l.rgb, .depth = l.depth, .normal = l.normal,
                   .albedo = l.albedo, .instance_id = l.instance, .species_id = l.species,
                   .object_id = l.object, .development = l.development,
                   .development_rgb = l.development_rgb, .rgb_half = rgb_half};
    const char *path = work_path(rgb_half ? "half.exr" : "float.exr");
    err_buf err = {{0}};
    int rc = exr_write(path, &f, &err);
    CHECK_INT(rc, 0);
    if (rc) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    image_f32 img = {0};
    rc = image_read(path, &img, &err);
    CHECK_INT(rc, 0);
    if (rc) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    CHECK_INT(img.width, W);
    CHECK_INT(img.height, H);
    CHECK_INT(img.channels, 17);
    static const char *const names[] = {"R", "G", "B", "Z", "N.X", "N.Y", "N.Z", "albedo.R",
                                        "albedo.G", "albedo.B", "id.instance", "id.species",
                                        "id.object", "development.A", "development.R",
                                        "development.G", "development.B"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        CHECK(channel_index(&img, names[k]) >= 0);

    check_float_channel(&img, "R", l.rgb + 0, 3, rgb_half);
    check_float_channel(&img, "G", l.rgb + 1, 3, rgb_half);
    check_float_channel(&img, "B", l.rgb + 2, 3, rgb_half);
    check_float_channel(&img, "Z", l.depth, 1, 0);
    check_float_channel(&img, "N.X", l.normal + 0, 3, 0);
    check_float_channel(&img, "N.Y", l.normal + 1, 3, 0);
    check_float_channel(&img, "N.Z", l.normal + 2, 3, 0);
    check_float_channel(&img, "albedo.R", l.albedo + 0, 3, 0);
    check_float_channel(&img, "albedo.G", l.albedo + 1, 3, 0);
    check_float_channel(&img, "albedo.B", l.albedo + 2, 3, 0);
    check_id_channel(&img, "id.instance", l.instance);
    check_id_channel(&img, "id.species", l.species);
    check_id_channel(&img, "id.object", l.object);
    check_float_channel(&img, "development.A", l.development, 1, 0);
    check_float_channel(&img, "development.R", l.development_rgb + 0, 3, 0);
    check_float_channel(&img, "development.G", l.development_rgb + 1, 3, 0);
    check_float_channel(&img, "development.B", l.development_rgb + 2, 3, 0);

    int r = channel_index(&img, "R"), g = channel_index(&img, "G"), z = channel_index(&img, "Z");
    if (r >= 0 && g >= 0 && z >= 0) {
        CHECK(isinf(img.pixels[0 * img.channels + (uint32_t)z])); /* sky */
        CHECK_NEAR(img.pixels[(size_t)(W + 1) * img.channels + (uint32_t)z], 10.25 + 3.5 * 8, 0);
        if (rgb_half) {
            CHECK(isinf(img.pixels[5 * img.channels + (uint32_t)r]));
            CHECK(img.pixels[6 * img.channels + (uint32_t)g] == 0.0f);
            /* 0.013*1 + 0.007 = 0.02 as half: within half a unit in the last place (2^-17) */
            CHECK_NEAR(img.pixels[1 * img.channels + (uint32_t)r], 0.02, 0x1p-17);
        } else {
            CHECK(img.pixels[5 * img.channels + (uint32_t)r] == 70000.0f);
            CHECK(img.pixels[6 * img.channels + (uint32_t)g] == 1e-8f);
        }
    }
    image_free(&img);
}

TEST(all_layers_float_rgb)
{
    round_trip(0);
}

TEST(all_layers_half_rgb)
{
    round_trip(1);
}

TEST(some_layers_left_out)
{
    float depth[N];
    for (int i = 0; i < N; i++) depth[i] = (float)i * 0.5f;
    exr_frame f = {.width = W, .height = H, .depth = depth};
    const char *path = work_path("depth_only.exr");
    err_buf err = {{0}};
    CHECK_INT(exr_write(path, &f, &err), 0);
    image_f32 img = {0};
    CHECK_INT(image_read(path, &img, &err), 0);
    CHECK_INT(img.channels, 1);
    if (img.channels == 1) {
        CHECK_STR_CONTAINS(img.channel_names[0], "Z");
        CHECK_NEAR(img.pixels[N - 1], (N - 1) * 0.5, 0);
    }
    image_free(&img);
}

TEST(tall_frame_spans_many_chunks)
{
    /* 3x40: ZIP packs 16 scanlines per chunk, so three chunks, the last one short */
    enum { TW = 3, TH = 40 };
    float rgb[3 * TW * TH];
    for (int i = 0; i < 3 * TW * TH; i++) rgb[i] = (float)i / 8.0f;
    exr_frame f = {.width = TW, .height = TH, .rgb = rgb, .rgb_half = 1};
    const char *path = work_path("tall.exr");
    err_buf err = {{0}};
    CHECK_INT(exr_write(path, &f, &err), 0);
    image_f32 img = {0};
    CHECK_INT(image_read(path, &img, &err), 0);
    CHECK_INT(img.height, TH);
    CHECK_INT(img.channels, 3);
    int bad = 0;
    for (int i = 0; img.pixels && i < 3 * TW * TH; i++)
        if (img.pixels[i] != half_to_float(half_from_float(rgb[i]))) bad++;
    CHECK_INT(bad, 0);
    image_free(&img);
}

TEST(missing_folder_fails_cleanly)
{
    float depth[N] = {0};
    exr_frame f = {.width = W, .height = H, .depth = depth};
    char path[1024];
    snprintf(path, sizeof path, "%s/no/such/folder/frame.exr", work_path(""));
    err_buf err = {{0}};
    CHECK_INT(exr_write(path, &f, &err), -1);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "No such file or directory");
    CHECK_INT(access(path, F_OK), -1);
}

TEST(failed_rename_leaves_no_file)
{
    /* the target is a non-empty folder: refused before the file is written */
    char target[1024], inner[1100];
    snprintf(target, sizeof target, "%s", work_path("occupied"));
    CHECK_INT(mkdir(target, 0755), 0);
    snprintf(inner, sizeof inner, "%s/keep", target);
    CHECK_INT(mkdir(inner, 0755), 0);
    int before = count_entries(work_path(""));
    float depth[N] = {0};
    exr_frame f = {.width = W, .height = H, .depth = depth};
    err_buf err = {{0}};
    CHECK_INT(exr_write(target, &f, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "occupied: is a folder");
    CHECK_INT(count_entries(work_path("")), before);
    rmdir(inner);
    rmdir(target);
}

TEST(invalid_frames_are_refused)
{
    float depth[N] = {0};
    err_buf err = {{0}};
    exr_frame empty = {.width = W, .height = H};
    CHECK_INT(exr_write(work_path("empty.exr"), &empty, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "no layers");
    exr_frame zero = {.width = 0, .height = H, .depth = depth};
    CHECK_INT(exr_write(work_path("zero.exr"), &zero, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "0x5 pixels cannot be written");
    CHECK_INT(access(work_path("empty.exr"), F_OK), -1);
    CHECK_INT(access(work_path("zero.exr"), F_OK), -1);
}

TEST(no_temporary_files_after_success)
{
    float depth[N] = {0};
    exr_frame f = {.width = W, .height = H, .depth = depth};
    err_buf err = {{0}};
    int before = count_entries(work_path(""));
    CHECK_INT(access(work_path("clean.exr"), F_OK), -1);
    CHECK_INT(exr_write(work_path("clean.exr"), &f, &err), 0);
    CHECK_INT(count_entries(work_path("")), before + 1);
    /* writing again replaces the file */
    CHECK_INT(exr_write(work_path("clean.exr"), &f, &err), 0);
    CHECK_INT(count_entries(work_path("")), before + 1);
}

TEST(half_known_values)
{
    CHECK_INT(half_from_float(0.0f), 0x0000);
    CHECK_INT(half_from_float(-0.0f), 0x8000);
    CHECK_INT(half_from_float(1.0f), 0x3c00);
    CHECK_INT(half_from_float(-2.0f), 0xc000);
    CHECK_INT(half_from_float(0.5f), 0x3800);
    CHECK_INT(half_from_float(0.1f), 0x2e66);       /* 0.0999755859375 is nearest */
    CHECK_INT(half_from_float(65504.0f), 0x7bff);   /* largest half */
    CHECK_INT(half_from_float(65519.0f), 0x7bff);   /* below the halfway point */
    CHECK_INT(half_from_float(65520.0f), 0x7c00);   /* halfway: ties to even = infinity */
    CHECK_INT(half_from_float(70000.0f), 0x7c00);
    CHECK_INT(half_from_float(-70000.0f), 0xfc00);
    CHECK_INT(half_from_float(INFINITY), 0x7c00);
    CHECK_INT(half_from_float(-INFINITY), 0xfc00);
    CHECK_INT(half_from_float(0x1p-14f), 0x0400);   /* smallest normal */
    CHECK_INT(half_from_float(0x1p-24f), 0x0001);   /* smallest subnormal */
    CHECK_INT(half_from_float(0x1p-25f), 0x0000);   /* halfway to it: ties to even = 0 */
    CHECK_INT(half_from_float(0x1.8p-25f), 0x0001); /* past halfway */
    CHECK_INT(half_from_float(1e-8f), 0x0000);      /* below 2^-25 */
    CHECK_INT(half_from_float(1e-7f), 0x0002);      /* 1e-7 / 2^-24 = 1.68 */
    CHECK_INT(half_from_float(6.1e-5f), 0x03ff);    /* largest subnormal, 6.0976e-5 */
    CHECK_INT(half_from_float(1.0f + 0x1p-11f), 0x3c00);      /* tie, even stays */
    CHECK_INT(half_from_float(1.0f + 3 * 0x1p-11f), 0x3c02);  /* tie, odd rounds up */
    CHECK_INT(half_from_float(2047.5f), 0x6800);    /* rounding carries into the exponent */

    uint16_t nan_bits = half_from_float(NAN);
    CHECK_INT(nan_bits & 0x7c00, 0x7c00);
    CHECK(nan_bits & 0x03ff);
    CHECK(isnan(half_to_float(nan_bits)));

    CHECK(half_to_float(0x3c00) == 1.0f);
    CHECK(half_to_float(0x7bff) == 65504.0f);
    CHECK(half_to_float(0x0001) == 0x1p-24f);
    CHECK(half_to_float(0x03ff) == 1023 * 0x1p-24f);
    CHECK(isinf(half_to_float(0xfc00)) && half_to_float(0xfc00) < 0);
    /* every finite half survives half → float → half */
    int bad = 0;
    for (uint32_t h = 0; h < 0x10000u; h++) {
        if ((h & 0x7c00u) == 0x7c00u && (h & 0x3ffu)) continue; /* NaNs */
        if (half_from_float(half_to_float((uint16_t)h)) != h) bad++;
    }
    CHECK_INT(bad, 0);
}

TEST_LIST(TEST_CASE(all_layers_float_rgb), TEST_CASE(all_layers_half_rgb),
          TEST_CASE(some_layers_left_out), TEST_CASE(tall_frame_spans_many_chunks),
          TEST_CASE(missing_folder_fails_cleanly), TEST_CASE(failed_rename_leaves_no_file),
          TEST_CASE(invalid_frames_are_refused), TEST_CASE(no_temporary_files_after_success),
          TEST_CASE(half_known_values))
