/* test_photo.c — photographs read as plates: the EXIF of the real photographs of the shared data
 * set (photos/README.md) against what exiftool reports for the same files, the sensor width each
 * gives against the camera's known pixel pitch, 8- and 16-bit PNGs written here read back in
 * linear light, the eight EXIF orientations (and a TIFF tagged with one), the memory check and
 * the errors for files that are not photographs or are damaged. Without the shared data (or exiftool, or
 * oiiotool) those parts report themselves skipped. */
#include <stdint.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "cut_image.h"
#include "damaged_png.h"
#include "harness.h"
#include "work_dir.h"
#include "io/image_io.h"
#include "io/photo.h"
#include "util/srgb.h"

#define PHOTOS SYLVA_SHARED_DATA_DIR "/photos/"

static int photos_present(void)
{
    struct stat st;
    return stat(PHOTOS "README.md", &st) == 0;
}

/* exiftool's JSON for the file (the tags the record holds), or "" when exiftool cannot run. */
static void exiftool_json(const char *path, char *out, size_t n)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd,
             "exiftool -n -json -Make -Model -LensModel -FocalLength -FocalLengthIn35mmFormat "
             "-GPSLatitude -GPSLongitude -GPSAltitude -GPSAltitudeRef -GPSImgDirection "
             "-GPSImgDirectionRef -DateTimeOriginal -OffsetTimeOriginal '%s' 2>/dev/null", path);
    out[0] = 0;
    FILE *f = popen(cmd, "r");
    if (!f) return;
    size_t len = fread(out, 1, n - 1, f);
    out[len] = 0;
    if (pclose(f) != 0) out[0] = 0;
}

/* The value of "key": in exiftool's one-object JSON: a number into *v (returns 1), a string
 * into s (returns 2), absent 0. */
static int json_field(const char *json, const char *key, double *v, char *s, size_t n)
{
    char pattern[128];
    snprintf(pattern, sizeof pattern, "\"%s\": ", key);
    const char *at = strstr(json, pattern);
    if (!at) return 0;
    at += strlen(pattern);
    if (*at == '"') {
        const char *end = strchr(at + 1, '"');
        size_t len = end ? (size_t)(end - at - 1) : 0;
        if (len >= n) len = n - 1;
        memcpy(s, at + 1, len);
        s[len] = 0;
        return 2;
    }
    *v = strtod(at, NULL);
    return 1;
}

static void check_number(const char *json, const char *key, int has, double got, double tol)
{
    double want = 0;
    char s[8];
    int present = json_field(json, key, &want, s, sizeof s) == 1;
    CHECK_INT(has, present);
    if (present && has) {
        if (fabs(got - want) > tol) fprintf(stderr, "%s:\n", key);
        CHECK_NEAR(got, want, tol);
    }
}

static void check_text(const char *json, const char *key, int has, const char *got)
{
    char want[256];
    double v;
    int present = json_field(json, key, &v, want, sizeof want) == 2;
    CHECK_INT(has, present);
    if (present && has && strcmp(got, want)) {
        fprintf(stderr, "%s: got \"%s\", exiftool says \"%s\"\n", key, got, want);
        CHECK(0);
    }
}

static int read_photo(const char *rel, photo *p)
{
    char path[1024];
    snprintf(path, sizeof path, "%s%s", PHOTOS, rel);
    err_buf err = {{0}};
    int rc = photo_read(path, p, &err);
    CHECK_INT(rc, 0);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    return rc;
}

static const char *const real_photos[] = {"lychee/hochuferweg.jpg", "lychee/train.jpg",
                                          "lychee/undefined-exif-tag.jpg",
                                          "imgraft-engabreen/IMG_8902.jpg"};

/* Every field the record holds agrees with exiftool -n for each real photograph, present where
 * exiftool finds the tag and absent where it does not. */
