/* test_render_math.c — transforms, the camera, BSDFs, sun sampling and meshes. */
#include "harness.h"

#include "render/bsdf.h"
#include "render/camera.h"
#include "render/film.h"
#include "render/leaf_coat.h"
#include "render/lights.h"
#include "scene/mesh.h"
#include "scene_build/shapes.h"
#include "util/vec3.h"

TEST(normal_transform_rotation)
{
    /* A rotation maps normals like vectors. */
    xform3x4 x = xf_trs(v3(1, 2, 3), v3(0, 0, 45), v3(1, 1, 1));
    vec3 n = v3_norm(xf_normal(&x, v3(1, 0, 0)));
    vec3 d = v3_norm(xf_vector(&x, v3(1, 0, 0)));
    CHECK_NEAR(n.x, d.x, 1e-6);
    CHECK_NEAR(n.y, d.y, 1e-6);
    CHECK_NEAR(n.z, d.z, 1e-6);
    CHECK_NEAR(n.x, sqrt(0.5), 1e-6);
    CHECK_NEAR(n.y, sqrt(0.5), 1e-6);
}

TEST(normal_transform_nonuniform_scale)
{
    /* A plane x + z = 0 (normal (1,0,1)) stretched 2x along x becomes x/2 + z = 0: normal
     * (1, 0, 2) before normalising; normals must stay perpendicular to transformed tangents. */
    xform3x4 x = xf_trs(v3(0, 0, 0), v3(10, 20, 30), v3(2, 1, 0.5f));
    vec3 n0 = v3_norm(v3(1, 0.3f, 1)), t0 = v3_norm(v3_cross(n0, v3(0, 1, 0)));
    vec3 n = xf_normal(&x, n0), t = xf_vector(&x, t0);
    CHECK_NEAR(v3_dot(v3_norm(n), v3_norm(t)), 0.0, 1e-6);
    /* mirroring keeps the normal on the outside: det < 0 flips the cofactor result back */
    xform3x4 m = xf_trs(v3(0, 0, 0), v3(0, 0, 0), v3(-1, 1, 1));
    vec3 nm = v3_norm(xf_normal(&m, v3(1, 0, 0)));
    CHECK_NEAR(nm.x, -1.0, 1e-6);
}

TEST(trs_composition)
{
    xform3x4 a = xf_trs(v3(1, 0, 0), v3(0, 0, 90), v3(2, 2, 2));
    vec3 p = xf_point(&a, v3(1, 0, 0)); /* scale → (2,0,0), rotate 90° about z → (0,2,0), +t */
    CHECK_NEAR(p.x, 1.0, 1e-6);
    CHECK_NEAR(p.y, 2.0, 1e-6);
    CHECK_NEAR(p.z, 0.0, 1e-6);
    xform3x4 b = xf_trs(v3(0, 0, 5), v3(0, 0, 0), v3(1, 1, 1));
    xform3x4 ab = xf_compose(&b, &a);
    vec3 q = xf_point(&ab, v3(1, 0, 0));
    CHECK_NEAR(q.z, 5.0, 1e-6);
    CHECK_NEAR(q.y, 2.0, 1e-6);
}

TEST(camera_frame)
{
    camera_settings cs = {.position = {0, 0, 0}, .has_look_at = 1, .look_at = {0, 10, 0}, .up = {0, 0, 1}, .fov_deg = 90};
    camera c;
    camera_init(&c, &cs, 200, 100);
    vec3 mid = camera_direction(&c, 100, 50);
    CHECK_NEAR(mid.y, 1.0, 1e-6);
    /* right edge of a 90° horizontal field: 45° to the right (+x when looking north) */
    vec3 r = camera_direction(&c, 200, 50);
    CHECK_NEAR(r.x, sqrt(0.5), 1e-6);
    CHECK_NEAR(r.y, sqrt(0.5), 1e-6);
    /* top row looks up; vertical half-angle follows the aspect */
    vec3 t = camera_direction(&c, 100, 0);
    CHECK(t.z > 0);
    CHECK_NEAR(t.z / t.y, 0.5, 1e-6);
}

