/* test_planting.c — planting plans (the planting: section, scene_build/scene_planting.h): bad plans
 * refused at their place (unknown species, a polygon crossing itself, zero spacing, a plan off the
 * terrain), each planted plant keeping its number and place from year to year while its height
 * follows its species' growth curve from the age its stock gives, fellings and thinning, and a
 * screening belt between an observer and a mast: it hides nothing while the stock is below the
 * sightlines, hides the mast from each observer once its height passes that observer's sightline,
 * and the area from which the mast is seen never grows from one year to the next. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "render/film.h"
#include "render/render.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "work_dir.h"
#include "ztv_fixture.h"

/* A flat site 200 m by 20 m (x -100 to 100, y -10 to 10, nodes 5 m apart) with a species of a block
 * 12 m tall, 4 m across and standing on the ground (one variant, full grown at 60 years: 0.2 m a year), then `tail`. */
static const char *site_text(const char *tail)
{
    static char text[16384];
    int at = snprintf(text, sizeof text, "earth: {curvature: false}\n"
                      "species:\n  screen: {shape: mesh, vertices: [[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0], [-2, -2, 12], "
                      "[2, -2, 12], [2, 2, 12], [-2, 2, 12]], triangles: [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], "
                      "[0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]]}\n"
                      "  other: {shape: box, size: [1, 1, 3]}\n"
                      "  leafy: {shape: box, size: [3, 3, 6], material: foliage, phenology: {habit: deciduous, "
                      "leaf_out: 120, colouring: 260, leaf_fall: 300}}\n"
                      "materials: {foliage: {type: leaf, albedo: [0.1, 0.3, 0.1], transmittance: [0.05, 0.1, 0.05]}}\n"
                      "terrain: {origin: [-100, -10], spacing: [5, 5], grid: [");
    for (int j = 0; j < 5; j++) {
        at += snprintf(text + at, sizeof text - at, "%s[", j ? ", " : "");
        for (int i = 0; i <= 40; i++) at += snprintf(text + at, sizeof text - at, "%s0", i ? ", " : "");
        at += snprintf(text + at, sizeof text - at, "]");
    }
    snprintf(text + at, sizeof text - at, "]}\n%s", tail);
    return text;
}

/* The scene of tail at `year` years after planting (year < 0: before the plan), or NULL with err. */
static scene *build_at(const char *tail, double year, err_buf *err)
{
    const char *path = work_file("plan.yaml", site_text(tail));
    scene_file *sf = path ? scene_file_load_with(path, NULL, SCENE_FILE_NO_CAMERA, err) : NULL;
    build_options bo = {.analysis = 1, .quiet = 1, .planting_shown = year >= 0, .planting_years = year};
    scene *s = sf ? scene_build(sf, NULL, &bo, err) : NULL;
    scene_file_free(sf);
    return s;
}

/* The sentence a plan is refused with; "" when it builds. */
static const char *refusal(const char *tail)
{
    static err_buf err;
    memset(&err, 0, sizeof err);
    scene *s = build_at(tail, 1, &err);
    scene_free(s);
    return s ? "" : err.msg;
}

static double instance_height(const scene *s, uint32_t i)
{
    return s->prototypes[s->instances[i].prototype].height * s->instances[i].xf.m[2][2];
}