TEST(exif_matches_exiftool)
{
    if (!photos_present()) SKIP("no shared photographs at %s", PHOTOS);
    if (system("exiftool -ver >/dev/null 2>&1") != 0) SKIP("exiftool is not installed");
    for (size_t i = 0; i < sizeof real_photos / sizeof real_photos[0]; i++) {
        photo p;
        if (read_photo(real_photos[i], &p)) continue;
        char path[1024], json[8192];
        snprintf(path, sizeof path, "%s%s", PHOTOS, real_photos[i]);
        exiftool_json(path, json, sizeof json);
        CHECK(json[0] != 0);
        fprintf(stderr, "%s\n", real_photos[i]);
        const photo_exif *x = &p.exif;
        check_text(json, "Make", x->has_make, x->make);
        check_text(json, "Model", x->has_model, x->model);
        check_text(json, "LensModel", x->has_lens_model, x->lens_model);
        check_number(json, "FocalLength", x->has_focal_length, x->focal_length_mm, 1e-6);
        check_number(json, "FocalLengthIn35mmFormat", x->has_focal_length_35mm,
                     x->focal_length_35mm, 1e-6);
        check_number(json, "GPSLatitude", x->has_gps_position, x->latitude_deg, 1e-7);
        check_number(json, "GPSLongitude", x->has_gps_position, x->longitude_deg, 1e-7);
        check_number(json, "GPSAltitude", x->has_gps_altitude, fabs(x->altitude_m), 1e-4);
        check_number(json, "GPSImgDirection", x->has_gps_direction, x->direction_deg, 1e-4);
        char ref[8];
        double v;
        if (json_field(json, "GPSImgDirectionRef", &v, ref, sizeof ref) == 2)
            CHECK_INT(x->direction_true, ref[0] == 'T');
        char date[32] = "";
        if (x->has_date_time)
            snprintf(date, sizeof date, "%04d:%02d:%02d %02d:%02d:%02d", x->year, x->month, x->day,
                     x->hour, x->minute, x->second);
        check_text(json, "DateTimeOriginal", x->has_date_time, date);
        char offset[16] = "";
        if (x->has_utc_offset)
            snprintf(offset, sizeof offset, "%c%02d:%02d", x->utc_offset_min < 0 ? '-' : '+',
                     abs(x->utc_offset_min) / 60, abs(x->utc_offset_min) % 60);
        check_text(json, "OffsetTimeOriginal", x->has_utc_offset, offset);
        photo_free(&p);
    }
}

/* The values the README lists, so the test fails if both readers drift together. */
TEST(exif_known_values)
{
    if (!photos_present()) SKIP("no shared photographs at %s", PHOTOS);
    photo p;
    if (read_photo("lychee/train.jpg", &p)) return;
    CHECK_INT(p.width, 4032);
    CHECK_INT(p.height, 3024);
    CHECK_NEAR(p.exif.latitude_deg, 52.209678, 1e-6);
    CHECK_NEAR(p.exif.longitude_deg, -0.895531, 1e-6); /* West: negative */
    CHECK_NEAR(p.exif.altitude_m, 103.64, 0.01);
    CHECK_NEAR(p.exif.direction_deg, 109.81, 0.01);
    CHECK_INT(p.exif.direction_true, 1);
    CHECK_INT(p.exif.utc_offset_min, 60);
    CHECK_INT(p.exif.hour, 11);
    char when[32];
    CHECK_INT(photo_exif_iso8601(&p.exif, when), 0);
    CHECK(!strcmp(when, "2021-04-10T11:44:00+01:00"));
    /* the plate is linear: a mid-grey JPEG sample of 0.5 would be 0.214 */
    double sum = 0;
    for (size_t i = 0; i < (size_t)p.width * p.height * 3; i++) sum += p.rgb[i];
    double mean = sum / ((double)p.width * p.height * 3);
    CHECK(mean > 0.0 && mean < 1.0);
    photo_free(&p);
    if (read_photo("lychee/undefined-exif-tag.jpg", &p)) return;
    CHECK_INT(p.exif.has_date_time, 1); /* stored in IFD0 only by this camera's software */
    CHECK_INT(photo_exif_iso8601(&p.exif, when), -1); /* no OffsetTimeOriginal */
    CHECK(when[0] == 0);
    CHECK_INT(p.exif.year, 2022);
    CHECK_INT(p.exif.has_gps_position, 0);
    CHECK_INT(p.exif.has_focal_plane, 1);
    CHECK_INT(p.exif.focal_plane_unit, 2);
    photo_free(&p);
}

