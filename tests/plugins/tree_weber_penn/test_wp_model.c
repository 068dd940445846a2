/* test_wp_model.c — Weber–Penn trees grown as Arbaro 1.9 grows them: java.util.Random against
 * values Java printed; the 16 shared Arbaro species at seed 13 against Arbaro's own figures
 * (faces per OBJ group exactly, the bounding box within 1 % of the tree's height); more seeds and
 * species variants against figures measured on Arbaro's output (arbaro-measured.csv); the leaf
 * shapes' face counts; the limits refused with a sentence. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "wp_frame.h"
#include "wp_leaf_shape.h"
#include "wp_model.h"
#include "wp_random.h"
#include "wp_species_read.h"

TEST(java_random)
{
    /* printed by Java 17: new java.util.Random(13).nextDouble() x 5, ... */
    static const double doubles13[] = { 0.7298032243379924, 0.44461356134079055, 0.05128392223198952,
                                        0.7200775170504272, 0.41028338463901914 };
    wp_random r;
    wp_random_seed(&r, 13);
    for (int i = 0; i < 5; i++) CHECK(wp_random_double(&r) == doubles13[i]);
    wp_random_seed(&r, 13);
    CHECK(wp_random_long(&r) == INT64_C(-4984250756083210152));
    CHECK(wp_random_long(&r) == INT64_C(8201672769755439997));
    CHECK(wp_random_long(&r) == INT64_C(946021207972520316));
    wp_random_seed(&r, -5);
    CHECK(wp_random_double(&r) == 0.26930095796932485);
    CHECK(wp_random_long(&r) == INT64_C(6162916890256202832));
    /* Arbaro's Random(13): getState(), then nextDouble(), then uniform(-2.5, 4) */
    wp_random_seed(&r, 13);
    CHECK(wp_random_save(&r) == INT64_C(-4984250756083210152));
    CHECK(wp_random_double(&r) == 0.4453058364719601);
    CHECK(wp_random_uniform(&r, -2.5, 4) == 3.8335473569886727);
    wp_random_seed(&r, 42);
    CHECK_INT(wp_random_int_below(&r, 10), 0);
    CHECK_INT(wp_random_int(&r), 234785527);
}

TEST(frame_rotations)
{
    wp_frame f = wp_frame_identity();
    wp_frame g = wp_frame_rotaxis(&f, 90, wp_v(0, 0, 2));
    wp_vec x = wp_frame_x(&g);
    CHECK_NEAR(x.x, 0, 1e-15);
    CHECK_NEAR(x.y, 1, 1e-15);
    /* rotxz(delta, rho): about z by rho, then down by delta about the new x */
    g = wp_frame_rotxz(&f, 90, 90);
    wp_vec z = wp_frame_z(&g);
    CHECK_NEAR(z.x, 1, 1e-15);
    CHECK_NEAR(z.y, 0, 1e-15);
    CHECK_NEAR(z.z, 0, 1e-15);
    g = wp_frame_translate(&g, wp_v(1, 2, 3));
    wp_vec p = wp_frame_apply(&g, wp_v(0, 0, 1));
    CHECK_NEAR(p.x, 2, 1e-15);
    CHECK_NEAR(p.z, 3, 1e-15);
    CHECK_NEAR(wp_atan2_deg(-1, -1), -135, 1e-12);
}

/* One row of a figures file: the species file, changes to it, the seed, the faces per group
 * (trunk, stems_1..3, leaves; -1 where the group is absent) and the box in OBJ order. */
typedef struct figures {
    char file[128], changes[512];
    long seed;
    long faces[WP_LEVELS + 1];
    double box[6]; /* xmin ymin zmin xmax ymax zmax, y up */
} figures;

/* "trunk:240 stems_1:1250 leaves:99" into f->faces. */
static void parse_groups(char *groups, figures *f)
{
    for (int i = 0; i <= WP_LEVELS; i++) f->faces[i] = -1;
    for (char *tok = strtok(groups, " "); tok; tok = strtok(NULL, " ")) {
        char *colon = strchr(tok, ':');
        if (!colon) continue;
        *colon = '\0';
        long n = atol(colon + 1);
        if (!strcmp(tok, "trunk")) f->faces[0] = n;
        else if (!strcmp(tok, "leaves")) f->faces[WP_GROUP_LEAVES] = n;
        else if (!strncmp(tok, "stems_", 6) && atoi(tok + 6) < WP_LEVELS) f->faces[atoi(tok + 6)] = n;
    }
}

