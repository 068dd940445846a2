/* scene_file_points.c — a study's points file: each point a viewpoint, from a CSV (a layout,
 * scene_file_layout.c: id or name, a position, height_above_ground, heading) or a point layer
 * OGR reads (site/tree_survey.h: the fields name, height_above_ground and heading). A point's eye
 * stands eye_height above the ground unless it gives its height, and it faces the development
 * (the mean place of the development's objects, else of the ztv targets) unless it gives a
 * heading. Its view is level; the study gives it its frame's lens (study/study_frames.h). */
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "scene_file/scene_file.h"
#include "scene_file/scene_file_loader.h"
#include "site/tree_survey.h"

#define DEG (M_PI / 180.0)

/* The survey's attribute slots a viewpoint's fields take, by position. */
enum { POINT_NAME = 0, POINT_HEIGHT = 1, POINT_HEADING = 2 };

/* One point as read, before it becomes a viewpoint. */
typedef struct point_row {
    const char *name;
    double xy[2];             /* local metres */
    int has_height, has_heading;
    double height, heading_deg;
    uint32_t line;            /* of a CSV row; 0 for a feature */
    const char *feature;      /* "FID 12" for a feature OGR read, else NULL */
} point_row;

/* A problem with point r: at shown:line:1 for a CSV row, else a sentence naming its feature. */
static int point_error(loader *L, const char *shown, const point_row *r, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static int point_error(loader *L, const char *shown, const point_row *r, const char *fmt, ...)
{
    char what[ERR_MSG_MAX / 2];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (!r->feature) return sf_located(L->err, shown, r->line, 1, "%s", what);
    return err_fail(L->err, ERR_INPUT, "'%s' %s: %s", shown, r->feature, what);
}

/* A level camera at r's place, eye `above` metres over the ground, facing heading_deg, with the
 * single frame's lens (50 mm on a 36 mm sensor). */
static void point_camera(const point_row *r, double above, double heading_deg, camera_settings *c)
{
    double h = heading_deg * DEG;
    *c = (camera_settings){.position = {r->xy[0], r->xy[1], NAN}, .eye_ground = {1, above, r->line, 1},
                           .direction = {sin(h), cos(h), 0}, .up = {0, 0, 1}, .focal_length_mm = 50,
                           .sensor_width_mm = 36, .fov_deg = 2.0 * atan(36.0 / (2.0 * 50.0)) / DEG};
}

static int name_taken(const scene_file *sf, const char *name)
{
    for (uint32_t i = 0; i < sf->n_viewpoints; i++)
        if (!strcmp(sf->viewpoints[i].name, name)) return 1;
    for (uint32_t i = 0; i < sf->study.n_points; i++)
        if (!strcmp(sf->study.points[i].name, name)) return 1;
    return 0;
}

/* Point r appended to the study's viewpoints (the array has room). */
static int add_point(loader *L, const char *shown, const point_row *r, double eye_height)
{
    scene_file *sf = L->sf;
    if (name_taken(sf, r->name))
        return point_error(L, shown, r, "a viewpoint named '%s' is there already; give each viewpoint its own name",
                           r->name);
    double above = r->has_height ? r->height : eye_height, heading = r->heading_deg;
    if (!(above >= 0 && above <= 10000))
        return point_error(L, shown, r, "height_above_ground %g: an eye stands 0 to 10000 m above the ground", above);
    double at[2];
    if (!r->has_heading && scene_file_development_place(sf, at))
        return point_error(L, shown, r, "'%s' gives no heading, and the scene has no development to face; give a "
                           "heading (degrees clockwise from north)", r->name);
    if (!r->has_heading) heading = fmod(atan2(at[0] - r->xy[0], at[1] - r->xy[1]) / DEG + 360.0, 360.0);
    scene_viewpoint *v = &sf->study.points[sf->study.n_points++];
    *v = (scene_viewpoint){.name = r->name, .file = shown, .line = r->line, .column = 1};
    point_camera(r, above, heading, &v->camera);
    return 0;
}

/* Room for n more points in the study's array (the old one stays in the arena). */
static int make_room(loader *L, uint32_t n)
{
    study_settings *st = &L->sf->study;
    scene_viewpoint *grown = arena_alloc(L->a, ((size_t)st->n_points + n) * sizeof *grown + 1);
    if (!grown) return sf_out_of_memory(L);
    if (st->n_points) memcpy(grown, st->points, st->n_points * sizeof *grown);
    st->points = grown;
    return 0;
}

static int read_csv(loader *L, const char *path, const char *shown, double eye_height)
{
    layout_row *rows;
    uint32_t n;
    if (sf_read_layout(L, path, shown, &rows, &n) || make_room(L, n)) return -1;
    for (uint32_t i = 0; i < n; i++) {
        const layout_row *l = &rows[i];
        point_row r = {.name = l->id, .xy = {l->xy[0], l->xy[1]}, .has_height = l->has_height,
                       .height = l->height_above_ground, .has_heading = l->has_heading,
                       .heading_deg = l->heading_deg, .line = l->line};
        if (add_point(L, shown, &r, eye_height)) return -1;
    }
    return 0;
}

/* A number field of a feature into *v (*has 1), or nothing when it is empty. */
static int feature_number(loader *L, const char *shown, const point_row *r, const char *name, const char *text,
                          int *has, double *v)
{
    if (!text) return 0;
    char *end;
    *v = strtod(text, &end);
    if (*end || !isfinite(*v))
        return point_error(L, shown, r, "'%s' must be a finite number, got '%s'", name, text);
    *has = 1;
    return 0;
}

static int read_ogr(loader *L, const char *path, const char *shown, const char *layer, double eye_height)
{
    if (!L->sf->site.crs_wkt)
        return err_fail(L->err, ERR_INPUT, "'%s': a point layer's viewpoints are placed on the site's map, and the "
                        "scene has no site: section; add one, or give a CSV with x and y in local metres", shown);
    survey_request rq = {.path = path, .shown = shown, .layer = layer, .site_wkt = L->sf->site.crs_wkt,
                         .noun = "viewpoint", .optional = 1u << POINT_HEIGHT | 1u << POINT_HEADING,
                         .field = {[POINT_NAME] = "name", [POINT_HEIGHT] = "height_above_ground",
                                   [POINT_HEADING] = "heading"}};
    survey_points pts;
    survey_key bad;
    if (survey_read(L->a, &rq, &pts, &bad, L->err)) return err_default(L->err, ERR_INPUT);
    if (make_room(L, pts.n)) return -1;
    for (uint32_t i = 0; i < pts.n; i++) {
        const survey_point *p = &pts.points[i];
        point_row r = {.name = p->value[POINT_NAME], .feature = p->feature,
                       .xy = {p->map[0] - L->sf->site.origin[0], p->map[1] - L->sf->site.origin[1]}};
        if (!r.name) return point_error(L, shown, &r, "'name' is empty; name the viewpoint");
        if (feature_number(L, shown, &r, "height_above_ground", p->value[POINT_HEIGHT], &r.has_height, &r.height) ||
            feature_number(L, shown, &r, "heading", p->value[POINT_HEADING], &r.has_heading, &r.heading_deg) ||
            add_point(L, shown, &r, eye_height))
            return -1;
    }
    return 0;
}

static int is_csv_name(const char *path)
{
    size_t n = strlen(path);
    return n > 4 && !strcasecmp(path + n - 4, ".csv");
}

int sf_read_points(loader *L, const char *path, const char *shown, const char *layer, double eye_height)
{
    L->sf->study.points_file = path;
    return is_csv_name(path) ? read_csv(L, path, shown, eye_height) : read_ogr(L, path, shown, layer, eye_height);
}

int scene_file_read_points(scene_file *sf, const char *path, const char *layer, err_buf *err)
{
    err_clear(err);
    loader L = {.a = sf->arena, .err = err, .sf = sf, .file = sf->path, .dir = sf->dir};
    if (sf->site.crs_wkt && !(L.site = site_frame_new(sf->site.crs_wkt, NULL, err))) return -1;
    sf->study.n_points = 0;
    const char *kept = arena_strdup(sf->arena, path);
    int rc = kept ? sf_read_points(&L, kept, kept, layer, sf->study.eye_height) : sf_out_of_memory(&L);
    site_frame_free(L.site);
    return rc ? err_default(err, ERR_INPUT) : 0;
}

uint32_t scene_file_viewpoint_number(const scene_file *sf, const scene_viewpoint *v)
{
    if (v >= sf->viewpoints && v < sf->viewpoints + sf->n_viewpoints) return (uint32_t)(v - sf->viewpoints) + 1;
    if (v >= sf->study.points && v < sf->study.points + sf->study.n_points)
        return sf->n_viewpoints + (uint32_t)(v - sf->study.points) + 1;
    return 0;
}
