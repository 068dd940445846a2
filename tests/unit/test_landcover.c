/* test_landcover.c — land-cover maps read onto a site (site/landcover.h): the shipped legends and
 * the reading of class names; the shared Zion site's NLCD 2011 raster and its reclassified copy
 * (names only in its .aux.xml) against each other and against GDAL's own nearest-neighbour warp
 * onto the same nodes; the CORINE raster around Lausanne (EPSG:2056) on a flat site against the
 * raster's own histogram; harvest-block polygons against OGR's point-in-polygon test; a map
 * that misses the site refused at its key. The shared-data cases skip without ../shared/data. */
#include <gdal.h>
#include <gdal_utils.h>
#include <math.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include "geotiff_fixture.h"
#include "harness.h"
#include "plugin/plugin_host.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"
#include "site/landcover_legend.h"
#include "site/scene_probe.h"
#include "work_dir.h"
#include "scene_text.h"

#define SHARED SYLVA_SHARED_DATA_DIR
#define ZION SHARED "/sites/zion"
#define SCENES SYLVA_TEST_DATA_DIR "/scenes"

TEST(legends)
{
    const legend_class *c = landcover_legend_class(LEGEND_NLCD2011, 42);
    CHECK(c && c->kind == LAND_FOREST_EVERGREEN);
    CHECK(landcover_legend_class(LEGEND_NLCD2011, 95)->kind == LAND_WETLAND_HERBACEOUS);
    CHECK(landcover_legend_class(LEGEND_CORINE, 23)->kind == LAND_FOREST_DECIDUOUS);
    CHECK(landcover_legend_class(LEGEND_CORINE, 29)->kind == LAND_SHRUB);
    CHECK(landcover_legend_class(LEGEND_CORINE, 48)->no_data && landcover_legend_class(LEGEND_CORINE, 255)->no_data);
    CHECK(landcover_legend_class(LEGEND_NLCD2011, 1) == NULL);
    int64_t nlcd[] = {11, 42, 52, 95}, clc[] = {1, 12, 23, 44};
    CHECK(landcover_legend_fits(LEGEND_NLCD2011, nlcd, 4) && !landcover_legend_fits(LEGEND_CORINE, nlcd, 4));
    CHECK(landcover_legend_fits(LEGEND_CORINE, clc, 4) && !landcover_legend_fits(LEGEND_NLCD2011, clc, 4));
    int nd = 0;
    CHECK(landcover_kind_of_name("Forest", &nd) == LAND_FOREST && !nd);
    CHECK(landcover_kind_of_name("Shrubland", &nd) == LAND_SHRUB);
    CHECK(landcover_kind_of_name("Herbaceous", &nd) == LAND_GRASS);
    CHECK(landcover_kind_of_name("Emergent Herbaceous Wetlands", &nd) == LAND_WETLAND_HERBACEOUS);
    CHECK(landcover_kind_of_name("Woody Wetlands", &nd) == LAND_WETLAND_WOODY);
    CHECK(landcover_kind_of_name("Transitional woodland-shrub", &nd) == LAND_SHRUB);
    CHECK(landcover_kind_of_name("Rice fields", &nd) == LAND_CULTIVATED); /* not ice */
    CHECK(landcover_kind_of_name("Perennial Ice/Snow", &nd) == LAND_SNOW_ICE);
    CHECK(landcover_kind_of_name("Mixed Forest", &nd) == LAND_FOREST_MIXED);
    CHECK(landcover_kind_of_name("Wetlands", &nd) == LAND_WETLAND);
    CHECK(landcover_kind_of_name("NA", &nd) == LAND_UNKNOWN && nd);
    CHECK(landcover_kind_of_name("Quarry", &nd) == LAND_UNKNOWN && !nd);
    CHECK(land_kind_broad(LAND_FOREST_MIXED) == LAND_FOREST && land_kind_broad(LAND_SHRUB) == LAND_SHRUB);
}

/* The codes GDAL's warper gives the nodes of lc (nearest neighbour, exact transformation) from
 * the raster at path, row j = 0 south, in a malloc'ed array (255 where it has none); NULL on
 * failure. */
