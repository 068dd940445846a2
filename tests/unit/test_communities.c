/* test_communities.c — the land cover's plant communities (scene_build/scene_communities.h) on the
 * shared Zion site: over 3 x 3 km of the canyon's mouth, the NLCD 2011 raster's own 30 m cells
 * (read here through GDAL, not through sylva) hold trees where they are forest, shrubs where they
 * are shrubland and (nearly) nothing where they are bare, built or water; the reclassified copy
 * named through its .aux.xml plants the same plants; the counts follow the densities; bad
 * communities are refused at their keys. The Zion cases skip without ../shared/data. */
#include <gdal.h>
#include <math.h>

#include "harness.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "work_dir.h"
#include "scene_text.h"
#include "geotiff_fixture.h"

#define ZION SYLVA_SHARED_DATA_DIR "/sites/zion"
#define SPECIES SYLVA_TEST_DATA_DIR "/../scenes/species/zion.yaml"
#define WEST 322000.0
#define SOUTH 4117000.0
#define EAST 325000.0
#define NORTH 4120000.0

/* Zion with communities keyed by broad kind (so that the names legend's "Forest" takes the same
 * community as the NLCD's 41-43) on the map `map`. */
static scene *zion(const char *map, err_buf *err)
{
    char text[2048];
    snprintf(text, sizeof text,
             "image: {seed: 7}\n"
             "site: {}\n"
             "terrain: {plugin: terrain_ifs, dtm: %s/srtm.tif}\n"
             "species: {include: [%s]}\n"
             "landcover:\n"
             "  raster: %s/%s\n"
             "  plant_area: [%.0f, %.0f, %.0f, %.0f]\n"
             "  communities:\n"
             "    - {kind: forest, species: pinyon_juniper ponderosa, shares: [3, 1], density: 150, height: [3, 12]}\n"
             "    - {kind: shrub, species: sagebrush, density: 600, height: [0.4, 1.5]}\n",
             ZION, SPECIES, ZION, map, WEST, SOUTH, EAST, NORTH);
    return scene_text_build_analysis("zion.yaml", text, 1, err);
}

/* The NLCD's cells over the test area, read through GDAL: codes, their grid and the window. */
typedef struct nlcd_window {
    int x0, y0, w, h;           /* the window in the raster's cells */
    double gt[6];
    uint8_t *code;              /* w * h, row 0 north; owned */
} nlcd_window;

static int read_window(nlcd_window *win)
{
    GDALAllRegister();
    GDALDatasetH ds = GDALOpen(ZION "/nlcd2011.tif", GA_ReadOnly);
    if (!ds || GDALGetGeoTransform(ds, win->gt) != CE_None) return -1;
    /* whole cells inside the area, a cell's margin in from its edges */
    win->x0 = (int)ceil((WEST - win->gt[0]) / win->gt[1]) + 1, win->y0 = (int)ceil((NORTH - win->gt[3]) / win->gt[5]) + 1;
    win->w = (int)floor((EAST - win->gt[0]) / win->gt[1]) - 1 - win->x0;
    win->h = (int)floor((SOUTH - win->gt[3]) / win->gt[5]) - 1 - win->y0;
    win->code = malloc((size_t)win->w * win->h);
    int rc = win->code && GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, win->x0, win->y0, win->w, win->h, win->code,
                                       win->w, win->h, GDT_Byte, 0, 0) == CE_None ? 0 : -1;
    GDALClose(ds);
    return rc;
}

enum { HOLDS_TREE = 1, HOLDS_SHRUB = 2 };

/* What each NLCD cell of the window holds: the plants of s whose base stands in it. */
static uint8_t *cell_contents(const scene *s, const nlcd_window *win)
{
    uint8_t *holds = calloc((size_t)win->w * win->h, 1);
    for (uint32_t i = 0; holds && i < s->n_instances; i++) {
        const instance *in = &s->instances[i];
        if (scene_instance_is_ground_cover(s, i)) continue;
        double e = in->xf.m[0][3] + s->site.origin[0], n = in->xf.m[1][3] + s->site.origin[1];
        int cx = (int)floor((e - win->gt[0]) / win->gt[1]) - win->x0, cy = (int)floor((n - win->gt[3]) / win->gt[5]) - win->y0;
        if (cx < 0 || cy < 0 || cx >= win->w || cy >= win->h) continue;
        const char *name = s->species[s->prototypes[in->prototype].species].name;
        holds[(size_t)cy * win->w + cx] |= strcmp(name, "sagebrush") ? HOLDS_TREE : HOLDS_SHRUB;
    }
    return holds;
}