TEST(bad_plans_refused_at_their_place)
{
    CHECK_STR_CONTAINS(refusal("planting:\n  year: 2027\n  trees:\n    - {position: [0, 0], species: oak}\n"),
                       "plan.yaml:11:35: unknown species 'oak' in 'planting.trees[0]'");
    CHECK_STR_CONTAINS(refusal("planting:\n  year: 2027\n  coordinates: map\n  trees:\n    - {position: [0, 0], "
                               "species: screen}\n"), "plan.yaml:10:16: 'coordinates: map' gives the plan in the "
                       "site's CRS, but the scene has no 'site:' section");
    const char *bowtie = refusal("planting:\n  year: 2027\n  blocks:\n"
                                 "    - {polygon: [[0, 0], [10, 5], [10, 0], [0, 5]], species: screen, spacing: 2}\n");
    CHECK_STR_CONTAINS(bowtie, "plan.yaml:11:17");
    CHECK_STR_CONTAINS(bowtie, "the polygon crosses itself");
    const char *zero = refusal("planting:\n  year: 2027\n  belts:\n"
                               "    - {line: [[0, -5], [0, 5]], species: screen, spacing: 0}\n");
    CHECK_STR_CONTAINS(zero, "plan.yaml:11:59: 'spacing' must be in (0, 1000], got 0");
    const char *outside = refusal("planting:\n  year: 2027\n  belts:\n"
                                  "    - {name: far, line: [[0, 0], [300, 0]], species: screen, spacing: 2}\n");
    CHECK_STR_CONTAINS(outside, "plan.yaml:11:7");
    CHECK_STR_CONTAINS(outside, "the belt 'far' lies outside the terrain: its point 1 at local (300.0, 0.0)");
    CHECK_STR_CONTAINS(refusal("planting:\n  year: 2027\n  trees:\n    - {position: [0, 0], species: other, "
                               "stock_height: 3.5}\n"), "plan.yaml:11:7: planting: the tree 'trees[0]': its stock of 3.50 m is taller than species "
               "'other' grows (its full-grown model is 3.00 m)");
}

/* Year 1 and year 15 hold the same plants (numbers, places, turns), each as tall as the growth
 * curve says at its stock's age plus the years: 12 m x age / 60, the stock a whip of 0.6-0.9 m. */
TEST(plants_keep_their_place_and_follow_the_curve)
{
    const char *plan = "planting:\n  year: 2027\n  seed: 7\n  blocks:\n"
                       "    - {polygon: [[-40, -8], [-20, -8], [-20, 8], [-40, 8]], species: screen other, "
                       "shares: [3, 1], spacing: 3}\n"
                       "  belts:\n    - {line: [[0, -9], [0, 9]], species: screen, rows: 2, spacing: 1}\n";
    err_buf err = {{0}};
    scene *a = build_at(plan, 1, &err), *b = build_at(plan, 15, &err), *before = build_at(plan, -1, &err);
    CHECK(a && b && before);
    if (!a || !b || !before) {
        fprintf(stderr, "%s\n", err.msg);
        scene_free(a), scene_free(b), scene_free(before);
        return;
    }
    CHECK_INT(before->n_instances, 0);
    CHECK(a->n_instances > 60);
    CHECK_INT(a->n_instances, b->n_instances);
    uint32_t screens = 0, others = 0;
    for (uint32_t i = 0; i < a->n_instances && i < b->n_instances; i++) {
        const instance *p = &a->instances[i], *q = &b->instances[i];
        CHECK_INT(p->planted, i + 1);
        CHECK_INT(q->planted, p->planted);
        /* year 1 a young plant, year 15 its species' model: the same species */
        CHECK_INT(scene_plant_species(a, a->prototypes[p->prototype].species),
                  scene_plant_species(b, b->prototypes[q->prototype].species));
        CHECK(a->species[a->prototypes[p->prototype].species].young_stock_of != 0);
        CHECK_INT(b->species[b->prototypes[q->prototype].species].young_stock_of, 0);
        CHECK_NEAR(p->xf.m[0][3], q->xf.m[0][3], 1e-6);
        CHECK_NEAR(p->xf.m[1][3], q->xf.m[1][3], 1e-6);
        CHECK_NEAR(p->xf.m[0][0] / p->xf.m[2][2], q->xf.m[0][0] / q->xf.m[2][2], 1e-5); /* the same turn */
        uint32_t sp = scene_plant_species(a, a->prototypes[p->prototype].species);
        double full = sp == 0 ? 12 : 3, h1 = instance_height(a, i), h15 = instance_height(b, i);
        /* the stock's age from its height, then 14 years more: 14 / 60 of the full height */
        double stock = h1 - full / 60;
        CHECK(stock >= 0.6 - 1e-4 && stock <= 0.9 + 1e-4);
        CHECK_NEAR(h15, fmin(full, stock + full * 15 / 60), 0.05 * h15);
        screens += sp == 0, others += sp == 1;
    }
    CHECK(screens > 2 * others && others > 0); /* the block's shares of 3 to 1 */
    scene_free(a), scene_free(b), scene_free(before);
}

/* A felling takes out the existing plants inside its polygon and leaves the others; thinning
 * keeps about its share of a belt's plants from its year on. */
