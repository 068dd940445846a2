/* scene_file_settings.c — the sections that set one thing each: image, camera (look_at or
 * direction or heading/pitch/roll, fov or focal length with sensor width, an up vector not
 * parallel to the view) and the named viewpoints read as the camera is, sun (direction,
 * azimuth and elevation, or a date and time at a place), sky (keys that apply to its model
 * only), earth (curvature on by default only for a scene with a site, so read after the
 * site) and ground_cover (the grass and herbs placed near the camera). */
#include "scene_file/scene_file.h"
#include "scene_file/scene_file_loader.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "season/sun_position.h"

#define DEG (M_PI / 180.0)

/* Scales v to unit length without overflow or underflow (components of 1e300 or 1e-320 give a
 * direction too); returns 0, or -1 when v is zero or not finite. */
static int normalize3(double v[3])
{
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (!(m > 0.0) || !isfinite(m)) return -1;
    for (int k = 0; k < 3; k++) v[k] /= m;
    double l = sf_length3(v);
    for (int k = 0; k < 3; k++) v[k] /= l;
    return 0;
}

/* The renderer works in single precision: a coordinate beyond its range becomes infinite. */
static int beyond_float(const double v[3])
{
    return fabs(v[0]) > FLT_MAX || fabs(v[1]) > FLT_MAX || fabs(v[2]) > FLT_MAX;
}

static int read_section(loader *L, const char *name, const host_schema *schema,
                        const sylva_params **out)
{
    const ynode_pair *pr = ynode_get_pair(L->root, name);
    param_scope scope = {L->file, L->dir, name, NULL, 0, pr ? pr->key_line : L->root->line,
                         pr ? pr->key_column : L->root->column};
    return params_validate(L->a, pr ? pr->value : NULL, schema->params, schema->n_params, &scope,
                           out, L->err);
}

int sf_read_image(loader *L)
{
    const sylva_params *p;
    if (read_section(L, "image", &host_schema_image, &p)) return -1;
    image_settings *im = &L->sf->image;
    im->width = (uint32_t)sylva_param_int(p, "width");
    im->height = (uint32_t)sylva_param_int(p, "height");
    im->spp = (uint32_t)sylva_param_int(p, "spp");
    im->noise_target = sylva_param_real(p, "noise_target");
    im->seed = (uint64_t)sylva_param_int(p, "seed");
    im->max_depth = (uint32_t)sylva_param_int(p, "max_depth");
    im->exposure = sylva_param_real(p, "exposure");
    im->exposure_set = sylva_param(p, "exposure")->is_set;
    im->tone = (tone_curve)sylva_param(p, "tone")->i;
    im->crown_proxy = sylva_param_real(p, "crown_proxy");
    return 0;
}

/* Of two keys that exclude each other, the one given later in the file. */
static const sylva_value *later_of(const sylva_value *a, const sylva_value *b)
{
    if (a->line != b->line) return a->line > b->line ? a : b;
    return a->column > b->column ? a : b;
}

/* The camera's position and look_at, in local metres or map coordinates (sf_read_position),
 * with the eye's height above ground; each point's z is provisional while its height is above a
 * terrain not yet built: the height above ground itself, for the checks below. */
static int read_camera_points(loader *L, const ynode *map, const char *where, const sylva_params *p,
                              camera_settings *c, sylva_value *pos_at, sylva_value *look_at)
{
    sf_position pos, look;
    if (sf_read_position(L, map, sf_host_key(&host_schema_camera, "position"), where, &pos) ||
        sf_read_position(L, map, sf_host_key(&host_schema_camera, "look_at"), where, &look))
        return -1;
    const sylva_value *eye = sylva_param(p, "height_above_ground");
    if (eye->is_set && (pos.has_height || !isnan(pos.above_ground)))
        return sf_located(L->err, L->file, eye->line, eye->column,
                          "the camera takes its height from 'position' or from "
                          "'height_above_ground', not both; give position: [x, y] with it");
    if (eye->is_set) pos.above_ground = eye->r;
    if (!pos.has_height && isnan(pos.above_ground))
        return sf_located(L->err, L->file, pos.line, pos.column,
                          "the camera 'position' gives no height; give [x, y, z], or "
                          "height_above_ground: 1.6 (an eye height above the terrain)");
    if (look.given && !look.has_height && isnan(look.above_ground)) look.above_ground = 0.0;
    c->eye_ground = (ground_height){!isnan(pos.above_ground), pos.above_ground,
                                    eye->is_set ? eye->line : pos.line, eye->is_set ? eye->column : pos.column};
    c->look_at_ground = (ground_height){!isnan(look.above_ground), look.above_ground, look.line, look.column};
    if (!isnan(pos.above_ground)) pos.local[2] = pos.above_ground;
    if (!isnan(look.above_ground)) look.local[2] = look.above_ground;
    for (int k = 0; k < 3; k++) c->position[k] = pos.local[k], c->look_at[k] = look.local[k];
    *pos_at = (sylva_value){.is_set = 1, .line = pos.line, .column = pos.column};
    *look_at = (sylva_value){.is_set = look.given, .line = look.line, .column = look.column};
    return 0;
}

