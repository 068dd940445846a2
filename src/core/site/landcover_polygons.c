/* landcover_polygons.c — land-cover polygons (GeoPackage, Shapefile, GeoJSON through OGR)
 * classed by one attribute, burnt onto the site grid: each polygon, converted into the site
 * CRS, gives its class to the nodes it holds (GDAL's rasterisation on a grid whose cells are
 * centred on the nodes; where polygons overlap, the later one wins). A text attribute's names
 * are numbered 1, 2, ... in alphabetical order and come with the codes as the map's names. */
#include "site/landcover_codes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gdal_alg.h>

#include "site/gdal_offline.h"
#include "util/memory_budget.h"

/* "a, b, c": the layer's field names, cut when long. */
static void field_names(OGRFeatureDefnH defn, char *buf, size_t size)
{
    buf[0] = '\0';
    for (int i = 0, used = 0; i < OGR_FD_GetFieldCount(defn) && used < (int)size; i++)
        used += snprintf(buf + used, size - (size_t)used, "%s%s", i ? ", " : "",
                         OGR_Fld_GetNameRef(OGR_FD_GetFieldDefn(defn, i)));
}

OGRLayerH landcover_polygon_layer(GDALDatasetH ds, const landcover_source *src, int *field, landcover_fault *fault,
                                  err_buf *err)
{
    OGRLayerH layer = src->layer ? GDALDatasetGetLayerByName(ds, src->layer) : GDALDatasetGetLayer(ds, 0);
    *fault = src->layer ? LANDCOVER_FAULT_LAYER : LANDCOVER_FAULT_FILE;
    if (!layer) {
        char names[512] = "";
        for (int i = 0, used = 0; i < GDALDatasetGetLayerCount(ds) && used < (int)sizeof names; i++)
            used += snprintf(names + used, sizeof names - (size_t)used, "%s%s", i ? ", " : "",
                             OGR_L_GetName(GDALDatasetGetLayer(ds, i)));
        err_set(err, src->layer ? "it has no layer '%s'; its layers are %s" : "it has no layer%s%s",
                src->layer ? src->layer : "", names);
        return NULL;
    }
    OGRFeatureDefnH defn = OGR_L_GetLayerDefn(layer);
    *field = OGR_FD_GetFieldIndex(defn, src->class_field);
    *fault = LANDCOVER_FAULT_FIELD;
    if (*field < 0) {
        char names[512];
        field_names(defn, names, sizeof names);
        err_set(err, "its layer '%s' has no attribute '%s'; its attributes are %s", OGR_L_GetName(layer),
                src->class_field, names[0] ? names : "none");
        return NULL;
    }
    return layer;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(((const landcover_name *)a)->name, ((const landcover_name *)b)->name);
}

/* A text class field: its distinct names, numbered 1, 2, ... alphabetically, into c->names. */
static int number_names(OGRLayerH layer, int field, landcover_codes *c, err_buf *err)
{
    OGR_L_ResetReading(layer);
    for (OGRFeatureH f; (f = OGR_L_GetNextFeature(layer)); OGR_F_Destroy(f)) {
        const char *name = OGR_F_IsFieldSetAndNotNull(f, field) ? OGR_F_GetFieldAsString(f, field) : NULL;
        int known = 0;
        for (uint32_t i = 0; name && i < c->n_names && !known; i++) known = !strcmp(c->names[i].name, name);
        if (name && !known && landcover_codes_add_name(c, 0, name, err)) {
            OGR_F_Destroy(f);
            return -1;
        }
    }
    if (c->n_names) qsort(c->names, c->n_names, sizeof *c->names, by_name);
    for (uint32_t i = 0; i < c->n_names; i++) c->names[i].code = i + 1;
    return 0;
}

/* The code of feature f: its number, or the number of its name. */
static int feature_code(OGRFeatureH f, int field, int text, const landcover_codes *c, double *code)
{
    if (!OGR_F_IsFieldSetAndNotNull(f, field)) return -1;
    if (!text) {
        *code = round(OGR_F_GetFieldAsDouble(f, field));
        return fabs(*code) < 2147483647.0 ? 0 : -1;
    }
    const char *name = OGR_F_GetFieldAsString(f, field);
    for (uint32_t i = 0; i < c->n_names; i++)
        if (!strcmp(c->names[i].name, name)) return *code = (double)c->names[i].code, 0;
    return -1;
}

/* The polygons burnt into a node-centred MEM grid (row 0 north) in the site CRS. */
typedef struct burn_list {
    OGRGeometryH *geoms; double *codes; int n, cap;
} burn_list;

static void burn_list_free(burn_list *b)
{
    for (int i = 0; i < b->n; i++) OGR_G_DestroyGeometry(b->geoms[i]);
    free(b->geoms), free(b->codes);
}

static int burn_list_add(burn_list *b, OGRGeometryH g, double code, err_buf *err)
{
    if (b->n == b->cap) {
        int cap = b->cap ? 2 * b->cap : 64;
        OGRGeometryH *gs = realloc(b->geoms, (size_t)cap * sizeof *gs);
        if (gs) b->geoms = gs;
        double *cs = realloc(b->codes, (size_t)cap * sizeof *cs);
        if (cs) b->codes = cs;
        if (!gs || !cs) return OGR_G_DestroyGeometry(g), err_nomem(err, "out of memory reading the polygons");
        b->cap = cap;
    }
    b->geoms[b->n] = g, b->codes[b->n++] = code;
    return 0;
}