TEST(lambert_sampling_matches_eval)
{
    material m = {.bsdf = SYLVA_BSDF_LAMBERT, .albedo = {0.5f, 0.5f, 0.5f}, .texture = -1};
    vec3 n = v3_norm(v3(0.2f, -0.1f, 1)), wo = n;
    double est = 0;
    int k = 0;
    for (int i = 0; i < 64; i++)
        for (int j = 0; j < 64; j++) {
            bsdf_sample s;
            CHECK(bsdf_sample_dir(&m, m.albedo, n, wo, 0.5f, (i + 0.5f) / 64, (j + 0.5f) / 64, &s));
            float pdf;
            vec3 f = bsdf_eval(&m, m.albedo, n, wo, s.wi, &pdf);
            CHECK_NEAR(pdf, s.pdf, 1e-5);
            CHECK_NEAR(f.x, 0.5 / M_PI, 1e-6);
            est += f.x * v3_dot(n, s.wi) / s.pdf;
            k++;
        }
    CHECK_NEAR(est / k, 0.5, 1e-3); /* reflected fraction = albedo */
}

TEST(leaf_transmits_to_the_other_side)
{
    material m = {.bsdf = SYLVA_BSDF_LEAF, .albedo = {0.3f, 0.3f, 0.3f}, .transmittance = {0.1f, 0.1f, 0.1f}, .texture = -1};
    vec3 n = v3(0, 0, 1), wo = v3(0, 0, 1);
    float pdf, e = leaf_coat_albedo(1.0f), under = (1.0f - e) / (float)(M_PI * (1.0f - leaf_coat_albedo_mean()));
    /* straight through: the transmittance under the coat, entering and leaving at normal incidence */
    vec3 ft = bsdf_eval(&m, m.albedo, n, wo, v3(0, 0, -1), &pdf);
    CHECK_NEAR(ft.x, 0.1 * under * (1.0f - e), 1e-6);
    CHECK_NEAR(pdf, (1.0f - e / (e + (1.0f - e) * 0.4f)) * 0.25f / M_PI, 1e-6);
    CHECK_NEAR(bsdf_transmit_probability(&m, m.albedo), 0.25, 1e-6);
    /* the coat reflects 3 to 4 % at normal incidence (index 1.45: 3.4 % on a smooth face) */
    CHECK(e > 0.025f && e < 0.035f);
    CHECK_NEAR(leaf_coat_fresnel(1.0f, 1.45f), 0.0337, 1e-4);
    /* the leaf returns E + (1 - E)(r + t) */
    double est = 0;
    int k = 0;
    for (int l = 0; l < 8; l++)
        for (int i = 0; i < 64; i++)
            for (int j = 0; j < 64; j++) {
                bsdf_sample s;
                float u0 = (float)fmod((k + 0.5) * 0.6180339887, 1.0);
                if (bsdf_sample_dir(&m, m.albedo, n, wo, u0, (i + 0.5f) / 64, (j + 0.5f) / 64, &s))
                    est += s.f.x * fabsf(v3_dot(n, s.wi)) / s.pdf;
                k++;
            }
    CHECK_NEAR(est / k, e + (1.0f - e) * 0.4f, 2e-3);
}

/* White furnace: a leaf with r + t = 1 under light from every direction returns all of it and
 * never more, at every angle of view; the sampled pdf is the one bsdf_eval states, and the pdf
 * integrates to at most 1 over the sphere. Fails with an uncoupled coat (f_coat + r / pi). */
