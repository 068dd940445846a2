/* site_frame.c — the site CRS through PROJ: parsing, the projected-in-metres rule, and
 * conversions into the site CRS. Every transformation is normalised for visualisation, so its
 * axes are in GIS order (longitude then latitude, easting then northing) whatever the CRS's
 * authority says. */
#include "site/site_frame.h"

#include <ctype.h>
#include <math.h>
#include <proj.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

struct site_frame {
    PJ_CONTEXT *ctx; /* owned */
    PJ *crs;         /* owned: the site CRS */
    PJ *from_lonlat; /* owned: EPSG:4326 to the site CRS, made at first use, or NULL */
    char *wkt;       /* owned */
    char *name;      /* owned */
};

static PJ_CONTEXT *quiet_context(void)
{
    PJ_CONTEXT *ctx = proj_context_create();
    if (!ctx) return NULL;
    proj_log_level(ctx, PJ_LOG_NONE);
    proj_context_set_enable_network(ctx, 0);
    return ctx;
}

/* The length of a run of 1 to 9 digits at d, or 0. */
static size_t code_digits(const char *d)
{
    size_t n = 0;
    while (isdigit((unsigned char)d[n])) n++;
    return n <= 9 ? n : 0;
}

/* Digits of an "EPSG:NNNN" text (any case, no spaces), or NULL when it is not one. */
static const char *epsg_code(const char *text)
{
    if (strncasecmp(text, "EPSG:", 5)) return NULL;
    size_t n = code_digits(text + 5);
    return n && !text[5 + n] ? text + 5 : NULL;
}

/* 1 for "EPSG:NNNN+MMMM": a horizontal CRS with a vertical one (a compound CRS). */
static int epsg_compound(const char *text)
{
    if (strncasecmp(text, "EPSG:", 5)) return 0;
    size_t n = code_digits(text + 5);
    size_t m = n && text[5 + n] == '+' ? code_digits(text + 6 + n) : 0;
    return m && !text[6 + n + m];
}

/* The CRS of crs_text (EPSG:NNNN or WKT), or NULL with err set. */
static PJ *crs_parse(PJ_CONTEXT *ctx, const char *text, err_buf *err)
{
    const char *code = epsg_code(text);
    PJ *crs = NULL;
    if (code) {
        crs = proj_create_from_database(ctx, "EPSG", code, PJ_CATEGORY_CRS, 0, NULL);
        if (!crs)
            err_set(err, "'%s' is not a coordinate reference system in PROJ's EPSG database; give "
                    "an existing code (EPSG:32614 is WGS 84 / UTM zone 14N) or the CRS as WKT", text);
        return crs;
    }
    if (epsg_compound(text)) {
        crs = proj_create(ctx, text);
        if (!crs || !proj_is_crs(crs)) {
            proj_destroy(crs);
            err_set(err, "'%s' is not a horizontal and a vertical CRS of PROJ's EPSG database; give "
                    "existing codes (EPSG:32614+5703 is UTM zone 14N with NAVD88 heights)", text);
            return NULL;
        }
        return crs;
    }
    if (strncasecmp(text, "EPSG", 4) == 0 || text[0] == '+' || !strchr(text, '[')) {
        err_set(err, "'%.80s' is neither 'EPSG:NNNN' nor WKT; give the CRS as EPSG:NNNN (such as "
                "EPSG:32614; EPSG:NNNN+MMMM adds a vertical CRS) or as WKT (PROJCRS[...] or "
                "PROJCS[...])", text);
        return NULL;
    }
    PROJ_STRING_LIST warnings = NULL, errors = NULL;
    crs = proj_create_from_wkt(ctx, text, NULL, &warnings, &errors);
    if (!crs || !proj_is_crs(crs)) {
        err_set(err, "the WKT does not define a coordinate reference system: %s; give a WKT "
                "PROJCRS[...] (or EPSG:NNNN)", errors && errors[0] ? errors[0] : "PROJ cannot read it");
        proj_destroy(crs);
        crs = NULL;
    }
    proj_string_list_destroy(warnings);
    proj_string_list_destroy(errors);
    return crs;
}

/* The horizontal part of a CRS (the CRS itself, a compound CRS's first part, a bound CRS's
 * source); a new reference the caller destroys, or NULL. */
