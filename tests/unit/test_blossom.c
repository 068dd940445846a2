/* test_blossom.c — blossom as a particle system: a particle lives from its birth for its
 * lifetime and no longer, its draws and the petals' sizes and colours keep to their ranges, the
 * petals of a seed are the same in every run (and differ for another seed), they stand on the
 * plant's crown points in the plant's frame with radii in metres, and bad parameters get a clear
 * error. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "season/blossom.h"

/* A cherry prototype: a bark trunk (two triangles, 0-4 m) and 40 leaf triangles around the
 * crown at 4-6 m; two cherries (one at the origin, one moved, turned 90 degrees and scaled by 2)
 * and one plant of another species. */
static scene *orchard(void)
{
    scene *s = scene_new();
    err_buf err = {0};
    if (!s) return NULL;
    sylva_material_desc bark = {.size = sizeof bark, .name = "bark", .bsdf = SYLVA_BSDF_LAMBERT,
                                .albedo = {0.2f, 0.15f, 0.1f}, .texture = -1};
    sylva_material_desc leaf = {.size = sizeof leaf, .name = "leaf", .bsdf = SYLVA_BSDF_LEAF,
                                .albedo = {0.1f, 0.3f, 0.1f}, .texture = -1};
    int32_t mb = scene_add_material(s, &bark, &err), ml = scene_add_material(s, &leaf, &err);
    float pos[3 * (4 + 3 * 40)];
    uint32_t tri[3 * (2 + 40)];
    int32_t mat[2 + 40];
    const float trunk[12] = {-0.1f, 0, 0, 0.1f, 0, 0, 0.1f, 0, 4, -0.1f, 0, 4};
    memcpy(pos, trunk, sizeof trunk);
    tri[0] = 0, tri[1] = 1, tri[2] = 2, tri[3] = 0, tri[4] = 2, tri[5] = 3, mat[0] = mat[1] = mb;
    for (uint32_t k = 0; k < 40; k++) {
        double a = 2 * M_PI * k / 40, z = 4 + 2.0 * k / 40;
        float cx = (float)(1.5 * cos(a)), cy = (float)(1.5 * sin(a));
        float *p = pos + 12 + 9 * k;
        p[0] = cx, p[1] = cy, p[2] = (float)z;
        p[3] = cx + 0.1f, p[4] = cy, p[5] = (float)z;
        p[6] = cx, p[7] = cy + 0.1f, p[8] = (float)z + 0.05f;
        tri[6 + 3 * k] = 4 + 3 * k, tri[7 + 3 * k] = 5 + 3 * k, tri[8 + 3 * k] = 6 + 3 * k;
        mat[2 + k] = ml;
    }
    mesh *m = mesh_new(), *other = mesh_new();
    int ok = m && other && mb >= 0 && ml >= 0;
    ok = ok && !mesh_append(m, pos, NULL, NULL, 4 + 3 * 40, tri, mat, -1, 2 + 40, &err);
    ok = ok && !mesh_append(other, pos, NULL, NULL, 4 + 3 * 40, tri, mat, -1, 2 + 40, &err);
    int32_t sp = ok ? scene_add_species(s, "cherry", &err) : -1;
    int32_t pr = sp >= 0 ? scene_add_prototype(s, (uint32_t)sp, 0, 1.0, 6.0, m, &err) : -1;
    if (pr < 0) mesh_free(m);
    int32_t sp2 = pr >= 0 ? scene_add_species(s, "beech", &err) : -1;
    int32_t pr2 = sp2 >= 0 ? scene_add_prototype(s, (uint32_t)sp2, 0, 1.0, 6.0, other, &err) : -1;
    if (pr2 < 0) mesh_free(other);
    if (pr2 < 0) return scene_free(s), NULL;
    xform3x4 here = xf_identity();
    xform3x4 there = {{{0, -2, 0, 50}, {2, 0, 0, 20}, {0, 0, 2, 3}}};
    if (scene_add_instance(s, (uint32_t)pr, &here, &err) < 0 || scene_add_instance(s, (uint32_t)pr2, &here, &err) < 0 ||
        scene_add_instance(s, (uint32_t)pr, &there, &err) < 0)
        return scene_free(s), NULL;
    return s;
}

static blossom_params busy(void)
{
    blossom_params p;
    blossom_params_default(&p);
    p.per_point = 5; /* 200 flowers a plant over the season */
    return p;
}