static uint8_t *warped_codes(const char *path, const land_cover *lc, const double origin[2], const char *wkt)
{
    GDALAllRegister();
    GDALDatasetH src = GDALOpen(path, GA_ReadOnly);
    GDALDatasetH dst = GDALCreate(GDALGetDriverByName("MEM"), "", (int)lc->nx, (int)lc->ny, 1, GDT_Byte, NULL);
    double gt[6] = {origin[0] + lc->x0 - 0.5 * lc->dx, lc->dx, 0, origin[1] + lc->y0 + (lc->ny - 0.5) * lc->dy, 0,
                    -lc->dy};
    GDALSetGeoTransform(dst, gt);
    GDALSetProjection(dst, wkt);
    GDALFillRaster(GDALGetRasterBand(dst, 1), 255, 0);
    char *args[] = {"-r", "near", "-et", "0", NULL};
    GDALWarpAppOptions *o = GDALWarpAppOptionsNew(args, NULL);
    int usage = 0;
    GDALDatasetH done = src && dst && o ? GDALWarp(NULL, dst, 1, &src, o, &usage) : NULL;
    uint8_t *codes = done ? malloc((size_t)lc->nx * lc->ny) : NULL;
    for (uint32_t j = 0; codes && j < lc->ny; j++)
        if (GDALRasterIO(GDALGetRasterBand(dst, 1), GF_Read, 0, (int)(lc->ny - 1 - j), (int)lc->nx, 1,
                         codes + (size_t)j * lc->nx, (int)lc->nx, 1, GDT_Byte, 0, 0) != CE_None)
            free(codes), codes = NULL;
    GDALWarpAppOptionsFree(o);
    if (dst) GDALClose(dst);
    if (src) GDALClose(src);
    return codes;
}

static const char zion_scene[] = "site: {}\nterrain: {plugin: terrain_ifs, dtm: " ZION "/srtm.tif}\n"
                                 "landcover: {raster: " ZION "/%s}\n";

static scene *zion(const char *map, err_buf *err)
{
    char text[1024];
    snprintf(text, sizeof text, zion_scene, map);
    scene *s = scene_text_build_analysis("zion.yaml", text, 0, err);
    if (!s) fprintf(stderr, "%s\n", err->msg);
    return s;
}

/* Share of the nodes with a class in both whose classes' codes agree with GDAL's warp. */
static double agreement_with_warp(const scene *s, const char *path)
{
    const land_cover *lc = s->land_cover;
    uint8_t *w = warped_codes(path, lc, s->site.origin, s->site.crs_wkt);
    CHECK(w != NULL);
    if (!w) return 0;
    uint64_t both = 0, same = 0;
    for (size_t k = 0; k < (size_t)lc->nx * lc->ny; k++) {
        if (lc->node_class[k] == LAND_COVER_NONE || w[k] == 255) continue;
        both++;
        same += lc->classes[lc->node_class[k]].code == w[k];
    }
    free(w);
    return both ? (double)same / (double)both : 0;
}

/* The broad kinds of two land covers on the same grid: the share of nodes with a class in both
 * that agree. */
static double kind_agreement(const land_cover *a, const land_cover *b)
{
    uint64_t both = 0, same = 0;
    for (size_t k = 0; k < (size_t)a->nx * a->ny; k++) {
        uint16_t ca = a->node_class[k], cb = b->node_class[k];
        if (ca == LAND_COVER_NONE || cb == LAND_COVER_NONE) continue;
        both++;
        same += land_kind_broad(a->classes[ca].kind) == land_kind_broad(b->classes[cb].kind);
    }
    return both ? (double)same / (double)both : 0;
}

/* The class a probe of s finds at map point (e, n). */
static const land_class *probed(const scene *s, double e, double n)
{
    probe_result r;
    err_buf err = {{0}};
    int rc = scene_probe(s, e - s->site.origin[0], n - s->site.origin[1], 1, &r, &err);
    const land_class *c = !rc && r.land_class >= 0 ? &s->land_cover->classes[r.land_class] : NULL;
    probe_result_free(&r);
    return c;
}