static PJ *horizontal_part(PJ_CONTEXT *ctx, const PJ *crs)
{
    PJ_TYPE t = proj_get_type(crs);
    if (t == PJ_TYPE_BOUND_CRS) {
        PJ *src = proj_get_source_crs(ctx, crs);
        PJ *h = src ? horizontal_part(ctx, src) : NULL;
        proj_destroy(src);
        return h;
    }
    if (t == PJ_TYPE_COMPOUND_CRS) return proj_crs_get_sub_crs(ctx, crs, 0);
    return proj_clone(ctx, crs);
}

int site_utm_epsg(double lon, double lat)
{
    double l = isfinite(lon) ? fmod(fmod(lon + 180.0, 360.0) + 360.0, 360.0) : 0.0;
    int zone = (int)floor(l / 6.0) + 1;
    if (zone > 60) zone = 60;
    return (lat < 0 ? 32700 : 32600) + zone;
}

static void utm_hint(const double *near, char *buf, size_t size)
{
    if (near)
        snprintf(buf, size, "the site's UTM zone, EPSG:%d", site_utm_epsg(near[0], near[1]));
    else
        snprintf(buf, size, "the UTM zone of the site: EPSG:326ZZ north of the equator, EPSG:327ZZ "
                 "south, zone ZZ = floor((longitude + 180) / 6) + 1");
}

/* 0 when the horizontal part of f->crs is projected with metre axes pointing east and north;
 * otherwise -1 with err set. */
static int check_projected_metres(site_frame *f, const char *text, const double *near, err_buf *err)
{
    PJ *h = horizontal_part(f->ctx, f->crs);
    PJ *cs = h ? proj_crs_get_coordinate_system(f->ctx, h) : NULL;
    char hint[160];
    utm_hint(near, hint, sizeof hint);
    int rc = 0;
    PJ_TYPE t = h ? proj_get_type(h) : PJ_TYPE_UNKNOWN;
    const char *name = proj_get_name(f->crs);
    if (t == PJ_TYPE_GEOGRAPHIC_2D_CRS || t == PJ_TYPE_GEOGRAPHIC_3D_CRS || t == PJ_TYPE_GEOCENTRIC_CRS) {
        rc = err_set(err, "the site CRS '%s' (%.60s) is geographic, in degrees; the site needs a "
                     "projected CRS in metres, such as %s", name ? name : "?", text, hint);
    } else if (t != PJ_TYPE_PROJECTED_CRS || !cs) {
        rc = err_set(err, "the site CRS '%s' (%.60s) is not a projected CRS; the site needs a "
                     "projected CRS in metres, such as %s", name ? name : "?", text, hint);
    } else {
        int n = proj_cs_get_axis_count(f->ctx, cs), east = 0, north = 0;
        for (int i = 0; i < n && !rc && i < 2; i++) {
            const char *dir = NULL, *unit = NULL;
            double factor = 0;
            proj_cs_get_axis_info(f->ctx, cs, i, NULL, NULL, &dir, &factor, &unit, NULL, NULL);
            if (!(fabs(factor - 1.0) < 1e-12))
                rc = err_set(err, "the site CRS '%s' (%.60s) has axes in %s, not metres; the site "
                             "needs a projected CRS in metres, such as %s", name ? name : "?", text,
                             unit ? unit : "another unit", hint);
            east += dir && !strcasecmp(dir, "east");
            north += dir && !strcasecmp(dir, "north");
        }
        if (!rc && (n < 2 || east != 1 || north != 1))
            rc = err_set(err, "the site CRS '%s' (%.60s) has axes that do not point east and north; "
                         "the site needs a projected CRS with easting and northing in metres, such "
                         "as %s", name ? name : "?", text, hint);
    }
    proj_destroy(cs);
    proj_destroy(h);
    return rc;
}

site_frame *site_frame_new(const char *crs_text, const double *near_lonlat, err_buf *err)
{
    site_frame *f = calloc(1, sizeof *f);
    if (!f || !(f->ctx = quiet_context())) {
        free(f);
        err_nomem(err, "out of memory for the site CRS");
        return NULL;
    }
    if (!crs_text || !crs_text[0]) {
        err_set(err, "the site CRS is empty; give EPSG:NNNN or WKT");
        goto fail;
    }
    if (!(f->crs = crs_parse(f->ctx, crs_text, err))) goto fail;
    if (check_projected_metres(f, crs_text, near_lonlat, err)) goto fail;
    const char *wkt = proj_as_wkt(f->ctx, f->crs, PJ_WKT2_2019, NULL); /* owned by f->crs */
    const char *name = proj_get_name(f->crs);
    f->wkt = strdup(wkt ? wkt : crs_text);
    f->name = strdup(name ? name : crs_text);
    if (!f->wkt || !f->name) {
        err_nomem(err, "out of memory for the site CRS");
        goto fail;
    }
    return f;
fail:
    site_frame_free(f);
    return NULL;
}