TEST(leaf_white_furnace)
{
    material m = {.bsdf = SYLVA_BSDF_LEAF, .albedo = {0.7f, 0.7f, 0.7f}, .transmittance = {0.3f, 0.3f, 0.3f}, .texture = -1};
    vec3 n = v3(0, 0, 1);
    for (int a = 0; a <= 8; a++) {
        float mu = a == 0 ? 0.05f : a / 8.0f;
        vec3 wo = v3(sqrtf(1.0f - mu * mu), 0, mu);
        double est = 0, pdf_sum = 0;
        int k = 0, mismatched = 0;
        for (int l = 0; l < 16; l++)
            for (int i = 0; i < 64; i++)
                for (int j = 0; j < 64; j++) {
                    bsdf_sample s;
                    /* lobe choice from a golden-ratio sequence: strata of u0 would
                     * quantize the coat's share */
                    float u0 = (float)fmod((k + 0.5) * 0.6180339887, 1.0), u1 = (i + 0.5f) / 64, u2 = (j + 0.5f) / 64;
                    if (bsdf_sample_dir(&m, m.albedo, n, wo, u0, u1, u2, &s)) {
                        est += s.f.x * fabsf(v3_dot(n, s.wi)) / s.pdf;
                        float pdf;
                        bsdf_eval(&m, m.albedo, n, wo, s.wi, &pdf);
                        mismatched += fabsf(pdf - s.pdf) > 1e-4f * s.pdf;
                    }
                    k++;
                    /* the pdf over the sphere, uniform directions from (u1, u2) and u0's sign */
                    float z = 1.0f - 2.0f * u1, r = sqrtf(fmaxf(0.0f, 1.0f - z * z)), phi = 2.0f * (float)M_PI * (u2 + (l + 0.5f) / 1024);
                    float pdf;
                    bsdf_eval(&m, m.albedo, n, wo, v3(r * cosf(phi), r * sinf(phi), z), &pdf);
                    pdf_sum += pdf * 4.0 * M_PI;
                }
        CHECK_INT(mismatched, 0);
        CHECK(est / k <= 1.0 + 2e-3);
        CHECK(est / k > 0.98);
        CHECK(pdf_sum / k <= 1.0 + 2e-3);
        CHECK(pdf_sum / k > 0.9);
    }
}

TEST(sun_cone_sampling)
{
    sun_settings sun = {.enabled = 1, .direction = {0, 0.6, 0.8}, .irradiance = 2, .color = {1, 1, 1},
                        .angular_diameter_deg = 2};
    sky_settings sky = {.model = SKY_NONE};
    lights l;
    err_buf err;
    CHECK(lights_init(&l, &sun, &sky, 0, 0, 0, &err) == 0);
    /* irradiance at normal incidence recovered from the disk radiance: E = L * pi sin^2 */
    double e = 0;
    int n = 0;
    for (int i = 0; i < 32; i++)
        for (int j = 0; j < 32; j++) {
            vec3 wi;
            float pdf = lights_sun_sample(&l, (i + 0.5f) / 32, (j + 0.5f) / 32, &wi);
            CHECK(lights_in_sun(&l, wi));
            e += l.summary.sun_radiance.x * v3_dot(wi, l.summary.sun_dir) / pdf;
            n++;
        }
    CHECK_NEAR(e / n, 2.0, 1e-3);
    lights_free(&l);
}

TEST(shapes_closed_and_outward)
{
    err_buf err;
    shape_spec specs[2] = {{.kind = SHAPE_BOX, .size = {1, 2, 3}}, {.kind = SHAPE_SPHERE, .radius = 2, .subdivisions = 3}};
    for (int k = 0; k < 2; k++) {
        mesh *m = mesh_new();
        CHECK(shape_build(&specs[k], 0, m, &err) == 0);
        /* divergence theorem: sum of (centroid . area normal) / 3 = volume > 0 for outward faces */
        double vol = 0;
        for (uint32_t t = 0; t < m->nt; t++) {
            const float *a = m->pos + m->tri[t * 3] * 3, *b = m->pos + m->tri[t * 3 + 1] * 3, *c = m->pos + m->tri[t * 3 + 2] * 3;
            vec3 pa = v3(a[0], a[1], a[2]), pb = v3(b[0], b[1], b[2]), pc = v3(c[0], c[1], c[2]);
            vol += v3_dot(pa, v3_cross(pb, pc)) / 6.0;
        }
        if (k == 0) CHECK_NEAR(vol, 6.0, 1e-4);
        else CHECK_NEAR(vol, 4.0 / 3.0 * M_PI * 8, 1.5); /* icosphere level 3 is slightly smaller */
        if (k == 1) CHECK_INT(m->nt, 20 * 64);
        mesh_free(m);
    }
}

