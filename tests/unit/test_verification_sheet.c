/* test_verification_sheet.c — the photomontage's verification sheet (montage/verification_sheet.h):
 * the HTML page holds every fact with its markup escaped, the residual table and the images'
 * links; the PNG holds the two images side by side; unknown values show as a dash; a failed
 * write leaves neither file. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "harness.h"
#include "io/image_io.h"
#include "montage/verification_sheet.h"
#include "work_dir.h"

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    return buf;
}

static verification_sheet sample(uint8_t *wire, uint8_t *mont, const sheet_residual *r, uint32_t nr)
{
    for (int k = 0; k < 64 * 48; k++) {
        wire[3 * k] = 200, wire[3 * k + 1] = 30, wire[3 * k + 2] = 30;
        mont[3 * k] = 30, mont[3 * k + 1] = 60, mont[3 * k + 2] = 200;
    }
    return (verification_sheet){
        .title = "Viewpoint 3 <east road> & farm", .photo = "IMG_0042.jpg", .crs_name = "WGS 84 / UTM zone 14N",
        .viewpoint = {653400.25, 3607000.5, 231.4}, .eye_above_ground = 1.5, .heading_deg = 263, .pitch_deg = 2,
        .roll_deg = 0.1, .hfov_deg = 39.6, .vfov_deg = 22.6, .focal_mm = 50, .sensor_width_mm = 36,
        .focal35_mm = NAN, .camera_model = "Canon EOS 5D", .k1 = -0.012, .k2 = 0.001,
        .development_distance_m = 4210, .development_bearing_deg = 251.3, .date_time = "2026-06-21T14:30:00+01:00",
        .sun_azimuth_deg = 221.5, .sun_elevation_deg = 52.75, .residuals = r, .n_residuals = nr, .rmse_px = 1.25,
        .wireline = {64, 48, wire}, .montage = {64, 48, mont}, .wireline_file = "wireline.png",
        .montage_file = "montage.png"};
}

TEST(html_and_png_hold_the_facts)
{
    static uint8_t wire[64 * 48 * 3], mont[64 * 48 * 3];
    sheet_residual r[2] = {{"pylon 7", 1210.5, 644.25, 0.75, -1.5}, {"barn <SW>", 88, 901, -0.25, 0.5}};
    verification_sheet v = sample(wire, mont, r, 2);
    err_buf err = {{0}};
    char html[4096], png[4096]; /* work_path's answer lasts until its next call */
    snprintf(html, sizeof html, "%s", work_path("sheet.html"));
    snprintf(png, sizeof png, "%s", work_path("sheet.png"));
    CHECK_INT(verification_sheet_write(&v, html, png, &err), 0);
    if (err.msg[0]) fprintf(stderr, "%s\n", err.msg);
    char *t = slurp(html);
    CHECK(t != NULL);
    if (!t) return;
    CHECK_STR_CONTAINS(t, "<title>Viewpoint 3 &lt;east road&gt; &amp; farm</title>");
    CHECK_STR_CONTAINS(t, "E 653400.2  N 3607000.5  (WGS 84 / UTM zone 14N)");
    CHECK_STR_CONTAINS(t, "263.00, 2.00, 0.10 deg");
    CHECK_STR_CONTAINS(t, "39.60 deg across, 22.60 deg down");
    CHECK_STR_CONTAINS(t, "<tr><th>35 mm equivalent</th><td>-</td></tr>"); /* unknown */
    CHECK_STR_CONTAINS(t, "4210 m, bearing 251.3 deg");
    CHECK_STR_CONTAINS(t, "azimuth 221.50 deg, elevation 52.75 deg");
    CHECK_STR_CONTAINS(t, "2, RMSE 1.25 px");
    CHECK_STR_CONTAINS(t, "<td>barn &lt;SW&gt;</td><td class=\"n\">88.0</td><td class=\"n\">901.0</td>");
    CHECK_STR_CONTAINS(t, "<td class=\"n\">1.68</td>"); /* |(0.75, -1.5)| */
    CHECK_STR_CONTAINS(t, "<img src=\"wireline.png\" alt=\"wireline\"><img src=\"montage.png\"");
    image_f32 img = {0};
    CHECK_INT(image_read(png, &img, &err), 0);
    CHECK_INT(img.width, 1600);
    /* the wireline's red on the left half, the montage's blue on the right, below the facts */
    int red = 0, blue = 0;
    for (uint32_t y = 0; img.pixels && y < img.height; y++)
        for (uint32_t x = 0; x < img.width; x++) {
            const float *p = &img.pixels[((size_t)y * img.width + x) * img.channels];
            int q[3] = {(int)lroundf(p[0] * 255), (int)lroundf(p[1] * 255), (int)lroundf(p[2] * 255)};
            if (q[0] == 200 && q[1] == 30 && q[2] == 30) red += x < 800;
            if (q[0] == 30 && q[1] == 60 && q[2] == 200) blue += x > 800;
        }
    CHECK(red > 100000 && blue > 100000); /* each image about 764 x 573 pixels */
    image_free(&img);
}

TEST(a_failed_write_leaves_no_file)
{
    static uint8_t wire[64 * 48 * 3], mont[64 * 48 * 3];
    verification_sheet v = sample(wire, mont, NULL, 0);
    err_buf err = {{0}};
    char html[4096], png[4096];
    snprintf(html, sizeof html, "%s", work_path("half.html"));
    snprintf(png, sizeof png, "%s", work_path("no/such/folder/sheet.png"));
    /* the PNG's folder does not exist: the HTML must not appear either */
    CHECK_INT(verification_sheet_write(&v, html, png, &err), -1);
    struct stat st;
    CHECK(stat(html, &st) != 0);
    CHECK(err.msg[0] != 0);
}

TEST_LIST(TEST_CASE(html_and_png_hold_the_facts), TEST_CASE(a_failed_write_leaves_no_file))
