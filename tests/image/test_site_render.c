/* test_site_render.c — georeferenced scenes rendered: a scene written in UTM magnitudes gives the
 * same layers as the same scene in local metres, bit for bit; a camera at height_above_ground
 * stands that high above the rendered ground; the EXR header carries the site's CRS and origin;
 * a height above ground with no terrain under it is an error at its line. */
#include <math.h>
#include <openexr.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "render/film.h"
#include "render/render.h"
#include "scene_build/scene_build.h"
#include "work_dir.h"

#define SCENES SYLVA_TEST_DATA_DIR "/scenes/site"

static scene *build(const char *path, err_buf *err)
{
    scene_file *sf = scene_file_load(path, NULL, err);
    scene *s = sf ? scene_build(sf, NULL, NULL, err) : NULL;
    scene_file_free(sf);
    return s;
}

static film *render(const scene *s, unsigned threads)
{
    render_options ro = {.threads = threads, .quiet = 1};
    err_buf err = {{0}};
    film *f = render_scene(s, &ro, NULL, &err);
    if (!f) fprintf(stderr, "render: %s\n", err.msg);
    return f;
}

/* Number of values that differ in their bits between two layers of n floats (or uint32s). */
static size_t differing(const void *a, const void *b, size_t n)
{
    size_t d = 0;
    for (size_t i = 0; i < n; i++) d += memcmp((const char *)a + 4 * i, (const char *)b + 4 * i, 4) != 0;
    return d;
}

/* The same scene at UTM magnitudes and in local metres: every layer the EXR holds is the same,
 * bit for bit (map coordinates become local ones in double precision before anything is
 * rounded to single precision), on one thread and on two. */
TEST(utm_equals_local)
{
    err_buf err = {{0}};
    scene *u = build(SCENES "/utm.yaml", &err);
    if (!u) fprintf(stderr, "utm.yaml: %s\n", err.msg);
    scene *l = build(SCENES "/local.yaml", &err);
    if (!l) fprintf(stderr, "local.yaml: %s\n", err.msg);
    CHECK(u && l);
    if (!u || !l) return;
    CHECK(u->site.crs_wkt && !l->site.crs_wkt);
    CHECK_INT(u->n_instances, 4);
    for (unsigned threads = 1; threads <= 2; threads++) {
        film *fu = render(u, threads), *fl = render(l, threads);
        CHECK(fu && fl);
        if (fu && fl) {
            size_t n = (size_t)fu->width * fu->height;
            CHECK_INT(differing(fu->rgb, fl->rgb, 3 * n), 0);
            CHECK_INT(differing(fu->depth, fl->depth, n), 0);
            CHECK_INT(differing(fu->normal, fl->normal, 3 * n), 0);
            CHECK_INT(differing(fu->albedo, fl->albedo, 3 * n), 0);
            CHECK_INT(differing(fu->instance_id, fl->instance_id, n), 0);
            CHECK_INT(differing(fu->species_id, fl->species_id, n), 0);
            size_t ground = 0, crate = 0; /* the view shows both, so the comparison means something */
            for (size_t i = 0; i < n; i++) ground += fu->instance_id[i] == 0 && isfinite(fu->depth[i]),
                                           crate += fu->instance_id[i] != 0;
            CHECK(ground > n / 4 && crate > n / 50);
        }
        film_free(fu);
        film_free(fl);
    }
    scene_free(u);
    scene_free(l);
}

/* A non-planar cell (heights 0, 1, 1, 4) where the drawn triangles and the bilinear surface part
 * by 0.12 m under the camera: the eye must stand 1.6 m above the triangles, as rendered. The
 * view is straight down, so the centre pixel's depth is the eye's height above the ground. */
static const char *down_scene(const char *position, const char *terrain_origin)
{
    static char text[2048];
    snprintf(text, sizeof text,
             "image: {width: 3, height: 3, spp: 1}\n"
             "site: {crs: EPSG:32614, origin: [650000, 3600000]}\n"
             "camera:\n"
             "  position: %s\n"
             "  height_above_ground: 1.6\n"
             "  look_at: %s\n"
             "  up: [0, 1, 0]\n"
             "  fov: 1\n"
             "terrain:\n"
             "  grid: [[0, 1, 3], [1, 4, 5], [2, 6, 9]]\n"
             "  origin: %s\n"
             "  spacing: [10, 10]\n",
             position, position, terrain_origin);
    return text;
}

static double centre_depth(const char *text, err_buf *err)
{
    const char *path = work_file("down.yaml", text);
    scene *s = path ? build(path, err) : NULL;
    film *f = s ? render(s, 1) : NULL;
    double d = f ? f->depth[4] : NAN;
    film_free(f);
    scene_free(s);
    return d;
}

TEST(camera_height_above_ground)
{
    err_buf err = {{0}};
    /* local (7, 2) in the first cell: fx 0.7, fy 0.2; triangles 1.3 m, bilinear 1.18 m */
    double d = centre_depth(down_scene("[7, 2]", "[0, 0]"), &err);
    if (isnan(d)) fprintf(stderr, "%s\n", err.msg);
    CHECK_NEAR(d, 1.6, 1e-3);
    /* the same in map coordinates; the second cell's slope (1, 3, 4, 5) at fx 0.25, fy 0.6 */
    d = centre_depth(down_scene("{easting: 650012.5, northing: 3600006}",
                                "{easting: 650000, northing: 3600000}"), &err);
    if (isnan(d)) fprintf(stderr, "%s\n", err.msg);
    CHECK_NEAR(d, 1.6, 1e-3);
}