/* The sensor width from each photograph against the camera's known sensor: the Nexus 5X's
 * 1.55 um pixels (Sony IMX377) and the iPhone 6s's 1.22 um pixels over 4032 columns, the Canon
 * EOS 100D's 22.3 mm sensor (5184 columns; this copy was cropped to 3059 columns, so the plate
 * covers 3059/5184 of it). The Engabreen photograph has neither tag: the caller gives it. */
TEST(sensor_width)
{
    if (!photos_present()) SKIP("no shared photographs at %s", PHOTOS);
    photo p;
    double w;
    if (!read_photo("lychee/hochuferweg.jpg", &p)) {
        CHECK_INT(photo_sensor_width(&p, &w), PHOTO_SENSOR_35MM);
        fprintf(stderr, "Nexus 5X: %.3f mm (pixels: %.3f mm)\n", w, 4032 * 1.55e-3);
        CHECK_NEAR(w, 4032 * 1.55e-3, 0.06);
        photo_free(&p);
    }
    if (!read_photo("lychee/train.jpg", &p)) {
        CHECK_INT(photo_sensor_width(&p, &w), PHOTO_SENSOR_35MM);
        fprintf(stderr, "iPhone 6s: %.3f mm (pixels: %.3f mm)\n", w, 4032 * 1.22e-3);
        CHECK_NEAR(w, 4032 * 1.22e-3, 0.06);
        photo_free(&p);
    }
    if (!read_photo("lychee/undefined-exif-tag.jpg", &p)) {
        CHECK_INT(photo_sensor_width(&p, &w), PHOTO_SENSOR_FOCAL_PLANE);
        fprintf(stderr, "EOS 100D: %.3f mm for 3059 columns, %.3f mm for the full 5184\n", w,
                w * 5184 / 3059);
        CHECK_NEAR(w, 3059 / 5798.657718 * 25.4, 0.001);
        CHECK_NEAR(w * 5184 / 3059, 22.3, 0.5);
        photo_free(&p);
    }
    if (!read_photo("imgraft-engabreen/IMG_8902.jpg", &p)) {
        CHECK_INT(photo_sensor_width(&p, &w), PHOTO_SENSOR_UNKNOWN);
        CHECK_NEAR(w, 0.0, 0.0);
        CHECK_STR_CONTAINS(photo_sensor_source_name(PHOTO_SENSOR_UNKNOWN), "give the sensor width");
        photo_free(&p);
    }
}

/* A PNG written here comes back decoded from sRGB: 0 -> 0, 10 -> 0.003035, 128 -> 0.215861,
 * 255 -> 1 (IEC 61966-2-1); grey becomes three equal channels. */
TEST(png_round_trip_linear)
{
    const uint8_t rgb[2 * 2 * 3] = {0, 10, 128, 255, 0, 10, 128, 255, 0, 10, 10, 10};
    char path[1200];
    snprintf(path, sizeof path, "%s/plate.png", work_dir());
    err_buf err = {{0}};
    CHECK_INT(image_write_u8(path, 2, 2, 3, rgb, &err), 0);
    photo p;
    CHECK_INT(photo_read(path, &p, &err), 0);
    CHECK_INT(p.width, 2);
    CHECK_INT(p.height, 2);
    CHECK_INT(p.bits, 8);
    const double want[4] = {0.0, 0.0030353, 0.2158605, 1.0};
    const int code[256] = {[0] = 0, [10] = 1, [128] = 2, [255] = 3};
    for (int i = 0; i < 12; i++) CHECK_NEAR(p.rgb[i], want[code[rgb[i]]], 2e-6);
    CHECK_INT(p.exif.has_make, 0);
    CHECK_INT(p.exif.has_gps_position, 0);
    CHECK_INT(p.exif.orientation, 1);
    double w;
    CHECK_INT(photo_sensor_width(&p, &w), PHOTO_SENSOR_UNKNOWN);
    photo_free(&p);

    const uint8_t grey[3] = {0, 128, 255};
    CHECK_INT(image_write_u8(path, 3, 1, 1, grey, &err), 0);
    CHECK_INT(photo_read(path, &p, &err), 0);
    for (int x = 0; x < 3; x++)
        for (int k = 0; k < 3; k++) CHECK_NEAR(p.rgb[x * 3 + k], want[code[grey[x]]], 2e-6);
    photo_free(&p);
}

