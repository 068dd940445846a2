/* scene_build.c — running the scene file through the plugins into a scene graph. */
#include "scene/scene_build.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/image_io.h"
#include "scene/host.h"
#include "scene/shapes.h"
#include "util/rng.h"

xform3x4 plant_transform(const double p[3], double rot_deg, double scale)
{
    return xf_trs(v3((float)p[0], (float)p[1], (float)p[2]), v3(0, 0, (float)rot_deg),
                  v3((float)scale, (float)scale, (float)scale));
}

/* Loads an image file as an RGBA8 texture. */
static int32_t load_texture(scene *s, const char *path, err_buf *err)
{
    image_f32 img = {0};
    if (image_read(path, &img, err)) return -1;
    size_t n = (size_t)img.width * img.height;
    uint8_t *rgba = malloc(n * 4);
    if (!rgba) {
        image_free(&img);
        return err_set(err, "%s: out of memory for a %ux%u texture", path, img.width, img.height);
    }
    for (size_t i = 0; i < n; i++) {
        const float *px = img.pixels + i * img.channels;
        for (int c = 0; c < 4; c++) {
            float v;
            if (c < 3) v = img.channels >= 3 ? px[c] : px[0];
            else v = img.channels == 4 ? px[3] : img.channels == 2 ? px[1] : 1.0f;
            v = v < 0 ? 0 : v > 1 ? 1 : v;
            rgba[i * 4 + c] = (uint8_t)lrintf(v * 255.0f);
        }
    }
    int32_t id = scene_add_texture(s, path, img.width, img.height, rgba, err);
    free(rgba);
    image_free(&img);
    return id;
}

static int add_materials(scene *s, const scene_file *sf, err_buf *err)
{
    for (uint32_t i = 0; i < sf->n_materials; i++) {
        const material_spec *m = &sf->materials[i];
        int32_t tex = -1;
        if (m->texture_path) {
            tex = load_texture(s, m->texture_path, err);
            if (tex < 0) return err_prefix(err, "%s:%u:%u: material '%s': ", sf->path, m->line, m->column, m->name);
        }
        sylva_material_desc d = {.size = sizeof d, .name = m->name, .bsdf = m->bsdf, .texture = tex,
                                 .alpha_mask = m->alpha_mask};
        for (int k = 0; k < 3; k++) d.albedo[k] = (float)m->albedo[k], d.transmittance[k] = (float)m->transmittance[k];
        if (scene_add_material(s, &d, err) < 0) return -1;
    }
    /* Built-in defaults for terrain and water unless the scene defines them by name. */
    if (scene_find_material(s, "ground") < 0) {
        sylva_material_desc g = {.size = sizeof g, .name = "ground", .bsdf = SYLVA_BSDF_LAMBERT,
                                 .albedo = {0.16f, 0.20f, 0.09f}, .texture = -1};
        if (scene_add_material(s, &g, err) < 0) return -1;
    }
    if (scene_find_material(s, "water") < 0) {
        sylva_material_desc w = {.size = sizeof w, .name = "water", .bsdf = SYLVA_BSDF_LAMBERT,
                                 .albedo = {0.02f, 0.05f, 0.08f}, .texture = -1};
        if (scene_add_material(s, &w, err) < 0) return -1;
    }
    s->terrain_material = scene_find_material(s, "ground");
    s->water_material = scene_find_material(s, "water");
    return 0;
}

/* Reports a plugin's failure, located in the scene file: a sentence from param_error already
 * starts with the parameter's file:line:column and gets the plugin named after it; any other
 * sentence is placed at the plugin's block. */
static int plugin_failed(err_buf *err, const sylva_host *h, const loaded_plugin *lp, const char *op, int rc,
                         const char *path, uint32_t line, uint32_t column)
{
    if (!h->error_set) err_set(err, "returned status %d from %s without saying why", rc, op);
    size_t n = strlen(path);
    if (!strncmp(err->msg, path, n) && err->msg[n] == ':') {
        char msg[ERR_MSG_MAX];
        snprintf(msg, sizeof msg, "%s", err->msg);
        return err_set(err, "%s (%s: %s failed; %s)", msg, h->context, op, lp->file);
    }
    return err_prefix(err, "%s:%u:%u: %s: %s failed (%s): ", path, line, column, h->context, op, lp->file);
}

