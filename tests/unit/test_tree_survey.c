/* test_tree_survey.c — the trees: section. The 1,115 tree tops ForestTools found in its test
 * canopy height model (ttops_test.gpkg, UTM zone 11N, a height each, no species), placed on a
 * flat site: every tree stands where the file says, read back through OGR here, and is as tall
 * as its measured height (the prototype's height times the instance's vertical scale). A CSV in
 * longitude and latitude whose species names are mapped to the scene's, with crown diameters.
 * Bad surveys refused at the key they are about: an unknown species, a missing height column, a
 * polygon, a missing file, a point beyond the pole (with no message of GDAL's own). Without the
 * shared data set the ForestTools case is skipped. */
#include <math.h>
#include <string.h>
#include <sys/stat.h>

#include <cpl_error.h>
#include <gdal.h>
#include <ogr_api.h>

#include "harness.h"
#include "work_dir.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

#define TTOPS SYLVA_SHARED_DATA_DIR "/canopy/foresttools/ttops_test.gpkg"
#define ORIGIN_E 439944.0
#define ORIGIN_N 5526694.0

/* A flat site at 800 m in UTM zone 11N over the CHM's footprint, then `trees` (its own lines). */
static const char *site_yaml = "site: {crs: \"EPSG:32611\", origin: [439944, 5526694]}\n"
                               "camera: {position: [0, -130, 860], look_at: [0, 0, 805]}\n"
                               "terrain: {grid: [[800, 800], [800, 800]], origin: [-100, -100], spacing: [200, 200]}\n"
                               "species:\n"
                               "  fir: {shape: box, size: [2, 2, 10]}\n"
                               "  beech: {shape: sphere, radius: 3}\n"
                               "trees:\n";

/* The scene of site_yaml + trees, loaded quietly; NULL with err set. */
static scene *survey_scene(const char *trees, err_buf *err)
{
    char text[4096];
    snprintf(text, sizeof text, "%s%s", site_yaml, trees);
    const char *path = work_file("scene.yaml", text);
    scene_file *sf = path ? scene_file_load_with(path, NULL, SCENE_FILE_QUIET, err) : NULL;
    if (!sf) return NULL;
    build_options bo = {.quiet = 1};
    scene *s = scene_build(sf, NULL, &bo, err);
    scene_file_free(sf);
    return s;
}

/* The modelled height of instance i: its prototype's height times its vertical scale. */
static double instance_height(const scene *s, uint32_t i)
{
    const instance *in = &s->instances[i];
    return s->prototypes[in->prototype].height * in->xf.m[2][2];
}

