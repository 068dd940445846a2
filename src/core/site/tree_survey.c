/* tree_survey.c — a survey's points read (a CSV by its name, anything else through OGR) and
 * brought into the site CRS through OSR/OCT, in traditional GIS axis order. */
#include "site/tree_survey.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <ogr_srs_api.h>

static int is_csv_name(const char *path)
{
    size_t n = strlen(path);
    return n > 4 && !strcasecmp(path + n - 4, ".csv");
}

/* 1 for "EPSG:" then digits, optionally "+" and digits. */
static int epsg_text(const char *t)
{
    if (strncasecmp(t, "EPSG:", 5) || !isdigit((unsigned char)t[5])) return 0;
    t += 5;
    while (isdigit((unsigned char)*t)) t++;
    if (*t == '+' && isdigit((unsigned char)t[1]))
        for (t++; isdigit((unsigned char)*t);) t++;
    return !*t;
}

/* An OSR CRS from EPSG:NNNN[+MMMM] or WKT (no other form: a URL or a file name would be
 * fetched); NULL with err set. Destroyed by the caller. */
static OGRSpatialReferenceH srs_from_text(const char *text, err_buf *err)
{
    OGRSpatialReferenceH srs = OSRNewSpatialReference(NULL);
    OGRErr e = OGRERR_FAILURE;
    if (!srs) return err_nomem(err, "out of memory for a CRS"), NULL;
    if (epsg_text(text)) e = OSRSetFromUserInput(srs, text);
    else if (strchr(text, '[')) e = OSRImportFromWkt(srs, (char **)&(const char *){text});
    if (e != OGRERR_NONE) {
        OSRDestroySpatialReference(srs);
        err_set(err, "'%.80s' is not a CRS GDAL knows; give EPSG:NNNN (EPSG:NNNN+MMMM with heights) or WKT",
                text);
        return NULL;
    }
    OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
    return srs;
}

/* Moves every point by the transformation; the first that fails is named, with PROJ's reason. */
static int transform_points(survey_points *pts, OGRCoordinateTransformationH ct, const char *shown, err_buf *err)
{
    for (uint32_t i = 0; i < pts->n; i++) {
        survey_point *p = &pts->points[i];
        double x = p->map[0], y = p->map[1], z = 0;
        int ok = 0;
        CPLErrorReset();
        if (OCTTransformEx(ct, 1, &x, &y, &z, &ok) && ok) {
            p->map[0] = x, p->map[1] = y;
            continue;
        }
        const char *why = CPLGetLastErrorMsg();
        return err_set(err, "'%s' %s: the point (%.10g, %.10g) cannot be converted from %s into the site CRS%s%s%s; "
                       "give the survey's points in %s, or its own CRS as crs:", shown, p->feature, p->map[0],
                       p->map[1], pts->crs_name, why[0] ? " (" : "", why, why[0] ? ")" : "", pts->crs_name);
    }
    return 0;
}

int survey_to_site(arena *a, survey_points *pts, const char *shown, const char *from_crs, const char *from_wkt,
                   const char *site_wkt, survey_key *bad_key, err_buf *err)
{
    *bad_key = from_crs ? SURVEY_KEY_CRS : SURVEY_KEY_FILE;
    CPLPushErrorHandler(CPLQuietErrorHandler); /* GDAL's and PROJ's messages: the sentence says why */
    OGRSpatialReferenceH from = srs_from_text(from_crs ? from_crs : from_wkt, err);
    OGRSpatialReferenceH site = from ? srs_from_text(site_wkt, err) : NULL;
    const char *name = site ? OSRGetName(from) : NULL;
    int rc = site ? 0 : -1;
    if (!rc && !(pts->crs_name = arena_strdup(a, name ? name : "the file's CRS")))
        rc = err_nomem(err, "out of memory");
    if (!rc && !OSRIsSame(from, site)) {
        OGRCoordinateTransformationH ct = OCTNewCoordinateTransformation(from, site);
        if (!ct)
            rc = err_set(err, "GDAL finds no conversion from %s into the site CRS: %s", pts->crs_name,
                         CPLGetLastErrorMsg());
        else
            rc = transform_points(pts, ct, shown, err);
        OCTDestroyCoordinateTransformation(ct);
    }
    OSRDestroySpatialReference(from);
    OSRDestroySpatialReference(site);
    CPLPopErrorHandler();
    return rc;
}

int survey_read(arena *a, const survey_request *rq, survey_points *out, survey_key *bad_key, err_buf *err)
{
    memset(out, 0, sizeof *out);
    *bad_key = SURVEY_KEY_FILE;
    char *file_wkt = NULL; /* CPLFree'd here */
    int rc = is_csv_name(rq->path) ? survey_read_csv(a, rq, out, bad_key, err)
                                   : survey_read_ogr(a, rq, out, bad_key, &file_wkt, err);
    if (!rc) {
        const char *from_wkt = file_wkt ? file_wkt : rq->site_wkt; /* a file with no CRS: the site's */
        rc = survey_to_site(a, out, rq->shown, rq->crs, from_wkt, rq->site_wkt, bad_key, err);
    }
    CPLFree(file_wkt);
    return rc;
}
