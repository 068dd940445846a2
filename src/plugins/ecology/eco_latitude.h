/* eco_latitude.h — the latitude the sun path is drawn for: the scene's `latitude` when it gives
 * one, else the site's (ABI 1.6 request), else the schema's default (46 degrees, 004's). A site beyond
 * 80 degrees is taken at 80, the parameter's limit. */
#ifndef ECO_LATITUDE_H
#define ECO_LATITUDE_H

#include "sylva/plugin.h"

/* The latitude (degrees north) for `configured`, the value the parameters hold; given: 1 when
 * the scene set it. *whence names its origin for the log ("the scene", "the site", "the
 * default"). */
double eco_latitude_for(double configured, int given, const sylva_ecology_request *req, const char **whence);

#endif