TEST(alive_by_lifetime)
{
    blossom_params p = busy();
    blossom_particle q = {.point = 0, .birth = 100, .lifetime = 10, .velocity = {0.002f, 0, -0.001f},
                          .normal = {0, 0, 1}, .size = 0.01, .aspect = 1, .tint = 0.5};
    CHECK_INT(blossom_particle_at(&p, &q, 99.99).alive, 0);
    blossom_state born = blossom_particle_at(&p, &q, 100);
    CHECK_INT(born.alive, 1);
    CHECK_NEAR(born.radius, p.bud_size * q.size, 1e-12); /* a bud at birth */
    CHECK_NEAR(born.colour, p.colour_jitter * q.tint, 1e-12);
    blossom_state open = blossom_particle_at(&p, &q, 100 + 10 * p.opening);
    CHECK_NEAR(open.radius, q.size, 1e-12); /* open after its opening share of life */
    blossom_state late = blossom_particle_at(&p, &q, 109.99);
    CHECK_INT(late.alive, 1);
    CHECK_NEAR(late.age, 0.999, 1e-9);
    CHECK_NEAR(late.offset.x, 0.002 * 9.99, 1e-6); /* p = p0 + v (t - t_birth) */
    CHECK_NEAR(late.offset.z, -0.001 * 9.99, 1e-6);
    CHECK_NEAR(late.colour, (1 - p.colour_jitter) * 0.999 + p.colour_jitter * 0.5, 1e-9);
    CHECK_INT(blossom_particle_at(&p, &q, 110).alive, 0); /* deleted at the end of its life */
}

TEST(draws_within_their_ranges)
{
    blossom_params p = busy();
    double first = 1e9, last = -1e9;
    for (uint32_t k = 0; k < 20000; k++) {
        blossom_particle q;
        blossom_particle_draw(&p, 11, 3, k, 40, &q);
        CHECK(q.point < 40);
        CHECK(q.birth >= p.first_day && q.birth < p.last_day);
        CHECK(q.lifetime >= p.lifetime_min && q.lifetime <= p.lifetime_max);
        CHECK(q.size >= p.size_min && q.size <= p.size_max);
        CHECK(q.aspect >= p.aspect_min && q.aspect <= 1);
        CHECK(v3_len(q.velocity) <= p.speed_max * 1.0001);
        CHECK_NEAR(v3_len(q.normal), 1, 1e-5);
        CHECK(q.tint >= 0 && q.tint < 1);
        first = fmin(first, q.birth), last = fmax(last, q.birth);
        for (double day = 95; day < 135; day += 3.7) {
            blossom_state st = blossom_particle_at(&p, &q, day);
            if (!st.alive) continue;
            CHECK(st.radius >= p.bud_size * p.size_min && st.radius <= p.size_max);
            CHECK(st.colour >= 0 && st.colour < 1);
            vec3 c = blossom_colour(&p, st.colour);
            const float *a = p.colour_open, *b = p.colour_faded;
            CHECK(c.x >= fminf(a[0], b[0]) && c.x <= fmaxf(a[0], b[0]));
            CHECK(c.y >= fminf(a[1], b[1]) && c.y <= fmaxf(a[1], b[1]));
            CHECK(c.z >= fminf(a[2], b[2]) && c.z <= fmaxf(a[2], b[2]));
        }
    }
    CHECK(first < p.first_day + 0.01 && last > p.last_day - 0.01); /* the whole season is used */
    CHECK_INT(blossom_particle_count(&p, 11, 3, 40), 200);      /* 5 a point, 40 points */
    p.max_per_plant = 50;
    CHECK_INT(blossom_particle_count(&p, 11, 3, 40), 50);
}

TEST(crown_points_are_the_leaves)
{
    scene *s = orchard();
    err_buf err = {0};
    float *pts = NULL;
    uint32_t n = 0;
    CHECK(s != NULL);
    if (!s) return;
    CHECK_INT(blossom_crown_points(s, 0, &pts, &n, &err), 0);
    CHECK_INT(n, 40);
    for (uint32_t k = 0; pts && k < n; k++) CHECK(pts[3 * k + 2] >= 4 && pts[3 * k + 2] <= 6.1);
    free(pts);
    scene_free(s);
}

