/* planting_ogr.c — a planting plan's features through OGR, quietly and offline (planting_ogr.h).
 * The vertices are converted into the site CRS as a survey's points are (tree_survey.h). */
#include "site/planting_ogr.h"

#include <stdio.h>
#include <string.h>

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include "site/gdal_offline.h"
#include "site/tree_survey.h"
#include "util/file_check.h"

#define PLAN_MAX_VERTICES 10000000u

const char *const plan_field_names[PLAN_N_FIELDS] = {"name", "kind", "species", "shares", "spacing", "density",
                                                     "rows", "row_spacing", "stock", "stock_height"};

/* The feature's geometry into s (vertices in the file's CRS). */
static int read_geometry(arena *a, OGRGeometryH g, const char *shown, plan_shape *s, err_buf *err)
{
    OGRwkbGeometryType t = g ? wkbFlatten(OGR_G_GetGeometryType(g)) : wkbNone;
    if (!g || OGR_G_IsEmpty(g)) return err_set(err, "'%s' %s has no geometry", shown, s->feature);
    if ((t == wkbMultiPolygon || t == wkbMultiLineString || t == wkbMultiPoint) && OGR_G_GetGeometryCount(g) == 1)
        g = OGR_G_GetGeometryRef(g, 0), t = wkbFlatten(OGR_G_GetGeometryType(g));
    if (t == wkbPolygon && OGR_G_GetGeometryCount(g) != 1)
        return err_set(err, "'%s' %s is a polygon with %d holes; a plan's polygon is one outline (draw the holes "
                       "as polygons of their own)", shown, s->feature, OGR_G_GetGeometryCount(g) - 1);
    OGRGeometryH line = t == wkbPolygon ? OGR_G_GetGeometryRef(g, 0) : g;
    if (t != wkbPolygon && t != wkbLineString && t != wkbPoint)
        return err_set(err, "'%s' %s is a %s; a plan's feature is a polygon (a block or a felling), a line (a "
                       "belt) or a point (a tree), one part each", shown, s->feature, OGRGeometryTypeToName(t));
    s->geometry = t == wkbPolygon ? PLAN_POLYGON : t == wkbLineString ? PLAN_LINE : PLAN_POINT;
    int n = OGR_G_GetPointCount(line);
    if (s->geometry == PLAN_POLYGON && n > 1 && OGR_G_GetX(line, 0) == OGR_G_GetX(line, n - 1) &&
        OGR_G_GetY(line, 0) == OGR_G_GetY(line, n - 1))
        n--; /* the closing vertex */
    if (n < 1 || (uint32_t)n > PLAN_MAX_VERTICES) return err_set(err, "'%s' %s has %d vertices", shown, s->feature, n);
    if (!(s->xy = arena_alloc(a, (size_t)n * sizeof *s->xy))) return err_nomem(err, "out of memory");
    for (int k = 0; k < n; k++) s->xy[k][0] = OGR_G_GetX(line, k), s->xy[k][1] = OGR_G_GetY(line, k);
    s->n_xy = (uint32_t)n;
    return 0;
}

static int read_feature(arena *a, OGRFeatureH f, const int index[PLAN_N_FIELDS], const char *shown, plan_shape *s,
                        err_buf *err)
{
    char fid[32];
    snprintf(fid, sizeof fid, "FID %lld", (long long)OGR_F_GetFID(f));
    if (!(s->feature = arena_strdup(a, fid))) return err_nomem(err, "out of memory");
    if (read_geometry(a, OGR_F_GetGeometryRef(f), shown, s, err)) return -1;
    for (int k = 0; k < PLAN_N_FIELDS; k++) {
        s->value[k] = NULL;
        if (index[k] < 0 || !OGR_F_IsFieldSetAndNotNull(f, index[k])) continue;
        const char *text = OGR_F_GetFieldAsString(f, index[k]);
        if (text[0] && !(s->value[k] = arena_strdup(a, text))) return err_nomem(err, "out of memory");
    }
    return 0;
}

