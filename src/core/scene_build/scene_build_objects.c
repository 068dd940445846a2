/* scene_build_objects.c — the objects section into the scene graph. A built-in shape is built
 * once per (shape, material) into a shared model, a model file is imported once per (file,
 * scale, up axis), and a group's parts become shared models on first use; objects place them as
 * instances, so twenty turbines hold one copy of each mesh and a layout of a million boxes one
 * box. Heights are resolved here, against the terrain already built: a given z, the origin a
 * height above the ground at (x, y), or the lowest point on the lowest ground under the
 * object's footprint; each object keeps the z of its entry's lowest point as placed (its
 * base, from which targets above it are measured). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model_import.h"
#include "scene_build/scene_build.h"
#include "scene_file/shape_index.h"
#include "site/terrain_extent.h"

/* Footprint samples at most per object; beyond it the spacing grows past the terrain's. */
#define FOOTPRINT_MAX_SAMPLES 1000000.0

typedef struct imported_file {
    const char *path;          /* borrowed from the scene file */
    double scale;
    int up;
    const char *root;          /* borrowed from the scene file; NULL: the model's folder */
    uint32_t model;
} imported_file;

typedef struct object_builder {
    scene *s;
    const scene_file *sf;
    imported_file *files; uint32_t n_files; /* owned (malloc) */
    shape_index shapes;        /* the distinct (shape, material) pairs; owned */
    uint32_t *shape_model;     /* the model of shape number k; owned (malloc) */
    uint32_t shape_model_cap;
    int32_t *part_model;       /* per part of every group, -1 until built; owned (malloc) */
    uint32_t *first_part;      /* group g's parts at first_part[g] + i; owned (malloc) */
} object_builder;

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* The model of a model file (o is an object or part with kind OBJECT_MODEL). */
static int32_t model_for_file(object_builder *b, const object_spec *o, err_buf *err)
{
    for (uint32_t i = 0; i < b->n_files; i++) {
        const imported_file *f = &b->files[i];
        if (!strcmp(f->path, o->model_path) && f->scale == o->model_scale && f->up == o->model_up &&
            !strcmp(f->root ? f->root : "", o->model_root ? o->model_root : ""))
            return (int32_t)f->model;
    }
    imported_file *grown = realloc(b->files, (b->n_files + 1) * sizeof *grown);
    if (!grown) return err_nomem(err, "out of memory");
    b->files = grown;
    model_import_options opt = {.scale = o->model_scale, .up = (model_up)o->model_up, .root = o->model_root};
    mesh *m = NULL;
    model_import_info info;
    if (model_import(b->s, o->model_path, &opt, &m, &info, err)) return -1;
    if (info.missing[0]) /* said once a file, as the model is read once */
        fprintf(stderr, "sylva: warning: %s: the model names the file '%s', which cannot be read (missing, or "
                "not a file); the model is read without it (an OBJ without its material library takes the "
                "default material)\n", o->model_path, info.missing);
    int32_t id = scene_add_model(b->s, base_name(o->model_path), m, err);
    if (id < 0) return -1;
    b->files[b->n_files++] = (imported_file){o->model_path, o->model_scale, o->model_up, o->model_root, (uint32_t)id};
    return id;
}

/* A name for the model of a shape: its kind and size, after the first object that placed it. */
static void shape_model_name(const object_spec *o, char *name, size_t n)
{
    const shape_spec *sh = &o->shape;
    switch (sh->kind) {
    case SHAPE_BOX: snprintf(name, n, "box %g x %g x %g", sh->size[0], sh->size[1], sh->size[2]); break;
    case SHAPE_QUAD: snprintf(name, n, "quad %g x %g", sh->size[0], sh->size[1]); break;
    case SHAPE_DISK: snprintf(name, n, "disk of radius %g", sh->radius); break;
    case SHAPE_SPHERE: snprintf(name, n, "sphere of radius %g", sh->radius); break;
    default: snprintf(name, n, "mesh of %u triangles", sh->n_triangles); break;
    }
    size_t used = strlen(name);
    snprintf(name + used, n - used, " (%s, as '%s')", o->material ? o->material : "default material",
             o->name ? o->name : "object");
}

/* The model of a shape object's shape and material, built on first use. */
static int32_t model_for_shape(object_builder *b, const object_spec *o, err_buf *err)
{
    uint32_t known = b->shapes.count;
    int64_t k = shape_index_add(&b->shapes, &o->shape, o->material);
    if (k < 0) return err_nomem(err, "out of memory");
    if (k < known) return (int32_t)b->shape_model[k];
    if (k >= b->shape_model_cap) {
        uint32_t cap = b->shape_model_cap ? 2 * b->shape_model_cap : 16;
        uint32_t *grown = realloc(b->shape_model, (size_t)cap * sizeof *grown);
        if (!grown) return err_nomem(err, "out of memory");
        b->shape_model = grown, b->shape_model_cap = cap;
    }
    mesh *m = scene_shape_mesh(b->s, &o->shape, o->material, o->file, o->line, o->column, "object", o->name, err);
    if (!m) return -1;
    char name[256];
    shape_model_name(o, name, sizeof name);
    int32_t id = scene_add_model(b->s, name, m, err);
    if (id >= 0) b->shape_model[k] = (uint32_t)id;
    return id;
}

