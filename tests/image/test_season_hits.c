/* test_season_hits.c — the image tests' season scene (tests/scenes/image/season_*.yaml: the
 * shipped beech, maple and spruce) built with the real tree plugins in each season: the four
 * seasons hold identical instance lists (prototype, transform, development); in winter no ray
 * through a pixel of the image meets a deciduous leaf (the hit the id layer records names the
 * species, its material says leaf or wood) while in summer many do; in autumn the share of each
 * deciduous species' leaves that is down is the one its phenology gives for the day; snow's
 * min_height is read as a map height. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "plugin/plugin_host.h"
#include "render/accel.h"
#include "render/camera.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "work_dir.h"

static plugin_registry *registry; /* opened once, freed at exit */

static void registry_free(void) { plugin_registry_free(registry); }

/* The season scene with its `season: summer` line set to `season: name` and the line `extra`
 * after it, loaded; NULL after a failed CHECK. The caller frees it. */
static scene_file *load_in(const char *name, const char *extra)
{
    err_buf err = {{0}};
    if (!registry) {
        registry = plugin_registry_open(&err);
        atexit(registry_free);
        if (registry && plugin_registry_load_all(registry, &err)) fprintf(stderr, "%s\n", err.msg);
    }
    CHECK(registry != NULL);
    FILE *f = fopen(SYLVA_TEST_DATA_DIR "/scenes/image/season_summer.yaml", "rb");
    CHECK(f != NULL);
    if (!f || !registry) {
        if (f) fclose(f);
        return NULL;
    }
    static char text[1 << 16];
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = 0;
    char *at = strstr(text, "\nseason: summer\n");
    CHECK(at != NULL);
    if (!at) return NULL;
    static char changed[1 << 16];
    snprintf(changed, sizeof changed, "%.*s\nseason: %s\n%s%s", (int)(at - text), text, name, extra,
             at + strlen("\nseason: summer\n"));
    char file[64];
    snprintf(file, sizeof file, "season_%s%s.yaml", name, extra[0] ? "_extra" : "");
    const char *path = work_file(file, changed);
    scene_file *sf = path ? scene_file_load(path, registry, &err) : NULL;
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    return sf;
}

