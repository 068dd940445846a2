/* test_image_io.c — the OpenImageIO shim: 8-bit PNG written and read back exactly (grey, RGB,
 * RGBA with unassociated alpha), readable errors for files that are not images, damaged PNGs
 * refused in sylva's sentence alone, and no temporary file left beside the target after a
 * success or a failure. */
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cut_image.h"
#include "damaged_png.h"
#include "harness.h"
#include "work_dir.h"
#include "io/image_io.h"

/* Names in the work folder other than the given ones, counted (temporary files, leftovers). */
static int count_other_entries(const char *keep1, const char *keep2)
{
    DIR *d = opendir(work_dir());
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        const char *s = e->d_name;
        if (!strcmp(s, ".") || !strcmp(s, "..")) continue;
        if ((keep1 && !strcmp(s, keep1)) || (keep2 && !strcmp(s, keep2))) continue;
        fprintf(stderr, "unexpected file in the work folder: %s\n", s);
        n++;
    }
    closedir(d);
    return n;
}

static void round_trip(const char *name, uint32_t w, uint32_t h, uint32_t channels,
                       const char *const *want_names)
{
    uint8_t px[64 * 4];
    for (uint32_t i = 0; i < w * h * channels; i++) px[i] = (uint8_t)((i * 37u + 11u) & 0xffu);
    if (channels == 4) {
        px[3] = 0;      /* fully transparent pixel with colour: must survive unchanged */
        px[4 + 3] = 1;
    }
    err_buf err = {{0}};
    const char *path = work_path(name);
    int rc = image_write_u8(path, w, h, channels, px, &err);
    CHECK_INT(rc, 0);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    image_f32 img = {0};
    rc = image_read(path, &img, &err);
    CHECK_INT(rc, 0);
    if (rc) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    CHECK_INT(img.width, w);
    CHECK_INT(img.height, h);
    CHECK_INT(img.channels, channels);
    for (uint32_t c = 0; c < img.channels && c < channels; c++)
        CHECK_STR_CONTAINS(img.channel_names[c], want_names[c]);
    int bad = 0;
    for (uint32_t i = 0; i < w * h * channels && img.channels == channels; i++)
        if (fabsf(img.pixels[i] - (float)px[i] / 255.0f) > 1e-7f) { /* OIIO scales by 1/255 */
            if (bad < 3)
                fprintf(stderr, "value %u = %.9g, expected %u/255\n", i, img.pixels[i], px[i]);
            bad++;
        }
    CHECK_INT(bad, 0);
    image_free(&img);
    CHECK(img.pixels == NULL && img.channel_names == NULL && img.channels == 0);
}

TEST(png_rgb_round_trip)
{
    static const char *const names[] = {"R", "G", "B"};
    round_trip("rgb.png", 5, 3, 3, names);
    CHECK_INT(count_other_entries("rgb.png", NULL), 0);
    remove(work_path("rgb.png"));
}

TEST(png_rgba_round_trip)
{
    static const char *const names[] = {"R", "G", "B", "A"};
    round_trip("rgba.png", 4, 4, 4, names);
    CHECK_INT(count_other_entries("rgba.png", NULL), 0);
    remove(work_path("rgba.png"));
}

TEST(png_grey_round_trip)
{
    static const char *const names[] = {"Y"};
    round_trip("grey.png", 8, 2, 1, names);
    remove(work_path("grey.png"));
}

TEST(overwrite_replaces_the_file)
{
    uint8_t dark[3 * 4] = {0}, light[3 * 4];
    memset(light, 200, sizeof light);
    err_buf err = {{0}};
    const char *path = work_path("again.png");
    CHECK_INT(image_write_u8(path, 2, 2, 3, dark, &err), 0);
    CHECK_INT(image_write_u8(path, 2, 2, 3, light, &err), 0);
    image_f32 img = {0};
    CHECK_INT(image_read(path, &img, &err), 0);
    if (img.pixels) CHECK_NEAR(img.pixels[11], 200.0 / 255.0, 1e-7);
    image_free(&img);
    CHECK_INT(count_other_entries("again.png", NULL), 0);
    remove(path);
}

TEST(unreadable_files)
{
    err_buf err = {{0}};
    image_f32 img = {0};
    const char *missing = work_path("missing.png");
    CHECK_INT(image_read(missing, &img, &err), -1);
    CHECK_STR_CONTAINS(err.msg, missing);
    CHECK_STR_CONTAINS(err.msg, "cannot read the image");
    CHECK(img.pixels == NULL && img.channels == 0);

    const char *junk = work_path("junk.png");
    FILE *f = fopen(junk, "wb");
    CHECK(f != NULL);
    if (f) {
        fputs("this is not a PNG file\n", f);
        fclose(f);
    }
    err_clear(&err);
    CHECK_INT(image_read(junk, &img, &err), -1);
    CHECK_STR_CONTAINS(err.msg, junk);
    CHECK(strlen(err.msg) > strlen(junk) + 25); /* the reason follows the name */
    CHECK(img.pixels == NULL);
    remove(junk);
}

