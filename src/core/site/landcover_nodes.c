/* landcover_nodes.c — the site grid's nodes in a map's CRS through GDAL's coordinate
 * transformation (axes in GIS order on both sides, as site_frame.c normalises PROJ's), and the
 * names a map carries (landcover_codes.h). */
#include "site/landcover_codes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "util/memory_budget.h"

void landcover_codes_release(landcover_codes *c)
{
    if (!c) return;
    for (uint32_t i = 0; i < c->n_names; i++) free(c->names[i].name);
    free(c->names);
    free(c->code);
    memset(c, 0, sizeof *c);
}

int landcover_codes_add_name(landcover_codes *c, int64_t code, const char *name, err_buf *err)
{
    landcover_name *grown = realloc(c->names, (c->n_names + 1) * sizeof *grown);
    if (grown) c->names = grown;
    char *copy = strdup(name);
    if (!grown || !copy) {
        free(copy);
        return err_nomem(err, "out of memory reading the land-cover map's class names");
    }
    c->names[c->n_names++] = (landcover_name){code, copy};
    return 0;
}

const char *landcover_codes_name(const landcover_codes *c, int64_t code)
{
    for (uint32_t i = 0; i < c->n_names; i++)
        if (c->names[i].code == code) return c->names[i].name;
    return NULL;
}

OGRSpatialReferenceH landcover_site_srs(const landcover_grid *g, err_buf *err)
{
    OGRSpatialReferenceH srs = OSRNewSpatialReference(NULL);
    if (!srs) {
        err_nomem(err, "out of memory for the site's CRS");
        return NULL;
    }
    if (OSRSetFromUserInput(srs, g->site_wkt) != OGRERR_NONE) {
        OSRRelease(srs);
        err_set(err, "GDAL cannot read the site's CRS");
        return NULL;
    }
    OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
    return srs;
}

/* Fills x, y with the nodes' map coordinates in the site CRS. */
static void site_coords(const landcover_grid *g, double *x, double *y)
{
    for (uint32_t j = 0; j < g->ny; j++)
        for (uint32_t i = 0; i < g->nx; i++) {
            size_t k = (size_t)j * g->nx + i;
            x[k] = g->origin[0] + g->x0 + i * g->dx;
            y[k] = g->origin[1] + g->y0 + j * g->dy;
        }
}

/* Converts the n points of x, y from the site CRS into map_srs in place; failures HUGE_VAL. */
static int convert(const landcover_grid *g, OGRSpatialReferenceH map_srs, double *x, double *y, size_t n,
                   err_buf *err)
{
    OGRSpatialReferenceH site = landcover_site_srs(g, err);
    if (!site) return -1;
    OGRCoordinateTransformationH ct = OCTNewCoordinateTransformation(site, map_srs);
    OSRRelease(site);
    if (!ct) return err_set(err, "PROJ finds no conversion from the site's CRS into the land-cover map's");
    int *ok = malloc(n * sizeof *ok);
    if (!ok) {
        OCTDestroyCoordinateTransformation(ct);
        return err_nomem(err, "out of memory converting the site grid's nodes");
    }
    OCTTransformEx(ct, (int)n, x, y, NULL, ok);
    for (size_t k = 0; k < n; k++)
        if (!ok[k] || !isfinite(x[k]) || !isfinite(y[k])) x[k] = y[k] = HUGE_VAL;
    free(ok);
    OCTDestroyCoordinateTransformation(ct);
    return 0;
}

int landcover_node_coords(const landcover_grid *g, OGRSpatialReferenceH map_srs, double **x, double **y,
                          err_buf *err)
{
    size_t n = (size_t)g->nx * g->ny;
    *x = *y = NULL;
    if (n > INT32_MAX) return err_set(err, "the site grid has %zu nodes, more than a land-cover map is read onto", n);
    if (memory_check(n * (2 * sizeof(double) + sizeof(int) + sizeof(int32_t)), "reading the land-cover map "
                     "onto the site grid", err))
        return -1;
    *x = malloc(n * sizeof **x);
    *y = malloc(n * sizeof **y);
    if (!*x || !*y) {
        free(*x), free(*y);
        *x = *y = NULL;
        return err_nomem(err, "out of memory for the site grid's %zu nodes", n);
    }
    site_coords(g, *x, *y);
    if (!convert(g, map_srs, *x, *y, n, err)) return 0;
    free(*x), free(*y);
    *x = *y = NULL;
    return -1;
}

void landcover_codes_centre(landcover_codes *c, OGRSpatialReferenceH map_srs, double x, double y)
{
    OGRSpatialReferenceH wgs84 = OSRNewSpatialReference(NULL);
    if (!wgs84) return;
    OGRCoordinateTransformationH ct = NULL;
    if (OSRImportFromEPSG(wgs84, 4326) == OGRERR_NONE) {
        OSRSetAxisMappingStrategy(wgs84, OAMS_TRADITIONAL_GIS_ORDER);
        ct = OCTNewCoordinateTransformation(map_srs, wgs84);
    }
    if (ct && OCTTransform(ct, 1, &x, &y, NULL) && isfinite(x) && isfinite(y)) {
        c->centre_lonlat[0] = x, c->centre_lonlat[1] = y;
        c->has_centre = 1;
    }
    if (ct) OCTDestroyCoordinateTransformation(ct);
    OSRRelease(wgs84);
}