/* The season scene in season `name`, built; NULL after a failed CHECK. The caller frees both. */
static scene *build_in(const char *name, scene_file **out_sf)
{
    err_buf err = {{0}};
    scene_file *sf = load_in(name, "");
    if (!sf) return NULL;
    build_options bo = {.quiet = 1};
    scene *s = scene_build(sf, registry, &bo, &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    if (!s) {
        scene_file_free(sf);
        return NULL;
    }
    *out_sf = sf;
    return s;
}

static int deciduous(const scene_file *sf, uint32_t species_id)
{
    return species_id > 0 && species_id <= sf->n_species &&
           sf->species[species_id - 1].phenology.habit == HABIT_DECIDUOUS;
}

/* Rays through 4 x 4 points of every pixel of the scene's camera: how many first meet a
 * deciduous species' leaf, its wood, and an evergreen's leaf. */
static void count_hits(const scene *s, const scene_file *sf, uint32_t counts[3])
{
    accel a;
    err_buf err = {{0}};
    counts[0] = counts[1] = counts[2] = 0;
    CHECK_INT(accel_build(&a, s, 1, &err), 0);
    camera c;
    camera_init(&c, &sf->camera, sf->image.width, sf->image.height);
    for (uint32_t y = 0; y < 4 * sf->image.height; y++)
        for (uint32_t x = 0; x < 4 * sf->image.width; x++) {
            vec3 d = camera_direction(&c, (x + 0.5f) / 4, (y + 0.5f) / 4);
            struct RTCRayHit rh = {
                .ray = {.org_x = c.origin.x, .org_y = c.origin.y, .org_z = c.origin.z, .dir_x = d.x, .dir_y = d.y,
                        .dir_z = d.z, .tnear = 0, .tfar = INFINITY, .mask = 0xffu & ~(unsigned)ACCEL_MASK_PROXY},
                .hit = {.geomID = RTC_INVALID_GEOMETRY_ID, .instID = {RTC_INVALID_GEOMETRY_ID}}};
            struct RTCIntersectContext ic;
            rtcInitIntersectContext(&ic);
            rtcIntersect1(a.top, &ic, &rh);
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
            hit_info h;
            accel_shade(&a, &rh, &h);
            if (!h.species_id) continue;
            int leaf = h.mat && h.mat->bsdf == SYLVA_BSDF_LEAF;
            if (deciduous(sf, h.species_id)) counts[leaf ? 0 : 1]++;
            else if (leaf) counts[2]++;
        }
    accel_free(&a);
}

TEST(winter_pixels_meet_no_deciduous_leaf)
{
    scene_file *sf_summer = NULL, *sf_winter = NULL;
    scene *summer = build_in("summer", &sf_summer), *winter = build_in("winter", &sf_winter);
    if (summer && winter) {
        uint32_t cs[3], cw[3];
        count_hits(summer, sf_summer, cs);
        count_hits(winter, sf_winter, cw);
        fprintf(stderr, "summer: %u deciduous leaf, %u deciduous wood, %u evergreen leaf hits\n", cs[0], cs[1], cs[2]);
        fprintf(stderr, "winter: %u deciduous leaf, %u deciduous wood, %u evergreen leaf hits\n", cw[0], cw[1], cw[2]);
        CHECK(cs[0] > 5000);   /* the beech and the maple in leaf fill much of the frame */
        CHECK_INT(cw[0], 0);   /* bare in winter */
        CHECK(cw[1] > 500);    /* yet their trunks and branches are seen */
        CHECK(cw[1] >= cs[1]); /* and more of them, no longer behind leaves */
        CHECK(cw[2] >= cs[2] && cw[2] < cs[2] + cs[2] / 100); /* the spruce as in summer (the maple
                                                          * overlaps its edge) */
    }
    scene_free(summer), scene_free(winter);
    scene_file_free(sf_summer), scene_file_free(sf_winter);
}

TEST(four_seasons_hold_the_same_instances)
{
    static const char *names[4] = {"summer", "spring", "autumn", "winter"};
    scene_file *sf[4] = {0};
    scene *s[4] = {0};
    for (int k = 0; k < 4; k++) s[k] = build_in(names[k], &sf[k]);
    if (s[0] && s[1] && s[2] && s[3]) {
        CHECK_INT(s[0]->n_instances, 3); /* the three trees (the ground cover's tufts come later) */
        for (int k = 1; k < 4; k++) {
            CHECK_INT(s[k]->n_instances, s[0]->n_instances);
            CHECK_INT(s[k]->n_prototypes, s[0]->n_prototypes);
            for (uint32_t i = 0; i < s[0]->n_instances && i < s[k]->n_instances; i++) {
                CHECK_INT(s[k]->instances[i].prototype, s[0]->instances[i].prototype);
                CHECK_INT(s[k]->instances[i].development, s[0]->instances[i].development);
                CHECK(!memcmp(&s[k]->instances[i].xf, &s[0]->instances[i].xf, sizeof(xform3x4)));
            }
            for (uint32_t p = 0; p < s[0]->n_prototypes && p < s[k]->n_prototypes; p++)
                CHECK_INT(s[k]->prototypes[p].mesh->nv, s[0]->prototypes[p].mesh->nv);
        }
    }
    for (int k = 0; k < 4; k++) scene_free(s[k]), scene_file_free(sf[k]);
}

/* The leaf triangles of species i's prototypes in s. */
static uint32_t leaf_triangles(const scene *s, uint32_t i)
{
    uint32_t n = 0;
    const species *sp = &s->species[i];
    for (uint32_t v = 0; v < sp->n_variants; v++) {
        const mesh *m = s->prototypes[sp->first_prototype + v].mesh;
        for (uint32_t t = 0; t < m->nt; t++) n += s->materials[scene_triangle_material(s, m, t)].bsdf == SYLVA_BSDF_LEAF;
    }
    return n;
}

TEST(autumn_leaf_fall_matches_the_day)
{
    scene_file *sf_summer = NULL, *sf_autumn = NULL;
    scene *summer = build_in("summer", &sf_summer), *autumn = build_in("autumn", &sf_autumn);
    if (summer && autumn) {
        int checked = 0;
        for (uint32_t i = 0; i < sf_autumn->n_species; i++) {
            const phenology *p = &sf_autumn->species[i].phenology;
            double share = phenology_fallen_share(p, sf_autumn->season.day);
            uint32_t before = leaf_triangles(summer, i), after = leaf_triangles(autumn, i);
            double down = before ? 1.0 - (double)after / before : 0;
            fprintf(stderr, "%s: %u leaf triangles in summer, %u in autumn: %.4f down, the day gives %.4f\n",
                    sf_autumn->species[i].name, before, after, down, share);
            CHECK(before > 1000);
            CHECK_NEAR(down, share, 0.02); /* thousands of leaves: within two points */
            checked += p->habit == HABIT_DECIDUOUS;
        }
        CHECK_INT(checked, 2);
    }
    scene_free(summer), scene_free(autumn);
    scene_file_free(sf_summer), scene_file_free(sf_autumn);
}

/* snow: min_height is a map height, as the terrain's altitudes: the local frame's is that less
 * the site origin's height; left out, snow lies at every height. */
TEST(snow_min_height_is_a_map_height)
{
    scene_file *sf = load_in("winter", "site: {crs: EPSG:32633, origin: [500000, 5400000, 300]}\n"
                                       "snow: {cover: 0.5, min_height: 350}\n");
    CHECK(sf && sf->snow.on);
    if (sf) {
        CHECK_NEAR(sf->snow.min_height, 50, 1e-9);
        CHECK_NEAR(sf->snow.cover, 0.5, 0);
    }
    scene_file_free(sf);
    sf = load_in("winter", "snow: {}\n");
    CHECK(sf && sf->snow.on && sf->snow.cover == 1 && sf->snow.min_height == -HUGE_VAL);
    scene_file_free(sf);
}

TEST_LIST(TEST_CASE(snow_min_height_is_a_map_height), TEST_CASE(winter_pixels_meet_no_deciduous_leaf), TEST_CASE(four_seasons_hold_the_same_instances),
          TEST_CASE(autumn_leaf_fall_matches_the_day))