TEST(zion_nlcd_and_names)
{
    if (!scene_text_file_exists(ZION "/nlcd.tif.aux.xml")) SKIP("no shared data at %s", ZION);
    err_buf err = {{0}};
    scene *a = zion("nlcd2011.tif", &err), *b = a ? zion("nlcd.tif", &err) : NULL;
    CHECK(a && b && a->land_cover && b->land_cover);
    if (a && b && a->land_cover && b->land_cover) {
        CHECK(!strcmp(a->land_cover->legend, "nlcd2011") && !strcmp(b->land_cover->legend, "names"));
        CHECK_INT(b->land_cover->n_classes, 8);
        double kinds = kind_agreement(a->land_cover, b->land_cover);
        double warp = agreement_with_warp(a, ZION "/nlcd2011.tif");
        fprintf(stderr, "zion: broad kinds of nlcd2011.tif and nlcd.tif agree on %.4f %% of nodes; nlcd2011.tif's "
                "codes agree with GDAL's nearest-neighbour warp on %.4f %%\n", 100 * kinds, 100 * warp);
        CHECK(kinds >= 0.999);
        CHECK(warp >= 0.999);
        /* 318000 E 4135000 N (UTM 12N): every NLCD cell within 90 m is 42 (gdallocationinfo) */
        const land_class *ca = probed(a, 318000, 4135000), *cb = probed(b, 318000, 4135000);
        CHECK(ca && ca->code == 42 && ca->kind == LAND_FOREST_EVERGREEN && !strcmp(ca->name, "Evergreen Forest"));
        CHECK(cb && cb->code == 4 && cb->kind == LAND_FOREST && !strcmp(cb->name, "Forest"));
    }
    scene_free(a);
    scene_free(b);
}

/* A GeoTIFF of w x h cells from (x0, y0) (the north-west corner) in EPSG:epsg, every cell
 * `value` (Float32 for a DTM, Byte for a map), in the work folder; its path or NULL. */
static const char *write_tif(const char *name, int epsg, double x0, double y0, double cell, int w, int h, double value,
                             GDALDataType type)
{
    static char copies[4][1200];
    static int next;
    char *path = strcpy(copies[next++ % 4], work_path(name));
    GDALDatasetH ds = geotiff_create(path, epsg, x0, y0, cell, w, h, type);
    if (!ds) return NULL;
    int ok = GDALFillRaster(GDALGetRasterBand(ds, 1), value, 0) == CE_None;
    GDALClose(ds);
    return ok ? path : NULL;
}

/* Each broad kind's share of the classed nodes of lc (shares[kind], summing to 1). */
static void node_shares(const land_cover *lc, double shares[LAND_KIND_COUNT])
{
    double total = 0;
    for (int k = 0; k < LAND_KIND_COUNT; k++) shares[k] = 0;
    for (uint32_t c = 0; c < lc->n_classes; c++) {
        shares[land_kind_broad(lc->classes[c].kind)] += (double)lc->classes[c].nodes;
        total += (double)lc->classes[c].nodes;
    }
    for (int k = 0; total > 0 && k < LAND_KIND_COUNT; k++) shares[k] /= total;
}

/* The same shares from the raster's own histogram of codes (gdalinfo -hist's counts), through
 * the CORINE legend; no-data codes left out. */
static int histogram_shares(const char *path, double shares[LAND_KIND_COUNT])
{
    GDALDatasetH ds = GDALOpen(path, GA_ReadOnly);
    if (!ds) return -1;
    GUIntBig counts[256] = {0};
    int rc = GDALGetRasterHistogramEx(GDALGetRasterBand(ds, 1), -0.5, 255.5, 256, counts, 0, 0, NULL, NULL) == CE_None
                 ? 0 : -1;
    GDALClose(ds);
    double total = 0;
    for (int k = 0; k < LAND_KIND_COUNT; k++) shares[k] = 0;
    for (int v = 0; v < 256; v++) {
        const legend_class *c = landcover_legend_class(LEGEND_CORINE, v);
        if (!counts[v] || !c || c->no_data) continue;
        shares[land_kind_broad(c->kind)] += (double)counts[v];
        total += (double)counts[v];
    }
    for (int k = 0; total > 0 && k < LAND_KIND_COUNT; k++) shares[k] /= total;
    return rc;
}

