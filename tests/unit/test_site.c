/* test_site.c — the site frame and the site section: PROJ's conversion of longitude/latitude to
 * UTM against a published value, the CRS rules (EPSG code or WKT; projected in metres), the UTM
 * zone of a point, the site's CRS and origin taken from a DTM (a GeoTIFF made here through GDAL,
 * in degrees and in metres, or an ASCII grid with its .prj through the terrain plugin), and
 * positions in map coordinates becoming local ones. */
#include <gdal.h>
#include <ogr_srs_api.h>

#include "geotiff_fixture.h"
#include "harness.h"
#include "plugin/plugin_host.h"
#include "scene/heightfield.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "site/site_frame.h"
#include "work_dir.h"

/* PROJ's documentation (quick start) converts 12 E, 55 N to UTM zone 32 on GRS80 as
 * 691875.63 E, 6098907.83 N; WGS 84's ellipsoid differs from GRS80 by far less than 1 mm there. */
TEST(lonlat_to_utm)
{
    err_buf err = {{0}};
    site_frame *f = site_frame_new("EPSG:32632", NULL, &err);
    CHECK(f != NULL);
    if (!f) return;
    CHECK(!strcmp(site_frame_name(f), "WGS 84 / UTM zone 32N"));
    double map[2] = {0, 0};
    CHECK_INT(site_frame_from_lonlat(f, 12.0, 55.0, map, &err), 0);
    CHECK_NEAR(map[0], 691875.63, 0.01);
    CHECK_NEAR(map[1], 6098907.83, 0.01);
    /* the same CRS given as the WKT PROJ wrote for it converts the same */
    site_frame *w = site_frame_new(site_frame_wkt(f), NULL, &err);
    CHECK(w != NULL);
    double again[2] = {0, 0};
    if (w) CHECK_INT(site_frame_from_lonlat(w, 12.0, 55.0, again, &err), 0);
    CHECK(again[0] == map[0] && again[1] == map[1]);
    /* a point given in another CRS (ETRS89 / UTM 32N, EPSG:25832) */
    CHECK_INT(site_frame_from_crs(f, "EPSG:25832", 691875.63, 6098907.83, again, &err), 0);
    CHECK_NEAR(again[0], 691875.63, 2.0); /* the ETRS89 - WGS 84 shift, under a metre or two */
    CHECK_NEAR(again[1], 6098907.83, 2.0);
    site_frame_free(w);
    site_frame_free(f);
}