/* The capture instant in the form sun: date_time takes, west of Greenwich too. */
TEST(exif_instant)
{
    photo_exif x = {.has_date_time = 1, .year = 2026, .month = 6, .day = 21, .hour = 9,
                    .minute = 5, .second = 7, .has_utc_offset = 1, .utc_offset_min = -330};
    char when[32];
    CHECK_INT(photo_exif_iso8601(&x, when), 0);
    CHECK(!strcmp(when, "2026-06-21T09:05:07-05:30"));
    x.has_utc_offset = 0;
    CHECK_INT(photo_exif_iso8601(&x, when), -1);
}

/* The eight EXIF orientations on a 3x2 image holding its own indices. */
TEST(orientations)
{
    const float src[6] = {0, 1, 2, 3, 4, 5};
    const float want[8][6] = {
        {0, 1, 2, 3, 4, 5}, {2, 1, 0, 5, 4, 3}, {5, 4, 3, 2, 1, 0}, {3, 4, 5, 0, 1, 2},
        {0, 3, 1, 4, 2, 5}, {3, 0, 4, 1, 5, 2}, {5, 2, 4, 1, 3, 0}, {2, 5, 1, 4, 0, 3},
    };
    for (int o = 1; o <= 8; o++) {
        float dst[6] = {-1, -1, -1, -1, -1, -1};
        photo_orient(src, 3, 2, 1, o, dst);
        for (int i = 0; i < 6; i++)
            if (dst[i] != want[o - 1][i]) {
                fprintf(stderr, "orientation %d, index %d: %g, expected %g\n", o, i, dst[i],
                        want[o - 1][i]);
                CHECK(0);
            }
    }
}

/* Writes w x h 8-bit RGB as a PNG in the work folder, converts it with `oiiotool PNG ARGS -o
 * NAME` and reads NAME as a photo; 0, or -1 after a failed check. */