/* CORINE around Lausanne (472 x 325 cells of 99.992 m, EPSG:2056) on a flat site whose DTM has a
 * node at every cell's centre: the kinds' shares of the nodes are the raster's own, within 0.1
 * percentage point. */
TEST(corine_vaud)
{
    const char *map = SHARED "/landcover/corine-vaud/ls100_12.tif";
    if (!scene_text_file_exists(map)) SKIP("no shared data at %s", map);
    GDALAllRegister();
    GDALDatasetH ds = GDALOpen(map, GA_ReadOnly);
    double t[6] = {0};
    if (ds) GDALGetGeoTransform(ds, t), GDALClose(ds);
    const char *dtm = write_tif("vaud_flat.tif", 2056, t[0], t[3], t[1], 472, 325, 400.0, GDT_Float32);
    CHECK(dtm != NULL);
    char text[2048];
    snprintf(text, sizeof text, "site: {}\nterrain: {plugin: terrain_ifs, dtm: %s}\nlandcover: {raster: %s}\n", dtm,
             map);
    err_buf err = {{0}};
    scene *s = scene_text_build_analysis("vaud.yaml", text, 0, &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s && s->land_cover);
    if (!s || !s->land_cover) return scene_free(s);
    CHECK(!strcmp(s->land_cover->legend, "corine"));
    double got[LAND_KIND_COUNT], want[LAND_KIND_COUNT], worst = 0;
    node_shares(s->land_cover, got);
    CHECK_INT(histogram_shares(map, want), 0);
    for (int k = 0; k < LAND_KIND_COUNT; k++) {
        if (got[k] > 0 || want[k] > 0)
            fprintf(stderr, "corine vaud: %-12s nodes %6.2f %%, raster histogram %6.2f %%\n", land_kind_names[k],
                    100 * got[k], 100 * want[k]);
        worst = fmax(worst, fabs(got[k] - want[k]));
    }
    fprintf(stderr, "corine vaud: largest difference %.3f percentage points (tolerance 0.1)\n", 100 * worst);
    CHECK(worst <= 0.001);
    scene_free(s);
}

/* The BlockID of the block holding map point (x, y) (same CRS as the layer), or -1: OGR's own
 * point-in-polygon test. */
static int block_at(OGRLayerH layer, double x, double y)
{
    OGRGeometryH pt = OGR_G_CreateGeometry(wkbPoint);
    OGR_G_SetPoint_2D(pt, 0, x, y);
    int id = -1;
    OGR_L_ResetReading(layer);
    for (OGRFeatureH f; (f = OGR_L_GetNextFeature(layer)); OGR_F_Destroy(f))
        if (OGR_G_Contains(OGR_F_GetGeometryRef(f), pt)) id = OGR_F_GetFieldAsInteger(f, 0);
    OGR_G_DestroyGeometry(pt);
    return id;
}

/* Three harvest blocks (kootenayBlocks.shp, EPSG:32611, BlockID 101, 113 and 3308) over a flat site of 1 m
 * nodes: a node inside a block has that block's class, one outside none, as OGR's
 * point-in-polygon test says, on at least 99.5 % of the nodes (the rest on a block's edge). */
