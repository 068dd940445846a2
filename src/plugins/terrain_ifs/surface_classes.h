/* surface_classes.h — what covers the ground at each heightfield node: grass, dry grass, scree,
 * rock or snow, from the slope, the height and (when a humidity map is given) the humidity
 * there. The rules, first match wins:
 *
 *   slope >= rock_slope                                  rock
 *   z >= snow_z                                          snow
 *   slope >= scree_slope, or z >= scree_z                scree
 *   humidity < dry_humidity                              dry grass
 *   otherwise                                            grass
 *
 * Heights are the heightfield's (metres); the plugin turns the scene's altitudes (or the older
 * fractions of the DTM's height range) into them. The slope is the angle of the normal the
 * renderer computes, from central differences (one-sided at the border). */
#ifndef TERRAIN_IFS_SURFACE_CLASSES_H
#define TERRAIN_IFS_SURFACE_CLASSES_H

#include <stdint.h>

typedef enum ifs_surface_class {
    IFS_SURFACE_GRASS = 0,
    IFS_SURFACE_DRY_GRASS = 1,
    IFS_SURFACE_SCREE = 2,
    IFS_SURFACE_ROCK = 3,
    IFS_SURFACE_SNOW = 4,
    IFS_SURFACE_CLASSES = 5
} ifs_surface_class;

typedef struct ifs_surface_rules {
    double snow_z;          /* metres: height from which snow lies */
    double scree_z;         /* metres: height from which scree lies */
    double scree_slope;     /* degrees */
    double rock_slope;      /* degrees */
    double dry_humidity;    /* humidity in [0, 1] below which grass is dry */
} ifs_surface_rules;

/* The class of one node. */
ifs_surface_class ifs_surface_class_of(double slope_deg, double z, double humidity,
                                       const ifs_surface_rules *r);

/* Slope in degrees at node (i, j) of an nx x ny grid of heights with spacing dx, dy. */
double ifs_surface_slope(const float *z, uint32_t nx, uint32_t ny, double dx, double dy,
                         uint32_t i, uint32_t j);

/* Classes of every node into cls (nx * ny). humidity: nx * ny values in [0, 1], or NULL (1
 * everywhere). */
void ifs_surface_classify(const float *z, uint32_t nx, uint32_t ny, double dx, double dy,
                          const float *humidity, const ifs_surface_rules *r, uint8_t *cls);

/* Name of a class ("grass", "dry grass", ...). */
const char *ifs_surface_class_name(ifs_surface_class c);

#endif