static int read_converted(const uint8_t *rgb, uint32_t w, uint32_t h, const char *args,
                          const char *name, photo *p)
{
    char png[1200], out[1200], cmd[2600];
    snprintf(png, sizeof png, "%s/source.png", work_dir());
    snprintf(out, sizeof out, "%s/%s", work_dir(), name);
    err_buf err = {{0}};
    CHECK_INT(image_write_u8(png, w, h, 3, rgb, &err), 0);
    snprintf(cmd, sizeof cmd, "oiiotool '%s' %s -o '%s'", png, args, out);
    int rc = system(cmd);
    CHECK_INT(rc, 0);
    if (rc || photo_read(out, p, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        CHECK(0);
        return -1;
    }
    return 0;
}

/* A TIFF tagged Orientation 6 (taken with the camera turned a quarter clockwise; the tag written
 * by oiiotool, which installs with OpenImageIO) is read upright: 2 wide, 3 high, the stored left
 * column along the top. */
TEST(orientation_tag_honoured)
{
    if (system("oiiotool --version >/dev/null 2>&1") != 0) SKIP("oiiotool is not installed");
    const uint8_t level[6] = {0, 50, 100, 150, 200, 255};
    uint8_t rgb[18];
    for (int i = 0; i < 18; i++) rgb[i] = level[i / 3];
    photo p;
    if (read_converted(rgb, 3, 2, "--orientation 6", "turned.tif", &p)) return;
    CHECK_INT(p.exif.orientation, 6);
    CHECK_INT(p.width, 2);
    CHECK_INT(p.height, 3);
    CHECK_INT(p.stored_width, 3);
    const int want[6] = {3, 0, 4, 1, 5, 2};
    for (int i = 0; i < 6; i++)
        CHECK_NEAR(p.rgb[i * 3 + 1], srgb_to_linear(level[want[i]] / 255.0f), 1e-6);
    photo_free(&p);
}

/* A 16-bit PNG (converted by oiiotool from an 8-bit one: v becomes v x 257) is decoded with the
 * same sRGB curve, to the same linear values. */
TEST(sixteen_bit_png)
{
    if (system("oiiotool --version >/dev/null 2>&1") != 0) SKIP("oiiotool is not installed");
    const uint8_t rgb[6] = {0, 10, 64, 128, 200, 255};
    photo p;
    if (read_converted(rgb, 2, 1, "-d uint16", "sixteen.png", &p)) return;
    CHECK_INT(p.bits, 16);
    for (int i = 0; i < 6; i++) CHECK_NEAR(p.rgb[i], srgb_to_linear(rgb[i] / 255.0f), 1e-6);
    photo_free(&p);
}

/* A photograph larger than the memory budget is refused before its pixels are allocated. */
TEST(memory_budget)
{
    const uint8_t rgb[64 * 64 * 3] = {0};
    char path[1200];
    snprintf(path, sizeof path, "%s/big.png", work_dir());
    err_buf err = {{0}};
    CHECK_INT(image_write_u8(path, 64, 64, 3, rgb, &err), 0);
    setenv("SYLVA_MEMORY_LIMIT", "16K", 1);
    photo p = {0};
    CHECK_INT(photo_read(path, &p, &err), -1);
    unsetenv("SYLVA_MEMORY_LIMIT");
    CHECK_STR_CONTAINS(err.msg, "reading the photograph");
    CHECK_STR_CONTAINS(err.msg, "SYLVA_MEMORY_LIMIT");
    CHECK_INT(err.status, ERR_LIMIT);
    CHECK(p.rgb == NULL);
}

TEST(errors_name_the_file)
{
    char path[1200];
    err_buf err = {{0}};
    photo p = {0};
    snprintf(path, sizeof path, "%s/missing.jpg", work_dir());
    CHECK_INT(photo_read(path, &p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, path);
    /* notes, then a JPEG's signature and nothing of one after it (the JPEG reader's own reason) */
    const char *texts[2] = {"these are notes, not a photograph\n", "\xff\xd8\xff and then notes"};
    const char *reasons[2] = {"a JPEG, PNG or TIFF file is expected", "OpenImageIO says"};
    for (int i = 0; i < 2; i++) {
        const char *notes = work_file("notes.jpg", texts[i]);
        err_clear(&err);
        CHECK_INT(photo_read(notes, &p, &err), -1);
        CHECK_STR_CONTAINS(err.msg, notes);
        CHECK_STR_CONTAINS(err.msg, reasons[i]);
        fprintf(stderr, "%s\n", err.msg);
        CHECK_INT(err.status, ERR_INPUT);
    }
    err_clear(&err);
    CHECK_INT(photo_read(work_dir(), &p, &err), -1); /* a folder */
    CHECK_STR_CONTAINS(err.msg, work_dir());
}

/* A photograph cut short is refused, not read with its missing part filled in grey (libjpeg and
 * libtiff go on past the end and only note it): the file named, and what is wrong. */
TEST(cut_photographs_are_refused)
{
    const char *names[] = {"cut.jpg", "cut.tif", "cut.png"};
    for (int i = 0; i < 3; i++) {
        const char *path = cut_image_write(names[i], 0.6);
        err_buf err = {{0}};
        photo p = {0};
        CHECK_INT(photo_read(path, &p, &err), -1);
        fprintf(stderr, "%s\n", err.msg);
        CHECK_STR_CONTAINS(err.msg, path);
        CHECK_INT(err.status, ERR_INPUT);
        CHECK(p.rgb == NULL);
        if (i < 2) CHECK_STR_CONTAINS(err.msg, "damaged or cut short");
    }
    /* the whole file reads */
    const char *whole = cut_image_write("whole.jpg", 1.0);
    err_buf err = {{0}};
    photo p = {0};
    CHECK_INT(photo_read(whole, &p, &err), 0);
    photo_free(&p);
}

/* Writes a black w x h RGB image to the work folder as `name` (its format from the extension),
 * its path into path (size 1200) and its bytes into bytes (at most cap); returns their count, 0
 * when the image could not be written or read back. */
static size_t small_image_bytes(const char *name, int w, int h, char *path, unsigned char *bytes, size_t cap)
{
    uint8_t rgb[3 * 8 * 8] = {0};
    snprintf(path, 1200, "%s/%s", work_dir(), name);
    err_buf err = {{0}};
    if (w * h > 64 || image_write_u8(path, (uint32_t)w, (uint32_t)h, 3, rgb, &err)) return 0;
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(bytes, 1, cap, f) : 0;
    if (f) fclose(f);
    return n;
}

/* A PNG chunk that states more data than the file holds (libpng allocated all of it, up to
 * 2 GiB, before finding the file's end) is refused before the file is decoded. */
TEST(damaged_png_chunk)
{
    char path[1200];
    unsigned char bytes[4096];
    size_t n = small_image_bytes("damaged.png", 3, 2, path, bytes, sizeof bytes);
    err_buf err = {{0}};
    CHECK(n > 33 && n < sizeof bytes - 32);
    /* after the signature (8) and IHDR (25): a tEXt chunk stating 0x70000000 bytes */
    static const unsigned char text[] = {0x70, 0, 0, 0, 't', 'E', 'X', 't', 'S', 'o', 'f', 't', 0, 'x'};
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return;
    fwrite(bytes, 1, 33, f), fwrite(text, 1, sizeof text, f), fwrite(bytes + 33, 1, n - 33, f);
    fclose(f);
    photo p = {0};
    err_clear(&err);
    CHECK_INT(photo_read(path, &p, &err), -1);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "chunk 'tEXt' at byte 33 states 1879048192 bytes of data");
    CHECK_INT(err.status, ERR_INPUT);
    CHECK(p.rgb == NULL);
}

/* A JPEG whose frame states 65285 x 59651 pixels is refused by the memory budget before it is
 * opened: OpenImageIO's reader starts libjpeg's decompression on opening, and libjpeg allocated
 * 11 GB for such a frame in a file of 753 bytes. */
TEST(huge_jpeg_frame)
{
    char path[1200];
    unsigned char bytes[8192];
    size_t n = small_image_bytes("huge.jpg", 8, 8, path, bytes, sizeof bytes);
    err_buf err = {{0}};
    CHECK(n > 20 && n < sizeof bytes);
    size_t sof = 0;
    for (size_t i = 2; i + 9 < n && !sof; i++)
        if (bytes[i] == 0xFF && (bytes[i + 1] == 0xC0 || bytes[i + 1] == 0xC2)) sof = i;
    CHECK(sof > 0);
    if (!sof) return;
    bytes[sof + 5] = 0xE9, bytes[sof + 6] = 0x03; /* height 59651 */
    bytes[sof + 7] = 0xFF, bytes[sof + 8] = 0x05; /* width 65285 */
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return;
    fwrite(bytes, 1, n, f);
    fclose(f);
    photo p = {0};
    err_clear(&err);
    double t0 = harness_seconds();
    CHECK_INT(photo_read(path, &p, &err), -1);
    CHECK(harness_seconds() - t0 < 2.0);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "(65285x59651, as its JPEG frame states)");
    CHECK_INT(err.status, ERR_LIMIT);
    CHECK(p.rgb == NULL);
}