TEST(felling_and_thinning)
{
    const char *tail = "plants:\n  - {species: other, position: [10, 0]}\n  - {species: other, position: [50, 0]}\n"
                       "planting:\n  year: 2027\n  thinning_year: 10\n  thinning_keep: 0.5\n"
                       "  belts:\n    - {line: [[-90, 0], [-10, 0]], species: screen, spacing: 1}\n"
                       "  felling:\n    - {polygon: [[5, -5], [15, -5], [15, 5], [5, 5]]}\n";
    err_buf err = {{0}};
    scene *before = build_at(tail, -1, &err), *early = build_at(tail, 5, &err), *late = build_at(tail, 12, &err);
    CHECK(before && early && late);
    if (before && early && late) {
        CHECK_INT(before->n_instances, 2);
        uint32_t existing = 0, planted_early = 0, planted_late = 0;
        for (uint32_t i = 0; i < early->n_instances; i++) {
            if (early->instances[i].planted) {
                planted_early++;
                continue;
            }
            existing++;
            CHECK_NEAR(early->instances[i].xf.m[0][3], 50, 1e-6);
        }
        for (uint32_t i = 0; i < late->n_instances; i++) planted_late += late->instances[i].planted != 0;
        CHECK_INT(existing, 1);
        CHECK_INT(planted_early, 80);
        CHECK(planted_late > 28 && planted_late < 52);
    } else {
        fprintf(stderr, "%s\n", err.msg);
    }
    scene_free(before), scene_free(early), scene_free(late);
}

typedef struct sight_map {
    uint32_t nx, ny;
    uint16_t *visible; /* screened */
    uint8_t *cls;
} sight_map;

static int copy_block(void *user, const ztv_block *b, err_buf *err)
{
    (void)err;
    sight_map *m = user;
    const ztv_layer *l = b->layer[ZTV_VEGETATION];
    if (!l) return 0;
    memcpy(m->visible + (size_t)b->j0 * m->nx, l->visible, (size_t)b->rows * m->nx * sizeof(uint16_t));
    memcpy(m->cls + (size_t)b->j0 * m->nx, l->cls, (size_t)b->rows * m->nx);
    return 0;
}

static void map_alloc(void *user, const ztv_grid *g)
{
    sight_map *m = user;
    m->nx = g->nx, m->ny = g->ny;
    m->visible = calloc((size_t)m->nx * m->ny, sizeof *m->visible), m->cls = calloc((size_t)m->nx * m->ny, 1);
}

/* The vegetation-screened map of the plan at `year`, into m (arrays the caller frees). */
static int map_at(const char *tail, double year, sight_map *m)
{
    err_buf err = {{0}};
    const char *path = work_file("plan.yaml", site_text(tail));
    scene_file *sf = path ? scene_file_load_with(path, NULL, SCENE_FILE_NO_CAMERA, &err) : NULL;
    build_options bo = {.analysis = 1, .quiet = 1, .planting_shown = 1, .planting_years = year};
    scene *s = sf ? scene_build(sf, NULL, &bo, &err) : NULL;
    int rc = s ? ztv_fixture_trace(sf, s, ZTV_VEGETATION, 2, map_alloc, copy_block, m, &err) : -1;
    if (rc) fprintf(stderr, "%s\n", err.msg);
    scene_free(s);
    scene_file_free(sf);
    return rc;
}

/* A belt of 12 m boxes (0.2 m a year, whips of 0.6-0.9 m) along x = 0, 0.25 m apart, between a
 * mast 10 m high at x = 100 and the observers west of it, 2 m up. The sightline from an observer
 * at x passes the belt at 2 + 8 (-x) / (100 - x) m: the belt hides the mast from that observer
 * once its plants are taller than that, and not before. At year 1 every plant is below 1 m,
 * under every sightline: nothing is hidden. The area seeing the mast never grows with the years. */