static int build_terrain(scene *s, const scene_file *sf, const plugin_registry *reg,
                         const build_options *opt, err_buf *err)
{
    const terrain_spec *t = &sf->terrain;
    if (t->material) s->terrain_material = scene_find_material(s, t->material);
    if (t->source == TERRAIN_NONE) return 0;
    if (t->source == TERRAIN_GRID) {
        sylva_host h;
        host_init(&h, s, sf->dir, 0, "terrain", err);
        sylva_heightfield *hf = host_api_table()->heightfield_new(&h, t->nx, t->ny, 0);
        host_release(&h);
        if (!hf) return err_prefix(err, "%s:%u:%u: terrain grid: ", sf->path, t->line, t->column);
        hf->x0 = t->origin[0], hf->y0 = t->origin[1], hf->dx = t->spacing[0], hf->dy = t->spacing[1];
        for (size_t i = 0; i < (size_t)t->nx * t->ny; i++) hf->z[i] = (float)t->grid[i];
        return 0;
    }
    err_buf lookup = {{0}};
    const loaded_plugin *lp = reg ? plugin_registry_find(reg, t->plugin, SYLVA_KIND_TERRAIN, &lookup) : NULL;
    if (!lp) return err_set(err, "%s:%u:%u: %s", sf->path, t->line, t->column, reg ? lookup.msg : "no plugins were loaded");
    char context[160];
    snprintf(context, sizeof context, "terrain plugin '%s'", t->plugin);
    sylva_host h;
    host_init(&h, s, sf->dir, rng_combine(sf->image.seed, rng_hash_str("terrain")), context, err);
    h.verbose = opt->verbose, h.quiet = opt->quiet, h.kind = SYLVA_KIND_TERRAIN;
    const sylva_host_api *api = host_api_table();
    void *state = NULL;
    int rc = lp->desc->create(api, &h, t->params, &state);
    if (rc) {
        plugin_failed(err, &h, lp, "create", rc, sf->path, t->line, t->column);
        host_release(&h);
        return -1;
    }
    sylva_terrain_request req = {.size = sizeof req, .seed = h.seed};
    sylva_terrain_out out = {.size = sizeof out};
    rc = lp->desc->generate(state, api, &h, &req, &out);
    lp->desc->destroy(state);
    if (!rc && (!out.terrain || out.terrain != s->terrain)) {
        h.error_set = 0;
        rc = SYLVA_ERR_INTERNAL;
        err_set(err, "gave no heightfield made with heightfield_new");
        h.error_set = 1;
    }
    if (!rc && !(s->terrain->dx > 0 && s->terrain->dy > 0 && isfinite(s->terrain->x0) && isfinite(s->terrain->y0))) {
        rc = SYLVA_ERR_INTERNAL;
        err_set(err, "gave a heightfield with spacing %g x %g; spacing must be positive", s->terrain->dx, s->terrain->dy);
        h.error_set = 1;
    }
    if (rc) {
        plugin_failed(err, &h, lp, "generate", rc, sf->path, t->line, t->column);
        host_release(&h);
        return -1;
    }
    host_release(&h);
    for (size_t i = 0; i < (size_t)s->terrain->nx * s->terrain->ny; i++)
        if (!isfinite(s->terrain->z[i]))
            return err_set(err, "%s (%s): generate gave a non-finite height at node %zu", context, lp->file, i);
    return 0;
}

