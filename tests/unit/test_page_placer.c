/* test_page_placer.c — a map's labels beside their marks (page/page_placer.h): a label goes to
 * the right of its mark when that is clear, elsewhere round it when a mark or label stands there,
 * never over another while a clear place is left, and within the map when it can. */
#include "harness.h"
#include "page/page_placer.h"

static int overlaps(page_box a, page_box b)
{
    return fmin(a.x1, b.x1) > fmax(a.x0, b.x0) && fmin(a.y1, b.y1) > fmax(a.y0, b.y0);
}

/* Five marks 4 mm apart in a row, each with a 6 x 2.5 mm label: the first label left of its mark
 * (the next mark stands to its right), the last to the right; none over a mark or another label. */
TEST(labels_in_a_crowded_row_do_not_overlap)
{
    page_placer pl;
    page_placer_init(&pl, (page_box){0, 0, 100, 100});
    enum { N = 5 };
    double r = 0.9;
    for (int k = 0; k < N; k++) page_placer_mark(&pl, 40 + 4 * k, 50, r);
    page_box label[N];
    for (int k = 0; k < N; k++) label[k] = page_placer_put(&pl, 40 + 4 * k, 50, r, 0.5, 6, 2.5);
    CHECK_NEAR(label[0].x1, 40 - r - 0.5, 1e-9);
    CHECK_NEAR(label[0].y0, 50 - 1.25, 1e-9);
    CHECK_NEAR(label[N - 1].x0, 40 + 4 * (N - 1) + r + 0.5, 1e-9);
    for (int a = 0; a < N; a++) {
        for (int b = a + 1; b < N; b++) CHECK(!overlaps(label[a], label[b]));
        for (int m = 0; m < N; m++) CHECK(!overlaps(label[a], (page_box){40 + 4 * m - r, 50 - r, 40 + 4 * m + r, 50 + r}));
    }
    page_placer_free(&pl);
}

/* A mark at the map's right edge: its label goes left, inside the map. */
TEST(a_label_stays_within_the_map)
{
    page_placer pl;
    page_placer_init(&pl, (page_box){0, 0, 50, 50});
    page_placer_mark(&pl, 49, 25, 1);
    page_box b = page_placer_put(&pl, 49, 25, 1, 0.5, 8, 3);
    CHECK(b.x1 <= 50 && b.x0 >= 0);
    CHECK(b.x1 <= 49 - 1);
    page_placer_free(&pl);
}

TEST_LIST(TEST_CASE(labels_in_a_crowded_row_do_not_overlap), TEST_CASE(a_label_stays_within_the_map))
