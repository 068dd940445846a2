/* imgdiff_selftest.c — runs sylva_imgdiff on small PNGs made here and checks its metrics line,
 * its exit status (0 bounds hold, 1 a bound fails, 2 error) and its heatmap. */
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include "harness.h"
#include "work_dir.h"
#include "io/image_io.h"

static char out_text[4096], err_text[4096];

static void slurp(const char *path, char *buf, size_t n)
{
    buf[0] = '\0';
    FILE *f = fopen(path, "r");
    if (!f) return;
    size_t k = fread(buf, 1, n - 1, f);
    buf[k] = '\0';
    fclose(f);
}

/* Runs the tool with args (already quoted where needed); returns its exit status. */
static int run_imgdiff(const char *args)
{
    char cmd[8192];
    snprintf(cmd, sizeof cmd, "cd '%s' && '%s' %s > out.txt 2> err.txt", work_dir(), SYLVA_IMGDIFF_PATH, args);
    int rc = system(cmd);
    slurp(work_path("out.txt"), out_text, sizeof out_text);
    slurp(work_path("err.txt"), err_text, sizeof err_text);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

/* 4x4 RGB, every value 100, except pixel (1, 2) at 151 in the test image: one pixel off by
 * 51/255 = 0.2 in all three channels. MAE 0.2*3/48 = 0.0125, RMSE sqrt(3*0.04/48) = 0.05,
 * PSNR 26.0206 dB, max 0.2, over(0.1) = 1/16. */
static void make_images(void)
{
    uint8_t ref[4 * 4 * 3], test[4 * 4 * 3], small[2 * 2 * 3];
    memset(ref, 100, sizeof ref);
    memset(test, 100, sizeof test);
    memset(small, 100, sizeof small);
    memset(test + (2 * 4 + 1) * 3, 151, 3);
    err_buf err = {{0}};
    CHECK_INT(image_write_u8(work_path("ref.png"), 4, 4, 3, ref, &err), 0);
    CHECK_INT(image_write_u8(work_path("test.png"), 4, 4, 3, test, &err), 0);
    CHECK_INT(image_write_u8(work_path("small.png"), 2, 2, 3, small, &err), 0);
}

/* Makes the work folder and images once, for whichever test runs first. */
static void ensure_images(void)
{
    static int ready;
    if (ready) return;
    ready = 1;
    make_images();
}

TEST(identical_images_pass)
{
    ensure_images();
    CHECK_INT(run_imgdiff("ref.png ref.png --max-rmse 0 --max-mae 0 --max-over 0"), 0);
    CHECK_STR_CONTAINS(out_text, "mae=0 rmse=0 psnr=inf max=0 over(0)=0 nonfinite=0");
}

TEST(metrics_line)
{
    ensure_images();
    CHECK_INT(run_imgdiff("ref.png test.png --threshold 0.1"), 0);
    double mae, rmse, psnr, max, over;
    int n = sscanf(out_text, "mae=%lf rmse=%lf psnr=%lf max=%lf over(0.1)=%lf", &mae, &rmse,
                   &psnr, &max, &over);
    CHECK_INT(n, 5);
    CHECK_NEAR(mae, 0.0125, 1e-6);
    CHECK_NEAR(rmse, 0.05, 1e-6);
    CHECK_NEAR(psnr, 26.0206, 1e-3);
    CHECK_NEAR(max, 0.2, 1e-6);
    CHECK_NEAR(over, 0.0625, 1e-9);
}

TEST(bounds_decide_exit_status)
{
    ensure_images();
    CHECK_INT(run_imgdiff("ref.png test.png --max-rmse 0.06 --max-mae 0.013"), 0);
    CHECK_INT(run_imgdiff("ref.png test.png --max-rmse 0.04"), 1);
    CHECK_STR_CONTAINS(err_text, "rmse 0.05 exceeds --max-rmse 0.04");
    CHECK_INT(run_imgdiff("ref.png test.png --max-mae 0.01"), 1);
    CHECK_STR_CONTAINS(err_text, "mae 0.0125 exceeds --max-mae 0.01");
    CHECK_INT(run_imgdiff("ref.png test.png --threshold 0.1 --max-over 0.07"), 0);
    CHECK_INT(run_imgdiff("ref.png test.png --threshold 0.1 --max-over 0.05"), 1);
    CHECK_STR_CONTAINS(err_text, "over(0.1) 0.0625 exceeds --max-over 0.05");
    CHECK_INT(run_imgdiff("ref.png test.png --threshold 0.3 --max-over 0"), 0);
}

TEST(errors_exit_2)
{
    ensure_images();
    CHECK_INT(run_imgdiff("ref.png small.png"), 2);
    CHECK_STR_CONTAINS(err_text, "image sizes differ: the reference is 4x4, the test image 2x2");
    CHECK_INT(run_imgdiff("ref.png missing.png"), 2);
    CHECK_STR_CONTAINS(err_text, "missing.png");
    CHECK_INT(run_imgdiff("ref.png test.png --max-rmse lots"), 2);
    CHECK_STR_CONTAINS(err_text, "--max-rmse needs a finite number >= 0");
    CHECK_INT(run_imgdiff("ref.png"), 2);
    CHECK_INT(run_imgdiff("ref.png test.png --colour"), 2);
    CHECK_STR_CONTAINS(err_text, "unknown option --colour");
}

TEST(diff_heatmap)
{
    ensure_images();
    CHECK_INT(run_imgdiff("ref.png test.png --max-rmse 0.01 --diff heat.png --diff-scale 0.1"), 1);
    image_f32 heat = {0};
    err_buf err = {{0}};
    CHECK_INT(image_read(work_path("heat.png"), &heat, &err), 0);
    if (heat.pixels) {
        CHECK_INT(heat.width, 4);
        CHECK_INT(heat.channels, 3);
        for (uint32_t i = 0; i < 16; i++) {
            float want = i == 2 * 4 + 1 ? 1.0f : 0.0f; /* saturated white, else black */
            for (int c = 0; c < 3; c++) CHECK_NEAR(heat.pixels[3 * i + c], want, 0.0);
        }
    }
    image_free(&heat);
}

TEST_LIST(TEST_CASE(identical_images_pass), TEST_CASE(metrics_line),
          TEST_CASE(bounds_decide_exit_status), TEST_CASE(errors_exit_2),
          TEST_CASE(diff_heatmap))