static int build_species(scene *s, const scene_file *sf, const plugin_registry *reg,
                         const build_options *opt, err_buf *err)
{
    s->species = calloc(sf->n_species ? sf->n_species : 1, sizeof(species));
    if (!s->species) return err_set(err, "out of memory for %u species", sf->n_species);
    const sylva_host_api *api = host_api_table();
    for (uint32_t i = 0; i < sf->n_species; i++) {
        const species_spec *sp = &sf->species[i];
        species *dst = &s->species[s->n_species++];
        dst->name = strdup(sp->name);
        if (!dst->name) return err_set(err, "out of memory");
        dst->first_prototype = s->n_prototypes;
        if (!sp->plugin) {
            int32_t mat = sp->material ? scene_find_material(s, sp->material) : s->default_material;
            mesh *m = mesh_new();
            if (!m) return err_set(err, "out of memory");
            if (shape_build(&sp->shape, mat, m, err)) {
                mesh_free(m);
                return err_prefix(err, "%s:%u:%u: species '%s': ", sf->path, sp->line, sp->column, sp->name);
            }
            float lo[3], hi[3];
            mesh_bounds(m, lo, hi);
            if (scene_add_prototype(s, i, 0, 1.0, hi[2] - lo[2], m, err) < 0) return -1;
            dst->n_variants = 1;
            continue;
        }
        err_buf lookup = {{0}};
        const loaded_plugin *lp = reg ? plugin_registry_find(reg, sp->plugin, SYLVA_KIND_TREE, &lookup) : NULL;
        if (!lp)
            return err_set(err, "%s:%u:%u: %s", sf->path, sp->line, sp->column, reg ? lookup.msg : "no plugins were loaded");
        char context[200];
        snprintf(context, sizeof context, "tree plugin '%s' for species '%s'", sp->plugin, sp->name);
        sylva_host h;
        host_init(&h, s, sf->dir, scene_species_seed(sf, sp->name, 0), context, err);
        h.verbose = opt->verbose, h.quiet = opt->quiet, h.kind = SYLVA_KIND_TREE;
        void *state = NULL;
        int rc = lp->desc->create(api, &h, sp->params, &state);
        if (rc) {
            plugin_failed(err, &h, lp, "create", rc, sf->path, sp->line, sp->column);
            host_release(&h);
            return -1;
        }
        for (uint32_t v = 0; v < sp->variants; v++) {
            mesh *m = mesh_new();
            if (!m) {
                rc = SYLVA_ERR_NOMEM;
                err_set(err, "out of memory");
                h.error_set = 1;
                break;
            }
            h.seed = scene_species_seed(sf, sp->name, v);
            sylva_tree_request req = {.size = sizeof req, .age = (double)(v + 1) / sp->variants, .variant = v,
                                      .n_variants = sp->variants, .lod = 0, .seed = h.seed};
            sylva_tree_out out = {.size = sizeof out, .mesh = m};
            rc = lp->desc->generate(state, api, &h, &req, &out);
            if (!rc && !(out.height > 0 && isfinite(out.height))) {
                float lo[3], hi[3];
                mesh_bounds(m, lo, hi);
                out.height = hi[2] - lo[2];
            }
            if (rc) {
                mesh_free(m);
                break;
            }
            if (scene_add_prototype(s, i, v, req.age, out.height, m, err) < 0) {
                rc = SYLVA_ERR_NOMEM;
                h.error_set = 1;
                break;
            }
            dst->n_variants++;
        }
        lp->desc->destroy(state);
        if (rc) {
            plugin_failed(err, &h, lp, "generate", rc, sf->path, sp->line, sp->column);
            host_release(&h);
            return -1;
        }
        host_release(&h);
    }
    return 0;
}

/* Places one plant as an instance; age selects the variant. */
static int place_plant(scene *s, uint32_t sp, double pos[3], int snap, double rot_deg, double scale,
                       double age, err_buf *err)
{
    if (snap) {
        double z = 0;
        if (!scene_terrain_height(s, pos[0], pos[1], &z)) pos[2] = z;
        else if (s->terrain) return err_set(err, "position (%g, %g) lies outside the terrain", pos[0], pos[1]);
        else pos[2] = 0;
    }
    uint32_t proto = s->species[sp].first_prototype + scene_variant_for_age(s, sp, age);
    xform3x4 xf = plant_transform(pos, rot_deg, scale);
    return scene_add_instance(s, proto, &xf, err) < 0 ? -1 : 0;
}