/* Reads a figures CSV (header line and '#' comments skipped) with or without the `changes`
 * column; returns the rows (up to cap) or -1 when the file cannot be read. */
static int read_figures(const char *path, int with_changes, figures *rows, int cap)
{
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    char line[2048];
    int n = 0, header = 1;
    while (n < cap && fgets(line, sizeof line, f)) {
        if (line[0] == '#' || line[0] == '\n') continue;
        if (header) {
            header = 0;
            continue;
        }
        figures *r = &rows[n];
        memset(r, 0, sizeof *r);
        char *field[12];
        int k = 0;
        for (char *p = line; k < 12 && p;) {
            field[k++] = p;
            p = strchr(p, ',');
            if (p) *p++ = '\0';
        }
        int c = with_changes;
        if (k < 9 + c) continue;
        snprintf(r->file, sizeof r->file, "%s", field[0]);
        if (c) snprintf(r->changes, sizeof r->changes, "%s", field[1]);
        r->seed = atol(field[1 + c]);
        parse_groups(field[2 + c], r);
        for (int i = 0; i < 6; i++) r->box[i] = atof(field[3 + c + i]);
        n++;
    }
    fclose(f);
    return n;
}

/* Applies "Name=value;Name=value" (Arbaro's names) to p. */
static void apply_changes(wp_params *p, const char *changes)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s", changes);
    for (char *tok = strtok(buf, ";"); tok; tok = strtok(NULL, ";")) {
        char *eq = strchr(tok, '=');
        CHECK(eq != NULL);
        if (!eq) continue;
        *eq = '\0';
        int level;
        const wp_param_def *d = wp_param_find_arbaro(tok, &level);
        CHECK(d != NULL);
        if (!d) continue;
        void *slot = wp_param_slot(d, p, level);
        if (d->type == WP_INT) *(int *)slot = atoi(eq + 1);
        else if (d->type == WP_FLOAT) *(double *)slot = atof(eq + 1);
        else snprintf(slot, d->text_size, "%s", eq + 1);
    }
}

/* Grows row r's species and compares: faces per group exactly, each box extent within 1 % of
 * the tree's height. Prints the figures. Returns 1 when it agrees. */
static int compare_row(const figures *r)
{
    char sub[256];
    snprintf(sub, sizeof sub, "weber-penn/arbaro/%s", r->file);
    const char *path = harness_shared_data(sub);
    CHECK(path != NULL);
    if (!path) return 0;
    wp_species_list l;
    plugin_err err = { 0 };
    int rc = wp_species_read_file(path, &l, &err);
    CHECK_INT(rc, 0);
    if (rc) return 0;
    wp_params p = l.items[0];
    wp_species_list_free(&l);
    if (r->changes[0]) apply_changes(&p, r->changes);
    wp_model m;
    double t0 = harness_seconds();
    rc = wp_model_grow(&p, r->seed, (size_t)1 << 30, (size_t)1 << 30, &m, &err);
    double seconds = harness_seconds() - t0;
    if (rc) fprintf(stderr, "%s\n", err.msg);
    CHECK_INT(rc, 0);
    if (rc) return 0;
    int same = 1;
    for (int i = 0; i <= WP_LEVELS; i++) {
        long want = r->faces[i] < 0 ? 0 : r->faces[i];
        if ((long)m.faces[i] != want) same = 0;
    }
    /* OBJ's frame: x, then z up, then y */
    double got[6] = { m.bbox_min[0], m.bbox_min[2], m.bbox_min[1], m.bbox_max[0], m.bbox_max[2], m.bbox_max[1] };
    double worst = 0;
    for (int i = 0; i < 6; i++)
        if (fabs(got[i] - r->box[i]) > worst) worst = fabs(got[i] - r->box[i]);
    double height = r->box[4];
    printf("%-22s %-40s seed %3ld  stems %zu/%zu/%zu/%zu  leaves %zu  faces %zu/%zu/%zu/%zu/%zu  box error %.5f m "
           "(%.4f %% of %.2f m)  %.3f s  %s\n",
           r->file, r->changes[0] ? r->changes : "-", r->seed, m.stems[0], m.stems[1], m.stems[2], m.stems[3],
           m.n_leaves, m.faces[0], m.faces[1], m.faces[2], m.faces[3], m.faces[4], worst, 100 * worst / height, height,
           seconds, same && worst <= 0.01 * height ? "agrees" : "DIFFERS");
    for (int i = 0; i <= WP_LEVELS; i++) CHECK_INT(m.faces[i], r->faces[i] < 0 ? 0 : r->faces[i]);
    CHECK(worst <= 0.01 * height);
    wp_model_release(&m);
    return same && worst <= 0.01 * height;
}