/* heading and pitch: the view as a compass bearing and an angle above the horizon, instead of
 * look_at or direction; the image's up is then the vertical tilted with the view, defined even
 * straight down. roll: a turn of the image about the view, with any way of aiming. The keys
 * heading and pitch exclude (checked first, before anything is aimed with them): */
static int camera_angles_clash(loader *L, const sylva_params *p, const sylva_value *look)
{
    const sylva_value *heading = sylva_param(p, "heading"), *pitch = sylva_param(p, "pitch"),
                      *dir = sylva_param(p, "direction"), *up = sylva_param(p, "up");
    if (!heading->is_set && !pitch->is_set) return 0;
    const sylva_value *angle = heading->is_set ? heading : pitch;
    const sylva_value *aim = look->is_set ? look : dir->is_set ? dir : NULL;
    if (aim) {
        const sylva_value *at = later_of(angle, aim);
        return sf_located(L->err, L->file, at->line, at->column,
                          "the camera takes 'look_at', 'direction' or 'heading'/'pitch', not two "
                          "of them");
    }
    if (up->is_set)
        return sf_located(L->err, L->file, up->line, up->column,
                          "'up' goes with look_at or direction; with 'heading'/'pitch' the image's "
                          "up is the vertical, turned by 'roll'");
    return 0;
}

static void read_camera_angles(const sylva_params *p, camera_settings *c)
{
    const sylva_value *heading = sylva_param(p, "heading"), *pitch = sylva_param(p, "pitch");
    c->roll_deg = sylva_param_real(p, "roll");
    if (!heading->is_set && !pitch->is_set) return;
    double h = heading->r * DEG, e = pitch->r * DEG;
    c->has_look_at = 0;
    c->direction[0] = sin(h) * cos(e), c->direction[1] = cos(h) * cos(e), c->direction[2] = sin(e);
    c->up[0] = -sin(h) * sin(e), c->up[1] = -cos(h) * sin(e), c->up[2] = cos(e);
}

/* One camera block (the camera: section, or a viewpoint), `where` naming it in messages; the key
 * (line, column) locates a block with a missing key. */