static int build_plants(scene *s, const scene_file *sf, err_buf *err)
{
    for (uint32_t i = 0; i < sf->n_plants; i++) {
        const plant_spec *p = &sf->plants[i];
        double pos[3] = {p->position[0], p->position[1], p->position[2]};
        if (place_plant(s, p->species, pos, p->snap_to_terrain, p->rotation_deg, p->scale, p->age, err))
            return err_prefix(err, "%s:%u:%u: plant %u: ", sf->path, p->line, p->column, i);
    }
    return 0;
}

uint64_t scene_species_seed(const scene_file *sf, const char *name, uint32_t variant)
{
    return rng_combine(rng_combine(sf->image.seed, rng_hash_str(name)), variant);
}

uint64_t scene_ecology_seed(const scene_file *sf) { return rng_combine(sf->image.seed, rng_hash_str("ecology")); }

sylva_species_info *scene_ecology_species(const scene *s, const scene_file *sf, err_buf *err)
{
    sylva_species_info *info = calloc(sf->n_species ? sf->n_species : 1, sizeof *info);
    if (!info) {
        err_set(err, "out of memory for %u species", sf->n_species);
        return NULL;
    }
    for (uint32_t i = 0; i < sf->n_species && i < s->n_species; i++) {
        const species *sp = &s->species[i];
        double h = sp->n_variants ? s->prototypes[sp->first_prototype + sp->n_variants - 1].height : 0;
        info[i] = (sylva_species_info){.size = sizeof *info, .name = sp->name, .ecology = sf->species[i].ecology,
                                       .model_height = h};
    }
    return info;
}

int scene_place_plants(scene *s, const sylva_plant *plants, uint32_t n, err_buf *err)
{
    for (uint32_t i = 0; i < n; i++) {
        const sylva_plant *p = &plants[i];
        if (p->species >= s->n_species || !s->species[p->species].n_variants)
            return err_set(err, "plant %u: species %u has no model (%u species)", i, p->species, s->n_species);
        if (!(isfinite(p->position[0]) && isfinite(p->position[1]) && isfinite(p->position[2]) &&
              isfinite(p->rotation) && isfinite(p->height) && p->age > 0 && p->age <= 1))
            return err_set(err, "plant %u: position (%g, %g, %g), rotation %g, height %g and age %g must be finite "
                           "numbers, the age in (0, 1]", i, p->position[0], p->position[1], p->position[2],
                           p->rotation, p->height, p->age);
        /* The variant by normalised age (the tree plugin built each variant for its age); the
         * model scaled from that variant's height to the plant's; a turn about the vertical. */
        const species *sp = &s->species[p->species];
        uint32_t v = scene_variant_for_age(s, p->species, p->age);
        double ph = s->prototypes[sp->first_prototype + v].height;
        double scale = p->height > 0 && ph > 0 ? p->height / ph : 1.0;
        double pos[3] = {p->position[0], p->position[1], p->position[2]};
        if (place_plant(s, p->species, pos, p->snap_to_terrain, p->rotation * 180.0 / M_PI, scale, p->age, err))
            return err_prefix(err, "plant %u: ", i);
    }
    return 0;
}

