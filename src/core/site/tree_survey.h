/* tree_survey.h — the trees of a survey file, as points in the site CRS with the attributes a
 * scene reads: species name, measured height, crown diameter and age, as text. A study's file of
 * viewpoints is read the same way (its name, eye height and heading in the first three slots).
 *
 * A survey is a point layer that OGR reads (GeoPackage, Shapefile, GeoJSON, ...) or a CSV
 * with x and y columns. Points come out in the site CRS: transformed through OSR/OCT in
 * traditional GIS axis order (easting then northing, longitude then latitude) from the file's
 * CRS, or from `crs` when given (a CSV states none). GDAL never reaches the network while the
 * file is read, and its messages go to err, not stderr.
 *
 * Each point names the feature it came from (`FID 12`, `line 5`) for messages. What the
 * attributes mean (which species, whether a height is valid) is the caller's to judge; here a
 * field the request names must exist in the layer, and a point must be a point.
 *
 * Ownership: everything a read returns lives in the arena passed in. */
#ifndef SYLVA_TREE_SURVEY_H
#define SYLVA_TREE_SURVEY_H

#include <stdint.h>

#include "util/arena.h"
#include "util/err.h"

/* Which of a request's fields an error is about: the caller places the message at its key. */
typedef enum survey_key {
    SURVEY_KEY_FILE = 0, SURVEY_KEY_LAYER, SURVEY_KEY_CRS, SURVEY_KEY_X, SURVEY_KEY_Y,
    SURVEY_KEY_SPECIES, SURVEY_KEY_HEIGHT, SURVEY_KEY_CROWN, SURVEY_KEY_AGE, SURVEY_KEY_COUNT
} survey_key;

/* The attributes read from each point, in this order in survey_point.value. */
enum { SURVEY_SPECIES = 0, SURVEY_HEIGHT, SURVEY_CROWN, SURVEY_AGE, SURVEY_N_VALUES };

typedef struct survey_request {
    const char *path;           /* the file (resolved) */
    const char *shown;          /* its name in messages */
    const char *layer;          /* NULL: the file's first layer */
    const char *crs;            /* EPSG:NNNN, EPSG:NNNN+MMMM or WKT; NULL: the file's own */
    const char *x_field, *y_field; /* CSV columns of the coordinates */
    const char *field[SURVEY_N_VALUES]; /* attribute names; NULL: not read */
    const char *site_wkt;       /* the site CRS as WKT */
    const char *noun;           /* what a point is, in messages: "tree" when NULL (a study's
                                   viewpoints read the same way: "viewpoint") */
    unsigned optional;          /* bits 1u << k: field[k] may be absent from an OGR layer (its value
                                   is then NULL at every point) */
} survey_request;

typedef struct survey_point {
    double map[2];              /* easting, northing in the site CRS */
    const char *value[SURVEY_N_VALUES]; /* the attribute as text; NULL when unset or empty */
    const char *feature;        /* "FID 12" or "line 5" */
} survey_point;

typedef struct survey_points {
    survey_point *points; uint32_t n;
    const char *crs_name;       /* the CRS the file's points were read in */
    int is_csv;
} survey_points;

/* A file whose name ends in .csv (any case) is read as a CSV (survey_read_csv); any other
 * through OGR (survey_read_ogr). Returns 0, or -1 with err set and *bad_key the request field
 * the error is about (SURVEY_KEY_FILE for the file itself and its features). */
int survey_read(arena *a, const survey_request *rq, survey_points *out, survey_key *bad_key, err_buf *err);

/* The two readers; the points still in the file's CRS (map holds the file's x, y). */
int survey_read_ogr(arena *a, const survey_request *rq, survey_points *out, survey_key *bad_key,
                    char **crs_wkt_out, err_buf *err); /* *crs_wkt_out: CPLFree'd by the caller */
int survey_read_csv(arena *a, const survey_request *rq, survey_points *out, survey_key *bad_key, err_buf *err);

/* Converts every point from `from_wkt` (or the text `from_crs`: EPSG:NNNN, EPSG:NNNN+MMMM or
 * WKT, which wins when not NULL) into `site_wkt`; pts->crs_name is set (in a). Returns 0, or -1
 * with err set (a point that cannot be converted named by the file's name `shown` and its
 * feature, with PROJ's reason). */
int survey_to_site(arena *a, survey_points *pts, const char *shown, const char *from_crs, const char *from_wkt,
                   const char *site_wkt, survey_key *bad_key, err_buf *err);

#endif
