/* tree_survey_ogr.c — a survey's point layer through OGR (GeoPackage, Shapefile, GeoJSON, ...),
 * read quietly and offline: every feature must be a point, every field the request names must be
 * in the layer. The points stay in the file's CRS, which is handed back as WKT. */
#include "site/tree_survey.h"

#include <stdio.h>
#include <string.h>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include "site/gdal_offline.h"
#include "util/file_check.h"

#define SURVEY_MAX_POINTS 50000000u

static const survey_key value_key[SURVEY_N_VALUES] = {SURVEY_KEY_SPECIES, SURVEY_KEY_HEIGHT, SURVEY_KEY_CROWN,
                                                      SURVEY_KEY_AGE};

/* "a, b, c" of the names count(i) gives, cut to fit. */
static void list_names(char *buf, size_t size, int n, const char *(*name)(void *, int), void *ctx)
{
    size_t used = 0;
    buf[0] = 0;
    for (int i = 0; i < n && used + 1 < size; i++)
        used += (size_t)snprintf(buf + used, size - used, "%s'%s'", i ? ", " : "", name(ctx, i));
}

static const char *layer_name(void *ds, int i) { return OGR_L_GetName(GDALDatasetGetLayer(ds, i)); }
static const char *field_name(void *defn, int i) { return OGR_Fld_GetNameRef(OGR_FD_GetFieldDefn(defn, i)); }

static const char *noun(const survey_request *rq) { return rq->noun ? rq->noun : "tree"; }

static OGRLayerH pick_layer(GDALDatasetH ds, const survey_request *rq, survey_key *bad_key, err_buf *err)
{
    int n = GDALDatasetGetLayerCount(ds);
    char names[512];
    list_names(names, sizeof names, n, layer_name, ds);
    OGRLayerH layer = rq->layer ? GDALDatasetGetLayerByName(ds, rq->layer) : n == 1 ? GDALDatasetGetLayer(ds, 0) : NULL;
    if (layer) return layer;
    *bad_key = rq->layer ? SURVEY_KEY_LAYER : SURVEY_KEY_FILE;
    if (!n) err_set(err, "'%s' has no layers", rq->shown);
    else if (rq->layer) err_set(err, "'%s' has no layer '%s'; its layers are %s", rq->shown, rq->layer, names);
    else err_set(err, "'%s' has %d layers; name the %ss' one with %s (%s)", rq->shown, n, noun(rq),
                 rq->noun ? "points_layer:" : "layer:", names);
    return NULL;
}

/* The index of each named field in `index` (-1 when not named); an absent one is an error. */
static int find_fields(OGRFeatureDefnH defn, const survey_request *rq, int index[SURVEY_N_VALUES],
                       survey_key *bad_key, err_buf *err)
{
    for (int k = 0; k < SURVEY_N_VALUES; k++) {
        index[k] = rq->field[k] ? OGR_FD_GetFieldIndex(defn, rq->field[k]) : -1;
        if (!rq->field[k] || index[k] >= 0 || (rq->optional & 1u << k)) continue;
        char names[768];
        list_names(names, sizeof names, OGR_FD_GetFieldCount(defn), field_name, defn);
        *bad_key = value_key[k];
        return err_set(err, "'%s' has no field '%s'; its fields are %s", rq->shown, rq->field[k],
                       names[0] ? names : "none");
    }
    return 0;
}

/* A copy of s in the arena without surrounding spaces; NULL for an empty one (as *out). */
static int keep_text(arena *a, const char *s, const char **out)
{
    while (*s == ' ' || *s == '\t') s++;
    size_t n = strlen(s);
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t')) n--;
    *out = n ? arena_strndup(a, s, n) : NULL;
    return n && !*out ? -1 : 0;
}

