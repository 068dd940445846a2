/* scene_file_settings.c — the sections that set one thing each: image, camera (look_at or
 * direction, fov or focal length with sensor width, an up vector not parallel to the view), sun
 * (direction or azimuth and elevation) and sky (keys that apply to its model only). */
#include "scene/scene_file_loader.h"

#include <math.h>

#define DEG (M_PI / 180.0)

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
    im->seed = (uint64_t)sylva_param_int(p, "seed");
    im->max_depth = (uint32_t)sylva_param_int(p, "max_depth");
    im->exposure = sylva_param_real(p, "exposure");
    return 0;
}

/* Of two keys that exclude each other, the one given later in the file. */
static const sylva_value *later_of(const sylva_value *a, const sylva_value *b)
{
    if (a->line != b->line) return a->line > b->line ? a : b;
    return a->column > b->column ? a : b;
}

int sf_read_camera(loader *L)
{
    if (!ynode_get(L->root, "camera"))
        return sf_located(L->err, L->file, L->root->line, L->root->column,
                          "missing required section 'camera' (at least camera: {position: [x, y, z], "
                          "look_at: [x, y, z]})");
    const sylva_params *p;
    if (read_section(L, "camera", &host_schema_camera, &p)) return -1;
    camera_settings *c = &L->sf->camera;
    const sylva_value *pos = sylva_param(p, "position"), *look = sylva_param(p, "look_at"),
                      *dir = sylva_param(p, "direction"), *up = sylva_param(p, "up"),
                      *fov = sylva_param(p, "fov"), *focal = sylva_param(p, "focal_length"),
                      *sensor = sylva_param(p, "sensor_width");
    if (look->is_set && dir->is_set) {
        const sylva_value *at = later_of(look, dir);
        return sf_located(L->err, L->file, at->line, at->column,
                          "the camera takes 'look_at' or 'direction', not both");
    }
    if (fov->is_set && focal->is_set) {
        const sylva_value *at = later_of(fov, focal);
        return sf_located(L->err, L->file, at->line, at->column,
                          "the camera takes 'fov' or 'focal_length' (with sensor_width), not both");
    }
    if (sensor->is_set && !focal->is_set)
        return sf_located(L->err, L->file, sensor->line, sensor->column,
                          "'sensor_width' is used only with 'focal_length'; give focal_length too "
                          "or remove it");
    sf_copy3(c->position, pos);
    sf_copy3(c->up, up);
    c->has_look_at = look->is_set;
    const sylva_value *view = look->is_set ? look : dir;
    if (look->is_set) {
        sf_copy3(c->look_at, look);
        for (int k = 0; k < 3; k++) c->direction[k] = c->look_at[k] - c->position[k];
        if (sf_length3(c->direction) == 0.0)
            return sf_located(L->err, L->file, look->line, look->column,
                              "'look_at' must differ from the camera 'position'");
    } else {
        sf_copy3(c->direction, dir);
        if (sf_length3(c->direction) == 0.0)
            return sf_located(L->err, L->file, dir->line, dir->column, "'direction' must not be zero");
    }
    double dl = sf_length3(c->direction), ul = sf_length3(c->up);
    if (ul == 0.0)
        return sf_located(L->err, L->file, up->line, up->column, "'up' must not be zero");
    for (int k = 0; k < 3; k++) c->direction[k] /= dl;
    double cr[3] = {c->direction[1] * c->up[2] - c->direction[2] * c->up[1],
                    c->direction[2] * c->up[0] - c->direction[0] * c->up[2],
                    c->direction[0] * c->up[1] - c->direction[1] * c->up[0]};
    if (sf_length3(cr) / ul < 1e-9) {
        const sylva_value *at = up->is_set ? up : view->is_set ? view : pos;
        return sf_located(L->err, L->file, at->line, at->column,
                          "the viewing direction is parallel to 'up' [%g, %g, %g]; give another "
                          "'up' or turn the view",
                          c->up[0], c->up[1], c->up[2]);
    }
    c->sensor_width_mm = sensor->r;
    if (focal->is_set) {
        c->focal_length_mm = focal->r;
        c->fov_deg = 2.0 * atan(sensor->r / (2.0 * focal->r)) / DEG;
    } else {
        c->focal_length_mm = 0.0;
        c->fov_deg = fov->r;
    }
    return 0;
}

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
    if (dir->is_set) {
        sf_copy3(s->direction, dir);
        double len = sf_length3(s->direction);
        if (len == 0.0)
            return sf_located(L->err, L->file, dir->line, dir->column, "'direction' must not be zero");
        for (int k = 0; k < 3; k++) s->direction[k] /= len;
        double azimuth = atan2(s->direction[0], s->direction[1]) / DEG;
        s->azimuth_deg = azimuth < 0.0 ? azimuth + 360.0 : azimuth;
        s->elevation_deg = asin(fmax(-1.0, fmin(1.0, s->direction[2]))) / DEG;
    } else {
        s->azimuth_deg = az->r, s->elevation_deg = el->r;
        double a = az->r * DEG, e = el->r * DEG;
        s->direction[0] = sin(a) * cos(e);
        s->direction[1] = cos(a) * cos(e);
        s->direction[2] = sin(e);
    }
    s->enabled = (int)sylva_param_int(p, "enabled");
    s->irradiance = sylva_param_real(p, "irradiance");
    sf_copy3(s->color, sylva_param(p, "color"));
    s->angular_diameter_deg = sylva_param_real(p, "angular_diameter");
    return 0;
}

int sf_read_sky(loader *L)
{
    const sylva_params *p;
    if (read_section(L, "sky", &host_schema_sky, &p)) return -1;
    sky_settings *s = &L->sf->sky;
    const sylva_value *model = sylva_param(p, "model"), *color = sylva_param(p, "color"),
                      *turbidity = sylva_param(p, "turbidity");
    s->model = (sky_model)model->i;
    if (color->is_set && s->model != SKY_CONSTANT)
        return sf_located(L->err, L->file, color->line, color->column,
                          "'color' applies to model: constant; this sky is '%s'", model->s);
    if (turbidity->is_set && s->model != SKY_PREETHAM)
        return sf_located(L->err, L->file, turbidity->line, turbidity->column,
                          "'turbidity' applies to model: preetham; this sky is '%s'", model->s);
    s->turbidity = turbidity->r;
    s->scale = sylva_param_real(p, "scale");
    sf_copy3(s->color, color);
    s->ground_albedo = sylva_param_real(p, "ground_albedo");
    sf_copy3(s->ambient, sylva_param(p, "ambient"));
    return 0;
}
