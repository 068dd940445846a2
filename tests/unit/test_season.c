/* test_season.c — seasons and phenology (phenology.h, scene_season.h): season names and dates as
 * days of the year, bad ones refused at their place in the file; one scene built in summer and
 * in winter (and in autumn) holds the same instances (prototype, transform, development) in the
 * same order; in winter no ray meets a deciduous species' leaves, while its wood, an evergreen's
 * leaves and every plant's place stay; in autumn only the deciduous leaves' materials turn, and
 * the share of whole leaves the day gives is down, the same leaves on every run; the command
 * line's --season overrides the key. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "work_dir.h"
#include "render/accel.h"
#include "season/phenology.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "season/scene_season.h"
#include "scene/mesh.h"

/* A deciduous "oak" (a leaf quad 3 m up), an evergreen "pine" (the same), a deciduous "post" of
 * wood (a Lambertian box): one plant of each along x. */
static const char *scene_text =
    "image: {width: 16, height: 12, spp: 1}\n"
    "camera: {position: [0, -30, 5], look_at: [0, 0, 3]}\n"
    "%s"
    "materials:\n"
    "  foliage: {type: leaf, albedo: [0.1, 0.3, 0.05], transmittance: [0.05, 0.2, 0.02]}\n"
    "  wood: {albedo: [0.3, 0.25, 0.2]}\n"
    "species:\n"
    "  oak: {shape: quad, size: [2, 2], material: foliage, phenology: {habit: deciduous, leaf_out: 110, leaf_fall: 300}}\n"
    "  pine: {shape: quad, size: [2, 2], material: foliage, phenology: {habit: evergreen}}\n"
    "  post: {shape: box, size: [0.5, 0.5, 1], material: wood, phenology: {habit: deciduous}}\n"
    "plants:\n"
    "  - {species: oak, position: [0, 0, 3], rotation: 30}\n"
    "  - {species: pine, position: [10, 0, 3], scale: 1.5}\n"
    "  - {species: post, position: [20, 0, 3]}\n"
    "  - {species: oak, position: [30, 0, 3], age: 0.5}\n";

static scene_file *load_season(const char *season_line, err_buf *err)
{
    static char text[4096];
    static int k;
    char name[64];
    snprintf(text, sizeof text, scene_text, season_line);
    snprintf(name, sizeof name, "season_%d.yaml", k++);
    const char *path = work_file(name, text);
    CHECK(path != NULL);
    return path ? scene_file_load(path, NULL, err) : NULL;
}