/* The fuzzer's JPEG: a segment whose length falls short of its data leaves a stray byte before
 * the next marker, which libjpeg skips with a warning and then decodes the 65285 x 59651 frame
 * behind it; the frame is found the same way and refused. */
TEST(huge_jpeg_frame_behind_stray_bytes)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/fuzz/regressions/photo/jpeg_frame_65285x59651.jpg", SYLVA_TEST_DATA_DIR);
    err_buf err = {{0}};
    photo p = {0};
    /* the image module is opened by the first image read (io/image_io.c), not on this clock */
    photo_read(SYLVA_TEST_DATA_DIR "/image/plain_photo.png", &p, &err);
    photo_free(&p);
    err_clear(&err);
    double t0 = harness_seconds();
    CHECK_INT(photo_read(path, &p, &err), -1);
    CHECK(harness_seconds() - t0 < 2.0);
    CHECK_STR_CONTAINS(err.msg, "(65285x59651, as its JPEG frame states)");
    CHECK_INT(err.status, ERR_LIMIT);
    photo_free(&p);
}

/* A PNG photograph whose pixels are damaged (its zlib checksum) is refused in sylva's sentence
 * alone: libpng printed "libpng error: IDAT: incorrect data check" on stderr under OpenImageIO. */
TEST(damaged_png_refused_quietly)
{
    static uint8_t bytes[64 * 1024];
    const char *path = NULL;
    if (!damaged_png_write("damaged_pixels.png", bytes, sizeof bytes, &path)) return;
    err_buf err = {{0}};
    photo p = {0};
    stderr_begin();
    int rc = photo_read(path, &p, &err);
    CHECK_INT(stderr_end(), 0);
    CHECK_INT(rc, -1);
    CHECK_INT(err.status, ERR_INPUT);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "the PNG is damaged or cut short (libpng says: IDAT: incorrect data check)");
    CHECK(p.rgb == NULL);
}