TEST(belt_hides_the_mast_once_above_the_sightline)
{
    const char *tail = "ztv: {targets: [{position: [100, 0], height_above_ground: 10}]}\n"
                       "planting:\n  year: 2027\n  belts:\n    - {line: [[0, -9.9], [0, 9.9]], species: screen, "
                       "spacing: 0.25, rows: 2, row_spacing: 0.2}\n";
    static const double years[] = {1, 3, 6, 10, 15, 20, 25, 30, 40};
    long previous = -1;
    for (size_t y = 0; y < sizeof years / sizeof *years; y++) {
        sight_map m = {0};
        CHECK_INT(map_at(tail, years[y], &m), 0);
        double low = 0.6 + 12.0 * years[y] / 60, high = 0.9 + 12.0 * years[y] / 60; /* the belt's heights */
        long seen = 0;
        uint32_t checked = 0;
        for (uint32_t j = 0; m.visible && j < m.ny; j++)
            for (uint32_t i = 0; i < m.nx; i++) {
                size_t k = (size_t)j * m.nx + i;
                double x = -100 + 5.0 * i;
                if (m.cls[k] == ZTV_OPEN) seen += m.visible[k];
                if (x > -5 || m.cls[k] != ZTV_OPEN) continue;
                double sightline = 2 + 8 * (-x) / (100 - x);
                if (high < sightline - 0.05) {
                    CHECK_INT(m.visible[k], 1);
                    checked++;
                }
                if (low > sightline + 0.3) {
                    CHECK_INT(m.visible[k], 0);
                    checked++;
                }
                if (years[y] == 1) CHECK_INT(m.visible[k], 1);
            }
        CHECK(checked > 0);
        if (previous >= 0) CHECK(seen <= previous);
        previous = seen;
        free(m.visible), free(m.cls);
    }
}

/* A young plant (planting_stock.h) is its stock's form, no taller than the curve's height: a
 * whip in its first year a stem with a few short shoots (nothing farther than 15 % of its height
 * from its stem, no triangle above its leader's tip) and its guard; the same young plants from
 * two builds; the model itself from the end of the establishment years. */
TEST(young_plants_are_their_stock)
{
    const char *plan = "planting:\n  year: 2027\n  belts:\n    - {line: [[0, -9], [0, 9]], species: screen, spacing: 1}\n";
    err_buf err = {{0}};
    scene *a = build_at(plan, 1, &err), *again = build_at(plan, 1, &err), *grown = build_at(plan, 8, &err);
    CHECK(a && again && grown);
    if (a && again && grown) {
        CHECK_INT(a->n_prototypes, again->n_prototypes);
        for (uint32_t p = 0; p < a->n_prototypes && p < again->n_prototypes; p++) {
            const mesh *m = a->prototypes[p].mesh, *n = again->prototypes[p].mesh;
            CHECK(m->nv == n->nv && m->nt == n->nt && !memcmp(m->pos, n->pos, 3 * sizeof(float) * m->nv));
            if (!a->species[a->prototypes[p].species].young_stock_of) continue;
            float lo[3], hi[3];
            mesh_bounds(m, lo, hi);
            double h = a->prototypes[p].height;
            CHECK(hi[2] <= h + 1e-4 && hi[2] > 0.99 * h);
            CHECK(fmax(fmax(-lo[0], hi[0]), fmax(-lo[1], hi[1])) < 0.15 * h);
        }
        for (uint32_t i = 0; i < grown->n_instances; i++)
            CHECK_INT(grown->species[grown->prototypes[grown->instances[i].prototype].species].young_stock_of, 0);
    } else {
        fprintf(stderr, "%s\n", err.msg);
    }
    scene_free(a), scene_free(again), scene_free(grown);
}

/* A belt of young plants screens as little as their stems, shoots and leaves do: the sightlines
 * to a target 0.5 m up pass the belt of 12 m boxes planted as whips 1.25 to 1.9 m up, below the
 * plants' tops at year 6 (1.8-2.1 m); most of them pass between the young plants, and at year 10,
 * when the plants are the boxes 2.6 m tall and more, none does. */
TEST(young_belt_is_see_through_in_the_map)
{
    const char *tail = "ztv: {targets: [{position: [100, 0], height_above_ground: 0.5}]}\n"
                       "planting:\n  year: 2027\n  belts:\n    - {line: [[0, -9.9], [0, 9.9]], species: screen, "
                       "spacing: 0.25, rows: 2, row_spacing: 0.2}\n";
    for (int y = 0; y < 2; y++) {
        sight_map m = {0};
        CHECK_INT(map_at(tail, y ? 10 : 6, &m), 0);
        uint32_t cells = 0, seeing = 0;
        for (uint32_t j = 0; m.visible && j < m.ny; j++)
            for (uint32_t i = 0; i < m.nx; i++) {
                size_t k = (size_t)j * m.nx + i;
                double x = -100 + 5.0 * i;
                if (x > -20 || m.cls[k] != ZTV_OPEN) continue;
                cells++, seeing += m.visible[k] > 0;
            }
        CHECK(cells > 20);
        if (y) CHECK_INT(seeing, 0);
        else CHECK(seeing > cells / 2);
        fprintf(stderr, "year %d: %u of %u observers see the target\n", y ? 10 : 6, seeing, cells);
        free(m.visible), free(m.cls);
    }
}