TEST(foresttools_tree_tops)
{
    struct stat st;
    if (stat(TTOPS, &st) != 0) SKIP("the shared data set is not at %s", TTOPS);
    err_buf err = {{0}};
    scene *s = survey_scene("  file: " TTOPS "\n  species: fir\n", &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    if (!s) return;
    CHECK_INT(s->n_instances, 1115);
    GDALAllRegister();
    GDALDatasetH ds = GDALOpenEx(TTOPS, GDAL_OF_VECTOR | GDAL_OF_READONLY, NULL, NULL, NULL);
    CHECK(ds != NULL);
    OGRLayerH layer = ds ? GDALDatasetGetLayerByName(ds, "ttops_test") : NULL;
    CHECK(layer != NULL);
    double worst_xy = 0, worst_z = 0, worst_h = 0;
    uint32_t i = 0;
    for (OGRFeatureH f; layer && (f = OGR_L_GetNextFeature(layer)); i++) {
        OGRGeometryH g = OGR_F_GetGeometryRef(f);
        double h = OGR_F_GetFieldAsDouble(f, OGR_F_GetFieldIndex(f, "height"));
        if (i < s->n_instances) {
            const xform3x4 *xf = &s->instances[i].xf;
            double dx = xf->m[0][3] + ORIGIN_E - OGR_G_GetX(g, 0), dy = xf->m[1][3] + ORIGIN_N - OGR_G_GetY(g, 0);
            worst_xy = fmax(worst_xy, hypot(dx, dy));
            worst_z = fmax(worst_z, fabs(xf->m[2][3] - 800.0));
            worst_h = fmax(worst_h, fabs(instance_height(s, i) - h) / h);
        }
        OGR_F_Destroy(f);
    }
    if (ds) GDALClose(ds);
    fprintf(stderr, "1115 tree tops: largest position error %.2g m, base off the ground %.2g m, height error %.2g %%\n",
            worst_xy, worst_z, 100 * worst_h);
    CHECK_INT(i, 1115);
    CHECK(worst_xy < 0.01);
    CHECK(worst_z < 0.01);
    CHECK(worst_h < 0.05);
    scene_free(s);
}

/* Three trees in longitude and latitude (the UTM points 439900 5526700, 439950 5526650 and
 * 440000 5526740 converted with gdaltransform), their Latin names mapped to the scene's
 * species; a crown diameter stretches the middle one's crown, within twice its proportions. */
TEST(csv_mapped_species)
{
    work_file("survey.csv", "lon,lat,name,h,crown\n"
                            "-117.836691786,49.889674948,Abies grandis,12.5,\n"
                            "\n"
                            "# a comment line\n"
                            "-117.835988014,49.889230305,Fagus sylvatica,20,9\n"
                            "-117.835305986,49.890044715,beech,3,\n");
    err_buf err = {{0}};
    scene *s = survey_scene("  file: survey.csv\n  crs: EPSG:4326\n  x_field: lon\n  y_field: lat\n"
                            "  species_field: name\n  height_field: h\n  crown_field: crown\n"
                            "  species_map: {Abies grandis: fir, Fagus sylvatica: beech}\n", &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    if (!s) return;
    CHECK_INT(s->n_instances, 3);
    static const double want[3][4] = {{-44, 6, 0, 12.5}, {6, -44, 1, 20}, {56, 46, 1, 3}}; /* x, y, species, h */
    for (uint32_t i = 0; i < 3 && i < s->n_instances; i++) {
        const instance *in = &s->instances[i];
        CHECK_NEAR(in->xf.m[0][3], want[i][0], 0.01);
        CHECK_NEAR(in->xf.m[1][3], want[i][1], 0.01);
        CHECK_INT(s->prototypes[in->prototype].species, (uint32_t)want[i][2]);
        CHECK_NEAR(instance_height(s, i), want[i][3], 1e-4);
    }
    /* The sphere (about 6 m across and 6 m tall) scaled to 20 m tall would be about 20 m wide; the
     * survey's 9 m crown is narrower than half that, so the crown is kept at half. */
    const instance *in = &s->instances[1];
    const prototype *pr = &s->prototypes[in->prototype];
    float lo[3], hi[3];
    mesh_bounds(pr->mesh, lo, hi);
    double width = 0.5 * ((hi[0] - lo[0]) + (hi[1] - lo[1])), vertical = 20.0 / pr->height;
    CHECK_NEAR(hypot(in->xf.m[0][0], in->xf.m[1][0]) * width, fmax(9.0, 0.5 * vertical * width), 1e-3);
    CHECK(0.5 * vertical * width > 9.0);
    scene_free(s);
}

/* The loader's sentence for a survey; "" when the scene loads. */
static const char *refusal(const char *trees)
{
    static err_buf err;
    memset(&err, 0, sizeof err);
    scene *s = survey_scene(trees, &err);
    scene_free(s);
    return s ? "" : err.msg;
}

TEST(bad_surveys)
{
    work_file("named.csv", "x,y,name,h\n0,0,fir,5\n10,0,Quercus robur,7\n");
    const char *e = refusal("  file: named.csv\n  crs: EPSG:32611\n  species_field: name\n  height_field: h\n");
    fprintf(stderr, "%s\n", e);
    CHECK_STR_CONTAINS(e, "scene.yaml:10:18: trees: 'named.csv' line 3: species 'Quercus robur' is neither in "
                          "species_map nor a species of the scene (fir, beech)");
    e = refusal("  file: named.csv\n  species_field: name\n  height_field: height\n  species: fir\n");
    fprintf(stderr, "%s\n", e);
    CHECK_STR_CONTAINS(e, "scene.yaml:10:17: trees: 'named.csv' has no column 'height'");
    e = refusal("  file: named.csv\n  species: fir\n");
    CHECK_STR_CONTAINS(e, "scene.yaml:8:9: trees: 'named.csv' has no column 'height'");
    work_file("zero.csv", "x,y,height\n0,0,5\n1,1,0\n");
    e = refusal("  file: zero.csv\n  species: fir\n");
    fprintf(stderr, "%s\n", e);
    CHECK_STR_CONTAINS(e, "scene.yaml:8:9: trees: 'zero.csv' line 3: height 0 is not above 0");
    work_file("stand.geojson", "{\"type\": \"FeatureCollection\", \"features\": [\n"
                               " {\"type\": \"Feature\", \"properties\": {\"height\": 9}, \"geometry\": {\"type\": "
                               "\"Point\", \"coordinates\": [439944, 5526694]}},\n"
                               " {\"type\": \"Feature\", \"properties\": {\"height\": 9}, \"geometry\": {\"type\": "
                               "\"Polygon\", \"coordinates\": [[[439944, 5526694], [439954, 5526694], [439954, "
                               "5526704], [439944, 5526694]]]}}]}\n");
    e = refusal("  file: stand.geojson\n  crs: EPSG:32611\n  species: fir\n");
    fprintf(stderr, "%s\n", e);
    CHECK_STR_CONTAINS(e, "scene.yaml:8:9: trees: 'stand.geojson' FID 1 is a Polygon, not a point");
    e = refusal("  file: nowhere.gpkg\n  species: fir\n");
    fprintf(stderr, "%s\n", e);
    CHECK_STR_CONTAINS(e, "scene.yaml:8:9: trees: nowhere.gpkg: cannot open");
    e = refusal("  file: named.csv\n  species: oak\n");
    CHECK_STR_CONTAINS(e, "scene.yaml:9:12: unknown species 'oak' in 'trees'");
}

/* Trees off the terrain are left out with a warning; a survey wholly off it is refused. */
TEST(off_the_terrain)
{
    work_file("far.csv", "x,y,height\n439944,5526694,5\n449944,5526694,5\n");
    err_buf err = {{0}};
    scene *s = survey_scene("  file: far.csv\n  species: fir\n", &err);
    CHECK(s != NULL);
    if (s) CHECK_INT(s->n_instances, 1);
    scene_free(s);
    work_file("farther.csv", "x,y,height\n449944,5526694,5\n");
    const char *e = refusal("  file: farther.csv\n  species: fir\n");
    fprintf(stderr, "%s\n", e);
    CHECK_STR_CONTAINS(e, "scene.yaml:8:9: trees: none of the 1 trees of farther.csv stands on the terrain");
}

/* GDAL's messages that reached its handler of last resort (stderr, outside this test). */
static int gdal_messages;
static void count_gdal_message(CPLErr level, CPLErrorNum number, const char *text)
{
    (void)number, (void)text;
    if (level != CE_Debug) gdal_messages++;
}

/* A point PROJ cannot convert (a latitude beyond the pole) is refused at the crs key, naming the
 * file, its line and PROJ's reason; GDAL's own message of it does not reach stderr. */
TEST(point_beyond_the_pole)
{
    work_file("pole.csv", "lon,lat,h\n-117.836691786,49.889674948,12\n-117.8,95,8\n");
    CPLErrorHandler before = CPLSetErrorHandler(count_gdal_message);
    gdal_messages = 0;
    const char *e = refusal("  file: pole.csv\n  crs: EPSG:4326\n  x_field: lon\n  y_field: lat\n"
                            "  height_field: h\n  species: fir\n");
    CPLSetErrorHandler(before);
    fprintf(stderr, "%s\n", e);
    CHECK_STR_CONTAINS(e, "scene.yaml:9:8: trees: 'pole.csv' line 3: the point (-117.8, 95) cannot be converted "
                          "from WGS 84 into the site CRS (");
    CHECK_STR_CONTAINS(e, "give the survey's points in WGS 84, or its own CRS as crs:");
    CHECK_INT(gdal_messages, 0);
}

TEST_LIST(TEST_CASE(foresttools_tree_tops), TEST_CASE(csv_mapped_species), TEST_CASE(bad_surveys),
          TEST_CASE(off_the_terrain), TEST_CASE(point_beyond_the_pole))