static int read_feature(arena *a, OGRFeatureH f, const int index[SURVEY_N_VALUES], const survey_request *rq,
                        survey_point *p, err_buf *err)
{
    const char *shown = rq->shown;
    long long fid = (long long)OGR_F_GetFID(f);
    if (!(p->feature = arena_alloc(a, 32))) return err_nomem(err, "out of memory");
    snprintf((char *)p->feature, 32, "FID %lld", fid);
    OGRGeometryH g = OGR_F_GetGeometryRef(f);
    OGRwkbGeometryType t = g ? wkbFlatten(OGR_G_GetGeometryType(g)) : wkbNone;
    if (!g || OGR_G_IsEmpty(g))
        return err_set(err, "'%s' %s has no geometry; every %s must be a point", shown, p->feature, noun(rq));
    if (t != wkbPoint)
        return err_set(err, "'%s' %s is a %s, not a point; %s", shown, p->feature, OGRGeometryTypeToName(t),
                       rq->noun ? "give each viewpoint as a point (the eye's place on the ground)"
                                : "a survey gives each tree as a point (its trunk)");
    p->map[0] = OGR_G_GetX(g, 0), p->map[1] = OGR_G_GetY(g, 0);
    for (int k = 0; k < SURVEY_N_VALUES; k++) {
        p->value[k] = NULL;
        if (index[k] >= 0 && OGR_F_IsFieldSetAndNotNull(f, index[k]) &&
            keep_text(a, OGR_F_GetFieldAsString(f, index[k]), &p->value[k]))
            return err_nomem(err, "out of memory");
    }
    return 0;
}

static int read_layer(arena *a, OGRLayerH layer, const survey_request *rq, survey_points *out, survey_key *bad_key,
                      err_buf *err)
{
    int index[SURVEY_N_VALUES];
    if (find_fields(OGR_L_GetLayerDefn(layer), rq, index, bad_key, err)) return -1;
    GIntBig count = OGR_L_GetFeatureCount(layer, 1);
    if (count < 0 || count > SURVEY_MAX_POINTS)
        return err_set(err, "'%s' holds %lld features; a survey may hold at most %u", rq->shown, (long long)count,
                       SURVEY_MAX_POINTS);
    if (!(out->points = arena_alloc(a, (size_t)count * sizeof *out->points + 1)))
        return err_nomem(err, "out of memory for %lld %ss", (long long)count, noun(rq));
    OGR_L_ResetReading(layer);
    int rc = 0;
    for (OGRFeatureH f; !rc && (f = OGR_L_GetNextFeature(layer));) {
        if (out->n == count) rc = err_set(err, "'%s' gave more features than it counted", rq->shown);
        else rc = read_feature(a, f, index, rq, &out->points[out->n++], err);
        OGR_F_Destroy(f);
    }
    return rc;
}

/* The layer's CRS as WKT (CPLFree'd by the caller), or NULL when it states none. */
static char *layer_wkt(OGRLayerH layer)
{
    OGRSpatialReferenceH srs = OGR_L_GetSpatialRef(layer);
    char *wkt = NULL;
    const char *const options[] = {"FORMAT=WKT2_2019", NULL};
    if (srs && OSRExportToWktEx(srs, &wkt, options) != OGRERR_NONE) {
        CPLFree(wkt);
        wkt = NULL;
    }
    return wkt;
}

static int read_dataset(arena *a, GDALDatasetH ds, const survey_request *rq, survey_points *out,
                        survey_key *bad_key, char **crs_wkt_out, err_buf *err)
{
    OGRLayerH layer = pick_layer(ds, rq, bad_key, err);
    if (!layer) return -1;
    *bad_key = SURVEY_KEY_FILE;
    if (read_layer(a, layer, rq, out, bad_key, err)) return -1;
    *crs_wkt_out = layer_wkt(layer);
    return 0;
}

int survey_read_ogr(arena *a, const survey_request *rq, survey_points *out, survey_key *bad_key,
                    char **crs_wkt_out, err_buf *err)
{
    *crs_wkt_out = NULL;
    int virtual_path = file_is_gdal_virtual(rq->path); /* only when the command line allowed it */
    if (!virtual_path && file_check_regular(rq->path, rq->shown, err)) return -1;
    gdal_offline off;
    if (virtual_path) GDALAllRegister();
    GDALDatasetH ds = virtual_path ? GDALOpenEx(rq->path, GDAL_OF_VECTOR | GDAL_OF_READONLY, NULL, NULL, NULL)
                                   : gdal_offline_open(rq->path, GDAL_OF_VECTOR, &off);
    int rc = ds ? read_dataset(a, ds, rq, out, bad_key, crs_wkt_out, err)
                : err_set(err, "'%s' is not a vector file GDAL reads (GeoPackage, Shapefile, GeoJSON, ...; a CSV "
                          "is read by its .csv name), or it is damaged", rq->shown);
    if (!virtual_path) gdal_offline_close(ds, &off);
    else if (ds) GDALClose(ds);
    return rc;
}
