/* test_leaf_outline.c — the affine leaf as triangles (leaf_outline.h): a square and a triangle
 * traced from their masks come out as those polygons, every preset's polygon keeps the area of
 * its mask's largest piece within a few per cent, its triangles are counter-clockwise and cover it exactly, and an
 * empty mask gives no polygon. */
#include "harness.h"
#include "leaf_affine.h"
#include "leaf_outline.h"

#include <stdint.h>

/* A mask of size x size with the texels whose centre (x, y up) satisfies `in`. */
static uint8_t *mask_of(uint32_t n, int (*in)(double x, double y))
{
    uint8_t *m = calloc((size_t)n * n, 1); /* owned by the caller */
    for (uint32_t row = 0; row < n; row++)
        for (uint32_t col = 0; col < n; col++)
            m[(size_t)row * n + col] = (uint8_t)in((col + 0.5) / n, 1 - (row + 0.5) / n);
    return m;
}

static int in_square(double x, double y) { return x > 0.1 && x < 0.9 && y > 0.1 && y < 0.9; }
static int in_triangle(double x, double y) /* (0.1, 0.1), (0.9, 0.1), (0.5, 0.9) */
{
    return y > 0.1 && y < 0.9 && fabs(x - 0.5) < 0.4 * (0.9 - y) / 0.8;
}

/* Triangles counter-clockwise, indices in range, their areas summing to the shoelace area. */
static void check_triangles(const leaf_outline *o)
{
    CHECK_INT(o->nt, o->n - 2);
    double shoelace = 0;
    for (uint32_t i = 0; i < o->n; i++) {
        const double *p = o->xy[i], *q = o->xy[(i + 1) % o->n];
        shoelace += 0.5 * (p[0] * q[1] - q[0] * p[1]);
        CHECK(p[0] >= 0 && p[0] <= 1 && p[1] >= 0 && p[1] <= 1);
    }
    for (uint32_t t = 0; t < o->nt; t++) {
        CHECK(o->tri[t][0] < o->n && o->tri[t][1] < o->n && o->tri[t][2] < o->n);
        const double *p = o->xy[o->tri[t][0]], *q = o->xy[o->tri[t][1]], *r = o->xy[o->tri[t][2]];
        CHECK((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]) > 0);
    }
    CHECK_NEAR(leaf_outline_area(o), shoelace, 1e-12);
}

TEST(square_is_four_corners)
{
    uint8_t *m = mask_of(64, in_square);
    leaf_outline o;
    CHECK_INT(leaf_outline_trace(m, 64, 1.0, &o), 0);
    CHECK_INT(o.n, 4);
    CHECK_NEAR(leaf_outline_area(&o), 0.64, 0.03);
    check_triangles(&o);
    leaf_outline_free(&o);
    free(m);
}

TEST(triangle_within_its_tolerance)
{
    uint8_t *m = mask_of(128, in_triangle);
    leaf_outline o;
    CHECK_INT(leaf_outline_trace(m, 128, 1.0, &o), 0);
    CHECK(o.n >= 3 && o.n <= 8);
    CHECK_NEAR(leaf_outline_area(&o), 0.32, 0.32 * 0.03);
    check_triangles(&o);
    /* every vertex lies on (within a texel and a half of) the triangle's edges */
    for (uint32_t i = 0; i < o.n; i++) {
        double x = o.xy[i][0], y = o.xy[i][1], t = 1.5 / 128;
        int on_base = fabs(y - 0.1) < t, on_side = fabs(fabs(x - 0.5) - 0.4 * (0.9 - y) / 0.8) < 2 * t;
        CHECK(on_base || on_side);
    }
    leaf_outline_free(&o);
    free(m);
}

/* Texels of the largest 4-connected piece of the mask (the polygon is that piece's outline). */
static size_t largest_piece(const uint8_t *inside, uint32_t n)
{
    uint8_t *seen = calloc((size_t)n * n, 1);          /* owned here */
    uint32_t *stack = malloc((size_t)n * n * sizeof *stack); /* owned here */
    size_t best = 0;
    for (uint32_t s = 0; s < n * n; s++) {
        if (!inside[s] || seen[s]) continue;
        size_t top = 0, size = 0;
        stack[top++] = s, seen[s] = 1;
        while (top) {
            uint32_t k = stack[--top], r = k / n, c = k % n;
            size++;
            uint32_t nb[4] = {r ? k - n : k, r + 1 < n ? k + n : k, c ? k - 1 : k, c + 1 < n ? k + 1 : k};
            for (int j = 0; j < 4; j++)
                if (inside[nb[j]] && !seen[nb[j]]) seen[nb[j]] = 1, stack[top++] = nb[j];
        }
        if (size > best) best = size;
    }
    free(seen), free(stack);
    return best;
}

TEST(presets_keep_their_area)
{
    const uint32_t n = 128;
    for (int p = 0; p < LEAF_AFFINE_PRESET_COUNT; p++) {
        leaf_affine_maps maps;
        leaf_affine_preset_maps((leaf_affine_preset)p, &maps);
        leaf_affine_raster r;
        char err[200];
        CHECK_INT(leaf_affine_attractor(&maps, n, 7, &r, err, sizeof err), 0);
        uint8_t *inside = malloc((size_t)n * n);
        CHECK_INT(leaf_affine_outline(&r, inside), 0);
        size_t texels = largest_piece(inside, n);
        leaf_outline o;
        CHECK_INT(leaf_outline_trace(inside, n, 1.0, &o), 0);
        double mask_area = (double)texels / ((double)n * n), area = leaf_outline_area(&o);
        fprintf(stderr, "%-7s %3u vertices, area %.4f (its piece of the mask %.4f)\n", leaf_affine_preset_name((leaf_affine_preset)p),
                o.n, area, mask_area);
        CHECK(o.n >= 3 && o.n <= LEAF_OUTLINE_MAX_VERTICES);
        CHECK(fabs(area - mask_area) < 0.04 * mask_area);
        check_triangles(&o);
        leaf_outline_free(&o);
        free(inside);
        leaf_affine_raster_free(&r);
    }
}

TEST(empty_mask_gives_no_polygon)
{
    uint8_t m[16 * 16] = {0};
    leaf_outline o;
    CHECK_INT(leaf_outline_trace(m, 16, 1.0, &o), 1);
    CHECK(o.n == 0 && o.xy == NULL && o.tri == NULL);
    leaf_outline_free(&o);
}

TEST_LIST(TEST_CASE(square_is_four_corners), TEST_CASE(triangle_within_its_tolerance),
          TEST_CASE(presets_keep_their_area), TEST_CASE(empty_mask_gives_no_polygon))
