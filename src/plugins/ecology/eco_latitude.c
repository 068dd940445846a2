/* eco_latitude.c — the scene's latitude, else the site's (eco_latitude.h). */
#include "eco_latitude.h"

#include <math.h>

double eco_latitude_for(double configured, int given, const sylva_ecology_request *req, const char **whence)
{
    if (given) {
        *whence = "the scene";
        return configured;
    }
    if (req && SYLVA_HAS_FIELD(req, sylva_ecology_request, site_latitude) && isfinite(req->site_latitude)) {
        *whence = "the site";
        return fmax(-80.0, fmin(80.0, req->site_latitude)); /* the schema's range */
    }
    *whence = "the default";
    return configured;
}