/* Every vertex into the site CRS, through the survey's conversion. */
static int to_site(arena *a, plan_shape *shapes, uint32_t n, const char *shown, const char *crs,
                   const char *file_wkt, const char *site_wkt, err_buf *err)
{
    uint64_t total = 0;
    for (uint32_t i = 0; i < n; i++) total += shapes[i].n_xy;
    if (total > PLAN_MAX_VERTICES) return err_set(err, "'%s' holds more than %u vertices", shown, PLAN_MAX_VERTICES);
    survey_points pts = {.points = arena_alloc(a, (size_t)total * sizeof *pts.points + 1), .n = (uint32_t)total};
    if (!pts.points) return err_nomem(err, "out of memory");
    for (uint32_t i = 0, k = 0; i < n; i++)
        for (uint32_t v = 0; v < shapes[i].n_xy; v++, k++)
            pts.points[k] = (survey_point){.map = {shapes[i].xy[v][0], shapes[i].xy[v][1]}, .feature = shapes[i].feature};
    survey_key key;
    if (survey_to_site(a, &pts, shown, crs, file_wkt, site_wkt, &key, err)) return -1;
    for (uint32_t i = 0, k = 0; i < n; i++)
        for (uint32_t v = 0; v < shapes[i].n_xy; v++, k++)
            shapes[i].xy[v][0] = pts.points[k].map[0], shapes[i].xy[v][1] = pts.points[k].map[1];
    return 0;
}

static int read_layer(arena *a, OGRLayerH layer, const char *shown, plan_shape **shapes, uint32_t *n, err_buf *err)
{
    OGRFeatureDefnH defn = OGR_L_GetLayerDefn(layer);
    int index[PLAN_N_FIELDS];
    for (int k = 0; k < PLAN_N_FIELDS; k++) index[k] = OGR_FD_GetFieldIndex(defn, plan_field_names[k]);
    GIntBig count = OGR_L_GetFeatureCount(layer, 1);
    if (count <= 0 || count > 1000000) return err_set(err, "'%s' holds %lld features; a plan holds 1 to 1000000", shown,
                                                      (long long)count);
    if (!(*shapes = arena_alloc(a, (size_t)count * sizeof **shapes))) return err_nomem(err, "out of memory");
    *n = 0;
    OGR_L_ResetReading(layer);
    int rc = 0;
    for (OGRFeatureH f; !rc && (f = OGR_L_GetNextFeature(layer));) {
        if (*n == count) rc = err_set(err, "'%s' gave more features than it counted", shown);
        else rc = read_feature(a, f, index, shown, &(*shapes)[(*n)++], err);
        OGR_F_Destroy(f);
    }
    return rc;
}

int plan_read_ogr(arena *a, const char *path, const char *shown, const char *layer_name, const char *crs,
                  const char *site_wkt, plan_shape **shapes, uint32_t *n, err_buf *err)
{
    int virtual_path = file_is_gdal_virtual(path);
    if (!virtual_path && file_check_regular(path, shown, err)) return -1;
    gdal_offline off;
    if (virtual_path) GDALAllRegister();
    GDALDatasetH ds = virtual_path ? GDALOpenEx(path, GDAL_OF_VECTOR | GDAL_OF_READONLY, NULL, NULL, NULL)
                                   : gdal_offline_open(path, GDAL_OF_VECTOR, &off);
    int rc = 0;
    OGRLayerH layer = NULL;
    if (!ds) rc = err_set(err, "'%s' is not a vector file GDAL reads (GeoPackage, Shapefile, GeoJSON, ...), or it is "
                          "damaged", shown);
    else if (layer_name && !(layer = GDALDatasetGetLayerByName(ds, layer_name)))
        rc = err_set(err, "'%s' has no layer '%s'", shown, layer_name);
    else if (!layer_name && GDALDatasetGetLayerCount(ds) != 1)
        rc = err_set(err, "'%s' has %d layers; name the plan's with layer:", shown, GDALDatasetGetLayerCount(ds));
    else if (!layer_name)
        layer = GDALDatasetGetLayer(ds, 0);
    if (!rc) rc = read_layer(a, layer, shown, shapes, n, err);
    char *wkt = NULL; /* CPLFree'd here */
    OGRSpatialReferenceH srs = rc ? NULL : OGR_L_GetSpatialRef(layer);
    const char *const options[] = {"FORMAT=WKT2_2019", NULL};
    if (srs && OSRExportToWktEx(srs, &wkt, options) != OGRERR_NONE) CPLFree(wkt), wkt = NULL;
    if (!rc) rc = to_site(a, *shapes, *n, shown, crs, wkt, site_wkt, err);
    CPLFree(wkt);
    if (!virtual_path) gdal_offline_close(ds, &off);
    else if (ds) GDALClose(ds);
    return rc;
}
