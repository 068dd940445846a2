/* ztv_layers.c — the GeoPackage of ztv_layers.h through OGR: built under /vsimem/, each layer's
 * features in the map's CRS (local + the site's origin), the rings buffered from the targets by
 * GEOS, the styles put in `layer_styles`, then the whole file copied to the caller's stream. */
#include "ztv/ztv_layers.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include "ztv/ztv_qml.h"

unsigned ztv_ring_distances(double radius, const ztv_grid *g, double out[5])
{
    static const double usual[4] = {1000, 2000, 5000, 10000};
    double reach = isfinite(radius) ? radius : hypot(g->nx * g->cell, g->ny * g->cell);
    unsigned n = 0;
    for (int k = 0; k < 4; k++)
        if (usual[k] < reach - 1e-9) out[n++] = usual[k];
    if (isfinite(radius)) out[n++] = radius;
    return n;
}

static const char *ogr_why(void)
{
    const char *why = CPLGetLastErrorMsg();
    return why && *why ? why : "GDAL gave no reason";
}

typedef struct gpkg {
    const ztv_info *info;
    GDALDatasetH ds;
    OGRSpatialReferenceH srs; /* NULL: local metres */
    err_buf *err;
} gpkg;

typedef struct field_def {
    const char *name;
    OGRFieldType type;
    int width;          /* 0: none */
    int boolean;        /* 1: an integer read as true or false */
} field_def;

static OGRLayerH make_layer(gpkg *g, const char *name, OGRwkbGeometryType type, const field_def *fields,
                           unsigned n)
{
    char *opts[] = {type == wkbNone ? "FID=id" : "FID=fid", NULL};
    OGRLayerH l = GDALDatasetCreateLayer(g->ds, name, type == wkbNone ? NULL : g->srs, type, opts);
    if (!l) {
        err_fail(g->err, ERR_OUTPUT, "GDAL cannot create the layer %s: %s", name, ogr_why());
        return NULL;
    }
    for (unsigned k = 0; k < n; k++) {
        OGRFieldDefnH fd = OGR_Fld_Create(fields[k].name, fields[k].type);
        if (fields[k].width) OGR_Fld_SetWidth(fd, fields[k].width);
        if (fields[k].boolean) OGR_Fld_SetSubType(fd, OFSTBoolean);
        OGRErr e = OGR_L_CreateField(l, fd, TRUE);
        OGR_Fld_Destroy(fd);
        if (e != OGRERR_NONE) {
            err_fail(g->err, ERR_OUTPUT, "GDAL cannot add the field %s to %s: %s", fields[k].name, name, ogr_why());
            return NULL;
        }
    }
    return l;
}

/* Adds feature f (its geometry taken over) to l and destroys it. */
static int add_feature(gpkg *g, OGRLayerH l, OGRFeatureH f, OGRGeometryH geom)
{
    if (geom) OGR_F_SetGeometryDirectly(f, geom);
    OGRErr e = OGR_L_CreateFeature(l, f);
    OGR_F_Destroy(f);
    return e == OGRERR_NONE ? 0 : err_fail(g->err, ERR_OUTPUT, "GDAL cannot add a feature to %s: %s",
                                           OGR_L_GetName(l), ogr_why());
}

static void set_real(OGRFeatureH f, const char *field, double v)
{
    if (isfinite(v)) OGR_F_SetFieldDouble(f, OGR_F_GetFieldIndex(f, field), v);
}

static OGRGeometryH map_point(const ztv_info *info, const double xy[2])
{
    OGRGeometryH p = OGR_G_CreateGeometry(wkbPoint);
    OGR_G_SetPoint_2D(p, 0, info->origin[0] + xy[0], info->origin[1] + xy[1]);
    return p;
}