static int read_camera_block(loader *L, const ynode *map, uint32_t key_line, uint32_t key_column,
                             const char *where, camera_settings *c)
{
    static const char *const points[] = {"position", "look_at"};
    const sylva_params *p;
    uint32_t n_keys;
    const sylva_param_spec *keys = sf_keys_without(L, &host_schema_camera, points, 2, &n_keys);
    param_scope scope = {L->file, L->dir, where, points, 2, key_line, key_column};
    if (!keys || params_validate(L->a, map, keys, n_keys, &scope, &p, L->err)) return -1;
    sylva_value pos_at = {0}, look_at = {0};
    if (read_camera_points(L, map, where, p, c, &pos_at, &look_at)) return -1;
    const sylva_value *pos = &pos_at, *look = &look_at,
                      *dir = sylva_param(p, "direction"), *up = sylva_param(p, "up"),
                      *fov = sylva_param(p, "fov"), *focal = sylva_param(p, "focal_length"),
                      *sensor = sylva_param(p, "sensor_width");
    if (look->is_set && dir->is_set) {
        const sylva_value *at = later_of(look, dir);
        return sf_located(L->err, L->file, at->line, at->column,
                       "the camera takes 'look_at' or 'direction', not both");
    }
    if (camera_angles_clash(L, p, look)) return -1;
    if (fov->is_set && focal->is_set) {
        const sylva_value *at = later_of(fov, focal);
        return sf_located(L->err, L->file, at->line, at->column,
                       "the camera takes 'fov' or 'focal_length' (with sensor_width), not both");
    }
    if (sensor->is_set && !focal->is_set)
        return sf_located(L->err, L->file, sensor->line, sensor->column,
                       "'sensor_width' is used only with 'focal_length'; give focal_length too "
                       "or remove it");
    sf_copy3(c->up, up);
    c->has_look_at = look->is_set;
    const sylva_value *view = look->is_set ? look : dir;
    if (beyond_float(c->position))
        return sf_located(L->err, L->file, pos->line, pos->column,
                       "the camera 'position' lies beyond single precision (+-%g m), where the "
                       "renderer cannot place it", (double)FLT_MAX);
    if (look->is_set) {
        if (beyond_float(c->look_at))
            return sf_located(L->err, L->file, look->line, look->column,
                           "'look_at' lies beyond single precision (+-%g m), where the renderer "
                           "cannot aim; give a nearer point on the same line, or 'direction'",
                           (double)FLT_MAX);
        int same = 1;
        for (int k = 0; k < 3; k++) {
            c->direction[k] = c->look_at[k] - c->position[k];
            same &= (float)c->look_at[k] == (float)c->position[k];
        }
        if (same)
            return sf_located(L->err, L->file, look->line, look->column,
                           "'look_at' must differ from the camera 'position' (in single "
                           "precision, as the renderer holds them)");
    } else {
        sf_copy3(c->direction, dir);
    }
    if (normalize3(c->direction))
        return sf_located(L->err, L->file, view->line, view->column,
                       look->is_set ? "the view from 'position' to 'look_at' has no usable "
                                      "direction; give a nearer 'look_at'"
                                    : "'direction' must not be zero");
    double u[3]; /* the unit up, for the check; c->up keeps the value given */
    sf_copy3(u, up);
    if (normalize3(u))
        return sf_located(L->err, L->file, up->line, up->column, "'up' must not be zero");
    double cr[3] = {c->direction[1] * u[2] - c->direction[2] * u[1],
                    c->direction[2] * u[0] - c->direction[0] * u[2],
                    c->direction[0] * u[1] - c->direction[1] * u[0]};
    if (sf_length3(cr) < 1e-9) {
        const sylva_value *at = up->is_set ? up : view->is_set ? view : pos;
        return sf_located(L->err, L->file, at->line, at->column,
                       "the viewing direction is parallel to 'up' [%g, %g, %g]; give another "
                       "'up' or turn the view",
                       c->up[0], c->up[1], c->up[2]);
    }
    c->sensor_width_mm = sensor->r;
    const sylva_value *projection = sylva_param(p, "projection");
    c->cylindrical = (int)projection->i == 1;
    if (focal->is_set) {
        c->focal_length_mm = focal->r;
        /* a cylinder of radius f unrolled onto the sensor: the width spans sensor / f radians */
        c->fov_deg = c->cylindrical ? sensor->r / focal->r / DEG : 2.0 * atan(sensor->r / (2.0 * focal->r)) / DEG;
        if (c->fov_deg > 360.0)
            return sf_located(L->err, L->file, focal->line, focal->column,
                              "a cylindrical camera with focal_length %g mm on a %g mm sensor would see %.0f "
                              "degrees across, more than a full turn; give a longer focal length", focal->r,
                              sensor->r, c->fov_deg);
    } else {
        c->focal_length_mm = 0.0;
        c->fov_deg = fov->r;
    }
    if (!c->cylindrical && c->fov_deg >= 180.0)
        return sf_located(L->err, L->file, fov->line, fov->column,
                          "a perspective camera sees less than 180 degrees across, got fov %g; use "
                          "projection: cylindrical for a panorama", c->fov_deg);
    const sylva_value *f_number = sylva_param(p, "f_number"), *focus = sylva_param(p, "focus_distance");
    c->f_number = f_number->r;
    c->focus_distance = focus->r;
    c->vignette = sylva_param_real(p, "vignette");
    if (c->f_number > 0.0 && !focus->is_set)
        return sf_located(L->err, L->file, f_number->line, f_number->column,
                          "'f_number' %g needs 'focus_distance' (metres to what is sharp), e.g. "
                          "focus_distance: 50", c->f_number);
    if (c->eye_ground.given) c->position[2] = NAN;   /* known once the terrain is built */
    if (c->look_at_ground.given) c->look_at[2] = NAN;
    read_camera_angles(p, c);
    return 0;
}

/* viewpoints: named camera blocks beside the scene's camera, each read and checked as the camera
 * is; `render --viewpoint NAME` renders from one (scene_file_use_viewpoint). */