/* A PNG that ends before its IEND chunk, whether in a chunk's header or just after a whole
 * chunk, is refused as cut short before it is decoded. */
TEST(png_without_its_end)
{
    const uint8_t rgb[3 * 2 * 3] = {0};
    char path[1200];
    snprintf(path, sizeof path, "%s/ended.png", work_dir());
    err_buf err = {{0}};
    CHECK_INT(image_write_u8(path, 3, 2, 3, rgb, &err), 0);
    const long keep[] = {10, 33}; /* two bytes of IHDR's header; the signature and all of IHDR */
    for (int i = 0; i < 2; i++) {
        CHECK_INT(truncate(path, keep[i]), 0);
        photo p = {0};
        err_clear(&err);
        CHECK_INT(photo_read(path, &p, &err), -1);
        fprintf(stderr, "%s\n", err.msg);
        CHECK_STR_CONTAINS(err.msg, path);
        char want[80];
        snprintf(want, sizeof want, "cut short: it ends at byte %ld without its 'IEND' chunk", keep[i]);
        CHECK_STR_CONTAINS(err.msg, want);
        CHECK_INT(err.status, ERR_INPUT);
        CHECK(p.rgb == NULL);
    }
}

TEST_LIST(TEST_CASE(cut_photographs_are_refused), TEST_CASE(exif_matches_exiftool), TEST_CASE(exif_known_values), TEST_CASE(sensor_width),
          TEST_CASE(png_round_trip_linear), TEST_CASE(exif_instant), TEST_CASE(orientations),
          TEST_CASE(orientation_tag_honoured), TEST_CASE(sixteen_bit_png), TEST_CASE(memory_budget),
          TEST_CASE(errors_name_the_file), TEST_CASE(damaged_png_chunk),
          TEST_CASE(png_without_its_end), TEST_CASE(damaged_png_refused_quietly), TEST_CASE(huge_jpeg_frame), TEST_CASE(huge_jpeg_frame_behind_stray_bytes))
