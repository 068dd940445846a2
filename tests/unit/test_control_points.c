/* test_control_points.c — control-point files (montage/control_points.h): CSV with map or local
 * columns, ImGRAFT's whitespace text with '%' comments and U/V written as sums, each malformed
 * input refused at its file:line:column, and the real Engabreen survey (28 points; skipped
 * without the shared data set). */
#include <sys/stat.h>

#include "harness.h"
#include "work_dir.h"
#include "montage/control_points.h"
#include "util/rng.h"

#define ENGABREEN SYLVA_SHARED_DATA_DIR "/photos/imgraft-engabreen/gcp8902.txt"

/* text written to the work folder under name; the path (static until the next call). */
static const char *write_file(const char *name, const char *text)
{
    static char path[1200];
    snprintf(path, sizeof path, "%s/%s", work_dir(), name);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) fputs(text, f), fclose(f);
    return path;
}

TEST(csv_map_columns)
{
    const char *path = write_file("map.csv", "# a survey\n"
                                             "id, u, v, easting, northing, height\n"
                                             "pylon foot, 1020.5, 880.25, 445562, 7395662, 596.4\n"
                                             "\n"
                                             "\"summit\",12,34.5,445620.5,7395161,898.2\r\n");
    err_buf err = {{0}};
    control_points *cp = control_points_read(path, "map.csv", &err);
    if (!cp) fprintf(stderr, "%s\n", err.msg);
    CHECK(cp != NULL);
    if (!cp) return;
    CHECK_INT(cp->n, 2);
    CHECK_INT(cp->map, 1);
    CHECK(!strcmp(cp->points[0].id, "pylon foot"));
    CHECK(!strcmp(cp->points[1].id, "summit"));
    CHECK_NEAR(cp->points[0].pixel[0], 1020.5, 0);
    CHECK_NEAR(cp->points[0].pixel[1], 880.25, 0);
    CHECK_NEAR(cp->points[0].world[0], 445562, 0);
    CHECK_NEAR(cp->points[1].world[2], 898.2, 0);
    CHECK_INT(cp->points[1].line, 5);
    control_points_free(cp);
}

/* A spreadsheet's CSV starts with a UTF-8 byte-order mark: read as if it had none. */
TEST(csv_with_byte_order_mark)
{
    const char *path = write_file("bom.csv", "\xef\xbb\xbfu,v,x,y,z\n1,2,3,4,5\n");
    err_buf err = {{0}};
    control_points *cp = control_points_read(path, NULL, &err);
    if (!cp) fprintf(stderr, "%s\n", err.msg);
    CHECK(cp != NULL);
    if (!cp) return;
    CHECK_INT(cp->n, 1);
    CHECK_NEAR(cp->points[0].pixel[0], 1, 0);
    control_points_free(cp);
}

TEST(csv_local_columns_any_order_without_id)
{
    const char *path = write_file("local.csv", "x,y,z,v,u\n1,2,3,40,50\n-1.5e2,2,0.5,4,5\n");
    err_buf err = {{0}};
    control_points *cp = control_points_read(path, NULL, &err);
    CHECK(cp != NULL);
    if (!cp) return;
    CHECK_INT(cp->n, 2);
    CHECK_INT(cp->map, 0);
    CHECK(!strcmp(cp->points[1].id, "2"));
    CHECK_NEAR(cp->points[0].pixel[0], 50, 0);
    CHECK_NEAR(cp->points[0].pixel[1], 40, 0);
    CHECK_NEAR(cp->points[1].world[0], -150, 0);
    control_points_free(cp);
}

TEST(imgraft_text)
{
    const char *path = write_file("gcp.txt", "% X,Y,Z    U,V\n"
                                             "    445562 7395662 596.4 1951+9 1490+4 % first, with a comma\n"
                                             "445359.2\t7396092.5 519.2  3851 1889 % a comment\n"
                                             "1 2 3 100-0.5+2 7e1 % X, Y, Z, U, V\n");
    err_buf err = {{0}};
    control_points *cp = control_points_read(path, NULL, &err);
    if (!cp) fprintf(stderr, "%s\n", err.msg);
    CHECK(cp != NULL);
    if (!cp) return;
    CHECK_INT(cp->n, 3);
    CHECK_INT(cp->map, 1);
    /* ImGRAFT's pixel (1, 1) is the centre of the top-left pixel: sylva's (0.5, 0.5) */
    CHECK_NEAR(cp->points[0].pixel[0], 1960 - 0.5, 0);
    CHECK_NEAR(cp->points[0].pixel[1], 1494 - 0.5, 0);
    CHECK_NEAR(cp->points[1].world[1], 7396092.5, 0);
    CHECK_NEAR(cp->points[1].pixel[0], 3850.5, 0);
    CHECK_NEAR(cp->points[2].pixel[0], 101.5 - 0.5, 1e-12);
    CHECK_NEAR(cp->points[2].pixel[1], 69.5, 0);
    CHECK(!strcmp(cp->points[2].id, "3"));
    CHECK_INT(cp->points[2].line, 4);
    control_points_free(cp);
}

