/* scene.c — the scene graph's storage: growable arrays of materials, textures, prototypes,
 * instances, objects and shared models, and terrain queries. */
#include "scene/scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/heightfield.h"

/* Grows *arr (element size sz) to hold at least need elements. */
static int grow(void **arr, uint32_t *cap, uint32_t need, size_t sz)
{
    if (need <= *cap) return 0;
    uint32_t c = *cap ? *cap : 16;
    while (c < need) {
        if (c > UINT32_MAX / 2) return -1;
        c *= 2;
    }
    void *p = realloc(*arr, (size_t)c * sz);
    if (!p) return -1;
    *arr = p;
    *cap = c;
    return 0;
}

scene *scene_new(void)
{
    scene *s = calloc(1, sizeof *s);
    if (!s) return NULL;
    sylva_material_desc grey = {.size = sizeof grey, .name = "default", .bsdf = SYLVA_BSDF_LAMBERT,
                                .albedo = {0.5f, 0.5f, 0.5f}, .texture = -1};
    s->default_material = scene_add_material(s, &grey, NULL);
    if (s->default_material < 0) {
        scene_free(s);
        return NULL;
    }
    s->terrain_material = s->default_material;
    s->water_material = s->default_material;
    return s;
}

void scene_free(scene *s)
{
    if (!s) return;
    if (s->surveyed != s->terrain) heightfield_free(s->surveyed);
    heightfield_free(s->terrain);
    land_cover_free(s->land_cover);
    canopy_free(s->canopy);
    for (uint32_t i = 0; i < s->n_materials; i++) free(s->materials[i].name);
    for (uint32_t i = 0; i < s->n_textures; i++) free(s->textures[i].name), free(s->textures[i].rgba);
    for (uint32_t i = 0; i < s->n_species; i++) free(s->species[i].name);
    for (uint32_t i = 0; i < s->n_prototypes; i++) mesh_free(s->prototypes[i].mesh);
    for (uint32_t i = 0; i < s->n_objects; i++) free(s->objects[i].name), mesh_free(s->objects[i].mesh);
    for (uint32_t i = 0; i < s->n_models; i++) free(s->models[i].name), mesh_free(s->models[i].mesh);
    free(s->materials);
    name_index_free(&s->material_names);
    free(s->textures);
    free(s->species);
    free(s->prototypes);
    free(s->instances);
    free(s->objects);
    free(s->models);
    free((char *)s->site.crs_wkt), free((char *)s->site.crs_name);
    free(s);
}

int scene_set_site(scene *s, const site_settings *site, err_buf *err)
{
    free((char *)s->site.crs_wkt), free((char *)s->site.crs_name);
    s->site = *site;
    s->site.crs_wkt = site->crs_wkt ? strdup(site->crs_wkt) : NULL;
    s->site.crs_name = site->crs_name ? strdup(site->crs_name) : NULL;
    if ((site->crs_wkt && !s->site.crs_wkt) || (site->crs_name && !s->site.crs_name))
        return err_nomem(err, "out of memory copying the site's CRS");
    return 0;
}

int32_t scene_add_material(scene *s, const sylva_material_desc *d, err_buf *err)
{
    if (grow((void **)&s->materials, &s->cap_materials, s->n_materials + 1, sizeof(material)))
        return err_nomem(err, "out of memory adding a material");
    char *name = strdup(d->name ? d->name : "unnamed");
    if (!name || name_index_add(&s->material_names, name, s->n_materials) < 0) {
        free(name);
        return err_nomem(err, "out of memory adding a material");
    }
    material *m = &s->materials[s->n_materials];
    *m = (material){.name = name, .bsdf = d->bsdf == SYLVA_BSDF_LEAF ? SYLVA_BSDF_LEAF : SYLVA_BSDF_LAMBERT,
                    .albedo = v3(d->albedo[0], d->albedo[1], d->albedo[2]),
                    .transmittance = v3(d->transmittance[0], d->transmittance[1], d->transmittance[2]),
                    .texture = d->texture, .alpha_mask = d->alpha_mask};
    if (m->texture < 0 || (uint32_t)m->texture >= s->n_textures) m->texture = -1, m->alpha_mask = 0;
    return (int32_t)s->n_materials++;
}

int32_t scene_add_texture(scene *s, const char *name, uint32_t w, uint32_t h, const uint8_t *rgba,
                          err_buf *err)
{
    if (!w || !h || w > 16384 || h > 16384)
        return err_set(err, "texture '%s' is %ux%u; sizes from 1 to 16384 are valid", name, w, h);
    if (grow((void **)&s->textures, &s->cap_textures, s->n_textures + 1, sizeof(texture)))
        return err_nomem(err, "out of memory adding texture '%s'", name);
    size_t n = (size_t)w * h * 4;
    uint8_t *copy = malloc(n);
    char *nm = strdup(name ? name : "texture");
    if (!copy || !nm) {
        free(copy), free(nm);
        return err_nomem(err, "out of memory adding texture '%s'", name);
    }
    memcpy(copy, rgba, n);
    int alpha = 0;
    for (size_t i = 3; i < n; i += 4) alpha |= copy[i] < 255;
    s->textures[s->n_textures] = (texture){.name = nm, .width = w, .height = h, .rgba = copy, .has_alpha = alpha};
    return (int32_t)s->n_textures++;
}

int32_t scene_add_species(scene *s, const char *name, err_buf *err)
{
    species *grown = realloc(s->species, (s->n_species + 1) * sizeof *grown);
    if (!grown) return err_nomem(err, "out of memory adding species '%s'", name);
    s->species = grown;
    char *nm = strdup(name);
    if (!nm) return err_nomem(err, "out of memory adding species '%s'", name);
    s->species[s->n_species] = (species){.name = nm, .first_prototype = s->n_prototypes};
    return (int32_t)s->n_species++;
}