static int build_ecology(scene *s, const scene_file *sf, const plugin_registry *reg, const build_options *opt,
                         err_buf *err)
{
    const ecology_spec *e = &sf->ecology;
    if (!e->plugin || opt->no_ecology) return 0;
    if (!s->terrain) return err_set(err, "%s:%u:%u: the ecology needs a terrain", sf->path, e->line, e->column);
    err_buf lookup = {{0}};
    const loaded_plugin *lp = reg ? plugin_registry_find(reg, e->plugin, SYLVA_KIND_ECOLOGY, &lookup) : NULL;
    if (!lp) return err_set(err, "%s:%u:%u: %s", sf->path, e->line, e->column, reg ? lookup.msg : "no plugins were loaded");
    sylva_species_info *info = scene_ecology_species(s, sf, err);
    if (!info) return -1;
    char context[160];
    snprintf(context, sizeof context, "ecology plugin '%s'", e->plugin);
    sylva_host h;
    host_init(&h, s, sf->dir, scene_ecology_seed(sf), context, err);
    h.verbose = opt->verbose, h.quiet = opt->quiet, h.n_species = sf->n_species, h.kind = SYLVA_KIND_ECOLOGY;
    const sylva_host_api *api = host_api_table();
    void *state = NULL;
    int rc = lp->desc->create(api, &h, e->params, &state);
    if (rc) {
        plugin_failed(err, &h, lp, "create", rc, sf->path, e->line, e->column);
        goto done;
    }
    sylva_ecology_request req = {.size = sizeof req, .seed = h.seed, .terrain = s->terrain, .species = info,
                                 .n_species = sf->n_species};
    sylva_ecology_out out = {.size = sizeof out};
    rc = lp->desc->generate(state, api, &h, &req, &out);
    lp->desc->destroy(state);
    if (rc) {
        plugin_failed(err, &h, lp, "generate", rc, sf->path, e->line, e->column);
        goto done;
    }
    if (scene_place_plants(s, h.plants, h.n_plants, err)) {
        err_prefix(err, "%s (%s): ", context, lp->file);
        rc = -1;
    }
done:
    host_release(&h);
    free(info);
    return rc ? -1 : 0;
}

static int build_objects(scene *s, const scene_file *sf, err_buf *err)
{
    for (uint32_t i = 0; i < sf->n_objects; i++) {
        const object_spec *o = &sf->objects[i];
        int32_t mat = o->material ? scene_find_material(s, o->material) : s->default_material;
        mesh *m = mesh_new();
        if (!m) return err_set(err, "out of memory");
        if (shape_build(&o->shape, mat, m, err)) {
            mesh_free(m);
            return err_prefix(err, "%s:%u:%u: object '%s': ", sf->path, o->line, o->column, o->name ? o->name : "");
        }
        xform3x4 xf = xf_trs(v3((float)o->position[0], (float)o->position[1], (float)o->position[2]),
                             v3((float)o->rotation_deg[0], (float)o->rotation_deg[1], (float)o->rotation_deg[2]),
                             v3((float)o->scale[0], (float)o->scale[1], (float)o->scale[2]));
        for (uint32_t v = 0; v < m->nv; v++) {
            vec3 p = xf_point(&xf, v3(m->pos[v * 3], m->pos[v * 3 + 1], m->pos[v * 3 + 2]));
            vec3 n = v3_norm(xf_normal(&xf, v3(m->nrm[v * 3], m->nrm[v * 3 + 1], m->nrm[v * 3 + 2])));
            m->pos[v * 3] = p.x, m->pos[v * 3 + 1] = p.y, m->pos[v * 3 + 2] = p.z;
            m->nrm[v * 3] = n.x, m->nrm[v * 3 + 1] = n.y, m->nrm[v * 3 + 2] = n.z;
        }
        if (scene_add_object(s, o->name, m, err) < 0) return -1;
    }
    return 0;
}

scene *scene_build(const scene_file *sf, const plugin_registry *plugins, const build_options *opt, err_buf *err)
{
    build_options defaults = {0};
    if (!opt) opt = &defaults;
    scene *s = scene_new();
    if (!s) {
        err_set(err, "out of memory creating the scene");
        return NULL;
    }
    s->image = sf->image, s->camera = sf->camera, s->sun = sf->sun, s->sky = sf->sky;
    if (add_materials(s, sf, err) || build_terrain(s, sf, plugins, opt, err) ||
        build_species(s, sf, plugins, opt, err) || build_plants(s, sf, err) ||
        build_ecology(s, sf, plugins, opt, err) || build_objects(s, sf, err)) {
        scene_free(s);
        return NULL;
    }
    return s;
}