/* The petals alive on `day` in a fresh orchard, with their count; the scene is returned. */
static scene *bloom(const blossom_params *p, double day, uint64_t seed, blossom_report *rep)
{
    scene *s = orchard();
    err_buf err = {0};
    if (!s) return NULL;
    if (blossom_add(s, 0, p, day, seed, rep, &err)) {
        fprintf(stderr, "blossom_add: %s\n", err.msg);
        scene_free(s);
        return NULL;
    }
    return s;
}

TEST(petals_deterministic_for_a_seed)
{
    blossom_params p = busy();
    blossom_report r1, r2, r3;
    scene *a = bloom(&p, 110, 42, &r1), *b = bloom(&p, 110, 42, &r2), *c = bloom(&p, 110, 43, &r3);
    CHECK(a && b && c);
    if (!a || !b || !c) goto done;
    CHECK_INT(r1.plants, 2); /* the two cherries, not the beech */
    CHECK_INT(r1.particles, 400);
    CHECK(r1.petals > 50 && r1.petals < 400);
    CHECK_INT(a->n_instances, 3 + r1.petals);
    CHECK_INT(a->n_instances, b->n_instances);
    CHECK(memcmp(a->instances, b->instances, (size_t)a->n_instances * sizeof *a->instances) == 0);
    CHECK(a->n_instances != c->n_instances ||
          memcmp(a->instances, c->instances, (size_t)a->n_instances * sizeof *a->instances) != 0);
    /* the count is the particles alive on the day, counted directly */
    uint64_t alive = 0;
    for (uint32_t plant = 0; plant < 3; plant += 2)
        for (uint32_t k = 0; k < blossom_particle_count(&p, 42, plant, 40); k++) {
            blossom_particle q;
            blossom_particle_draw(&p, 42, plant, k, 40, &q);
            alive += (uint64_t)blossom_particle_at(&p, &q, 110).alive;
        }
    CHECK_INT(r1.petals, alive);
    /* one petal species, flagged as no plant, its variants the colour ramp */
    CHECK_INT(a->n_species, 3);
    CHECK_STR_CONTAINS(a->species[2].name, "blossom cherry");
    CHECK_INT(a->species[2].ground_cover, 1);
    CHECK_INT(a->species[2].n_variants, BLOSSOM_COLOURS);
    for (uint32_t v = 0; v < BLOSSOM_COLOURS; v++) {
        const prototype *pr = &a->prototypes[a->species[2].first_prototype + v];
        vec3 col = a->materials[scene_triangle_material(a, pr->mesh, 0)].albedo;
        CHECK(col.x >= fminf(p.colour_open[0], p.colour_faded[0]) && col.x <= fmaxf(p.colour_open[0], p.colour_faded[0]));
        CHECK(col.y >= fminf(p.colour_open[1], p.colour_faded[1]) && col.y <= fmaxf(p.colour_open[1], p.colour_faded[1]));
        CHECK(col.z >= fminf(p.colour_open[2], p.colour_faded[2]) && col.z <= fmaxf(p.colour_open[2], p.colour_faded[2]));
    }
done:
    scene_free(a), scene_free(b), scene_free(c);
}

TEST(none_outside_the_season)
{
    blossom_params p = busy();
    blossom_report r;
    scene *s = bloom(&p, 60, 42, &r);
    CHECK(s != NULL);
    if (!s) return;
    CHECK_INT(r.petals, 0);
    CHECK_INT(r.particles, 400);
    CHECK_INT(s->n_instances, 3);
    CHECK_INT(s->n_species, 2); /* no petal species for no petals */
    scene_free(s);
}

/* Without drift, every petal's centre is a crown point carried by its plant's transform, and
 * its radii are metres in the world whatever the plant's scale. */