static film *render_at(const char *tail, double year, const char *season, scene **out)
{
    err_buf err = {{0}};
    const char *path = work_file("plan.yaml", site_text(tail));
    scene_file *sf = path ? scene_file_load(path, NULL, &err) : NULL;
    build_options bo = {.quiet = 1, .planting_shown = 1, .planting_years = year};
    scene *s = sf && !scene_file_use_season(sf, season, &err) ? scene_build(sf, NULL, &bo, &err) : NULL;
    render_options ro = {.threads = 2, .quiet = 1};
    film *f = s ? render_scene(s, &ro, NULL, &err) : NULL;
    if (!f) fprintf(stderr, "%s\n", err.msg);
    scene_file_free(sf);
    *out = s;
    return f;
}

/* 1 when instance id of s is a planted plant or a deciduous one (0 for id 0: no plant). */
static int planted_or_seasonal(const scene *s, uint32_t id, uint32_t *planted, uint32_t *seasonal)
{
    if (!id) return 0;
    const instance *in = &s->instances[id - 1];
    uint32_t sp = s->prototypes[in->prototype].species;
    *planted += in->planted != 0, *seasonal += sp == 2;
    return in->planted != 0 || sp == 2;
}

/* The view of a belt planted in front of an evergreen and a deciduous plant, in year 1 in winter
 * and in year 15 in summer: pixel by pixel the instance seen differs only where the plant seen in
 * one of them (or both) is planted or deciduous; the belt has grown into view and the deciduous
 * plant has come into leaf (and is not hidden by it: the camera looks down over the belt). */
TEST(year_1_winter_and_year_15_summer_differ_in_planted_and_seasonal_plants)
{
    const char *tail = "camera: {position: [-40, 0, 12], look_at: [20, 0, 0], focal_length: 35}\n"
                       "image: {width: 96, height: 64, spp: 1}\n"
                       "plants:\n  - {species: other, position: [20, 4]}\n  - {species: leafy, position: [20, -4]}\n"
                       "planting:\n  year: 2027\n  belts:\n    - {line: [[0, -9.9], [0, 9.9]], species: screen, "
                       "spacing: 0.5}\n";
    scene *a, *b;
    film *winter = render_at(tail, 1, "winter", &a), *summer = render_at(tail, 15, "summer", &b);
    CHECK(winter && summer);
    if (winter && summer) {
        size_t n = (size_t)winter->width * winter->height, differ = 0, bad = 0;
        uint32_t planted = 0, seasonal = 0;
        for (size_t i = 0; i < n; i++) {
            uint32_t p = winter->instance_id[i], q = summer->instance_id[i];
            if (p == q) continue;
            differ++;
            int ok = planted_or_seasonal(a, p, &planted, &seasonal) | planted_or_seasonal(b, q, &planted, &seasonal);
            if (!ok) fprintf(stderr, "pixel %zu: winter %u, summer %u\n", i, p, q);
            bad += !ok;
        }
        uint32_t leafy[2] = {0, 0};
        for (size_t i = 0; i < n; i++)
            for (int k = 0; k < 2; k++) {
                const scene *s = k ? b : a;
                uint32_t id = (k ? summer : winter)->instance_id[i];
                leafy[k] += id && s->prototypes[s->instances[id - 1].prototype].species == 2;
            }
        CHECK_INT(leafy[0], 0); /* out of leaf */
        CHECK(leafy[1] > 0);
        CHECK(differ > 0);
        CHECK_INT(bad, 0);
        CHECK(planted > 0 && seasonal > 0);
        /* the evergreen keeps its number: the existing plants come first, in the same order */
        CHECK(a->n_instances > 2 && b->n_instances == a->n_instances);
        CHECK(a->instances[0].prototype == b->instances[0].prototype && !a->instances[0].planted);
    }
    film_free(winter), film_free(summer);
    scene_free(a), scene_free(b);
}

