/* surface_classes.c — ground cover by slope, height and humidity. */
#include "surface_classes.h"

#include <math.h>
#include <stddef.h>

ifs_surface_class ifs_surface_class_of(double slope_deg, double z, double humidity,
                                       const ifs_surface_rules *r)
{
    if (slope_deg >= r->rock_slope) return IFS_SURFACE_ROCK;
    if (z >= r->snow_z) return IFS_SURFACE_SNOW;
    if (slope_deg >= r->scree_slope || z >= r->scree_z) return IFS_SURFACE_SCREE;
    if (humidity < r->dry_humidity) return IFS_SURFACE_DRY_GRASS;
    return IFS_SURFACE_GRASS;
}

double ifs_surface_slope(const float *z, uint32_t nx, uint32_t ny, double dx, double dy,
                         uint32_t i, uint32_t j)
{
    uint32_t i0 = i ? i - 1 : i, i1 = i + 1 < nx ? i + 1 : i;
    uint32_t j0 = j ? j - 1 : j, j1 = j + 1 < ny ? j + 1 : j;
    double gx = ((double)z[(size_t)j * nx + i1] - z[(size_t)j * nx + i0]) / ((i1 - i0) * dx);
    double gy = ((double)z[(size_t)j1 * nx + i] - z[(size_t)j0 * nx + i]) / ((j1 - j0) * dy);
    return atan(sqrt(gx * gx + gy * gy)) * (180.0 / M_PI);
}

void ifs_surface_classify(const float *z, uint32_t nx, uint32_t ny, double dx, double dy,
                          const float *humidity, const ifs_surface_rules *r, uint8_t *cls)
{
    for (uint32_t j = 0; j < ny; j++)
        for (uint32_t i = 0; i < nx; i++) {
            size_t k = (size_t)j * nx + i;
            double wet = humidity ? humidity[k] : 1.0;
            cls[k] = (uint8_t)ifs_surface_class_of(ifs_surface_slope(z, nx, ny, dx, dy, i, j),
                                                   z[k], wet, r);
        }
}

const char *ifs_surface_class_name(ifs_surface_class c)
{
    static const char *const names[IFS_SURFACE_CLASSES] = {"grass", "dry grass", "scree", "rock",
                                                           "snow"};
    return (unsigned)c < IFS_SURFACE_CLASSES ? names[c] : "unknown";
}
