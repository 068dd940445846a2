/* lsys_silhouette.h — the turtle's wood drawn onto a box-counting raster (box_count.h): the
 * side view (x–z) a tree's D_B is measured on (002 eq. 3), leaves left out. */
#ifndef LSYS_SILHOUETTE_H
#define LSYS_SILHOUETTE_H

#include "box_count.h"
#include "lsys_turtle.h"

/* A sink that projects every segment onto r's x–z plane with its width (r's coordinates are the
 * turtle's: file units). */
lsys_sink lsys_silhouette_sink(box_raster *r);

#endif