TEST(petals_in_the_plants_frame)
{
    blossom_params p = busy();
    p.speed_max = 0;
    blossom_report r;
    scene *s = bloom(&p, 112, 9, &r);
    float *pts = NULL;
    uint32_t n = 0;
    err_buf err = {0};
    CHECK(s != NULL);
    if (!s) return;
    CHECK_INT(blossom_crown_points(s, 0, &pts, &n, &err), 0);
    uint32_t on_second = 0;
    for (uint32_t i = 3; pts && i < s->n_instances; i++) {
        const xform3x4 *xf = &s->instances[i].xf;
        vec3 c = v3(xf->m[0][3], xf->m[1][3], xf->m[2][3]);
        double best = 1e30;
        int best_plant = -1;
        for (uint32_t plant = 0; plant < 3; plant += 2)
            for (uint32_t k = 0; k < n; k++) {
                vec3 w = xf_point(&s->instances[plant].xf, v3(pts[3 * k], pts[3 * k + 1], pts[3 * k + 2]));
                double d = v3_len(v3_sub(w, c));
                if (d < best) best = d, best_plant = (int)plant;
            }
        CHECK(best < 1e-4);
        on_second += best_plant == 2;
        double rx = v3_len(v3(xf->m[0][0], xf->m[1][0], xf->m[2][0]));
        double ry = v3_len(v3(xf->m[0][1], xf->m[1][1], xf->m[2][1]));
        CHECK(rx >= p.bud_size * p.size_min * 0.999 && rx <= p.size_max * 1.001);
        CHECK(ry >= p.aspect_min * p.bud_size * p.size_min * 0.999 && ry <= rx * 1.001);
    }
    CHECK(on_second > 10 && on_second < r.petals - 10); /* both plants bloom */
    free(pts);
    scene_free(s);
}

/* A species' petals do not depend on which species bloomed before it: the plants keep their
 * instance indices, and only they seed the particles. */
TEST(species_order_does_not_matter)
{
    blossom_params p = busy();
    scene *a = orchard(), *b = orchard();
    err_buf err = {0};
    blossom_report ra0, ra1, rb0, rb1;
    CHECK(a && b);
    if (!a || !b) goto done;
    CHECK_INT(blossom_add(a, 0, &p, 111, 5, &ra0, &err), 0); /* cherry, then beech */
    CHECK_INT(blossom_add(a, 1, &p, 111, 5, &ra1, &err), 0);
    CHECK_INT(blossom_add(b, 1, &p, 111, 5, &rb1, &err), 0); /* beech, then cherry */
    CHECK_INT(blossom_add(b, 0, &p, 111, 5, &rb0, &err), 0);
    CHECK_INT(ra0.petals, rb0.petals);
    CHECK_INT(ra1.petals, rb1.petals);
    CHECK(ra0.petals > 0 && ra1.petals > 0);
    CHECK_INT(a->n_instances, b->n_instances);
    if (a->n_instances != b->n_instances) goto done;
    /* a holds 3 plants, cherry's petals, beech's; b holds 3 plants, beech's, cherry's */
    for (uint64_t k = 0; k < ra0.petals; k++)
        CHECK(memcmp(&a->instances[3 + k].xf, &b->instances[3 + rb1.petals + k].xf, sizeof(xform3x4)) == 0);
    for (uint64_t k = 0; k < ra1.petals; k++)
        CHECK(memcmp(&a->instances[3 + ra0.petals + k].xf, &b->instances[3 + k].xf, sizeof(xform3x4)) == 0);
done:
    scene_free(a), scene_free(b);
}

TEST(bad_parameters)
{
    scene *s = orchard();
    err_buf err = {0};
    CHECK(s != NULL);
    if (!s) return;
    blossom_params p = busy();
    p.last_day = p.first_day;
    CHECK_INT(blossom_add(s, 0, &p, 110, 1, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "last_day");
    p = busy(), p.lifetime_min = 0;
    CHECK_INT(blossom_add(s, 0, &p, 110, 1, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "lifetime");
    p = busy(), p.colour_open[1] = 1.5f;
    CHECK_INT(blossom_add(s, 0, &p, 110, 1, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "[0, 1]");
    p = busy(), p.size_max = NAN;
    CHECK_INT(blossom_add(s, 0, &p, 110, 1, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "size");
    p = busy();
    CHECK_INT(blossom_add(s, 7, &p, 110, 1, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "species 7");
    CHECK_INT(s->n_instances, 3);
    p.max_instances = 5;
    CHECK_INT(blossom_add(s, 0, &p, 110, 1, NULL, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "max_instances");
    CHECK_INT(s->n_instances, 3 + 5);
    scene_free(s);
}

TEST_LIST(TEST_CASE(alive_by_lifetime), TEST_CASE(draws_within_their_ranges), TEST_CASE(crown_points_are_the_leaves),
          TEST_CASE(petals_deterministic_for_a_seed), TEST_CASE(none_outside_the_season),
          TEST_CASE(petals_in_the_plants_frame), TEST_CASE(species_order_does_not_matter),
          TEST_CASE(bad_parameters))