int32_t scene_add_prototype(scene *s, uint32_t sp, uint32_t variant, double age, double height,
                            mesh *m, err_buf *err)
{
    if (grow((void **)&s->prototypes, &s->cap_prototypes, s->n_prototypes + 1, sizeof(prototype))) {
        mesh_free(m);
        return err_nomem(err, "out of memory adding a prototype");
    }
    s->prototypes[s->n_prototypes] =
        (prototype){.species = sp, .variant = variant, .age = age, .height = height, .mesh = m};
    return (int32_t)s->n_prototypes++;
}

int32_t scene_add_instance(scene *s, uint32_t proto, const xform3x4 *xf, err_buf *err)
{
    if (s->n_instances >= 100000000u)
        return err_set(err, "more than 100000000 instances (the scene limit)");
    if (grow((void **)&s->instances, &s->cap_instances, s->n_instances + 1, sizeof(instance)))
        return err_nomem(err, "out of memory adding instance %u", s->n_instances);
    s->instances[s->n_instances] = (instance){.prototype = proto, .xf = *xf};
    return (int32_t)s->n_instances++;
}

/* Adds ob (its name copied); frees ob.mesh on failure. */
static int32_t add_object(scene *s, const char *name, object ob, err_buf *err)
{
    ob.name = strdup(name ? name : "object");
    if (!ob.name || grow((void **)&s->objects, &s->cap_objects, s->n_objects + 1, sizeof(object))) {
        free(ob.name);
        mesh_free(ob.mesh);
        return err_nomem(err, "out of memory adding object '%s'", name ? name : "object");
    }
    s->objects[s->n_objects] = ob;
    return (int32_t)s->n_objects++;
}

int32_t scene_add_object(scene *s, const char *name, mesh *m, err_buf *err)
{
    return add_object(s, name, (object){.mesh = m, .model = -1, .xf = xf_identity()}, err);
}

int32_t scene_add_model_object(scene *s, const char *name, uint32_t model_index, const xform3x4 *xf, err_buf *err)
{
    return add_object(s, name, (object){.mesh = NULL, .model = (int32_t)model_index, .xf = *xf}, err);
}

int32_t scene_add_model(scene *s, const char *name, mesh *m, err_buf *err)
{
    char *nm = strdup(name ? name : "model");
    if (!nm || grow((void **)&s->models, &s->cap_models, s->n_models + 1, sizeof(object_model))) {
        free(nm);
        mesh_free(m);
        return err_nomem(err, "out of memory adding model '%s'", name ? name : "model");
    }
    s->models[s->n_models] = (object_model){.name = nm, .mesh = m};
    return (int32_t)s->n_models++;
}

const mesh *scene_object_mesh(const scene *s, uint32_t o, const xform3x4 **xf)
{
    const object *ob = &s->objects[o];
    if (ob->mesh) {
        if (xf) *xf = NULL;
        return ob->mesh;
    }
    if (xf) *xf = &ob->xf;
    return s->models[ob->model].mesh;
}

void scene_object_bounds(const scene *s, uint32_t o, double lo[3], double hi[3])
{
    const xform3x4 *xf;
    const mesh *m = scene_object_mesh(s, o, &xf);
    for (uint32_t v = 0; m && v < m->nv; v++) {
        vec3 p = v3(m->pos[3 * v], m->pos[3 * v + 1], m->pos[3 * v + 2]);
        if (xf) p = xf_point(xf, p);
        double q[3] = {p.x, p.y, p.z};
        for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], q[k]), hi[k] = fmax(hi[k], q[k]);
    }
}

int32_t scene_find_material(const scene *s, const char *name)
{
    return (int32_t)name_index_find(&s->material_names, name);
}

uint32_t scene_variant_for_age(const scene *s, uint32_t sp, double t)
{
    const species *p = &s->species[sp];
    uint32_t best = p->n_variants - 1;
    for (uint32_t v = 0; v < p->n_variants; v++)
        if (s->prototypes[p->first_prototype + v].age >= t - 1e-9) {
            best = v;
            break;
        }
    return best;
}

uint32_t scene_variant_nearest_height(const scene *s, uint32_t sp, double h)
{
    const species *p = &s->species[sp];
    uint32_t best = 0;
    for (uint32_t v = 1; v < p->n_variants; v++)
        if (fabs(s->prototypes[p->first_prototype + v].height - h) <
            fabs(s->prototypes[p->first_prototype + best].height - h))
            best = v;
    return best;
}

int scene_terrain_height(const scene *s, double x, double y, double *z)
{
    return s->terrain ? heightfield_height(s->terrain, x, y, z) : -1;
}

int scene_terrain_normal(const scene *s, double x, double y, double n[3])
{
    return s->terrain ? heightfield_normal(s->terrain, x, y, n) : -1;
}

int scene_surveyed_height(const scene *s, double x, double y, double *z)
{
    return s->surveyed ? heightfield_height(s->surveyed, x, y, z) : -1;
}

int scene_surveyed_normal(const scene *s, double x, double y, double n[3])
{
    return s->surveyed ? heightfield_normal(s->surveyed, x, y, n) : -1;
}

xform3x4 plant_transform(const double p[3], double rot_deg, double scale)
{
    return xf_trs(v3((float)p[0], (float)p[1], (float)p[2]), v3(0, 0, (float)rot_deg),
                  v3((float)scale, (float)scale, (float)scale));
}