/* The file `text` is refused with a message holding `where` (file:line:column) and `what`. */
static void refused(const char *text, const char *where, const char *what)
{
    const char *path = write_file("bad.txt", text);
    err_buf err = {{0}};
    control_points *cp = control_points_read(path, "bad.txt", &err);
    CHECK(cp == NULL);
    control_points_free(cp);
    CHECK_STR_CONTAINS(err.msg, where);
    CHECK_STR_CONTAINS(err.msg, what);
    CHECK_INT(err.status, ERR_INPUT);
}

TEST(malformed_files_refused_where_they_are_wrong)
{
    refused("", "bad.txt:1:1:", "no control points");
    refused("% only a comment\n\n", "bad.txt:2:1:", "no control points");
    refused("id,u,v,easting,northing,height\n", "bad.txt:1:1:", "no control points");
    refused("1 2 3 1951*9 4\n", "bad.txt:1:7:", "'U' must be a finite number (or numbers joined by + and -");
    refused("1 2 3 4 5+\n", "bad.txt:1:9:", "'V' must be a finite number");
    refused("1 2 3 4 0x10\n", "bad.txt:1:9:", "got '0x10'");
    refused("1 2 3 4 nan\n", "bad.txt:1:9:", "got 'nan'");
    refused("1 2 3 4 1e999\n", "bad.txt:1:9:", "finite");
    refused("1 2 3+1 4 5\n", "bad.txt:1:5:", "'Z' must be a finite number, got '3+1'");
    refused("% X Y Z U V\n1 2 3 4\n", "bad.txt:2:1:", "4 columns; a line holds 5");
    refused("1 2 3 4 5 6\n", "bad.txt:1:11:", "more than 5 columns");
    refused("id,u,v,easting,northing\n", "bad.txt:1:1:", "the first line must name the columns");
    refused("u,v,x,y,z,height\n", "bad.txt:1:1:", "the first line must name the columns");
    refused("u,v,x,y,z,colour\n", "bad.txt:1:11:", "unknown column 'colour'");
    refused("u,v,x,y,z,u\n", "bad.txt:1:11:", "column 'u' appears twice");
    refused("u,v,x,y,z\n1,2,3,4\n", "bad.txt:2:1:", "4 fields, but the first line names 5 columns");
    refused("u,v,x,y,z\n1,2,3,4,5+1\n", "bad.txt:2:9:", "'z' must be a finite number, got '5+1'");
    refused("id,u,v,x,y,z\n,1,2,3,4,5\n", "bad.txt:2:1:", "'id' is empty");
    refused("id,u,v,x,y,z\n\"p1,1,2,3,4,5\n", "bad.txt:2:1:", "opens a double quote that is not closed");
    refused("id,u,v,x,y,z\np1,1, \"2,3,4,5\n", "bad.txt:2:7:", "opens a double quote that is not closed");
    err_buf err = {{0}};
    CHECK(control_points_read(work_dir(), "a folder", &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "a folder");
    err_clear(&err);
    CHECK(control_points_read("/nonexistent/gcp.txt", NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "/nonexistent/gcp.txt");
}

TEST(nul_byte_refused)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/nul.txt", work_dir());
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return;
    fwrite("1 2 3 4 5\n\0\n", 1, 12, f);
    fclose(f);
    err_buf err = {{0}};
    CHECK(control_points_read(path, "nul.txt", &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "nul.txt:1:1: the file holds a NUL byte");
}

TEST(random_text_read_or_refused)
{
    /* texts of the characters the formats use, in random order: each is read or refused with a
     * located message, never a crash (the ASan build checks the memory) */
    static const char alphabet[] = "0123456789+-.,% \t\n\re#\"xyzuvid";
    char text[400];
    int read = 0;
    for (int t = 0; t < 2000; t++) {
        sylva_rng r;
        rng_stream(&r, 15, "control point text", (uint64_t)t);
        if (t % 2) { /* random characters */
            size_t len = 1 + (size_t)(rng_next_double(&r) * (sizeof text - 1));
            for (size_t i = 0; i + 1 < len; i++) text[i] = alphabet[(size_t)(rng_next_double(&r) * (sizeof alphabet - 1))];
            text[len - 1] = 0;
        } else { /* a valid file with a few characters changed */
            snprintf(text, sizeof text, "%s", t % 4 ? "% X Y Z U V\n1 2 3 4+1 5\n6.5 7 8e2 9 10-2\n"
                                                    : "id,u,v,x,y,z\na,1,2,3,4,5\nb,6,7,8,9,10\n");
            size_t len = strlen(text);
            for (int k = (int)(rng_next_double(&r) * 3); k > 0; k--)
                text[(size_t)(rng_next_double(&r) * len)] = alphabet[(size_t)(rng_next_double(&r) * (sizeof alphabet - 1))];
        }
        const char *path = write_file("random.txt", text);
        err_buf err = {{0}};
        control_points *cp = control_points_read(path, "random.txt", &err);
        if (cp) {
            read++;
            for (uint32_t i = 0; i < cp->n; i++) CHECK(isfinite(cp->points[i].pixel[0]) && cp->points[i].id);
        } else {
            CHECK(!strncmp(err.msg, "random.txt:", 11));
        }
        control_points_free(cp);
    }
    fprintf(stderr, "%d of 2000 random texts read\n", read);
}

/* A point off the photograph is refused at its line and column, its pixel as the file writes it:
 * ImGRAFT's pixels count from 1 at the centre of the first pixel. */
TEST(points_outside_the_photograph)
{
    const char *path = write_file("off.txt", "445562 7395662 596.4 1 1\n"
                                             "445563 7395663 597 3.5 0.5\n");
    err_buf err = {{0}};
    control_points *cp = control_points_read(path, "off.txt", &err);
    CHECK(cp != NULL);
    if (!cp) return;
    CHECK_INT(control_points_check_image(cp, "off.txt", "tiny.png", 3, 3, &err), 0);
    CHECK_INT(control_points_check_image(cp, "off.txt", "tiny.png", 2, 3, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "off.txt:2:20: control point '2' is at pixel (3.5, 0.5), outside the photograph "
                                "tiny.png of 2 x 3 pixels (u from 0.5 to 2.5, v from 0.5 to 3.5)");
    CHECK_INT(err.status, ERR_INPUT);
    control_points_free(cp);
}

TEST(engabreen_survey)
{
    struct stat st;
    if (stat(ENGABREEN, &st) != 0) SKIP("the shared data set is not at %s", ENGABREEN);
    err_buf err = {{0}};
    control_points *cp = control_points_read(ENGABREEN, NULL, &err);
    if (!cp) fprintf(stderr, "%s\n", err.msg);
    CHECK(cp != NULL);
    if (!cp) return;
    CHECK_INT(cp->n, 28);
    CHECK_INT(cp->map, 1);
    /* first row: 445562 7395662 596.4 1951+9 1490+4 */
    CHECK_NEAR(cp->points[0].world[0], 445562, 0);
    CHECK_NEAR(cp->points[0].world[2], 596.4, 0);
    CHECK_NEAR(cp->points[0].pixel[0], 1959.5, 0);
    CHECK_NEAR(cp->points[0].pixel[1], 1493.5, 0);
    CHECK_INT(cp->points[0].line, 6);
    /* last row: 445637.2 7395378.5 781.8 1011 764 */
    CHECK_NEAR(cp->points[27].world[1], 7395378.5, 0);
    CHECK_NEAR(cp->points[27].pixel[0], 1010.5, 0);
    CHECK_NEAR(cp->points[27].pixel[1], 763.5, 0);
    /* every point lies on ImGRAFT's 4290 x 2856 photograph, and none on a quarter of it */
    CHECK_INT(control_points_check_image(cp, "gcp8902.txt", "IMG_8902.jpg", 4290, 2856, &err), 0);
    CHECK_INT(control_points_check_image(cp, "gcp8902.txt", "IMG_8902.jpg", 1072, 714, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "gcp8902.txt:6:");
    control_points_free(cp);
}

TEST_LIST(TEST_CASE(points_outside_the_photograph), TEST_CASE(csv_map_columns), TEST_CASE(csv_with_byte_order_mark),
          TEST_CASE(csv_local_columns_any_order_without_id), TEST_CASE(imgraft_text),
          TEST_CASE(malformed_files_refused_where_they_are_wrong), TEST_CASE(nul_byte_refused), TEST_CASE(random_text_read_or_refused),
          TEST_CASE(engabreen_survey))
