/* landcover.c — a land-cover map checked as the scene file is read, and read once onto the site
 * grid (landcover.h): the reader of its form gives the map's codes at the nodes, the classifier
 * turns them into classes. */
#include "site/landcover.h"

#include <gdal.h>

#include "site/gdal_offline.h"
#include "site/landcover_codes.h"

static int check_raster(GDALDatasetH ds, err_buf *err)
{
    double gt[6];
    if (GDALGetRasterCount(ds) < 1) return err_set(err, "it has no raster band");
    if (GDALGetGeoTransform(ds, gt) != CE_None) return err_set(err, "it has no georeferencing (no geotransform)");
    if (!GDALGetSpatialRef(ds))
        return err_set(err, "it names no CRS (a .prj or .aux.xml beside it, or the file's own)");
    return 0;
}

static const char *form_phrase(landcover_form form)
{
    return form == LANDCOVER_RASTER ? "a classified raster GDAL reads (GeoTIFF, ...)"
                                    : "polygons OGR reads (GeoPackage, Shapefile, GeoJSON)";
}

int landcover_check(const landcover_source *src, landcover_fault *fault, err_buf *err)
{
    *fault = LANDCOVER_FAULT_FILE;
    gdal_offline off;
    int raster = src->form == LANDCOVER_RASTER;
    GDALDatasetH ds = gdal_offline_open(src->path, raster ? GDAL_OF_RASTER : GDAL_OF_VECTOR, &off);
    int field, rc = 0;
    if (!ds) rc = err_set(err, "it is not %s", form_phrase(src->form));
    else if (raster) rc = check_raster(ds, err);
    else rc = landcover_polygon_layer(ds, src, &field, fault, err) ? 0 : -1;
    gdal_offline_close(ds, &off);
    if (rc) err_prefix(err, "the land-cover map '%s': ", src->path);
    return rc;
}

land_cover *landcover_read(const landcover_source *src, const landcover_grid *grid, FILE *warnings,
                          FILE *summary, err_buf *err)
{
    landcover_codes c = {0};
    int rc = src->form == LANDCOVER_RASTER ? landcover_raster_codes(src, grid, &c, err)
                                           : landcover_polygon_codes(src, grid, &c, err);
    if (!rc && !c.covered)
        rc = err_set(err, "it covers none of the site's %u x %u nodes (%.0f m apart); check that the map is of "
                     "the site's area and that its CRS is right", grid->nx, grid->ny, grid->dx);
    land_cover *lc = rc ? NULL : landcover_classify(src, grid, &c, warnings, summary, err);
    if (!lc && err->status != ERR_NOMEM) err_prefix(err, "the land-cover map '%s': ", src->path);
    landcover_codes_release(&c);
    return lc;
}