TEST(arbaro_figures)
{
    const char *path = harness_shared_data("weber-penn/reference-outputs/arbaro-figures.csv");
    if (!path) SKIP("no ../shared/data/weber-penn");
    static figures rows[64];
    int n = read_figures(path, 0, rows, 64);
    CHECK_INT(n, 16);
    int agree = 0;
    for (int i = 0; i < n; i++) agree += compare_row(&rows[i]);
    printf("%d of %d species agree with Arbaro's figures\n", agree, n);
}

TEST(arbaro_measured)
{
    if (!harness_shared_data("weber-penn/arbaro")) SKIP("no ../shared/data/weber-penn");
    static figures rows[64];
    int n = read_figures(WP_MEASURED_CSV, 1, rows, 64);
    CHECK(n > 0);
    int agree = 0;
    for (int i = 0; i < n; i++) agree += compare_row(&rows[i]);
    printf("%d of %d measured trees agree\n", agree, n);
}

/* The default species with leaves. */
static wp_params leafy_default(void)
{
    wp_params p;
    wp_params_defaults(&p);
    p.leaves = 20;
    return p;
}

TEST(model_consistent)
{
    wp_params p = leafy_default();
    wp_model m;
    plugin_err err = { 0 };
    CHECK_INT(wp_model_grow(&p, 13, 1000000, 1000000, &m, &err), 0);
    CHECK(m.n_triangles > 0 && m.n_leaves > 0);
    CHECK_INT(m.stems[0], 1);
    CHECK_INT(m.faces[WP_GROUP_LEAVES], 3 * m.n_leaves); /* the default leaf: a disc of 3 quads */
    size_t bad = 0;
    for (size_t i = 0; i < m.n_triangles; i++)
        for (int c = 0; c < 3; c++) bad += m.triangle[i][c] >= m.n_vertices;
    CHECK_INT(bad, 0);
    for (size_t i = 0; i < m.n_leaves; i++) {
        double(*a)[3] = m.leaf[i].axis;
        double d = a[0][0] * a[2][0] + a[0][1] * a[2][1] + a[0][2] * a[2][2];
        double len = a[1][0] * a[1][0] + a[1][1] * a[1][1] + a[1][2] * a[1][2];
        if (fabs(d) > 1e-9 || fabs(len - 1) > 1e-9) bad++;
    }
    CHECK_INT(bad, 0);
    CHECK(m.height > 5 && m.height == m.bbox_max[2]);
    wp_model again;
    CHECK_INT(wp_model_grow(&p, 13, 1000000, 1000000, &again, &err), 0);
    CHECK(again.n_vertices == m.n_vertices && !memcmp(again.vertex, m.vertex, m.n_vertices * sizeof *m.vertex));
    wp_model_release(&again);
    CHECK_INT(wp_model_grow(&p, 14, 1000000, 1000000, &again, &err), 0);
    CHECK(again.n_vertices != m.n_vertices || memcmp(again.vertex, m.vertex, m.n_vertices * sizeof *m.vertex));
    wp_model_release(&again);
    wp_model_release(&m);
    CHECK(m.vertex == NULL && m.n_triangles == 0);
}

/* Grows p with the limits, expecting refusal with `status` and a message holding `needle`. */
static void expect_refused(const wp_params *p, size_t max_triangles, size_t max_leaves, int status, const char *needle)
{
    wp_model m;
    plugin_err err = { 0 };
    int rc = wp_model_grow(p, 13, max_triangles, max_leaves, &m, &err);
    printf("refused: %s\n", err.msg);
    CHECK_INT(rc, status);
    CHECK_STR_CONTAINS(err.msg, needle);
    CHECK(m.vertex == NULL && m.leaf == NULL && m.n_triangles == 0);
}