static scene *build_season(const char *season_line)
{
    err_buf err = {{0}};
    scene_file *sf = load_season(season_line, &err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    if (!sf) return NULL;
    scene *s = scene_build(sf, NULL, NULL, &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    scene_file_free(sf);
    return s;
}

/* The first thing a ray straight down from 10 m above (x, y) meets: 1 a plant's leaf, 2 a
 * plant's other surface, 0 nothing. */
static int probe(const accel *a, const scene *s, float x, float y)
{
    struct RTCRayHit rh = {.ray = {.org_x = x, .org_y = y, .org_z = 10, .dir_z = -1, .tnear = 0, .tfar = INFINITY,
                                   .mask = 0xffffffffu},
                           .hit = {.geomID = RTC_INVALID_GEOMETRY_ID, .instID = {RTC_INVALID_GEOMETRY_ID}}};
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    rtcIntersect1(a->top, &ic, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return 0;
    hit_info h;
    accel_shade(a, &rh, &h);
    (void)s;
    return h.mat && h.mat->bsdf == SYLVA_BSDF_LEAF ? 1 : 2;
}

TEST(season_names_and_dates)
{
    err_buf err = {{0}};
    uint32_t d = 0;
    CHECK_INT(season_day_parse("winter", &d, &err), 0);
    CHECK_INT(d, SEASON_WINTER_DAY);
    CHECK_INT(season_day_parse("autumn", &d, &err), 0);
    CHECK_INT(d, SEASON_AUTUMN_DAY);
    CHECK_INT(season_day_parse("2026-01-01", &d, &err), 0);
    CHECK_INT(d, 1);
    CHECK_INT(season_day_parse("2024-03-01", &d, &err), 0); /* a leap year */
    CHECK_INT(d, 61);
    CHECK_INT(season_day_parse("2026-03-01", &d, &err), 0);
    CHECK_INT(d, 60);
    CHECK_INT(season_day_parse("2026-12-31", &d, &err), 0);
    CHECK_INT(d, 365);
    CHECK_INT(season_day_parse("2023-02-29", &d, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "days 01 to 28");
    CHECK_INT(season_day_parse("2026-13-01", &d, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "a month is 01 to 12");
    CHECK_INT(season_day_parse("fall", &d, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "spring, summer, autumn or winter");
    CHECK_INT(season_day_parse("2026-1-15", &d, &err), -1);
}

TEST(deciduous_in_leaf_between_its_days)
{
    phenology oak = {HABIT_DECIDUOUS, 110, 300}, pine = {HABIT_EVERGREEN, 110, 300};
    CHECK_INT(phenology_in_leaf(&oak, 109), 0);
    CHECK_INT(phenology_in_leaf(&oak, 110), 1);
    CHECK_INT(phenology_in_leaf(&oak, 299), 1);
    CHECK_INT(phenology_in_leaf(&oak, 300), 0);
    CHECK_INT(phenology_in_leaf(&pine, 1), 1);
    phenology south = {HABIT_DECIDUOUS, 280, 120}; /* in leaf over the new year */
    CHECK_INT(phenology_in_leaf(&south, 10), 1);
    CHECK_INT(phenology_in_leaf(&south, 200), 0);
}

TEST(leaves_turn_from_colouring_to_leaf_fall)
{
    phenology oak = {HABIT_DECIDUOUS, 110, 300, 270, {0.3, 0.1, 0}}, pine = {HABIT_EVERGREEN, 110, 300, 270, {0}};
    CHECK_NEAR(phenology_autumn_share(&oak, 200), 0, 0);
    CHECK_NEAR(phenology_autumn_share(&oak, 270), 0, 0);
    CHECK_NEAR(phenology_autumn_share(&oak, 285), 0.5, 1e-12);
    CHECK_NEAR(phenology_autumn_share(&oak, 299), 29.0 / 30, 1e-12);
    CHECK_NEAR(phenology_autumn_share(&oak, 300), 0, 0); /* leaf-off */
    CHECK_NEAR(phenology_autumn_share(&oak, 50), 0, 0);
    CHECK_NEAR(phenology_autumn_share(&pine, 285), 0, 0);
    phenology south = {HABIT_DECIDUOUS, 280, 120, 60, {0.3, 0.1, 0}}; /* turning from March to April */
    CHECK_NEAR(phenology_autumn_share(&south, 90), 0.5, 1e-12);
    CHECK_NEAR(phenology_autumn_share(&south, 10), 0, 0);
}

TEST(summer_and_winter_hold_the_same_instances)
{
    scene *summer = build_season(""), *winter = build_season("season: winter\n"),
          *dated = build_season("season: 2026-07-01\n");
    CHECK(summer && winter && dated);
    if (summer && winter && dated) {
        CHECK_INT(summer->n_instances, 4);
        CHECK_INT(winter->n_instances, summer->n_instances);
        CHECK_INT(winter->n_prototypes, summer->n_prototypes);
        for (uint32_t i = 0; i < summer->n_instances && i < winter->n_instances; i++) {
            CHECK_INT(winter->instances[i].prototype, summer->instances[i].prototype);
            CHECK_INT(winter->instances[i].development, summer->instances[i].development);
            CHECK(!memcmp(&winter->instances[i].xf, &summer->instances[i].xf, sizeof(xform3x4)));
        }
        /* the oak bare, the pine and the post as in summer; a July date is summer */
        CHECK_INT(summer->prototypes[0].mesh->nt, 2);
        CHECK_INT(winter->prototypes[0].mesh->nt, 0);
        CHECK_INT(dated->prototypes[0].mesh->nt, 2);
        CHECK_INT(winter->prototypes[1].mesh->nt, summer->prototypes[1].mesh->nt);
        CHECK_INT(winter->prototypes[2].mesh->nt, summer->prototypes[2].mesh->nt);
        CHECK(summer->prototypes[2].mesh->nt > 0);
    }
    scene_free(summer), scene_free(winter), scene_free(dated);
}

TEST(winter_rays_meet_no_deciduous_leaf)
{
    scene *summer = build_season("season: summer\n"), *winter = build_season("season: winter\n");
    CHECK(summer && winter);
    if (summer && winter) {
        accel as, aw;
        err_buf err = {{0}};
        CHECK_INT(accel_build(&as, summer, 1, &err), 0);
        CHECK_INT(accel_build(&aw, winter, 1, &err), 0);
        static const float x[4] = {0, 10, 20, 30};
        static const int in_summer[4] = {1, 1, 2, 1}, in_winter[4] = {0, 1, 2, 0};
        for (int i = 0; i < 4; i++) {
            CHECK_INT(probe(&as, summer, x[i], 0.1f), in_summer[i]);
            CHECK_INT(probe(&aw, winter, x[i], 0.1f), in_winter[i]);
        }
        /* nowhere over the oaks' crowns does a winter ray meet a leaf */
        for (int k = 0; k < 21 * 21; k++) {
            float dx = -1.5f + 0.15f * (float)(k % 21), dy = -1.5f + 0.15f * (float)(k / 21);
            CHECK(probe(&aw, winter, dx, dy) != 1);
            CHECK(probe(&aw, winter, 30 + dx, dy) != 1);
        }
        accel_free(&as), accel_free(&aw);
    }
    scene_free(summer), scene_free(winter);
}

TEST(autumn_turns_only_the_deciduous_leaves)
{
    scene *summer = build_season(""), *autumn = build_season("season: 2026-10-12\n"); /* day 285 */
    CHECK(summer && autumn);
    if (summer && autumn) {
        CHECK_INT(autumn->n_instances, summer->n_instances);
        for (uint32_t i = 0; i < summer->n_instances && i < autumn->n_instances; i++) {
            CHECK_INT(autumn->instances[i].prototype, summer->instances[i].prototype);
            CHECK(!memcmp(&autumn->instances[i].xf, &summer->instances[i].xf, sizeof(xform3x4)));
        }
        /* the oak (colouring 270, leaf_fall 300: half turned) toward the default autumn colour
         * (0.3, 0.14, 0.03) from foliage (0.1, 0.3, 0.05), its transmittance in proportion */
        const mesh *oak = autumn->prototypes[0].mesh, *pine = autumn->prototypes[1].mesh;
        CHECK_INT(oak->nt, 2);
        const material *turned = &autumn->materials[scene_triangle_material(autumn, oak, 0)];
        const material *green = &autumn->materials[scene_triangle_material(autumn, pine, 0)];
        CHECK_INT(turned->bsdf, SYLVA_BSDF_LEAF);
        CHECK_STR_CONTAINS(turned->name, "oak, autumn");
        CHECK_NEAR(turned->albedo.x, 0.2, 1e-6);
        CHECK_NEAR(turned->albedo.y, 0.22, 1e-6);
        CHECK_NEAR(turned->albedo.z, 0.04, 1e-6);
        CHECK_NEAR(turned->transmittance.x, 0.05 * 2.0, 1e-6);
        CHECK_NEAR(turned->transmittance.y, 0.2 * 0.22 / 0.3, 1e-6);
        /* the evergreen keeps the shared material, untouched */
        CHECK_STR_CONTAINS(green->name, "foliage");
        CHECK_NEAR(green->albedo.y, 0.3, 1e-6);
        CHECK_INT(autumn->n_materials, summer->n_materials + 1);
    }
    scene_free(summer), scene_free(autumn);
}

TEST(leaves_fall_ever_faster_while_they_turn)
{
    phenology oak = {HABIT_DECIDUOUS, 110, 300, 270, {0.3, 0.1, 0}}, pine = {HABIT_EVERGREEN, 110, 300, 270, {0}};
    CHECK_NEAR(phenology_fallen_share(&oak, 200), 0, 0);
    CHECK_NEAR(phenology_fallen_share(&oak, 270), 0, 0);
    CHECK_NEAR(phenology_fallen_share(&oak, 285), 0.25, 1e-12); /* half turned, a quarter down */
    CHECK_NEAR(phenology_fallen_share(&oak, 294), 0.64, 1e-12);
    CHECK_NEAR(phenology_fallen_share(&oak, 300), 1, 0); /* leaf-off */
    CHECK_NEAR(phenology_fallen_share(&oak, 20), 1, 0);
    CHECK_NEAR(phenology_fallen_share(&pine, 294), 0, 0);
}

/* A mesh of n leaf quads (4 vertices, 2 triangles each, of material leaf) with a wood triangle
 * after every tenth quad; caller frees. */
static mesh *leaf_quads(uint32_t n, int32_t leaf, int32_t wood)
{
    mesh *m = mesh_new();
    CHECK(m != NULL);
    err_buf err = {{0}};
    for (uint32_t q = 0; m && q < n; q++) {
        float x = (float)(q % 64), y = (float)(q / 64);
        const float pos[12] = {x, y, 0, x + 0.5f, y, 0, x + 0.5f, y + 0.5f, 0, x, y + 0.5f, 0};
        static const uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
        CHECK_INT(mesh_append(m, pos, NULL, NULL, 4, tri, NULL, leaf, 2, &err), 0);
        if (q % 10 == 9) CHECK_INT(mesh_append(m, pos, NULL, NULL, 3, tri, NULL, wood, 1, &err), 0);
    }
    return m;
}

/* Whole leaves fall, the share the day gives (within sampling error), the same leaves on every
 * run, more of them on a later day; wood and vertices stay. */
TEST(partial_leaf_fall_drops_whole_leaves_by_the_share)
{
    scene *s = build_season("");
    CHECK(s != NULL);
    if (!s) return;
    int32_t leaf = scene_find_material(s, "foliage"), wood = scene_find_material(s, "wood");
    CHECK(leaf >= 0 && wood >= 0);
    enum { N = 4000 };
    static const double shares[] = {0.04, 0.25, 0.5, 0.9, 1};
    uint64_t key = scene_leaf_fall_key("oak", 0);
    mesh *before = NULL;
    for (size_t i = 0; i < sizeof shares / sizeof shares[0]; i++) {
        mesh *m = leaf_quads(N, leaf, wood), *again = leaf_quads(N, leaf, wood);
        uint32_t nv = m->nv, dropped = 0, dropped_again = 0;
        err_buf err = {{0}};
        CHECK_INT(scene_drop_fallen_leaves(s, m, key, shares[i], &dropped, &err), 0);
        CHECK_INT(scene_drop_fallen_leaves(s, again, key, shares[i], &dropped_again, &err), 0);
        CHECK_INT(dropped % 2, 0); /* a leaf's two triangles together */
        /* binomial: 4 standard deviations of the share of N leaves */
        double got = dropped / 2.0 / N, sd = sqrt(shares[i] * (1 - shares[i]) / N);
        fprintf(stderr, "share %.2f: %.4f of the leaves down\n", shares[i], got);
        CHECK_NEAR(got, shares[i], 4 * sd + 1e-12);
        CHECK_INT(m->nv, nv);
        CHECK_INT(again->nt, m->nt);
        CHECK(!memcmp(again->tri, m->tri, (size_t)m->nt * 3 * sizeof *m->tri));
        uint32_t wood_left = 0, quads_left = 0;
        for (uint32_t t = 0; t < m->nt; t++) {
            if (m->mat[t] == wood) wood_left++;
            /* the first triangle of each leaf left is followed by its second */
            else if (m->tri[t * 3 + 1] == m->tri[t * 3] + 1) {
                quads_left++;
                CHECK(t + 1 < m->nt && m->tri[(t + 1) * 3] == m->tri[t * 3] &&
                      m->tri[(t + 1) * 3 + 2] == m->tri[t * 3] + 3);
            }
        }
        CHECK_INT(wood_left, N / 10);
        CHECK_INT(quads_left * 2 + wood_left, m->nt);
        /* every leaf left at this share was left at the smaller one before it */
        if (before) {
            uint32_t j = 0;
            for (uint32_t t = 0; t < m->nt; t++) {
                while (j < before->nt && memcmp(before->tri + j * 3, m->tri + t * 3, 3 * sizeof *m->tri)) j++;
                CHECK(j < before->nt);
            }
        }
        mesh_free(before), mesh_free(again);
        before = m;
    }
    CHECK_INT(before->nt, N / 10); /* all down: the wood alone */
    mesh_free(before);
    scene_free(s);
}

/* A bad season, snow or phenology is refused at its place: file:line:column and what would be
 * valid. Snow needs a terrain with procedural ground (here there is none; an inline grid
 * likewise). */
TEST(bad_season_is_located)
{
    static const struct { const char *line; const char *where; const char *says; } cases[] = {
        {"season: winterr\n", ":3:9:", "neither a season (spring, summer, autumn or winter) nor a date"},
        {"season: 2026-02-30\n", ":3:9:", "month 02 of 2026 has days 01 to 28"},
        {"season: {day: 3}\n", ":3:9:", "must be spring, summer, autumn, winter or a date YYYY-MM-DD"},
        {"snow: {cover: 0.8}\n", ":3:1:", "'snow' lies on the procedural ground of a terrain plugin"},
        {"snow: {cover: 1.5}\n", ":3:15:", "cover"},
        {"snow: {depth: 0.3}\n", ":3:8:", "depth"},
        {"snow: {min_height: 10000}\n", ":3:20:", "min_height"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        err_buf err = {{0}};
        scene_file *sf = load_season(cases[i].line, &err);
        CHECK(sf == NULL);
        scene_file_free(sf);
        CHECK_STR_CONTAINS(err.msg, cases[i].where);
        CHECK_STR_CONTAINS(err.msg, cases[i].says);
    }
}

/* Left out, a scene has no snow. */
TEST(snow_is_off_by_default)
{
    err_buf err = {{0}};
    scene_file *sf = load_season("", &err);
    CHECK(sf && !sf->snow.on);
    scene_file_free(sf);
}

TEST(bad_phenology_is_located)
{
    static const struct { const char *from, *to, *where, *says; } cases[] = {
        {"habit: deciduous, leaf_out: 110", "habit: leafy, leaf_out: 110", ":7:", "habit"},
        {"leaf_out: 110", "leaf_out: 400", ":7:", "leaf_out"},
        {"leaf_fall: 300", "leaf_fall: 110", ":7:", "leaf_fall (day 110) equals leaf_out"},
        {"{habit: evergreen}", "{habit: evergreen, leaf_fall: 200}", ":8:", "leaf days and autumn_color apply"},
        {"{habit: evergreen}", "{habit: evergreen, autumn_color: [1, 0, 0]}", ":8:", "leaf days and autumn_color apply"},
        {"leaf_fall: 300", "leaf_fall: 300, colouring: 310", ":7:", "colouring (day 310) must fall while the species is in leaf"},
        {"leaf_fall: 300", "leaf_fall: 300, autumn_color: [1.5, 0, 0]", ":7:", "autumn_color"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char text[4096], name[64];
        snprintf(text, sizeof text, scene_text, "");
        char *at = strstr(text, cases[i].from);
        CHECK(at != NULL);
        if (!at) continue;
        char rest[4096];
        snprintf(rest, sizeof rest, "%s", at + strlen(cases[i].from));
        snprintf(at, sizeof text - (size_t)(at - text), "%s%s", cases[i].to, rest);
        snprintf(name, sizeof name, "phenology_%zu.yaml", i);
        const char *path = work_file(name, text);
        err_buf err = {{0}};
        scene_file *sf = path ? scene_file_load(path, NULL, &err) : NULL;
        CHECK(sf == NULL);
        scene_file_free(sf);
        CHECK_STR_CONTAINS(err.msg, name);
        CHECK_STR_CONTAINS(err.msg, cases[i].where);
        CHECK_STR_CONTAINS(err.msg, cases[i].says);
    }
}

TEST(season_option_overrides_the_key)
{
    err_buf err = {{0}};
    scene_file *sf = load_season("season: summer\n", &err);
    CHECK(sf != NULL);
    if (!sf) return;
    CHECK(scene_file_use_season(sf, "2026-01-20", &err) == 0);
    CHECK(sf->season.day == 20 && !strcmp(sf->season.text, "2026-01-20"));
    CHECK(scene_file_use_season(sf, "winter", &err) == 0);
    CHECK(sf->season.day == SEASON_WINTER_DAY && !strcmp(sf->season.text, "winter"));
    CHECK(scene_file_use_season(sf, "wintr", &err) == -1);
    CHECK(err.status == ERR_USAGE && strstr(err.msg, "--season wintr: ") && strstr(err.msg, "nor a date"));
    CHECK(sf->season.day == SEASON_WINTER_DAY); /* a refused day leaves the one before */
    scene_file_free(sf);
}

TEST_LIST(TEST_CASE(season_names_and_dates), TEST_CASE(deciduous_in_leaf_between_its_days),
          TEST_CASE(leaves_turn_from_colouring_to_leaf_fall), TEST_CASE(leaves_fall_ever_faster_while_they_turn),
          TEST_CASE(partial_leaf_fall_drops_whole_leaves_by_the_share), TEST_CASE(autumn_turns_only_the_deciduous_leaves),
          TEST_CASE(summer_and_winter_hold_the_same_instances), TEST_CASE(winter_rays_meet_no_deciduous_leaf),
          TEST_CASE(bad_season_is_located), TEST_CASE(snow_is_off_by_default), TEST_CASE(bad_phenology_is_located),
          TEST_CASE(season_option_overrides_the_key))