static int read_viewpoints(loader *L)
{
    const ynode_pair *pr = ynode_get_pair(L->root, "viewpoints");
    if (!pr || ynode_is_null(pr->value)) return 0;
    const ynode *node = pr->value;
    if (node->kind != YNODE_MAPPING)
        return sf_located(L->err, L->file, node->line, node->column,
                          "'viewpoints' must be a mapping of names to camera blocks (viewpoints: {north: "
                          "{position: ..., heading: ...}}), got %s", ynode_kind_phrase(node));
    scene_file *sf = L->sf;
    sf->viewpoints = arena_alloc(L->a, (size_t)node->n_pairs * sizeof *sf->viewpoints + 1);
    if (!sf->viewpoints) return sf_out_of_memory(L);
    for (uint32_t i = 0; i < node->n_pairs; i++) {
        const ynode_pair *vp = &node->pairs[i];
        const char *where = sf_arena_printf(L->a, "viewpoints.%s", vp->key);
        if (!where) return sf_out_of_memory(L);
        if (vp->value->kind != YNODE_MAPPING)
            return sf_located(L->err, L->file, vp->value->line, vp->value->column,
                              "'%s' must be a camera block ({position: ..., heading: ... or look_at: ...}), "
                              "got %s", where, ynode_kind_phrase(vp->value));
        scene_viewpoint *v = &sf->viewpoints[sf->n_viewpoints];
        *v = (scene_viewpoint){.name = vp->key, .line = vp->key_line, .column = vp->key_column};
        if (read_camera_block(L, vp->value, vp->key_line, vp->key_column, where, &v->camera)) return -1;
        sf->n_viewpoints++;
    }
    return 0;
}

int sf_read_camera(loader *L)
{
    const ynode_pair *pr = ynode_get_pair(L->root, "camera");
    if (!pr && (L->flags & SCENE_FILE_NO_CAMERA)) return read_viewpoints(L); /* camera unset, has_camera 0 */
    if (!pr)
        return sf_located(L->err, L->file, L->root->line, L->root->column,
                       "missing required section 'camera' (at least camera: {position: [x, y, z], "
                       "look_at: [x, y, z]})");
    if (read_camera_block(L, pr->value, pr->key_line, pr->key_column, "camera", &L->sf->camera)) return -1;
    L->sf->has_camera = 1;
    return read_viewpoints(L);
}

int scene_file_use_viewpoint(scene_file *sf, const char *name, err_buf *err)
{
    char names[ERR_MSG_MAX / 2] = "";
    size_t used = 0;
    for (uint32_t i = 0; i < sf->n_viewpoints; i++) {
        if (!strcmp(sf->viewpoints[i].name, name)) {
            sf->camera = sf->viewpoints[i].camera;
            return 0;
        }
        int w = snprintf(names + used, sizeof names - used, "%s%s", i ? ", " : "", sf->viewpoints[i].name);
        if (w > 0 && (size_t)w < sizeof names - used) used += (size_t)w;
    }
    return err_fail(err, ERR_USAGE, "%s has no viewpoint '%s'; %s%s", sf->path, name,
                    sf->n_viewpoints ? "its viewpoints are: " : "it has no viewpoints: section",
                    sf->n_viewpoints ? names : "");
}

#define SUN_DATE_EXAMPLE "date_time: \"2026-06-21T14:30:00+01:00\" (or ...T13:30:00Z)"

/* With `date_time`, the sun's azimuth and elevation for that instant, seen from the site origin
 * or from the given latitude and longitude (docs/models/sun_position.md); s->date_time_utc stays
 * "" without it. Refuses date_time beside azimuth, elevation or direction, and latitude or
 * longitude without date_time or beside a site. */