TEST(kootenay_blocks)
{
    const char *shp = SHARED "/canopy/foresttools/kootenayBlocks.shp";
    if (!scene_text_file_exists(shp)) SKIP("no shared data at %s", shp);
    const char *dtm = write_tif("kootenay_flat.tif", 32611, 439670, 5526580, 2.0, 90, 75, 900.0, GDT_Float32);
    char text[2048];
    snprintf(text, sizeof text, "site: {}\nterrain: {plugin: terrain_ifs, dtm: %s}\n"
             "landcover:\n  polygons: %s\n  class_field: BlockID\n  classes:\n"
             "    - {code: 101, name: block 101, kind: forest_evergreen}\n"
             "    - {code: 113, name: block 113, kind: shrub}\n"
             "    - {code: 3308, name: block 3308, kind: grass}\n", dtm, shp);
    err_buf err = {{0}};
    scene *s = dtm ? scene_text_build_analysis("kootenay.yaml", text, 0, &err) : NULL;
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s && s->land_cover && s->land_cover->n_classes == 3);
    if (!s || !s->land_cover || s->land_cover->n_classes != 3) return scene_free(s);
    const land_cover *lc = s->land_cover;
    GDALDatasetH ds = GDALOpenEx(shp, GDAL_OF_VECTOR, NULL, NULL, NULL);
    OGRLayerH layer = ds ? GDALDatasetGetLayer(ds, 0) : NULL;
    uint64_t same = 0, inside = 0, n = (uint64_t)lc->nx * lc->ny;
    for (uint32_t j = 0; layer && j < lc->ny; j++)
        for (uint32_t i = 0; i < lc->nx; i++) {
            double x = s->site.origin[0] + lc->x0 + i * lc->dx, y = s->site.origin[1] + lc->y0 + j * lc->dy;
            int want = block_at(layer, x, y);
            uint16_t c = lc->node_class[(size_t)j * lc->nx + i];
            int got = c == LAND_COVER_NONE ? -1 : (int)lc->classes[c].code;
            same += got == want;
            inside += want >= 0;
        }
    if (ds) GDALClose(ds);
    fprintf(stderr, "kootenay: %llu of %llu nodes inside a block; the classes agree with OGR's point-in-polygon "
            "test on %.3f %% of the nodes\n", (unsigned long long)inside, (unsigned long long)n, 100.0 * same / n);
    CHECK(inside > 1000 && (double)same / n >= 0.995);
    for (uint32_t c = 0; c < 3; c++) CHECK(lc->classes[c].nodes > 100);
    CHECK(lc->classes[0].kind == LAND_FOREST_EVERGREEN && !strcmp(lc->classes[1].name, "block 113"));
    scene_free(s);
}

/* The share of the nodes of lc (every `step`-th) whose class (any, or none) is what OGR's
 * point-in-polygon test says of the first polygon of the layer at path: inside, a class; outside,
 * none. The nodes go into the layer's CRS through their own transformation. */
static double park_agreement(const scene *s, const char *path, uint32_t step, uint64_t *inside)
{
    const land_cover *lc = s->land_cover;
    GDALDatasetH ds = GDALOpenEx(path, GDAL_OF_VECTOR, NULL, NULL, NULL);
    OGRLayerH layer = ds ? GDALDatasetGetLayer(ds, 0) : NULL;
    OGRFeatureH f = layer ? OGR_L_GetNextFeature(layer) : NULL;
    OGRSpatialReferenceH site = OSRNewSpatialReference(s->site.crs_wkt);
    OGRSpatialReferenceH map = layer ? OGR_L_GetSpatialRef(layer) : NULL;
    OGRSpatialReferenceH gis = map ? OSRClone(map) : NULL;
    if (gis) OSRSetAxisMappingStrategy(gis, OAMS_TRADITIONAL_GIS_ORDER);
    OSRSetAxisMappingStrategy(site, OAMS_TRADITIONAL_GIS_ORDER);
    OGRCoordinateTransformationH ct = gis ? OCTNewCoordinateTransformation(site, gis) : NULL;
    OGRPreparedGeometryH park = f ? OGRCreatePreparedGeometry(OGR_F_GetGeometryRef(f)) : NULL;
    uint64_t same = 0, tried = 0;
    *inside = 0;
    for (size_t k = 0; park && ct && k < (size_t)lc->nx * lc->ny; k += step) {
        double x = s->site.origin[0] + lc->x0 + (double)(k % lc->nx) * lc->dx;
        double y = s->site.origin[1] + lc->y0 + (double)(k / lc->nx) * lc->dy;
        OCTTransform(ct, 1, &x, &y, NULL);
        OGRGeometryH pt = OGR_G_CreateGeometry(wkbPoint);
        OGR_G_SetPoint_2D(pt, 0, x, y);
        int in = OGRPreparedGeometryContains(park, pt);
        OGR_G_DestroyGeometry(pt);
        same += in == (lc->node_class[k] != LAND_COVER_NONE);
        *inside += in;
        tried++;
    }
    if (park) OGRDestroyPreparedGeometry(park);
    if (ct) OCTDestroyCoordinateTransformation(ct);
    if (gis) OSRRelease(gis);
    OSRRelease(site);
    if (f) OGR_F_Destroy(f);
    if (ds) GDALClose(ds);
    return tried ? (double)same / (double)tried : 0;
}