TEST(failed_writes_leave_nothing)
{
    uint8_t px[3 * 4] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    err_buf err = {{0}};
    char path[1024];

    snprintf(path, sizeof path, "%s/no/such/folder/out.png", work_dir());
    CHECK_INT(image_write_u8(path, 2, 2, 3, px, &err), -1);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_INT(access(path, F_OK), -1);

    const char *unknown = work_path("picture.unknownformat");
    err_clear(&err);
    CHECK_INT(image_write_u8(unknown, 2, 2, 3, px, &err), -1);
    CHECK_STR_CONTAINS(err.msg, unknown);
    CHECK_INT(access(unknown, F_OK), -1);

    /* the target is a non-empty folder: refused before anything is written */
    const char *folder = work_path("occupied.png");
    CHECK_INT(mkdir(folder, 0755), 0);
    char inner[1100];
    snprintf(inner, sizeof inner, "%s/keep", folder);
    CHECK_INT(mkdir(inner, 0755), 0);
    err_clear(&err);
    CHECK_INT(image_write_u8(folder, 2, 2, 3, px, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "occupied.png: is a folder");
    CHECK_INT(count_other_entries("occupied.png", NULL), 0);
    rmdir(inner);
    rmdir(folder);

    err_clear(&err);
    CHECK_INT(image_write_u8(work_path("five.png"), 2, 2, 5, px, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "1 to 4");
    err_clear(&err);
    CHECK_INT(image_write_u8(work_path("empty.png"), 0, 2, 3, px, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "0x2");
    CHECK_INT(count_other_entries(NULL, NULL), 0);
}

/* A device or a FIFO named as an image is refused at once (both used to hang OpenImageIO's
 * format detection or open); an alarm fails the test should it hang again. */
TEST(devices_and_fifos_are_refused)
{
    err_buf err = {{0}};
    image_f32 img = {0};
    const char *fifo = work_path("texture.png");
    CHECK_INT(mkfifo(fifo, 0600), 0);
    alarm(10);
    CHECK_INT(image_read(fifo, &img, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "texture.png: cannot read the image: not a regular file: it is a "
                                "FIFO (named pipe)");
    CHECK_INT(image_read("/dev/zero", &img, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "/dev/zero: cannot read the image: not a regular file: it is a "
                                "character device");
    alarm(0);
    CHECK(img.pixels == NULL);
    remove(fifo);
}

/* A file that is not an image is refused without quoting its bytes: OpenImageIO's reasons for
 * TIFF and JPEG include the file's first bytes as a "magic number". */
TEST(foreign_files_are_not_quoted)
{
    static const char *const names[] = {"secret.tif", "secret.jpg", "secret.png", "secret.exr"};
    for (int k = 0; k < 4; k++) {
        const char *path = work_file(names[k], "root:x:0:0:root:/root:/bin/bash\n");
        CHECK(path != NULL);
        if (!path) continue;
        err_buf err = {{0}};
        image_f32 img = {0};
        CHECK_INT(image_read(path, &img, &err), -1);
        CHECK_STR_CONTAINS(err.msg, "is not in an image format OpenImageIO reads");
        CHECK(!strstr(err.msg, "0x") && !strstr(err.msg, "magic") && !strstr(err.msg, "root"));
        remove(path);
    }
}

/* A texture cut short is refused with its name and what is wrong, not read with grey for the
 * missing part. */
TEST(cut_images_are_refused)
{
    const char *names[] = {"cut.jpg", "cut.tif", "cut.png"};
    for (int i = 0; i < 3; i++) {
        const char *path = cut_image_write(names[i], 0.6);
        err_buf err = {{0}};
        image_f32 img = {0};
        CHECK_INT(image_read(path, &img, &err), -1);
        fprintf(stderr, "%s\n", err.msg);
        CHECK_STR_CONTAINS(err.msg, path);
        CHECK(img.pixels == NULL);
        if (i < 2) CHECK_STR_CONTAINS(err.msg, "damaged or cut short");
        remove(path);
    }
}

/* An image whose header claims more pixels than the memory budget holds is refused before they
 * are allocated (ERR_LIMIT, as a photograph or a DTM): a PPM header of 60000 x 60000 pixels
 * followed by three bytes, and a real 64 x 64 PNG under a 16 KiB budget. */
TEST(images_beyond_the_memory_budget)
{
    char huge[1200];
    snprintf(huge, sizeof huge, "%s", work_path("huge.ppm"));
    FILE *f = fopen(huge, "wb");
    CHECK(f != NULL);
    if (f) fputs("P6\n60000 60000\n255\n\x01\x02\x03", f), fclose(f);
    err_buf err = {{0}};
    image_f32 img = {0};
    setenv("SYLVA_MEMORY_LIMIT", "1G", 1);
    CHECK_INT(image_read(huge, &img, &err), -1);
    CHECK_INT(err.status, ERR_LIMIT);
    CHECK_STR_CONTAINS(err.msg, "(60000x60000, 3 channels) needs about 67.1 GiB of memory, more than the 1.0 GiB "
                                "SYLVA_MEMORY_LIMIT allows");
    CHECK(img.pixels == NULL);
    const uint8_t rgb[64 * 64 * 3] = {0};
    const char *small = work_path("small.png");
    CHECK_INT(image_write_u8(small, 64, 64, 3, rgb, &err), 0);
    setenv("SYLVA_MEMORY_LIMIT", "16K", 1);
    err_clear(&err);
    CHECK_INT(image_read(small, &img, &err), -1);
    CHECK_INT(err.status, ERR_LIMIT);
    CHECK_STR_CONTAINS(err.msg, small);
    unsetenv("SYLVA_MEMORY_LIMIT");
    CHECK_INT(image_read(small, &img, &err), 0);
    image_free(&img);
    remove(huge);
    remove(small);
}

/* A damaged PNG texture, as a file and as the bytes a model embeds, is refused in sylva's
 * sentence with nothing else on stderr: pixels whose zlib checksum is wrong (libpng printed
 * "libpng error: IDAT: incorrect data check" under OpenImageIO), and a tEXt chunk stating
 * 1.8 GB in a file of 44 bytes (libpng allocated it before finding the file's end, as it did for
 * photographs). */
TEST(damaged_pngs_are_refused_quietly)
{
    static uint8_t bytes[64 * 1024];
    const char *path = NULL;
    size_t n = damaged_png_write("damaged.png", bytes, sizeof bytes, &path);
    if (!n) return;
    static const uint8_t text[] = {0x6b, 0x49, 0xd2, 0x00, 't', 'E', 'X', 't', 'a', 'b', 'c'};
    static uint8_t stated[33 + sizeof text];
    memcpy(stated, bytes, 33), memcpy(stated + 33, text, sizeof text); /* signature, IHDR, the tEXt's start */
    char stated_path[1200]; /* a copy: work_path's string lives until its next call */
    snprintf(stated_path, sizeof stated_path, "%s", work_path("stated.png"));
    FILE *f = fopen(stated_path, "wb");
    CHECK(f && fwrite(stated, 1, sizeof stated, f) == sizeof stated);
    if (f) fclose(f);
    struct {
        const char *path;
        const uint8_t *bytes;
        size_t n;
        const char *want;
    } cases[] = {{path, bytes, n, "the PNG is damaged or cut short (libpng says: IDAT: incorrect data check)"},
                 {stated_path, stated, sizeof stated, "the PNG is damaged or cut short: chunk 'tEXt' at byte 33 "
                                                      "states 1800000000 bytes of data, and 0 bytes follow it"}};
    for (int c = 0; c < 2; c++)
        for (int memory = 0; memory < 2; memory++) {
            err_buf err = {{0}};
            image_f32 img = {0};
            stderr_begin();
            int rc = memory ? image_read_memory(cases[c].bytes, cases[c].n, "png", "embedded", &img, &err)
                            : image_read(cases[c].path, &img, &err);
            CHECK_INT(stderr_end(), 0);
            CHECK_INT(rc, -1);
            CHECK_INT(err.status, ERR_INPUT);
            CHECK_STR_CONTAINS(err.msg, memory ? "embedded" : cases[c].path);
            CHECK_STR_CONTAINS(err.msg, cases[c].want);
            CHECK(img.pixels == NULL);
        }
    remove(path);
    remove(stated_path);
}

TEST_LIST(TEST_CASE(images_beyond_the_memory_budget), TEST_CASE(cut_images_are_refused), TEST_CASE(png_rgb_round_trip), TEST_CASE(png_rgba_round_trip),
          TEST_CASE(png_grey_round_trip), TEST_CASE(overwrite_replaces_the_file),
          TEST_CASE(unreadable_files), TEST_CASE(failed_writes_leave_nothing),
          TEST_CASE(devices_and_fifos_are_refused), TEST_CASE(foreign_files_are_not_quoted),
          TEST_CASE(damaged_pngs_are_refused_quietly))