TEST(crs_rules)
{
    err_buf err = {{0}};
    double near[2] = {-97.4, 32.5};
    CHECK(site_frame_new("EPSG:4326", near, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "the site CRS 'WGS 84' (EPSG:4326) is geographic, in degrees; the site "
                                "needs a projected CRS in metres, such as the site's UTM zone, EPSG:32614");
    CHECK(site_frame_new("EPSG:2276", NULL, &err) == NULL); /* Texas North Central, US survey feet */
    CHECK_STR_CONTAINS(err.msg, "has axes in US survey foot, not metres");
    CHECK(site_frame_new("EPSG:99999", NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "'EPSG:99999' is not a coordinate reference system in PROJ's EPSG database");
    CHECK(site_frame_new("PROJCRS[\"broken\"", NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "the WKT does not define a coordinate reference system");
    CHECK(site_frame_new("utm zone 14", NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "is neither 'EPSG:NNNN' nor WKT");
    site_frame *f = site_frame_new("epsg:3035", NULL, &err); /* ETRS89-LAEA: northing first */
    CHECK(f != NULL);
    double map[2] = {0, 0};
    if (f) CHECK_INT(site_frame_from_lonlat(f, 10.0, 52.0, map, &err), 0);
    CHECK_NEAR(map[0], 4321000.0, 1e-3); /* the projection's false easting at its centre */
    CHECK_NEAR(map[1], 3210000.0, 1e-3);
    site_frame_free(f);
    /* UTM 14N with NAVD88 heights: a compound CRS whose horizontal part is checked */
    f = site_frame_new("EPSG:32614+5703", NULL, &err);
    if (!f) fprintf(stderr, "%s\n", err.msg);
    CHECK(f != NULL);
    if (f) CHECK_INT(site_frame_from_lonlat(f, -99.0, 32.0, map, &err), 0);
    CHECK_NEAR(map[0], 500000.0, 1e-3); /* zone 14's central meridian */
    site_frame_free(f);
    CHECK(site_frame_new("EPSG:4326+5703", NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "is geographic, in degrees");
    CHECK(site_frame_new("EPSG:32614+1", NULL, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "'EPSG:32614+1' is not a horizontal and a vertical CRS");
}

TEST(utm_zones)
{
    CHECK_INT(site_utm_epsg(-97.4, 32.5), 32614);
    CHECK_INT(site_utm_epsg(12.0, -33.0), 32733);
    CHECK_INT(site_utm_epsg(-180.0, 0.0), 32601);
    CHECK_INT(site_utm_epsg(180.0, 0.0), 32601); /* the antimeridian is zone 1 again */
    CHECK_INT(site_utm_epsg(179.9, 10.0), 32660);
    CHECK_INT(site_utm_epsg(-117.0, 34.0), 32611); /* 117 W is zone 11's west edge */
}

/* A 21 x 11 GeoTIFF whose north-west corner is (x0, y0), cells `cell` wide, in the CRS of
 * `epsg`; its path (until the next call), or NULL when GDAL cannot write it. */
static const char *write_dtm(const char *name, int epsg, double x0, double y0, double cell)
{
    static char path_copy[1200]; /* work_path's buffer is reused by the next work file */
    const char *path = strcpy(path_copy, work_path(name));
    GDALDatasetH ds = geotiff_create(path, epsg, x0, y0, cell, 21, 11, GDT_Float32);
    if (!ds) return NULL;
    float row[21];
    for (int j = 0; j < 11; j++) {
        for (int i = 0; i < 21; i++) row[i] = (float)(500 + 3 * i + 2 * j);
        if (GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, j, 21, 1, row, 21, 1, GDT_Float32, 0, 0) != CE_None)
            path = NULL;
    }
    GDALClose(ds);
    return path;
}

static scene_file *load_with_dtm(const char *site, const char *dtm, const char *camera, err_buf *err)
{
    static char text[2048];
    snprintf(text, sizeof text, "site: %s\ncamera: %s\nterrain: {plugin: terrain_ifs, dtm: %s}\n", site,
             camera, dtm);
    const char *path = work_file("dtm_site.yaml", text);
    plugin_registry *reg = plugin_registry_open(err);
    scene_file *sf = reg && path ? scene_file_load(path, reg, err) : NULL;
    plugin_registry_free(reg);
    return sf;
}

/* site: {} over a DTM in degrees: the UTM zone of its centre, the centre rounded as origin. */
TEST(site_from_geographic_dtm)
{
    /* 0.001 degree cells from 117.02 W, 34.01 N: the centre at 117.0095 W, 34.0045 N */
    const char *dtm = write_dtm("geo.tif", 4326, -117.02, 34.01, 0.001);
    CHECK(dtm != NULL);
    if (!dtm) return;
    err_buf err = {{0}};
    scene_file *sf = load_with_dtm("{}", dtm, "{position: {longitude: -117.0095, latitude: 34.0045}, "
                                   "height_above_ground: 1.6, look_at: [0, 100]}", &err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    if (!sf) return;
    CHECK(sf->site.crs_name && !strcmp(sf->site.crs_name, "WGS 84 / UTM zone 11N"));
    site_frame *f = site_frame_new("EPSG:32611", NULL, &err);
    double centre[2] = {0, 0};
    CHECK(f && !site_frame_from_lonlat(f, -117.0095, 34.0045, centre, &err));
    CHECK(sf->site.origin[0] == round(centre[0]) && sf->site.origin[1] == round(centre[1]));
    CHECK(sf->site.origin[2] == 0.0);
    /* the camera at the centre: local = map - origin, less than half a metre each way */
    CHECK_NEAR(sf->camera.position[0], centre[0] - sf->site.origin[0], 1e-6);
    CHECK_NEAR(sf->camera.position[1], centre[1] - sf->site.origin[1], 1e-6);
    CHECK(fabs(sf->camera.position[0]) <= 0.5 && fabs(sf->camera.position[1]) <= 0.5);
    CHECK(isnan(sf->camera.position[2]) && sf->camera.eye_ground.given && sf->camera.eye_ground.above == 1.6);
    /* a look_at of two numbers is on the ground */
    CHECK(sf->camera.look_at_ground.given && sf->camera.look_at_ground.above == 0.0);
    site_frame_free(f);
    scene_file_free(sf);
}

/* crs given, origin from a DTM in metres; and a DTM in metres giving both. */
TEST(site_from_projected_dtm)
{
    const char *dtm = write_dtm("utm.tif", 32614, 649990.3, 3600110.7, 10.0); /* centre 650095.3, 3600055.7 */
    CHECK(dtm != NULL);
    if (!dtm) return;
    err_buf err = {{0}};
    scene_file *sf = load_with_dtm("{}", dtm, "{position: {easting: 650100, northing: 3600050, height: 530}}", &err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    if (sf) {
        CHECK(!strcmp(sf->site.crs_name, "WGS 84 / UTM zone 14N"));
        CHECK(sf->site.origin[0] == 650095.0 && sf->site.origin[1] == 3600056.0);
        CHECK(sf->camera.position[0] == 5.0 && sf->camera.position[1] == -6.0 && sf->camera.position[2] == 530.0);
    }
    scene_file_free(sf);
    sf = load_with_dtm("{origin: [650000, 3600000, 400]}", dtm,
                       "{position: {easting: 650100, northing: 3600050, height: 530}}", &err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    if (sf) CHECK(sf->camera.position[0] == 100.0 && sf->camera.position[1] == 50.0 && sf->camera.position[2] == 130.0);
    scene_file_free(sf);
    /* a geographic CRS named as the site's, with a DTM: refused, naming the zone */
    sf = load_with_dtm("{crs: EPSG:4326, origin: [-97.4, 32.5]}", dtm, "{position: [0, 0, 600]}", &err);
    CHECK(sf == NULL);
    CHECK_STR_CONTAINS(err.msg, "dtm_site.yaml:1:13: the site CRS 'WGS 84' (EPSG:4326) is geographic");
    CHECK_STR_CONTAINS(err.msg, "EPSG:32614");
    /* a DTM that is not a raster */
    char junk[1200];
    strcpy(junk, work_file("junk.tif", "not a raster\n"));
    sf = load_with_dtm("{}", junk, "{position: [0, 0, 600]}", &err);
    CHECK(sf == NULL);
    CHECK_STR_CONTAINS(err.msg, "is not a raster GDAL reads");
}

/* tests/scenes/site/dtm_site.yaml: an ESRI ASCII grid with its .prj, read through the terrain
 * plugin; the site from the DTM, the camera 1.6 m above the built terrain at a map position. */
TEST(site_scene_from_dtm)
{
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open(&err);
    scene_file *sf = reg ? scene_file_load(SYLVA_TEST_DATA_DIR "/scenes/site/dtm_site.yaml", reg, &err) : NULL;
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    if (sf) {
        CHECK(!strcmp(sf->site.crs_name, "WGS 84 / UTM zone 11N"));
        CHECK(sf->site.origin[0] == 440135.0 && sf->site.origin[1] == 3760135.0 && sf->site.origin[2] == 0.0);
        CHECK(sf->camera.position[0] == -75.0 && sf->camera.position[1] == -95.0);
        build_options quiet = {.quiet = 1};
        scene *s = scene_build(sf, reg, &quiet, &err);
        if (!s) fprintf(stderr, "%s\n", err.msg);
        CHECK(s != NULL);
        double ground = NAN;
        if (s) CHECK_INT(heightfield_surface_height(s->terrain, -75.0, -95.0, &ground), 0);
        if (s) CHECK_NEAR(s->camera.position[2] - ground, 1.6, 1e-9);
        CHECK(ground > 600 && ground < 760); /* the DTM's heights, in its own datum */
        scene_free(s);
    }
    scene_file_free(sf);
    plugin_registry_free(reg);
}

/* The scene built from load_with_dtm's file, or NULL with err set. */
static scene *build_with_dtm(const char *site, const char *dtm, err_buf *err)
{
    plugin_registry *reg = plugin_registry_open(err);
    scene_file *sf = load_with_dtm(site, dtm, "{position: [0, 0, 900]}", err);
    build_options quiet = {.quiet = 1};
    scene *s = sf && reg ? scene_build(sf, reg, &quiet, err) : NULL;
    scene_file_free(sf);
    plugin_registry_free(reg);
    return s;
}

/* A site is local: a DTM whose footprint lies more than 100 km plus its own size from the site
 * origin is refused at the terrain section with the distance in km; one within it is built. */
TEST(dtm_far_from_the_site_origin)
{
    const char *dtm = write_dtm("far.tif", 32614, 649990.3, 3600110.7, 10.0); /* 210 x 110 m */
    CHECK(dtm != NULL);
    if (!dtm) return;
    err_buf err = {{0}};
    /* an origin given 2,900 km from the DTM (in the DTM's own CRS) */
    scene *s = build_with_dtm("{origin: [100000, 1000000]}", dtm, &err);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(err.msg, "dtm_site.yaml:3:10: the DTM '");
    CHECK_STR_CONTAINS(err.msg, "' lies 2658 km from the site origin (easting 100000, northing 1000000)");
    CHECK_STR_CONTAINS(err.msg, "spans easting 649995 to 650195, northing 3600006 to 3600106, 0.2 km across");
    CHECK_STR_CONTAINS(err.msg, "must come within 100.2 km of the origin");
    scene_free(s);
    /* the site in another CRS's area: the DTM warped into UTM zone 33N, thousands of km away */
    s = build_with_dtm("{crs: EPSG:32633, origin: [500000, 5000000]}", dtm, &err);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(err.msg, " km from the site origin (easting 500000, northing 5000000): in the site's CRS "
                                "(WGS 84 / UTM zone 33N)");
    scene_free(s);
    /* 99.8 km beyond the DTM's east edge: local enough; 100.3 km: not */
    s = build_with_dtm("{origin: [750000, 3600056]}", dtm, &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s != NULL);
    scene_free(s);
    s = build_with_dtm("{origin: [750500, 3600056]}", dtm, &err);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(err.msg, "lies 100 km from the site origin");
    scene_free(s);
}

TEST_LIST(TEST_CASE(lonlat_to_utm), TEST_CASE(crs_rules), TEST_CASE(utm_zones),
          TEST_CASE(site_from_geographic_dtm), TEST_CASE(site_from_projected_dtm), TEST_CASE(site_scene_from_dtm),
          TEST_CASE(dtm_far_from_the_site_origin))