/* Every classed polygon of the layer, converted into the site CRS. */
static int gather(OGRLayerH layer, int field, int text, OGRCoordinateTransformationH ct, const landcover_codes *c,
                  burn_list *b, err_buf *err)
{
    OGR_L_ResetReading(layer);
    for (OGRFeatureH f; (f = OGR_L_GetNextFeature(layer)); OGR_F_Destroy(f)) {
        double code;
        OGRGeometryH g = OGR_F_GetGeometryRef(f);
        if (!g || feature_code(f, field, text, c, &code)) continue;
        OGRGeometryH mine = OGR_G_Clone(g);
        if (!mine || OGR_G_Transform(mine, ct) != OGRERR_NONE) {
            OGR_G_DestroyGeometry(mine);
            continue; /* a polygon the site's CRS cannot hold lies off the site */
        }
        if (burn_list_add(b, mine, code, err)) return OGR_F_Destroy(f), -1;
    }
    return 0;
}

static GDALDatasetH node_grid(const landcover_grid *g)
{
    GDALDriverH mem = GDALGetDriverByName("MEM");
    GDALDatasetH ds = mem ? GDALCreate(mem, "", (int)g->nx, (int)g->ny, 1, GDT_Int32, NULL) : NULL;
    if (!ds) return NULL;
    double gt[6] = {g->origin[0] + g->x0 - 0.5 * g->dx, g->dx, 0,
                    g->origin[1] + g->y0 + (g->ny - 0.5) * g->dy, 0, -g->dy};
    GDALSetGeoTransform(ds, gt);
    GDALSetProjection(ds, g->site_wkt);
    GDALFillRaster(GDALGetRasterBand(ds, 1), (double)LANDCOVER_NO_CODE, 0);
    return ds;
}

/* Burns b onto the grid and reads the codes back, row j = 0 south. */
static int burn(const landcover_grid *g, burn_list *b, landcover_codes *c, err_buf *err)
{
    size_t n = (size_t)g->nx * g->ny;
    GDALDatasetH ds = node_grid(g);
    if (!ds) return err_nomem(err, "out of memory for the site grid's polygons");
    int band = 1, rc = 0;
    if (b->n &&
        GDALRasterizeGeometries(ds, 1, &band, b->n, b->geoms, NULL, NULL, b->codes, NULL, NULL, NULL) != CE_None)
        rc = err_set(err, "GDAL cannot burn its polygons onto the site grid: %s", CPLGetLastErrorMsg());
    GDALRasterBandH rb = GDALGetRasterBand(ds, 1);
    for (uint32_t j = 0; !rc && j < g->ny; j++)
        if (GDALRasterIO(rb, GF_Read, 0, (int)(g->ny - 1 - j), (int)g->nx, 1, c->code + (size_t)j * g->nx, (int)g->nx,
                         1, GDT_Int32, 0, 0) != CE_None)
            rc = err_set(err, "GDAL cannot read the burnt polygons back");
    for (size_t k = 0; !rc && k < n; k++) c->covered += c->code[k] != LANDCOVER_NO_CODE;
    GDALClose(ds);
    return rc;
}

static int read_layer(OGRLayerH layer, int field, const landcover_grid *g, landcover_codes *c, err_buf *err)
{
    OGRSpatialReferenceH srs = OGR_L_GetSpatialRef(layer), site = NULL;
    if (!srs) return err_set(err, "its layer '%s' names no CRS", OGR_L_GetName(layer));
    OGRSpatialReferenceH map = OSRClone(srs);
    if (!map) return err_nomem(err, "out of memory for the polygons' CRS");
    OSRSetAxisMappingStrategy(map, OAMS_TRADITIONAL_GIS_ORDER);
    OGREnvelope e;
    if (OGR_L_GetExtent(layer, &e, 1) == OGRERR_NONE)
        landcover_codes_centre(c, map, 0.5 * (e.MinX + e.MaxX), 0.5 * (e.MinY + e.MaxY));
    int text = OGR_Fld_GetType(OGR_FD_GetFieldDefn(OGR_L_GetLayerDefn(layer), field)) == OFTString;
    OGRCoordinateTransformationH ct = NULL;
    burn_list b = {0};
    int rc = (site = landcover_site_srs(g, err)) ? 0 : -1;
    if (!rc && !(ct = OCTNewCoordinateTransformation(map, site)))
        rc = err_set(err, "PROJ finds no conversion from its CRS into the site's");
    if (!rc && text) rc = number_names(layer, field, c, err);
    if (!rc) rc = gather(layer, field, text, ct, c, &b, err);
    size_t n = (size_t)g->nx * g->ny;
    if (!rc) rc = memory_check(n * 2 * sizeof(int32_t), "burning the land-cover polygons onto the site grid", err);
    if (!rc && !(c->code = malloc(n * sizeof *c->code))) rc = err_nomem(err, "out of memory for %zu nodes' classes", n);
    if (!rc) rc = burn(g, &b, c, err);
    burn_list_free(&b);
    if (ct) OCTDestroyCoordinateTransformation(ct);
    OSRRelease(map);
    if (site) OSRRelease(site);
    return rc;
}

int landcover_polygon_codes(const landcover_source *src, const landcover_grid *g, landcover_codes *c, err_buf *err)
{
    gdal_offline off;
    GDALDatasetH ds = gdal_offline_open(src->path, GDAL_OF_VECTOR, &off);
    int field;
    landcover_fault fault;
    OGRLayerH layer = ds ? landcover_polygon_layer(ds, src, &field, &fault, err) : NULL;
    int rc = !ds      ? err_set(err, "it is not a vector file OGR reads")
             : !layer ? -1
                      : read_layer(layer, field, g, c, err);
    gdal_offline_close(ds, &off);
    return rc;
}