static int write_viewpoints(gpkg *g)
{
    static const field_def fields[] = {{"number", OFTInteger}, {"name", OFTString}, {"eye_height", OFTReal},
                                       {"heading", OFTReal}, {"ground_level", OFTReal}};
    OGRLayerH l = make_layer(g, "viewpoints", wkbPoint, fields, 5);
    if (!l) return -1;
    const ztv_info *info = g->info;
    for (uint32_t k = 0; k < info->n_study_views; k++) {
        const ztv_viewpoint *v = &info->study_views[k];
        OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(l));
        OGR_F_SetFieldInteger(f, 0, (int)v->number);
        OGR_F_SetFieldString(f, 1, v->name ? v->name : "");
        set_real(f, "eye_height", v->eye_height);
        set_real(f, "heading", v->heading);
        set_real(f, "ground_level", v->ground + info->origin[2]);
        if (add_feature(g, l, f, map_point(info, v->xy))) return -1;
    }
    return 0;
}

/* The points within d of the nearest target: the targets buffered by d, a (multi)polygon. */
static OGRGeometryH ring_around_targets(const ztv_info *info, double d)
{
    OGRGeometryH targets = OGR_G_CreateGeometry(wkbMultiPoint);
    for (uint32_t k = 0; k < info->n_targets; k++)
        OGR_G_AddGeometryDirectly(targets, map_point(info, info->target_xy[k]));
    OGRGeometryH ring = OGR_G_Buffer(targets, d, ZTV_RING_SEGMENTS);
    OGR_G_DestroyGeometry(targets);
    return ring ? OGR_G_ForceToMultiPolygon(ring) : NULL;
}

static int write_rings(gpkg *g)
{
    static const field_def fields[] = {{"distance", OFTReal}, {"label", OFTString}};
    OGRLayerH l = make_layer(g, "distance_rings", wkbMultiPolygon, fields, 2);
    if (!l) return -1;
    const ztv_info *info = g->info;
    double d[5];
    unsigned n = ztv_ring_distances(info->radius, &info->grid, d);
    for (unsigned k = 0; k < n; k++) {
        OGRGeometryH ring = ring_around_targets(info, d[k]);
        if (!ring)
            return err_fail(g->err, ERR_INTERNAL, "GDAL cannot buffer the targets by %g m (it needs GEOS): %s", d[k],
                            ogr_why());
        char label[64];
        int radius = k + 1 == n && isfinite(info->radius);
        snprintf(label, sizeof label, "%s%g km", radius ? "radius " : "", d[k] / 1000);
        OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(l));
        OGR_F_SetFieldDouble(f, 0, d[k]);
        OGR_F_SetFieldString(f, 1, label);
        if (add_feature(g, l, f, ring)) return -1;
    }
    return 0;
}

static int write_structures(gpkg *g)
{
    static const field_def fields[] = {{"name", OFTString}, {"development", OFTString}, {"base_level", OFTReal},
                                       {"top_level", OFTReal}, {"height", OFTReal}};
    OGRLayerH l = make_layer(g, "developments", wkbPoint, fields, 5);
    if (!l) return -1;
    const ztv_info *info = g->info;
    for (uint32_t k = 0; k < info->n_structures; k++) {
        const ztv_structure *s = &info->structures[k];
        OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(l));
        OGR_F_SetFieldString(f, 0, s->name ? s->name : "");
        if (s->development) OGR_F_SetFieldString(f, 1, s->development);
        set_real(f, "base_level", s->base + info->origin[2]);
        set_real(f, "top_level", s->top + info->origin[2]);
        set_real(f, "height", s->top - s->base);
        if (add_feature(g, l, f, map_point(info, s->xy))) return -1;
    }
    return 0;
}