void site_frame_free(site_frame *f)
{
    if (!f) return;
    proj_destroy(f->from_lonlat);
    proj_destroy(f->crs);
    if (f->ctx) proj_context_destroy(f->ctx);
    free(f->wkt);
    free(f->name);
    free(f);
}

const char *site_frame_wkt(const site_frame *f) { return f->wkt; }
const char *site_frame_name(const site_frame *f) { return f->name; }

/* The transformation from `from` to the site CRS in GIS axis order; a new PJ or NULL. */
static PJ *transformation_from(site_frame *f, PJ *from)
{
    PJ *raw = proj_create_crs_to_crs_from_pj(f->ctx, from, f->crs, NULL, NULL);
    PJ *norm = raw ? proj_normalize_for_visualization(f->ctx, raw) : NULL;
    proj_destroy(raw);
    return norm;
}

static int transform_point(site_frame *f, PJ *op, double x, double y, double map[2], const char *what,
                           err_buf *err)
{
    proj_errno_reset(op);
    PJ_COORD out = proj_trans(op, PJ_FWD, proj_coord(x, y, 0, 0));
    if (proj_errno(op) || !isfinite(out.xy.x) || !isfinite(out.xy.y)) {
        int e = proj_errno(op);
        return err_set(err, "%s (%.10g, %.10g) cannot be converted into the site CRS '%s'%s%s", what,
                       x, y, f->name, e ? ": " : "", e ? proj_context_errno_string(f->ctx, e) : "");
    }
    map[0] = out.xy.x, map[1] = out.xy.y;
    return 0;
}

/* The transformation from longitude/latitude into the site CRS, made at first use. */
static int lonlat_op(site_frame *f, err_buf *err)
{
    if (f->from_lonlat) return 0;
    PJ *wgs84 = proj_create_from_database(f->ctx, "EPSG", "4326", PJ_CATEGORY_CRS, 0, NULL);
    f->from_lonlat = wgs84 ? transformation_from(f, wgs84) : NULL;
    proj_destroy(wgs84);
    if (!f->from_lonlat)
        return err_set(err, "PROJ finds no conversion from longitude/latitude (EPSG:4326) into "
                       "the site CRS '%s'", f->name);
    return 0;
}

int site_frame_from_lonlat(site_frame *f, double lon, double lat, double map[2], err_buf *err)
{
    if (lonlat_op(f, err)) return -1;
    return transform_point(f, f->from_lonlat, lon, lat, map, "longitude/latitude", err);
}

int site_frame_to_lonlat(site_frame *f, double easting, double northing, double lonlat[2],
                         err_buf *err)
{
    if (lonlat_op(f, err)) return -1;
    proj_errno_reset(f->from_lonlat);
    PJ_COORD out = proj_trans(f->from_lonlat, PJ_INV, proj_coord(easting, northing, 0, 0));
    int e = proj_errno(f->from_lonlat);
    if (e || !isfinite(out.lp.lam) || !isfinite(out.lp.phi) || fabs(out.lp.phi) > 90.0)
        return err_set(err, "the map point (%.10g, %.10g) of the site CRS '%s' cannot be converted "
                       "into longitude/latitude%s%s", easting, northing, f->name, e ? ": " : "",
                       e ? proj_context_errno_string(f->ctx, e) : "");
    lonlat[0] = out.lp.lam, lonlat[1] = out.lp.phi;
    return 0;
}

int site_frame_from_crs(site_frame *f, const char *from_crs, double x, double y, double map[2],
                        err_buf *err)
{
    PJ *from = crs_parse(f->ctx, from_crs, err);
    if (!from) return -1;
    PJ *op = transformation_from(f, from);
    proj_destroy(from);
    if (!op)
        return err_set(err, "PROJ finds no conversion into the site CRS '%s' from '%.60s'", f->name,
                       from_crs);
    int rc = transform_point(f, op, x, y, map, "the point", err);
    proj_destroy(op);
    return rc;
}