/* height_above_ground where the terrain does not reach: an error at the line that gave it. */
TEST(height_above_ground_off_terrain)
{
    err_buf err = {{0}};
    const char *path = work_file("off.yaml", down_scene("{easting: 650030, northing: 3600005}", "[0, 0]"));
    scene *s = path ? build(path, &err) : NULL;
    CHECK(s == NULL);
    scene_free(s);
    CHECK_STR_CONTAINS(err.msg, "off.yaml:5:24: the camera 'position' (easting 650030.00, northing "
                                "3600005.00) lies outside the terrain (easting 650000.00 to 650020.00");
    CHECK_STR_CONTAINS(err.msg, "height_above_ground needs ground under it");
    /* a plant placed above a ground that is not there */
    path = work_file("plant_off.yaml",
                     "site: {crs: EPSG:32614, origin: [650000, 3600000]}\n"
                     "camera: {position: [0, -10, 2]}\n"
                     "terrain: {grid: [[0, 0], [0, 0]], spacing: [10, 10]}\n"
                     "species: {box: {shape: box}}\n"
                     "plants: [{species: box, position: {easting: 650050, northing: 3600000, "
                     "height_above_ground: 2}}]\n");
    s = path ? build(path, &err) : NULL;
    CHECK(s == NULL);
    scene_free(s);
    CHECK_STR_CONTAINS(err.msg, "plant_off.yaml:5:10: plant 0: position (50, 0) lies outside the terrain");
    /* its extent in local metres, and on the site's map the position and the extent */
    CHECK_STR_CONTAINS(err.msg, "which spans x from 0.000 to 10.000 and y from 0.000 to 10.000 (local metres); on "
                                "the map (WGS 84 / UTM zone 14N) the point is at easting 650050.000, northing "
                                "3600000.000 and the terrain spans easting 650000.000 to 650010.000, northing "
                                "3600000.000 to 3600010.000");
}

/* Every EXR sylva writes names the site's CRS (WKT and name) and origin in its header, and the
 * exposure its PNG takes when given one. */
TEST(exr_header_names_the_site)
{
    err_buf err = {{0}};
    scene *s = build(SCENES "/utm.yaml", &err);
    film *f = s ? render(s, 1) : NULL;
    CHECK(f != NULL);
    const char *path = work_path("site.exr");
    if (f) CHECK_INT(film_write_exr(f, &s->site, -1.25, path, &err), 0);
    exr_context_t ctx = NULL;
    CHECK(exr_start_read(&ctx, path, NULL) == EXR_ERR_SUCCESS);
    if (ctx) {
        int32_t len = 0;
        const char *name = NULL, *wkt = NULL;
        double e = 0, n = 0, h = -1;
        CHECK(exr_attr_get_string(ctx, 0, "siteCrsName", &len, &name) == EXR_ERR_SUCCESS);
        CHECK(name && len == 21 && !strncmp(name, "WGS 84 / UTM zone 14N", 21));
        CHECK(exr_attr_get_string(ctx, 0, "siteCrsWkt", &len, &wkt) == EXR_ERR_SUCCESS);
        CHECK(wkt && len > 100 && !strncmp(wkt, "PROJCRS[\"WGS 84 / UTM zone 14N\"", 31));
        CHECK(wkt && strstr(wkt, "ID[\"EPSG\",32614]"));
        CHECK(exr_attr_get_double(ctx, 0, "siteOriginEasting", &e) == EXR_ERR_SUCCESS);
        CHECK(exr_attr_get_double(ctx, 0, "siteOriginNorthing", &n) == EXR_ERR_SUCCESS);
        CHECK(exr_attr_get_double(ctx, 0, "siteOriginHeight", &h) == EXR_ERR_SUCCESS);
        CHECK(e == 650000.0 && n == 3600000.0 && h == 0.0);
        double ev = 0;
        CHECK(exr_attr_get_double(ctx, 0, "exposureStops", &ev) == EXR_ERR_SUCCESS);
        CHECK(ev == -1.25);
        exr_finish(&ctx);
    }
    /* a scene without a site writes no site attributes */
    scene *l = build(SCENES "/local.yaml", &err);
    film *fl = l ? render(l, 1) : NULL;
    const char *plain = work_path("local.exr");
    if (fl) CHECK_INT(film_write_exr(fl, &l->site, NAN, plain, &err), 0);
    ctx = NULL;
    CHECK(exr_start_read(&ctx, plain, NULL) == EXR_ERR_SUCCESS);
    if (ctx) {
        double e = 0;
        CHECK(exr_attr_get_double(ctx, 0, "siteOriginEasting", &e) == EXR_ERR_NO_ATTR_BY_NAME);
        CHECK(exr_attr_get_double(ctx, 0, "exposureStops", &e) == EXR_ERR_NO_ATTR_BY_NAME); /* NAN: none */
        exr_finish(&ctx);
    }
    film_free(f);
    film_free(fl);
    scene_free(s);
    scene_free(l);
}

TEST_LIST(TEST_CASE(utm_equals_local), TEST_CASE(camera_height_above_ground),
          TEST_CASE(height_above_ground_off_terrain), TEST_CASE(exr_header_names_the_site))