/* The model of part i of group g, built on first use. */
static int32_t model_for_part(object_builder *b, uint32_t g, uint32_t i, err_buf *err)
{
    int32_t *slot = &b->part_model[b->first_part[g] + i];
    if (*slot >= 0) return *slot;
    const group_spec *gs = &b->sf->groups[g];
    const object_spec *part = &gs->parts[i];
    if (part->kind == OBJECT_MODEL) {
        *slot = model_for_file(b, part, err);
        if (*slot < 0 && !err_has_place(err)) err_prefix(err, "group '%s', part '%s': ", gs->name, part->name);
        return *slot;
    }
    mesh *m = scene_shape_mesh(b->s, &part->shape, part->material, part->file, part->line, part->column, "part",
                               part->name, err);
    if (!m) return -1;
    char name[256];
    snprintf(name, sizeof name, "%s/%s", gs->name, part->name);
    return *slot = scene_add_model(b->s, name, m, err);
}

/* A part's transform in its group's frame: scale (shapes), rotation, then its position. */
static xform3x4 part_transform(const object_spec *p)
{
    return xf_trs(v3((float)p->position[0], (float)p->position[1], (float)p->position[2]),
                  v3((float)p->rotation_deg[0], (float)p->rotation_deg[1], (float)p->rotation_deg[2]),
                  v3((float)p->scale[0], (float)p->scale[1], (float)p->scale[2]));
}

/* The object's own turn: scale, rotation, then the heading about +Z (clockwise from north). */
static xform3x4 object_turn(const object_spec *o)
{
    xform3x4 inner = xf_trs(v3(0, 0, 0), v3((float)o->rotation_deg[0], (float)o->rotation_deg[1],
                                             (float)o->rotation_deg[2]),
                            v3((float)o->scale[0], (float)o->scale[1], (float)o->scale[2]));
    xform3x4 heading = xf_trs(v3(0, 0, 0), v3(0, 0, (float)-o->heading_deg), v3(1, 1, 1));
    return xf_compose(&heading, &inner);
}

/* Grows lo/hi by m's bounding box carried through xf. */
static void bounds_add(const mesh *m, const xform3x4 *xf, double lo[3], double hi[3])
{
    if (!m->nv) return;
    float a[3], c[3];
    mesh_bounds(m, a, c);
    for (int k = 0; k < 8; k++) {
        vec3 q = xf_point(xf, v3(k & 1 ? c[0] : a[0], k & 2 ? c[1] : a[1], k & 4 ? c[2] : a[2]));
        double p[3] = {q.x, q.y, q.z};
        for (int d = 0; d < 3; d++) lo[d] = fmin(lo[d], p[d]), hi[d] = fmax(hi[d], p[d]);
    }
}

/* The lowest ground as surveyed under the rectangle [x0, x1] x [y0, y1], sampled at its spacing
 * with its edges included (objects stand on the same ground whatever the camera); 0 without a terrain. -1 when no point of it lies on the terrain. */
static int lowest_ground(const scene *s, double x0, double y0, double x1, double y1, double *z)
{
    if (!s->surveyed) {
        *z = 0;
        return 0;
    }
    double step = fmin(s->surveyed->dx, s->surveyed->dy);
    double nx = ceil((x1 - x0) / step), ny = ceil((y1 - y0) / step);
    while ((nx + 1) * (ny + 1) > FOOTPRINT_MAX_SAMPLES) step *= 2, nx = ceil((x1 - x0) / step), ny = ceil((y1 - y0) / step);
    double best = INFINITY;
    for (double j = 0; j <= ny; j++)
        for (double i = 0; i <= nx; i++) {
            double h, x = nx > 0 ? x0 + (x1 - x0) * i / nx : x0, y = ny > 0 ? y0 + (y1 - y0) * j / ny : y0;
            if (!scene_surveyed_height(s, x, y, &h)) best = fmin(best, h);
        }
    if (!isfinite(best)) return -1;
    *z = best;
    return 0;
}