static int sun_place_by_date(loader *L, const sylva_params *p, sun_settings *s)
{
    const sylva_value *dt = sylva_param(p, "date_time"), *lat = sylva_param(p, "latitude"),
                      *lon = sylva_param(p, "longitude");
    const sylva_value *given = lat->is_set ? lat : lon->is_set ? lon : NULL;
    s->date_time_utc[0] = 0, s->date_time_local[0] = 0;
    if (!dt->is_set) {
        if (given)
            return sf_located(L->err, L->file, given->line, given->column,
                              "'%s' places the sun only with 'date_time'; give %s",
                              given == lat ? "latitude" : "longitude", SUN_DATE_EXAMPLE);
        return 0;
    }
    const char *const others[] = {"azimuth", "elevation", "direction"};
    for (int k = 0; k < 3; k++) {
        const sylva_value *o = sylva_param(p, others[k]);
        if (o->is_set) {
            const sylva_value *at = later_of(dt, o);
            return sf_located(L->err, L->file, at->line, at->column,
                              "the sun takes 'date_time' or '%s', not both: the date and the place "
                              "set its position", others[k]);
        }
    }
    sun_utc t;
    err_buf why = {{0}};
    if (sun_utc_parse(dt->s, &t, &why))
        return sf_located(L->err, L->file, dt->line, dt->column,
                          "'date_time' must be an ISO 8601 date and time with its UTC offset: %s; "
                          "for example %s", err_sentence(&why), SUN_DATE_EXAMPLE);
    double place[2] = {lon->r, lat->r};
    if (L->site) {
        if (given)
            return sf_located(L->err, L->file, given->line, given->column,
                              "the scene has a site: the sun is placed from its origin; leave out "
                              "'%s'", given == lat ? "latitude" : "longitude");
        const double *o = L->sf->site.origin;
        if (site_frame_to_lonlat(L->site, o[0], o[1], place, &why))
            return sf_located(L->err, L->file, dt->line, dt->column,
                              "the sun cannot be placed from the site origin: %s",
                              err_sentence(&why));
    } else if (!lat->is_set || !lon->is_set) {
        return sf_located(L->err, L->file, dt->line, dt->column,
                          "the scene has no site, so 'date_time' needs 'latitude' and 'longitude' "
                          "(degrees, north and east positive), as in sun: {%s, latitude: 51.5, "
                          "longitude: -0.12}", SUN_DATE_EXAMPLE);
    }
    sun_observer where = sun_observer_standard(place[1], place[0], 0.0);
    sun_position at;
    if (sun_position_at(&t, &where, &at, &why))
        return sf_located(L->err, L->file, dt->line, dt->column, "%s", err_sentence(&why));
    s->azimuth_deg = at.azimuth_deg, s->elevation_deg = at.elevation_deg;
    s->latitude_deg = place[1], s->longitude_deg = place[0];
    snprintf(s->date_time_utc, sizeof s->date_time_utc, "%04d-%02d-%02dT%02d:%02d:%02dZ", t.year,
             t.month, t.day, t.hour, t.minute, (int)t.second);
    snprintf(s->date_time_local, sizeof s->date_time_local, "%s", dt->s);
    return 0;
}

#define SUN_IRRADIANCE_MAX 1e6 /* sylva's unit: 1 is about 100 klx; 1e6 is beyond any sun */

int sf_read_sun(loader *L)
{
    const sylva_params *p;
    if (read_section(L, "sun", &host_schema_sun, &p)) return -1;
    sun_settings *s = &L->sf->sun;
    const sylva_value *az = sylva_param(p, "azimuth"), *el = sylva_param(p, "elevation"),
                      *dir = sylva_param(p, "direction");
    if (dir->is_set && (az->is_set || el->is_set)) {
        const sylva_value *at = later_of(dir, az->is_set ? az : el);
        return sf_located(L->err, L->file, at->line, at->column,
                       "the sun takes 'direction' or 'azimuth'/'elevation', not both");
    }
    if (sun_place_by_date(L, p, s)) return -1;
    if (!s->date_time_utc[0] && dir->is_set) {
        sf_copy3(s->direction, dir);
        if (normalize3(s->direction))
            return sf_located(L->err, L->file, dir->line, dir->column, "'direction' must not be zero");
        double azimuth = atan2(s->direction[0], s->direction[1]) / DEG;
        s->azimuth_deg = azimuth < 0.0 ? azimuth + 360.0 : azimuth;
        s->elevation_deg = asin(fmax(-1.0, fmin(1.0, s->direction[2]))) / DEG;
    } else {
        if (!s->date_time_utc[0]) s->azimuth_deg = az->r, s->elevation_deg = el->r;
        double a = s->azimuth_deg * DEG, e = s->elevation_deg * DEG;
        s->direction[0] = sin(a) * cos(e);
        s->direction[1] = cos(a) * cos(e);
        s->direction[2] = sin(e);
    }
    s->enabled = (int)sylva_param_int(p, "enabled");
    s->irradiance = sylva_param_real(p, "irradiance");
    sf_copy3(s->color, sylva_param(p, "color"));
    double brightest = s->irradiance * fmax(s->color[0], fmax(s->color[1], s->color[2]));
    if (!(brightest <= SUN_IRRADIANCE_MAX)) {
        const sylva_value *irr = sylva_param(p, "irradiance"), *col = sylva_param(p, "color");
        const sylva_value *at = irr->is_set ? irr : col->is_set ? col : NULL;
        return sf_located(L->err, L->file, at ? at->line : 1, at ? at->column : 1,
                       "the sun's irradiance times its colour reaches %g; it must stay at most "
                       "%g (1 is about 100 klx), or the image overflows to black",
                       brightest, SUN_IRRADIANCE_MAX);
    }
    s->angular_diameter_deg = sylva_param_real(p, "angular_diameter");
    return 0;
}