/* The GeoJSON plan below, its belt's south end at northing `south`. */
static void plan_json(char *json, size_t size, double south)
{
    snprintf(json, size, "{\"type\": \"FeatureCollection\", \"crs\": {\"type\": \"name\", \"properties\": "
             "{\"name\": \"urn:ogc:def:crs:EPSG::32611\"}}, \"features\": ["
             "{\"type\": \"Feature\", \"id\": 1, \"properties\": {\"species\": \"screen other\", \"shares\": \"3 1\", "
             "\"spacing\": 2}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[499940, 5499992], "
             "[499960, 5499992], [499960, 5500008], [499940, 5500008], [499940, 5499992]]]}},"
             "{\"type\": \"Feature\", \"id\": 2, \"properties\": {\"species\": \"screen\", \"rows\": 2, "
             "\"spacing\": 1, \"stock\": \"feathered\"}, \"geometry\": {\"type\": \"LineString\", \"coordinates\": "
             "[[500000, %.0f], [500000, 5500009]]}},"
             "{\"type\": \"Feature\", \"id\": 3, \"properties\": {\"species\": \"other\", \"stock_height\": 1.2}, "
             "\"geometry\": {\"type\": \"Point\", \"coordinates\": [500050, 5500005]}}]}\n", south);
}

/* A GeoJSON plan in UTM: its polygon a block, its line a belt, its point a tree, each where the
 * file draws it (less the site's origin), with its attributes; a feature naming an unknown species
 * is refused at the file key, naming its FID. */
TEST(plan_from_a_vector_file)
{
    char json[4096];
    plan_json(json, sizeof json, 4999991); /* the belt's south end 500 km off: in another place */
    CHECK(work_file("plan.geojson", json) != NULL);
    const char *tail = "site: {crs: \"EPSG:32611\", origin: [500000, 5500000]}\nplanting:\n  year: 2027\n  file: plan.geojson\n";
    CHECK_STR_CONTAINS(refusal(tail), "plan.yaml:11:9: planting: the belt 'plan.geojson FID 2' lies outside the terrain: its point 0 at local "
                       "(0.0, -500009.0)");
    plan_json(json, sizeof json, 5499991);
    CHECK(work_file("plan.geojson", json) != NULL);
    err_buf err = {{0}};
    scene *s = build_at(tail, 0, &err);
    CHECK(s != NULL);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    uint32_t block = 0, belt = 0, tree = 0;
    for (uint32_t i = 0; s && i < s->n_instances; i++) {
        double x = s->instances[i].xf.m[0][3], y = s->instances[i].xf.m[1][3];
        block += x < -19 && x > -61, belt += fabs(x) < 1.5, tree += fabs(x - 50) < 1e-3 && fabs(y - 5) < 1e-3;
        if (fabs(x - 50) < 1e-3) CHECK_NEAR(instance_height(s, i), 1.2, 1e-3);
    }
    CHECK_INT(block, 80); /* the 20 x 16 m polygon holds 10 x 8 nodes 2 m apart */
    CHECK_INT(belt, 36);
    CHECK_INT(tree, 1);
    scene_free(s);
    /* a feature of an unknown species, refused at the file key with its FID */
    char *at = strstr(json, "\"species\": \"other\", \"stock_height\"");
    if (at) memcpy(at, "\"species\": \"oakoo\"", 18);
    CHECK(work_file("plan.geojson", json) != NULL);
    CHECK_STR_CONTAINS(refusal(tail), "plan.yaml:11:9: unknown species 'oakoo' in 'plan.geojson FID 3'");
}

TEST_LIST(TEST_CASE(bad_plans_refused_at_their_place), TEST_CASE(plan_from_a_vector_file), TEST_CASE(year_1_winter_and_year_15_summer_differ_in_planted_and_seasonal_plants), TEST_CASE(plants_keep_their_place_and_follow_the_curve),
          TEST_CASE(felling_and_thinning), TEST_CASE(belt_hides_the_mast_once_above_the_sightline),
          TEST_CASE(young_plants_are_their_stock), TEST_CASE(young_belt_is_see_through_in_the_map))