TEST(mesh_append_checks)
{
    err_buf err;
    mesh *m = mesh_new();
    float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    uint32_t bad[3] = {0, 1, 3}, good[3] = {0, 1, 2};
    CHECK(mesh_append(m, pos, NULL, NULL, 3, bad, NULL, 0, 1, &err) != 0);
    CHECK_STR_CONTAINS(err.msg, "vertex 3");
    float nan_pos[9] = {0, 0, 0, NAN, 0, 0, 0, 1, 0};
    CHECK(mesh_append(m, nan_pos, NULL, NULL, 3, good, NULL, 0, 1, &err) != 0);
    CHECK(mesh_append(m, pos, NULL, NULL, 3, good, NULL, 2, 1, &err) == 0);
    CHECK(mesh_append(m, pos, NULL, NULL, 3, good, NULL, 2, 1, &err) == 0);
    CHECK_INT(m->nt, 2);
    CHECK_INT(m->tri[3], 3); /* second call's indices are offset */
    CHECK_NEAR(m->nrm[2], 1.0, 1e-6);
    CHECK_INT(m->mat[1], 2);
    mesh_free(m);
}

/* The frame stays finite whatever the scale of the numbers: a look_at whose offset from the
 * position is beyond float range, or below it, still aims the camera (both used to give NaN
 * directions and a black image). */
TEST(camera_frame_extreme_offsets)
{
    camera_settings far = {.position = {-3e38, 0, 0}, .has_look_at = 1, .look_at = {3e38, 0, 0},
                           .up = {0, 0, 1e300}, .fov_deg = 60};
    camera_settings near = {.position = {0, 0, 2}, .has_look_at = 1, .look_at = {0, 1e-30, 2},
                            .up = {0, 0, 1e-40}, .fov_deg = 60};
    camera c;
    camera_init(&c, &far, 64, 32);
    vec3 d = camera_direction(&c, 32, 16);
    CHECK_NEAR(d.x, 1.0, 1e-6);
    CHECK(isfinite(c.right.y) && isfinite(c.up.z));
    camera_init(&c, &near, 64, 32);
    d = camera_direction(&c, 32, 16);
    CHECK_NEAR(d.y, 1.0, 1e-6);
    CHECK_NEAR(c.up.z, 1.0, 1e-6);
}

/* A frame that cannot fit, and absurd work, are refused before anything is built. */
TEST(film_refuses_what_cannot_be_rendered)
{
    err_buf err = {{0}};
    CHECK_INT(film_check(640, 360, 16, &err), 0);
    CHECK_INT(film_check(16384, 16384, 1000000, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "16384x16384 pixels at 1000000 samples per pixel is 2.68e+14 "
                                "camera samples, more than the 1e+13");
    setenv("SYLVA_MEMORY_LIMIT", "100M", 1);
    CHECK_INT(film_check(4096, 4096, 1, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "a 4096x4096 frame needs about 1.4 GiB of memory, more than the "
                                "100 MiB SYLVA_MEMORY_LIMIT allows; lower the image size");
    CHECK(film_new(4096, 4096, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "a 4096x4096 frame needs");
    unsetenv("SYLVA_MEMORY_LIMIT");
}

TEST_LIST(TEST_CASE(normal_transform_rotation), TEST_CASE(normal_transform_nonuniform_scale),
          TEST_CASE(trs_composition), TEST_CASE(camera_frame),
          TEST_CASE(lambert_sampling_matches_eval), TEST_CASE(leaf_transmits_to_the_other_side), TEST_CASE(leaf_white_furnace),
          TEST_CASE(sun_cone_sampling), TEST_CASE(shapes_closed_and_outward), TEST_CASE(mesh_append_checks),
          TEST_CASE(camera_frame_extreme_offsets), TEST_CASE(film_refuses_what_cannot_be_rendered))