/* The sky keys that belong to one model: each is refused under another. */
static const struct {
    const char *key;
    sky_model model;
} sky_model_keys[] = {{"color", SKY_CONSTANT}, {"turbidity", SKY_PREETHAM}, {"visibility", SKY_PHYSICAL},
                      {"density", SKY_PHYSICAL}};

int sf_read_sky(loader *L)
{
    const sylva_params *p;
    if (read_section(L, "sky", &host_schema_sky, &p)) return -1;
    sky_settings *s = &L->sf->sky;
    const sylva_value *model = sylva_param(p, "model"), *color = sylva_param(p, "color"),
                      *turbidity = sylva_param(p, "turbidity"), *visibility = sylva_param(p, "visibility"),
                      *density = sylva_param(p, "density");
    s->model = (sky_model)model->i;
    for (size_t i = 0; i < sizeof sky_model_keys / sizeof sky_model_keys[0]; i++) {
        const sylva_value *v = sylva_param(p, sky_model_keys[i].key);
        if (v->is_set && s->model != sky_model_keys[i].model)
            return sf_located(L->err, L->file, v->line, v->column, "'%s' applies to model: %s; this sky is '%s'",
                              sky_model_keys[i].key, host_sky_models[sky_model_keys[i].model], model->s);
    }
    s->turbidity = turbidity->r;
    s->visibility_km = visibility->r;
    s->density = density->r;
    s->scale = sylva_param_real(p, "scale");
    sf_copy3(s->color, color);
    s->ground_albedo = sylva_param_real(p, "ground_albedo");
    sf_copy3(s->ambient, sylva_param(p, "ambient"));
    return 0;
}

int sf_read_earth(loader *L)
{
    const sylva_params *p;
    if (read_section(L, "earth", &host_schema_earth, &p)) return -1;
    earth_settings *e = &L->sf->earth;
    const sylva_value *curvature = sylva_param(p, "curvature");
    /* A site is a real place, seen over real distances; a scene in local metres alone keeps the
     * flat Earth it always had unless it asks. */
    e->curvature = curvature->is_set ? (int)curvature->i : L->sf->site.crs_wkt != NULL;
    e->refraction = sylva_param_real(p, "refraction");
    e->radius = sylva_param_real(p, "radius");
    return 0;
}

int sf_read_snow(loader *L)
{
    const sylva_params *p;
    if (read_section(L, "snow", &host_schema_snow, &p)) return -1;
    snow_settings *s = &L->sf->snow;
    const ynode_pair *pr = ynode_get_pair(L->root, "snow");
    const sylva_value *min_height = sylva_param(p, "min_height");
    s->on = pr != NULL;
    s->cover = sylva_param_real(p, "cover");
    /* a map height, as the terrain's altitudes are: the local frame's z = 0 is the site origin's */
    s->min_height = min_height->is_set ? min_height->r - L->sf->site.origin[2] : -HUGE_VAL;
    if (s->on && L->sf->terrain.source != TERRAIN_PLUGIN)
        return sf_located(L->err, L->file, pr->key_line, pr->key_column,
                          "'snow' lies on the procedural ground of a terrain plugin (terrain: {plugin: "
                          "terrain_ifs, ...}); this scene's terrain is %s, which keeps its own materials",
                          L->sf->terrain.source == TERRAIN_NONE ? "missing" : "an inline grid");
    return 0;
}

int sf_read_ground_cover(loader *L)
{
    const sylva_params *p;
    if (read_section(L, "ground_cover", &host_schema_ground_cover, &p)) return -1;
    ground_cover_settings *g = &L->sf->ground_cover;
    g->enabled = (int)sylva_param_int(p, "enabled");
    g->density = sylva_param_real(p, "density");
    g->radius = sylva_param_real(p, "radius");
    g->max_instances = (uint32_t)sylva_param_int(p, "max_instances");
    return 0;
}