/* The z of the object's origin. lo/hi: its bounds after its turn, before its translation. */
static int origin_height(const scene *s, const object_spec *o, const double lo[3], const double hi[3], double *z,
                         err_buf *err)
{
    double x = o->position[0], y = o->position[1], ground = 0;
    char where[512];
    terrain_extent_text(s, x, y, where, sizeof where);
    switch (o->base) {
    case OBJECT_AT_Z: *z = o->position[2]; return 0;
    case OBJECT_ABOVE_GROUND:
        if (s->surveyed && scene_surveyed_height(s, x, y, &ground))
            return err_set(err, "position (%g, %g) lies outside the terrain%s; height_above_ground needs the "
                           "ground there", x, y, where);
        *z = ground + o->height_above_ground;
        return 0;
    case OBJECT_ON_GROUND:
        if (!(lo[0] <= hi[0])) { /* no vertices: nothing to stand */
            *z = 0;
            return 0;
        }
        if (lowest_ground(s, x + lo[0], y + lo[1], x + hi[0], y + hi[1], &ground))
            return err_set(err, "the footprint [%g, %g] x [%g, %g] around (%g, %g) lies outside the terrain%s",
                           x + lo[0], x + hi[0], y + lo[1], y + hi[1], x, y, where);
        *z = ground - lo[2];
        return 0;
    }
    return 0;
}

/* The z of the object's origin, and its base: the z of its lowest point as placed. lo/hi: its
 * bounds after its turn, before its translation. */
static int resolve_height(const scene *s, const object_spec *o, const double lo[3], const double hi[3], double *z,
                          double *base, err_buf *err)
{
    if (origin_height(s, o, lo, hi, z, err)) return -1;
    *base = lo[2] <= hi[2] ? *z + lo[2] : *z;
    return 0;
}

static xform3x4 translated(const xform3x4 *turn, double x, double y, double z)
{
    xform3x4 t = *turn;
    t.m[0][3] += (float)x, t.m[1][3] += (float)y, t.m[2][3] += (float)z;
    return t;
}

/* A shape or model object: an instance of its shared model. */
static int place_model(object_builder *b, const object_spec *o, double *base, err_buf *err)
{
    int32_t id = o->kind == OBJECT_SHAPE ? model_for_shape(b, o, err) : model_for_file(b, o, err);
    if (id < 0) return -1;
    xform3x4 turn = object_turn(o);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, z;
    bounds_add(b->s->models[id].mesh, &turn, lo, hi);
    if (resolve_height(b->s, o, lo, hi, &z, base, err)) return -1;
    xform3x4 xf = translated(&turn, o->position[0], o->position[1], z);
    return scene_add_model_object(b->s, o->name, (uint32_t)id, &xf, err) < 0 ? -1 : 0;
}

/* Every part of the group, as one object each named "<object>/<part>". */
static int place_group(object_builder *b, const object_spec *o, double *base, err_buf *err)
{
    const group_spec *gs = &b->sf->groups[o->group];
    xform3x4 turn = object_turn(o);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, z;
    for (uint32_t i = 0; i < gs->n_parts; i++) {
        int32_t id = model_for_part(b, o->group, i, err);
        if (id < 0) return -1;
        xform3x4 local = part_transform(&gs->parts[i]), in_turn = xf_compose(&turn, &local);
        bounds_add(b->s->models[id].mesh, &in_turn, lo, hi);
    }
    if (resolve_height(b->s, o, lo, hi, &z, base, err)) return -1;
    xform3x4 place = translated(&turn, o->position[0], o->position[1], z);
    for (uint32_t i = 0; i < gs->n_parts; i++) {
        xform3x4 local = part_transform(&gs->parts[i]), xf = xf_compose(&place, &local);
        char name[512];
        snprintf(name, sizeof name, "%s/%s", o->name, gs->parts[i].name);
        if (scene_add_model_object(b->s, name, (uint32_t)b->part_model[b->first_part[o->group] + i], &xf, err) < 0)
            return -1;
    }
    return 0;
}

int scene_build_objects(scene *s, const scene_file *sf, err_buf *err)
{
    object_builder b = {.s = s, .sf = sf};
    uint32_t parts = 0;
    b.first_part = malloc(((size_t)sf->n_groups + 1) * sizeof *b.first_part);
    for (uint32_t g = 0; b.first_part && g < sf->n_groups; g++) b.first_part[g] = parts, parts += sf->groups[g].n_parts;
    b.part_model = malloc(((size_t)parts + 1) * sizeof *b.part_model);
    int rc = 0;
    if (!b.first_part || !b.part_model) rc = err_nomem(err, "out of memory placing the objects");
    for (uint32_t p = 0; !rc && p < parts; p++) b.part_model[p] = -1;
    for (uint32_t i = 0; !rc && i < sf->n_objects; i++) {
        const object_spec *o = &sf->objects[i];
        uint32_t first = s->n_objects;
        double base = 0;
        rc = o->kind == OBJECT_GROUP ? place_group(&b, o, &base, err) : place_model(&b, o, &base, err);
        if (rc && !err_has_place(err)) {
            err_prefix(err, "object '%s': ", o->name);
            err_locate(err, o->file, o->line, o->column);
        }
        for (uint32_t k = first; !rc && k < s->n_objects; k++)
            s->objects[k].development = o->development, s->objects[k].entry = i, s->objects[k].base = base;
    }
    free(b.files);
    shape_index_free(&b.shapes);
    free(b.shape_model);
    free(b.part_model);
    free(b.first_part);
    return rc;
}