TEST(zion_follows_the_nlcd)
{
    if (!scene_text_file_exists(ZION "/nlcd2011.tif")) SKIP("no shared data at %s", ZION);
    err_buf err = {{0}};
    scene *s = zion("nlcd2011.tif", &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    nlcd_window win = {0};
    CHECK(s && !read_window(&win));
    uint8_t *holds = s && win.code ? cell_contents(s, &win) : NULL;
    CHECK(holds != NULL);
    uint64_t forest = 0, forest_trees = 0, shrub = 0, shrub_shrubs = 0, shrub_trees = 0, bare = 0, bare_plants = 0;
    for (size_t c = 0; holds && c < (size_t)win.w * win.h; c++) {
        int code = win.code[c];
        if (code >= 41 && code <= 43) forest++, forest_trees += (holds[c] & HOLDS_TREE) != 0;
        if (code == 51 || code == 52)
            shrub++, shrub_shrubs += (holds[c] & HOLDS_SHRUB) != 0, shrub_trees += (holds[c] & HOLDS_TREE) != 0;
        if (code == 11 || code == 12 || (code >= 21 && code <= 24) || code == 31) bare++, bare_plants += holds[c] != 0;
    }
    fprintf(stderr, "zion: of %llu forest cells %.2f %% hold a tree; of %llu shrub cells %.2f %% hold a shrub, "
            "%.2f %% a tree; of %llu barren, built or water cells %.2f %% hold a plant\n", (unsigned long long)forest,
            100.0 * forest_trees / forest, (unsigned long long)shrub, 100.0 * shrub_shrubs / shrub,
            100.0 * shrub_trees / shrub, (unsigned long long)bare, 100.0 * bare_plants / bare);
    CHECK(forest > 500 && shrub > 500 && bare > 500); /* the area holds all three in numbers */
    CHECK(forest_trees >= 0.95 * forest);
    CHECK(shrub_shrubs >= 0.95 * shrub);
    CHECK(bare_plants <= 0.05 * bare);
    free(holds), free(win.code);
    scene_free(s);
}

/* The reclassified map with its names in the .aux.xml gives the very same plants. */
TEST(zion_names_plant_the_same)
{
    if (!scene_text_file_exists(ZION "/nlcd.tif.aux.xml")) SKIP("no shared data at %s", ZION);
    err_buf err = {{0}};
    scene *a = zion("nlcd2011.tif", &err), *b = a ? zion("nlcd.tif", &err) : NULL;
    if (!b) fprintf(stderr, "%s\n", err.msg);
    CHECK(a && b);
    if (a && b) {
        fprintf(stderr, "zion: %u plants from nlcd2011.tif, %u from nlcd.tif\n", a->n_instances, b->n_instances);
        CHECK_INT(a->n_instances, b->n_instances);
        CHECK(a->n_instances == b->n_instances &&
              !memcmp(a->instances, b->instances, a->n_instances * sizeof *a->instances));
    }
    scene_free(a);
    scene_free(b);
}

/* A flat site all of one class: the count is the density times the area, to the plant. */
static const char *flat_site(int code, const char *communities)
{
    static char text[2048];
    snprintf(text, sizeof text,
             "site: {crs: \"EPSG:32612\", origin: [400000, 4100000]}\n"
             "terrain: {grid: [[0, 0, 0], [0, 0, 0], [0, 0, 0]], spacing: [1000, 1000]}\n"
             "species: {include: [%s]}\n"
             "landcover:\n"
             "  polygons: %s\n"
             "  class_field: code\n"
             "  classes: [{code: %d, kind: shrub}]\n"
             "  communities:\n%s",
             SPECIES, work_file("one.geojson", "{\"type\": \"FeatureCollection\", \"crs\": {\"type\": \"name\", "
                                               "\"properties\": {\"name\": \"EPSG:32612\"}}, \"features\": [{\"type\": "
                                               "\"Feature\", \"properties\": {\"code\": 5}, \"geometry\": {\"type\": "
                                               "\"Polygon\", \"coordinates\": [[[398000, 4098000], [402000, 4098000], "
                                               "[402000, 4102000], [398000, 4102000], [398000, 4098000]]]}}]}"),
             code, communities);
    return text;
}

TEST(density_and_shares)
{
    err_buf err = {{0}};
    scene *s = scene_text_build_analysis("flat.yaml",
                          flat_site(5, "    - {code: 5, species: sagebrush pinyon_juniper, shares: [3, 1], density: 25, "
                                       "height: [1, 2]}\n  plant_spacing: 100\n"),
                          1, &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    uint32_t n[2] = {0, 0};
    for (uint32_t i = 0; s && i < s->n_instances; i++) {
        if (scene_instance_is_ground_cover(s, i)) continue;
        const char *name = s->species[s->prototypes[s->instances[i].prototype].species].name;
        n[strcmp(name, "sagebrush") != 0]++;
        float h = s->instances[i].xf.m[2][2] * (float)s->prototypes[s->instances[i].prototype].height;
        CHECK(h >= 0.999f && h <= 2.001f);
    }
    /* 2 x 2 km at 25 per hectare: 25 plants in each of the 400 cells of one hectare, a quarter
     * of them pinyon-juniper (2,500, give or take 43) */
    fprintf(stderr, "flat: %u sagebrush, %u pinyon_juniper\n", n[0], n[1]);
    CHECK_INT(n[0] + n[1], 10000);
    CHECK(n[1] >= 2300 && n[1] <= 2700);
    scene_free(s);
}

static void refused(const char *communities, const char *expect)
{
    err_buf err = {{0}};
    scene *s = scene_text_build_analysis("bad.yaml", flat_site(5, communities), 1, &err);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(err.msg, expect);
    scene_free(s);
}

TEST(bad_communities_refused)
{
    refused("    - {kind: shrub, species: sagebrsh, density: 10, height: [1, 2]}\n",
            "unknown species 'sagebrsh' in 'landcover.communities'; did you mean 'sagebrush'?");
    refused("    - {kind: shrub, code: 5, species: sagebrush, density: 10, height: [1, 2]}\n",
            "give kind: (forest, shrub, grass, ...) or code: (the map's code), not both");
    refused("    - {code: 5, species: sagebrush ponderosa, shares: [1], density: 10, height: [1, 2]}\n",
            "'shares' gives 1 numbers for 2 species");
    refused("    - {code: 5, species: sagebrush, density: 10, height: [2, 1]}\n", "'height' [2, 1] runs downward");
    refused("    - {code: 5, species: sagebrush, density: 10, height: [1, 2]}\n"
            "    - {code: 5, species: ponderosa, density: 10, height: [1, 2]}\n",
            "the class 5 has two communities");
    refused("    - {code: 5, species: sagebrush, density: 30000, height: [1, 2]}\n",
            "more than the 8000000 a scene takes");
    refused("    - {code: 5, species: sagebrush, density: 10, height: [1, 2]}\n  plant_area: [0, 0, 100, 100]\n",
            "the plant_area [0, 0, 100, 100] holds no cell of 5 m on the terrain");
}

/* The west (code 1) and east (code 2) halves of a 128 m square round (400000, 4100000) in
 * EPSG:32612, their boundary at 400004 E: a GeoJSON file in the work folder. */
static const char *halves_map(void)
{
    return work_file("halves.geojson",
        "{\"type\": \"FeatureCollection\", \"crs\": {\"type\": \"name\", \"properties\": {\"name\": \"EPSG:32612\"}},"
        " \"features\": ["
        "{\"type\": \"Feature\", \"properties\": {\"code\": 1}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": "
        "[[[399900, 4099900], [400004, 4099900], [400004, 4100100], [399900, 4100100], [399900, 4099900]]]}},"
        "{\"type\": \"Feature\", \"properties\": {\"code\": 2}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": "
        "[[[400004, 4099900], [400100, 4099900], [400100, 4100100], [400004, 4100100], [400004, 4099900]]]}}]}");
}

/* A 128 m square site whose west half is forest (code 1) and east half grass (code 2), the
 * boundary 4 m east of the middle nodes, with a mesh beech the ecology grows for 120 years;
 * `communities` (may be empty) under the landcover: section. */
static scene *halves(const char *communities, err_buf *err)
{
    static char text[16384];
    const char *map = halves_map();
    int n = snprintf(text, sizeof text,
                     "site: {crs: \"EPSG:32612\", origin: [400000, 4100000]}\n"
                     "terrain:\n  origin: [-64, -64]\n  spacing: [8, 8]\n  grid:\n");
    for (int j = 0; j < 17; j++) {
        n += snprintf(text + n, sizeof text - n, "    - [");
        for (int i = 0; i < 17; i++) n += snprintf(text + n, sizeof text - n, "%s0", i ? ", " : "");
        n += snprintf(text + n, sizeof text - n, "]\n");
    }
    snprintf(text + n, sizeof text - n,
             "species:\n"
             "  beech: {shape: box, size: [4, 4, 20], ecology: {profile: beech}}\n"
             "landcover:\n"
             "  polygons: %s\n"
             "  class_field: code\n"
             "  classes: [{code: 1, kind: forest}, {code: 2, kind: grass}]\n"
             "%s"
             "ecology: {plugin: ecology, years: 120, patches: 32}\n",
             map, communities);
    return scene_text_build_analysis("halves.yaml", text, 1, err);
}

/* The beeches standing east of x, and all of them. */
static uint32_t beeches_east_of(const scene *s, double x, uint32_t *all)
{
    uint32_t n = 0;
    *all = 0;
    for (uint32_t i = 0; s && i < s->n_instances; i++) {
        if (scene_instance_is_ground_cover(s, i)) continue;
        ++*all;
        n += s->instances[i].xf.m[0][3] > x;
    }
    return n;
}

/* A community's species with an ecology block is grown by the ecology, and only where the land
 * cover has its community (patches of 4 m: a patch belongs to the west half when its centre's
 * nearest node does, so no beech stands east of 6 m); without the community it grows on both. */
TEST(grown_within_habitat)
{
    err_buf err = {{0}};
    scene *with = halves("  communities: [{kind: forest, species: beech, density: 100, height: [5, 20]}]\n", &err);
    if (!with) fprintf(stderr, "%s\n", err.msg);
    scene *without = with ? halves("", &err) : NULL;
    CHECK(with && without);
    uint32_t all_with, all_without;
    uint32_t east_with = beeches_east_of(with, 6.0, &all_with), east_without = beeches_east_of(without, 6.0, &all_without);
    fprintf(stderr, "halves: %u beeches with the forest community, %u of them east of the boundary; %u without, %u "
            "east\n", all_with, east_with, all_without, east_without);
    CHECK(all_with > 20);
    CHECK_INT(east_with, 0);
    CHECK(east_without > 20);
    scene_free(with);
    scene_free(without);
}

/* Communities are fitted to a canopy height model as the ecology's plants are
 * (scene_build/scene_canopy.h): under a CHM of 8 m everywhere, every ponderosa placed at 4-12 m
 * reaches half the canopy and is scaled to 8 m exactly. */
TEST(fitted_to_the_canopy)
{
    char chm[1200]; /* work_path's buffer is reused by the next call */
    snprintf(chm, sizeof chm, "%s", work_path("chm8.tif"));
    GDALDatasetH ds = geotiff_create(chm, 32612, 397000, 4103000, 100, 60, 60, GDT_Float32);
    CHECK(ds != NULL);
    if (!ds) return;
    CHECK(GDALFillRaster(GDALGetRasterBand(ds, 1), 8.0, 0) == CE_None);
    GDALClose(ds);
    char text[4096];
    snprintf(text, sizeof text, "%s  plant_spacing: 100\ncanopy: {chm: %s}\n",
             flat_site(5, "    - {code: 5, species: ponderosa, density: 25, height: [4, 12]}\n"), chm);
    err_buf err = {{0}};
    scene *s = scene_text_build_analysis("fitted.yaml", text, 1, &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    uint32_t n = 0, at_8 = 0;
    for (uint32_t i = 0; s && i < s->n_instances; i++) {
        if (scene_instance_is_ground_cover(s, i)) continue;
        double h = s->instances[i].xf.m[2][2] * s->prototypes[s->instances[i].prototype].height;
        n++, at_8 += fabs(h - 8.0) < 1e-3;
    }
    fprintf(stderr, "canopy: %u of %u ponderosas stand 8 m tall under the 8 m canopy\n", at_8, n);
    CHECK_INT(n, 10000);
    CHECK_INT(at_8, n);
    scene_free(s);
}

/* Sagebrush over the west half on a 1 m grid: plants per square metre between x0 and x1. */
static double sage_density(const scene *s, double x0, double x1)
{
    uint32_t n = 0;
    for (uint32_t i = 0; s && i < s->n_instances; i++) {
        if (scene_instance_is_ground_cover(s, i)) continue;
        double x = s->instances[i].xf.m[0][3], y = s->instances[i].xf.m[1][3];
        n += x >= x0 && x < x1 && y > -60 && y < 60;
    }
    return n / ((x1 - x0) * 120.0);
}

/* A community thins out over plant_edge inside its edge, and keeps its density without one. */
static scene *sage_west(const char *edge, err_buf *err)
{
    char text[4096];
    snprintf(text, sizeof text,
             "site: {crs: \"EPSG:32612\", origin: [400000, 4100000]}\n"
             "terrain: {origin: [-64, -64], spacing: [64, 64], grid: [[0, 0, 0], [0, 0, 0], [0, 0, 0]]}\n"
             "species: {include: [%s]}\n"
             "landcover:\n  polygons: %s\n  class_field: code\n  classes: [{code: 1, kind: shrub}, {code: 2, kind: grass}]\n"
             "  plant_spacing: 1\n  %s\n"
             "  communities: [{kind: shrub, species: sagebrush, density: 2000, height: [0.5, 1]}]\n",
             SPECIES, halves_map(), edge);
    return scene_text_build_analysis("sage.yaml", text, 1, err);
}

TEST(edge_thins_out)
{
    err_buf err = {{0}};
    scene *soft = sage_west("plant_edge: 10", &err), *hard = soft ? sage_west("plant_edge: 0", &err) : NULL;
    if (!hard) fprintf(stderr, "%s\n", err.msg);
    CHECK(soft && hard);
    /* the boundary at x = 4: the band from 1 to 5 m inside it */
    double inner = sage_density(soft, -60, -30), band = sage_density(soft, -1, 3);
    double inner_hard = sage_density(hard, -60, -30), band_hard = sage_density(hard, -1, 3);
    fprintf(stderr, "edge: plants per m2 inside %.3f, 1-5 m inside the edge %.3f; hard edge %.3f and %.3f\n", inner,
            band, inner_hard, band_hard);
    CHECK(fabs(inner - 0.2) < 0.02 && fabs(inner_hard - 0.2) < 0.02);
    CHECK(band < 0.6 * inner);
    CHECK(band_hard > 0.85 * inner_hard);
    CHECK_INT(sage_density(soft, 5, 60) == 0 && sage_density(hard, 5, 60) == 0, 1);
    scene_free(soft);
    scene_free(hard);
}

TEST_LIST(TEST_CASE(zion_follows_the_nlcd), TEST_CASE(zion_names_plant_the_same), TEST_CASE(density_and_shares),
          TEST_CASE(bad_communities_refused), TEST_CASE(grown_within_habitat),
          TEST_CASE(fitted_to_the_canopy),
          TEST_CASE(edge_thins_out))