TEST(limits_refused)
{
    wp_params p = leafy_default();
    /* the default tree has 420 stem triangles: refused while it grows, or while it is meshed */
    expect_refused(&p, 100, 1000000, SYLVA_ERR_LIMIT, "more than 100 stem triangles (the limit max_triangles)");
    expect_refused(&p, 419, 1000000, SYLVA_ERR_LIMIT, "more than 419 stem triangles (the limit max_triangles)");
    expect_refused(&p, 1000000, 10, SYLVA_ERR_LIMIT, "more than 10 leaves (the limit max_leaves)");
    p.level[1].seg_splits = 1;
    expect_refused(&p, 1000000, 1000000, SYLVA_ERR_PARAM, "1SplitAngle is 0");
    p = leafy_default();
    p.levels = 5;
    expect_refused(&p, 1000000, 1000000, SYLVA_ERR_PARAM, "at most 4 stem levels");
    /* stems of level 2 pointing straight up with AttractionUp: Arbaro writes NaN vertices */
    p = leafy_default();
    p.attraction_up = 0.5;
    p.level[1].down_angle = p.level[2].down_angle = p.level[1].rotate = p.level[2].rotate = 0;
    p.level[2].curve_res = 3;
    expect_refused(&p, 1000000, 1000000, SYLVA_ERR_PARAM, "at no defined place");
    /* a clone at every segment of a trunk of 1000: clones of clones 200 deep */
    p = leafy_default();
    p.level[0].curve_res = 1000;
    p.level[0].seg_splits = 1;
    p.level[0].split_angle = 10;
    expect_refused(&p, 10000000, 10000000, SYLVA_ERR_LIMIT, "clones split from clones more than 200 deep");
    /* ten million children per stem, all too short to be kept */
    p = leafy_default();
    p.level[1].branches = 10000000;
    p.level[1].length = 1e-7;
    expect_refused(&p, 1000000, 1000000, SYLVA_ERR_LIMIT, "more than 1000000 stem triangles");
    p = leafy_default();
    snprintf(p.leaf_shape, sizeof p.leaf_shape, "disc5000");
    expect_refused(&p, 1000000, 1000000, SYLVA_ERR_LIMIT, "more than 1000 triangles per leaf");
}

/* The leaf shape `name`: expects Arbaro's faces, the points and the triangles. */
static void expect_shape(const char *name, size_t faces, size_t vertices, size_t triangles)
{
    wp_params p;
    wp_params_defaults(&p);
    snprintf(p.leaf_shape, sizeof p.leaf_shape, "%s", name);
    wp_leaf_shape s;
    plugin_err err = { 0 };
    CHECK_INT(wp_leaf_shape_make(&p, &s, &err), 0);
    printf("%-8s faces %zu, points %zu, triangles %zu\n", name, s.faces, s.n_vertices, s.n_triangles);
    CHECK_INT(s.faces, faces);
    CHECK_INT(s.n_vertices, vertices);
    CHECK_INT(s.n_triangles, triangles);
    wp_leaf_shape_release(&s);
}

TEST(leaf_shapes)
{
    expect_shape("0", 3, 8, 6);
    expect_shape("disc", 3, 8, 6);
    expect_shape("palm", 3, 8, 6);
    expect_shape("disc1", 1, 3, 1);
    expect_shape("disc2", 1, 4, 2);
    expect_shape("disc5", 3, 7, 5);
    expect_shape("disc10", 5, 12, 10);
    expect_shape("square", 1, 4, 2);
    expect_shape("sphere", 20, 12, 20);
    wp_params p;
    wp_params_defaults(&p);
    p.leaf_scale = 0.2, p.leaf_scale_x = 0.5, p.leaf_stem_len = 0.5, p.leaf_quality = 0.25;
    snprintf(p.leaf_shape, sizeof p.leaf_shape, "square");
    wp_leaf_shape s;
    plugin_err err = { 0 };
    CHECK_INT(wp_leaf_shape_make(&p, &s, &err), 0);
    /* length 0.2 / sqrt(0.25) = 0.4, width 0.2: the blade from 0.2 to 0.6 up z */
    CHECK_NEAR(s.vertex[1][2], 0.6, 1e-15);
    CHECK_NEAR(s.vertex[0][2], 0.2, 1e-15);
    CHECK_NEAR(s.vertex[2][0] - s.vertex[1][0], 0.2, 1e-15);
    wp_leaf_shape_release(&s);
}

TEST_LIST(TEST_CASE(java_random), TEST_CASE(frame_rotations), TEST_CASE(arbaro_figures), TEST_CASE(arbaro_measured),
          TEST_CASE(model_consistent), TEST_CASE(limits_refused), TEST_CASE(leaf_shapes))