/* The park boundary of zion.gpkg (one polygon, UTM 12N on GRS80 as a custom CRS) classed by its
 * text attribute UNIT_NAME: the names legend, one class named by the attribute, on the nodes
 * inside the boundary and no others (OGR's test, on every 7th node, 99.9 %). */
TEST(zion_park_boundary)
{
    if (!scene_text_file_exists(ZION "/zion.gpkg")) SKIP("no shared data at %s", ZION);
    err_buf err = {{0}};
    scene *s = scene_text_build_analysis("park.yaml", "site: {}\nterrain: {plugin: terrain_ifs, dtm: " ZION "/srtm.tif}\n"
                          "landcover: {polygons: " ZION "/zion.gpkg, class_field: UNIT_NAME}\n", 0, &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s && s->land_cover && s->land_cover->n_classes == 1);
    if (!s || !s->land_cover || s->land_cover->n_classes != 1) return scene_free(s);
    const land_class *c = &s->land_cover->classes[0];
    CHECK(!strcmp(s->land_cover->legend, "names") && c->code == 1 && !strcmp(c->name, "Zion National Park"));
    uint64_t inside;
    double agree = park_agreement(s, ZION "/zion.gpkg", 7, &inside);
    fprintf(stderr, "zion park: %llu of the sampled nodes inside the boundary; the classes agree with OGR's "
            "point-in-polygon test on %.4f %% of them\n", (unsigned long long)inside, 100 * agree);
    CHECK(inside > 1000 && agree >= 0.999);
    scene_free(s);
}

/* A 2 x 2 grid site at 440000 E 3760000 N (UTM 11N) with a map of 10 x 10 cells of 30 m, every
 * cell `code`, from (x0, y0); the scene (written as NAME) built, or NULL with err set. Its
 * landcover: raster: key stands at 4:11. */
static scene *grid_site(const char *name, double x0, double y0, int code, err_buf *err)
{
    const char *map = write_tif("map.tif", 32611, x0, y0, 30, 10, 10, code, GDT_Byte);
    char text[1024];
    snprintf(text, sizeof text, "site: {crs: EPSG:32611, origin: [440000, 3760000]}\n"
             "terrain: {grid: [[0, 0], [0, 0]], origin: [-50, -50], spacing: [100, 100]}\n"
             "landcover:\n  raster: %s\n", map);
    return map ? scene_text_build_analysis(name, text, 0, err) : NULL;
}

/* A map that lies off the site is refused at its key, with what to check. */
TEST(map_off_the_site)
{
    err_buf err = {{0}};
    scene *s = grid_site("off_site.yaml", 200000, 4000000, 42, &err);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(err.msg, "off_site.yaml:4:11: the land-cover map");
    CHECK_STR_CONTAINS(err.msg, "covers none of the site's 2 x 2 nodes");
    CHECK_INT(err.status, ERR_INPUT);
    scene_free(s);
}

/* Codes no legend names are kept as kind unknown and listed in a warning, not dropped. */
TEST(unknown_codes_kept)
{
    err_buf err = {{0}};
    scene *s = grid_site("odd.yaml", 439900, 3760100, 200, &err);
    if (!s) fprintf(stderr, "%s\n", err.msg);
    CHECK(s && s->land_cover && s->land_cover->n_classes == 1);
    if (s && s->land_cover && s->land_cover->n_classes == 1) {
        CHECK(s->land_cover->classes[0].code == 200 && s->land_cover->classes[0].kind == LAND_UNKNOWN);
        CHECK(!strcmp(s->land_cover->legend, "none") && s->land_cover->classes[0].nodes == 4);
    }
    scene_free(s);
}

TEST_LIST(TEST_CASE(legends), TEST_CASE(zion_nlcd_and_names), TEST_CASE(corine_vaud), TEST_CASE(kootenay_blocks),
          TEST_CASE(zion_park_boundary), TEST_CASE(map_off_the_site), TEST_CASE(unknown_codes_kept))
