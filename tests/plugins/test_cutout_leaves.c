/* test_cutout_leaves.c — a cut-out part's own test (cutout_part_point_kept, geometry/cutout.h)
 * takes the decision the mesh gives (cutout_point_kept), hit for hit, on the leaf cards and leaf
 * textures the tree plugins make: at random points of every cut-out triangle and at points put
 * on texel boundaries (the barycentrics of a texel corner, and their neighbours one and two ulps
 * away on either side); and on meshes over those textures whose uv tables need 2-, 4-, 8-, 16-
 * and 32-bit numbers, with uvs outside [0, 1) and two textures in one part. The part is the same
 * bytes when built again. */
#include <math.h>
#include <stdio.h>

#include "harness.h"
#include "geometry/cutout.h"
#include "plugin/plugin_host.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "util/rng.h"

/* The tree plugins' species of tests/scenes/tree_variants.yaml (caller frees), or NULL. */
static scene *leaf_scene(plugin_registry **reg)
{
    err_buf err = {{0}};
    *reg = plugin_registry_open_path(SYLVA_PLUGIN_BUILD_DIR, &err);
    CHECK(*reg != NULL);
    if (!*reg) return NULL;
    scene_file *sf = scene_file_load(SYLVA_TEST_DATA_DIR "/scenes/tree_variants.yaml", *reg, &err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    build_options bo = {.quiet = 1, .threads = 1};
    scene *s = sf ? scene_build(sf, *reg, &bo, &err) : NULL;
    if (sf && !s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    scene_file_free(sf);
    return s;
}

/* What the comparisons met. */
typedef struct tally {
    uint64_t points, kept, differ;  /* points compared, kept by the mesh, decided otherwise by the part */
    uint64_t edges;                 /* neighbouring boundary points the mesh decided differently */
} tally;

static void compare(const scene *s, const mesh *m, const cutout_part *p, uint32_t i, float bu, float bv, tally *c)
{
    int want = cutout_point_kept(s, m, p->to_mesh[i], bu, bv), got = cutout_part_point_kept(p, i, bu, bv);
    if (got != want && c->differ < 5)
        fprintf(stderr, "triangle %u at (%.9g, %.9g): the part says %d, the mesh %d\n", i, bu, bv, got, want);
    c->points++;
    c->kept += want;
    c->differ += got != want;
}

/* Points of triangle i of p on the corner (cu, cv) of a texel: the barycentrics that put the
 * triangle's uv there, and those one and two ulps away in each of bu and bv. */
static void compare_at_texel_corner(const scene *s, const mesh *m, const cutout_part *p, uint32_t i, double cu,
                                    double cv, tally *c)
{
    const uint32_t *k = p->tri + (size_t)i * 3;
    const float *a = m->uv + (size_t)k[0] * 2, *b = m->uv + (size_t)k[1] * 2, *d = m->uv + (size_t)k[2] * 2;
    double e1u = b[0] - a[0], e1v = b[1] - a[1], e2u = d[0] - a[0], e2v = d[1] - a[1];
    double det = e1u * e2v - e2u * e1v;
    if (fabs(det) < 1e-12) return;
    double bu = ((cu - a[0]) * e2v - e2u * (cv - a[1])) / det, bv = (e1u * (cv - a[1]) - (cu - a[0]) * e1v) / det;
    if (bu < 0 || bv < 0 || bu + bv > 1) return;
    int first = -1;
    for (int su = -2; su <= 2; su++)
        for (int sv = -2; sv <= 2; sv++) {
            float fu = (float)bu, fv = (float)bv;
            for (int n = 0; n < abs(su); n++) fu = nextafterf(fu, su < 0 ? -1.0f : 2.0f);
            for (int n = 0; n < abs(sv); n++) fv = nextafterf(fv, sv < 0 ? -1.0f : 2.0f);
            compare(s, m, p, i, fu, fv, c);
            int want = cutout_point_kept(s, m, p->to_mesh[i], fu, fv);
            if (first < 0) first = want;
            c->edges += want != first;
        }
}

/* Random points of every triangle of p, and points on texel corners within its uvs. */
static void compare_part(const scene *s, const mesh *m, const cutout_part *p, uint32_t points, tally *c)
{
    sylva_rng r;
    rng_stream(&r, 19, "cut-out points", p->n);
    for (uint32_t i = 0; i < p->n; i++) {
        for (uint32_t q = 0; q < points; q++) {
            float bu = (float)rng_next_double(&r), bv = (float)rng_next_double(&r);
            if (bu + bv > 1) bu = 1 - bu, bv = 1 - bv;
            compare(s, m, p, i, bu, bv, c);
        }
        /* texel corners near a random point of the triangle's uvs */
        const texture *tx = &s->textures[s->materials[scene_triangle_material(s, m, p->to_mesh[i])].texture];
        float bu = (float)rng_next_double(&r) / 2, bv = (float)rng_next_double(&r) / 2, uv[2];
        const uint32_t *k = p->tri + (size_t)i * 3;
        cutout_uv(m->uv + (size_t)k[0] * 2, m->uv + (size_t)k[1] * 2, m->uv + (size_t)k[2] * 2, bu, bv, uv);
        double x = floor(uv[0] * tx->width), y = floor(uv[1] * tx->height);
        for (int dx = 0; dx <= 1; dx++)
            for (int dy = 0; dy <= 1; dy++)
                compare_at_texel_corner(s, m, p, i, (x + dx) / tx->width, (y + dy) / tx->height, c);
    }
}

static int same_part(const cutout_part *a, const cutout_part *b)
{
    if (a->n != b->n || a->n_uv != b->n_uv || a->n_masks != b->n_masks || a->number_bits != b->number_bits) return 0;
    if (!a->n) return !a->corners && !b->corners;
    if (memcmp(a->corners, b->corners, (size_t)a->n * a->number_bits / 2 + 8)) return 0;
    if (memcmp(a->uv, b->uv, (size_t)a->n_uv * 2 * sizeof(float))) return 0;
    for (uint32_t k = 0; k < a->n_masks; k++)
        if (a->masks[k].width != b->masks[k].width || a->masks[k].height != b->masks[k].height ||
            memcmp(a->masks[k].bits, b->masks[k].bits, ((size_t)a->masks[k].width * a->masks[k].height + 63) / 64 * 8))
            return 0;
    return 1;
}

TEST(same_decision_on_the_plugins_leaf_cards)
{
    plugin_registry *reg = NULL;
    scene *s = leaf_scene(&reg);
    tally c = {0};
    uint32_t parts = 0, textures = 0;
    for (uint32_t t = 0; s && t < s->n_textures; t++) textures += s->textures[t].has_alpha;
    for (uint32_t pr = 0; s && pr < s->n_prototypes; pr++) {
        err_buf err = {{0}};
        const mesh *m = s->prototypes[pr].mesh;
        cutout_part p, again;
        CHECK_INT(cutout_part_build(s, m, 1, &p, &err), 0);
        CHECK_INT(cutout_part_build(s, m, 1, &again, &err), 0);
        CHECK(same_part(&p, &again));
        if (p.n) {
            parts++;
            CHECK_INT(p.n_uv, 4); /* leaf cards: the corners of the unit square */
            CHECK_INT(p.number_bits, 2);
            compare_part(s, m, &p, 16, &c);
        }
        cutout_part_free(&p);
        cutout_part_free(&again);
    }
    fprintf(stderr, "%u cut-out parts over %u textures with alpha: %llu points, %llu kept, %llu decided otherwise; "
            "%llu boundary neighbours on the other side\n", parts, textures, (unsigned long long)c.points,
            (unsigned long long)c.kept, (unsigned long long)c.differ, (unsigned long long)c.edges);
    CHECK(parts >= 3);     /* the vessel, Aono-Kunii and Weber-Penn species' variants */
    CHECK(textures >= 2);
    CHECK_INT(c.differ, 0);
    CHECK(c.points > 100000);
    CHECK(c.kept > c.points / 10 && c.kept < c.points - c.points / 10); /* both decisions, often */
    CHECK(c.edges > 1000); /* the boundary points straddle texel edges where alpha changes */
    scene_free(s);
    plugin_registry_free(reg);
}

/* A mesh of triangles whose corners take n_uv distinct uvs (some outside [0, 1), one -0), in
 * materials mat_a and mat_b alternately. */
static mesh *uv_mesh(uint32_t n_uv, int32_t mat_a, int32_t mat_b, err_buf *err)
{
    mesh *m = mesh_new();
    if (!m) return NULL;
    uint32_t nt = (n_uv + 2) / 3 + 8;
    for (uint32_t t = 0; t < nt; t++) {
        float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, uv[6];
        for (int k = 0; k < 3; k++) {
            uint32_t which = (3 * t + (uint32_t)k) % n_uv; /* every one of the n_uv at least once */
            sylva_rng ru;
            rng_stream(&ru, 19, "cut-out uv", which);
            uv[2 * k] = (float)(rng_next_double(&ru) * 3 - 1);
            uv[2 * k + 1] = which == 1 ? -0.0f : (float)(rng_next_double(&ru) * 3 - 1);
        }
        const uint32_t tri[3] = {0, 1, 2};
        int32_t mat = t % 2 ? mat_b : mat_a;
        if (mesh_append(m, pos, NULL, uv, 3, tri, &mat, -1, 1, err)) {
            mesh_free(m);
            return NULL;
        }
    }
    return m;
}

TEST(same_decision_for_every_number_width)
{
    plugin_registry *reg = NULL;
    scene *s = leaf_scene(&reg);
    int32_t cut[2] = {-1, -1}; /* two cut-out materials with different textures */
    for (uint32_t k = 0; s && k < s->n_materials; k++)
        if (cutout_material(s, &s->materials[k])) {
            if (cut[0] < 0) cut[0] = (int32_t)k;
            else if (cut[1] < 0 && s->materials[k].texture != s->materials[cut[0]].texture) cut[1] = (int32_t)k;
        }
    CHECK(cut[0] >= 0 && cut[1] >= 0);
    const uint32_t n_uv[] = {3, 16, 200, 5000, 70000}, bits[] = {2, 4, 8, 16, 32};
    for (size_t w = 0; s && cut[1] >= 0 && w < sizeof n_uv / sizeof n_uv[0]; w++) {
        err_buf err = {{0}};
        mesh *m = uv_mesh(n_uv[w], cut[0], cut[1], &err);
        CHECK(m != NULL);
        if (!m) break;
        cutout_part p, again;
        CHECK_INT(cutout_part_build(s, m, 1, &p, &err), 0);
        CHECK_INT(cutout_part_build(s, m, 1, &again, &err), 0);
        CHECK(same_part(&p, &again));
        CHECK_INT(p.n, m->nt);
        CHECK_INT(p.n_uv, n_uv[w]);
        CHECK_INT(p.n_masks, 2);
        CHECK_INT(p.number_bits, bits[w]);
        tally c = {0};
        if (p.n == m->nt) compare_part(s, m, &p, 8, &c);
        CHECK_INT(c.differ, 0);
        CHECK(c.kept > 0 && c.kept < c.points);
        cutout_part_free(&p);
        cutout_part_free(&again);
        mesh_free(m);
    }
    scene_free(s);
    plugin_registry_free(reg);
}

TEST_LIST(TEST_CASE(same_decision_on_the_plugins_leaf_cards), TEST_CASE(same_decision_for_every_number_width))