/* QGIS's table of styles (the schema QGIS creates), one default style per layer. */
static int write_styles(gpkg *g)
{
    static const field_def fields[] = {
        {"f_table_catalog", OFTString, 256}, {"f_table_schema", OFTString, 256}, {"f_table_name", OFTString, 256},
        {"f_geometry_column", OFTString, 256}, {"styleName", OFTString, 30}, {"styleQML", OFTString},
        {"styleSLD", OFTString}, {"useAsDefault", OFTInteger, 0, 1}, {"description", OFTString},
        {"owner", OFTString, 30}, {"ui", OFTString, 30}, {"update_time", OFTDateTime}};
    static const char *const tables[3] = {"viewpoints", "distance_rings", "developments"};
    OGRLayerH l = make_layer(g, "layer_styles", wkbNone, fields, sizeof fields / sizeof *fields);
    if (!l) return -1;
    for (int k = 0; k < 3; k++) {
        OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(l));
        OGR_F_SetFieldString(f, 0, "");
        OGR_F_SetFieldString(f, 1, "");
        OGR_F_SetFieldString(f, 2, tables[k]);
        OGR_F_SetFieldString(f, 3, "geom");
        OGR_F_SetFieldString(f, 4, tables[k]);
        OGR_F_SetFieldString(f, 5, ztv_qml_text((ztv_qml_style)k));
        OGR_F_SetFieldString(f, 6, "");
        OGR_F_SetFieldInteger(f, 7, 1);
        OGR_F_SetFieldString(f, 8, ztv_qml_name((ztv_qml_style)k));
        OGR_F_SetFieldString(f, 9, "");
        OGR_F_SetFieldDateTimeEx(f, 11, 2000, 1, 1, 0, 0, 0.0f, 100);
        if (add_feature(g, l, f, NULL)) return -1;
    }
    return 0;
}

/* Copies the finished memory file to f. */
static int copy_out(const char *mem, FILE *f, err_buf *err)
{
    vsi_l_offset len = 0;
    GByte *bytes = VSIGetMemFileBuffer(mem, &len, TRUE); /* owned now: CPLFree */
    if (!bytes) return err_fail(err, ERR_OUTPUT, "GDAL left no GeoPackage in memory (%s)", mem);
    int rc = fwrite(bytes, 1, (size_t)len, f) == (size_t)len ? 0 : err_fail(err, ERR_OUTPUT, "cannot write the GeoPackage");
    CPLFree(bytes);
    return rc;
}

int ztv_layers_write(const ztv_info *info, FILE *f, err_buf *err)
{
    GDALAllRegister();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    CPLSetThreadLocalConfigOption("OGR_CURRENT_DATE", SYLVA_GPKG_DATE);
    char mem[64];
    snprintf(mem, sizeof mem, "/vsimem/sylva_ztv_layers_%p.gpkg", (const void *)info);
    gpkg g = {.info = info, .err = err};
    int rc = 0;
    GDALDriverH drv = GDALGetDriverByName("GPKG");
    if (!drv) rc = err_fail(err, ERR_INTERNAL, "GDAL has no GeoPackage driver");
    if (!rc && info->crs_wkt) {
        g.srs = OSRNewSpatialReference(info->crs_wkt);
        if (!g.srs) rc = err_fail(err, ERR_INPUT, "GDAL does not accept the site's CRS: %s", ogr_why());
        else OSRSetAxisMappingStrategy(g.srs, OAMS_TRADITIONAL_GIS_ORDER);
    } else if (!rc) { /* a scene in local metres: an engineering CRS, not GDAL's undefined geographic one */
        g.srs = OSRNewSpatialReference(NULL);
        if (!g.srs || OSRSetLocalCS(g.srs, "sylva local metres") != OGRERR_NONE ||
            OSRSetLinearUnits(g.srs, SRS_UL_METER, 1.0) != OGRERR_NONE)
            rc = err_fail(err, ERR_INTERNAL, "GDAL cannot describe local metres: %s", ogr_why());
    }
    if (!rc && !(g.ds = GDALCreate(drv, mem, 0, 0, 0, GDT_Unknown, NULL)))
        rc = err_fail(err, ERR_OUTPUT, "GDAL cannot create a GeoPackage: %s", ogr_why());
    if (!rc) rc = write_viewpoints(&g) || write_rings(&g) || write_structures(&g) || write_styles(&g) ? -1 : 0;
    if (g.ds) GDALClose(g.ds);
    if (!rc && CPLGetLastErrorType() >= CE_Failure)
        rc = err_fail(err, ERR_OUTPUT, "GDAL cannot finish the GeoPackage: %s", ogr_why());
    if (!rc) rc = copy_out(mem, f, err);
    VSIUnlink(mem);
    if (g.srs) OSRDestroySpatialReference(g.srs);
    CPLSetThreadLocalConfigOption("OGR_CURRENT_DATE", NULL);
    CPLPopErrorHandler();
    return rc;
}
