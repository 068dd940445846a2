/* scene_build.c — running the scene file through the plugins into a scene graph. */
#include "scene_build/scene_build.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/image_io.h"
#include "scene_build/ecology_session.h"
#include "scene_build/planting_ecology.h"
#include "site/ground_departure.h"
#include "scene_build/host.h"
#include "scene_build/plugin_call.h"
#include "scene_build/scene_ground.h"
#include "scene_build/scene_communities.h"
#include "scene_build/scene_canopy.h"
#include "scene_build/scene_landcover.h"
#include "season/scene_season.h"
#include "season/scene_spring.h"
#include "scene_build/scene_tree_variants.h"
#include "scene_build/scene_planting.h"
#include "scene_build/scene_trees.h"
#include "scene_build/shapes.h"
#include "site/terrain_extent.h"
#include "scene_build/terrain_site.h"

/* Loads an image file as an RGBA8 texture. */
static int32_t load_texture(scene *s, const char *path, err_buf *err)
{
    image_f32 img = {0};
    if (image_read(path, &img, err)) return -1;
    size_t n = (size_t)img.width * img.height;
    uint8_t *rgba = malloc(n * 4);
    if (!rgba) {
        image_free(&img);
        return err_nomem(err, "%s: out of memory for a %ux%u texture", path, img.width, img.height);
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
            if (tex < 0) {
                err_prefix(err, "material '%s': ", m->name);
                return err_locate(err, sf->path, m->line, m->column);
            }
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

/* The terrain: an inline grid is both grounds; a plugin gives the ground as surveyed, then
 * (unless the scene is for an analysis) the ground to render, refined for the camera. */
static int build_terrain(scene *s, const scene_file *sf, const plugin_registry *reg, const build_options *opt,
                         const plugin_call_output *out, err_buf *err)
{
    const terrain_spec *t = &sf->terrain;
    if (t->material) s->terrain_material = scene_find_material(s, t->material);
    if (t->source == TERRAIN_NONE) return 0;
    if (t->source == TERRAIN_GRID) {
        sylva_host h;
        host_init(&h, s, sf->dir, 0, "terrain", err);
        sylva_heightfield *hf = host_api_table()->heightfield_new(&h, t->nx, t->ny, 0);
        host_release(&h);
        if (!hf) {
            err_prefix(err, "terrain grid: ");
            return err_locate(err, sf->path, t->line, t->column);
        }
        hf->x0 = t->origin[0], hf->y0 = t->origin[1], hf->dx = t->spacing[0], hf->dy = t->spacing[1];
        for (size_t i = 0; i < (size_t)t->nx * t->ny; i++) hf->z[i] = (float)t->grid[i];
        s->surveyed = hf;
        return 0;
    }
    plugin_call c;
    if (plugin_call_open_terrain(&c, sf, s, reg, out, err)) return -1;
    int rc;
    if (plugin_call_knows_surveyed(&c)) {
        rc = plugin_call_terrain(&c, 1, 0, err);
        if (!rc && !opt->analysis && !c.renders_as_is) rc = plugin_call_terrain(&c, 0, opt->detail_at_development, err);
        if (!rc && (opt->analysis || c.renders_as_is)) s->terrain = s->surveyed;
    } else {
        rc = plugin_call_terrain(&c, 0, opt->detail_at_development, err);
        if (!rc) {
            s->surveyed = s->terrain;
            if (!opt->quiet)
                fprintf(stderr, "sylva: %s:%u:%u: terrain plugin '%s' was built for plugin ABI %u.%u and cannot "
                        "give the ground as surveyed; the analyses read the ground it renders\n", sf->path,
                        t->line, t->column, t->plugin, c.plugin->desc->abi_major, c.plugin->desc->abi_minor);
        }
    }
    plugin_call_close(&c);
    return rc;
}

mesh *scene_shape_mesh(const scene *s, const shape_spec *shape, const char *material_name, const char *file,
                       uint32_t line, uint32_t column, const char *kind, const char *name, err_buf *err)
{
    int32_t mat = material_name ? scene_find_material(s, material_name) : s->default_material;
    mesh *m = mesh_new();
    if (!m) err_nomem(err, "out of memory");
    if (m && shape_build(shape, mat, m, err)) {
        mesh_free(m);
        m = NULL;
    }
    if (!m) {
        err_prefix(err, "%s '%s': ", kind, name ? name : "");
        err_locate(err, file, line, column);
    }
    return m;
}

/* A species' prototype from its built-in shape. */
static int build_shape_species(scene *s, const scene_file *sf, uint32_t i, err_buf *err)
{
    const species_spec *sp = &sf->species[i];
    mesh *m = scene_shape_mesh(s, &sp->shape, sp->material, sf->path, sp->line, sp->column, "species", sp->name, err);
    if (!m) return -1;
    float lo[3], hi[3];
    mesh_bounds(m, lo, hi);
    if (scene_add_prototype(s, i, 0, 1.0, hi[2] - lo[2], m, err) < 0) return -1;
    s->species[i].n_variants = 1;
    return 0;
}

/* A species' age variants from its tree plugin, one prototype each. */
static int build_plugin_species(scene *s, const scene_file *sf, uint32_t i, const plugin_registry *reg,
                                const plugin_call_output *out, err_buf *err)
{
    const species_spec *sp = &sf->species[i];
    phase_mark t0 = phase_start();
    plugin_call c;
    if (plugin_call_open_tree(&c, sf, sp, s, reg, out, err)) return -1;
    int rc = tree_variants_build(&c, s, i, sp->variants, out->threads, err);
    plugin_call_close(&c);
    phase_stop(out->times, PHASE_TREES, t0);
    if (rc && !err_has_place(err)) {
        err_prefix(err, "species '%s': ", sp->name);
        err_locate(err, sf->path, sp->line, sp->column);
    }
    return rc;
}

static int build_species(scene *s, const scene_file *sf, const plugin_registry *reg,
                         const plugin_call_output *out, err_buf *err)
{
    s->species = calloc(sf->n_species ? sf->n_species : 1, sizeof(species));
    if (!s->species) return err_nomem(err, "out of memory for %u species", sf->n_species);
    for (uint32_t i = 0; i < sf->n_species; i++) {
        const species_spec *sp = &sf->species[i];
        species *dst = &s->species[s->n_species++];
        dst->name = strdup(sp->name);
        if (!dst->name) return err_nomem(err, "out of memory");
        dst->first_prototype = s->n_prototypes;
        if (sp->plugin ? build_plugin_species(s, sf, i, reg, out, err) : build_shape_species(s, sf, i, err)) return -1;
    }
    return 0;
}

/* Places one plant as an instance; age selects the variant. With snap, the plant stands
 * `above` metres above the terrain. */
static int place_plant(scene *s, uint32_t sp, double pos[3], int snap, double above, double rot_deg,
                       double scale, double age, err_buf *err)
{
    if (snap) {
        double z = 0;
        if (!scene_terrain_height(s, pos[0], pos[1], &z)) pos[2] = z + above;
        else if (s->terrain) {
            char where[512];
            terrain_extent_text(s, pos[0], pos[1], where, sizeof where);
            return err_set(err, "position (%g, %g) lies outside the terrain%s", pos[0], pos[1], where);
        }
        else pos[2] = above;
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
        if (place_plant(s, p->species, pos, p->snap_to_terrain, p->above_ground, p->rotation_deg, p->scale,
                        p->age, err)) {
            err_prefix(err, "plant %u: ", i);
            return err_locate(err, sf->path, p->line, p->column);
        }
        s->instances[s->n_instances - 1].development = p->development;
    }
    return 0;
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
        if (place_plant(s, p->species, pos, p->snap_to_terrain, 0.0, p->rotation * 180.0 / M_PI, scale, p->age,
                        err))
            return err_prefix(err, "plant %u: ", i);
    }
    return 0;
}

/* The years a planting plan shown with `age_existing: true` grows the scene's ecology on by;
 * 0 when it does not. */
static uint32_t ecology_years_on(const scene_file *sf, const build_options *opt)
{
    if (!opt->planting_shown || !sf->planting.n_features || !sf->planting.age_existing) return 0;
    return opt->planting_years > 0 ? (uint32_t)fmin(floor(opt->planting_years), 100000) : 0;
}

/* The ecology run through a session and its plants placed as generate() would place them: the
 * saved run of plants: {file: F} (no year simulated), or a run of the scene's years; either
 * then stepped `more` years further (a planting plan's years, age_existing). With `kept`, the
 * session is handed to the caller (*kept, to free) for the planting plan's plants. */
static int place_session_run(scene *s, const scene_file *sf, const plugin_registry *reg, const build_options *opt,
                             uint32_t more, ecology_session **kept, err_buf *err)
{
    ecology_session *e = ecology_session_open(sf, s, reg, opt, err); /* owned here */
    if (!e) return -1;
    uint32_t placed = 0;
    err_buf load = {{0}};
    int rc = 0;
    if (sf->plants_file && (rc = ecology_session_load(e, sf->plants_file, &load))) /* the plants: key's fault */
        err_at(err, load.status, sf->path, sf->plants_file_line, sf->plants_file_column, "%s", err_sentence(&load));
    uint32_t from = sf->plants_file ? ecology_session_year(e) : 0;
    uint32_t steps = (sf->plants_file ? 0 : ecology_session_years_wanted(e)) + more;
    if (!rc && steps) rc = ecology_session_step(e, steps, err);
    if (!rc) rc = ecology_session_place(e, &placed, err);
    if (!rc && !opt->quiet && sf->plants_file) {
        uint32_t wanted = ecology_session_years_wanted(e);
        fprintf(stderr, "plants: %u from the ecology run saved in %s (year %u%s), not simulated again", placed,
                sf->plants_file, from, from == wanted ? "" : ", not the scene's years");
        if (more) fprintf(stderr, " but grown on %u years with the planting plan's (to year %u)", more, from + more);
        fprintf(stderr, "\n");
    } else if (!rc && !opt->quiet && more) {
        fprintf(stderr, "ecology: %u plants after %u years, the scene's %u and the planting plan's %u "
                "('age_existing: true')\n", placed, steps, steps - more, more);
    }
    if (!rc) rc = scene_place_plants(s, e->call.host.plants, e->call.host.n_plants, err);
    if (!rc && kept) *kept = e;
    else ecology_session_free(e);
    return rc;
}

/* The scene's ecology placed: by generate(), or through a session when a saved run, the plan's
 * age_existing or the plan's own plants (planting_ecology_wanted) need one; that session is
 * kept (*kept, the caller frees) for the plan, whose plants it then grows on the same terrain
 * factors. */
static int build_ecology(scene *s, const scene_file *sf, const plugin_registry *reg, const build_options *opt,
                         const plugin_call_output *out, ecology_session **kept, err_buf *err)
{
    if (!sf->ecology.plugin || opt->no_ecology) return 0;
    uint32_t more = ecology_years_on(sf, opt);
    int for_plan = planting_ecology_wanted(sf, opt);
    if (sf->plants_file || more || for_plan)
        return place_session_run(s, sf, reg, opt, more, for_plan ? kept : NULL, err);
    plugin_call c;
    if (plugin_call_open_ecology(&c, sf, s, reg, out, err)) return -1;
    int rc = plugin_call_ecology(&c, err);
    err_buf placing = {{0}};
    if (!rc && scene_place_plants(s, c.host.plants, c.host.n_plants, &placing))
        rc = plugin_call_refuse(&c, "generate", placing.status, err, "%s", placing.msg);
    plugin_call_close(&c);
    return rc;
}

/* The woodland: the land cover's communities placed and the ecology's plants grown, all of them
 * fitted to the canopy's heights when the scene has them. */
static int build_woodland(scene *s, const scene_file *sf, const plugin_registry *reg, const build_options *opt,
                          const plugin_call_output *out, ecology_session **kept, err_buf *err)
{
    uint32_t first = s->n_instances;
    if (scene_build_communities(s, sf, opt->quiet, err) || build_ecology(s, sf, reg, opt, out, kept, err)) return -1;
    return scene_canopy_fit_plants(s, sf, first, opt->quiet);
}

/* The season on the scene file's day, species by species (scene species i is scene-file species i;
 * ground cover and the flowers come after them): blossom first, while the leaves it grows from are
 * all there, then leaf fall and autumn colour, then spring's fresh leaves; a planting plan's young
 * plants as their species. */
static int apply_season(scene *s, const scene_file *sf, err_buf *err)
{
    const uint32_t day = sf->season.day;
    const uint32_t n = sf->n_species < s->n_species ? sf->n_species : s->n_species; /* before the petals */
    for (uint32_t i = 0; i < n; i++)
        if (scene_apply_blossom(s, i, &sf->species[i].phenology, day, sf->species[i].name, err)) return -1;
    for (uint32_t i = 0; i < sf->n_species && i < s->n_species; i++)
        if (scene_apply_season(s, i, &sf->species[i].phenology, day, err)) return -1;
    for (uint32_t i = 0; i < sf->n_species && i < s->n_species; i++)
        if (scene_apply_fresh_leaves(s, i, &sf->species[i].phenology, day, err)) return -1;
    /* a planting plan's young plants follow their species' year (they do not flower yet) */
    for (uint32_t i = sf->n_species; i < s->n_species; i++) {
        uint32_t of = scene_plant_species(s, i);
        if (of == i || of >= sf->n_species) continue;
        if (scene_apply_season(s, i, &sf->species[of].phenology, day, err) ||
            scene_apply_fresh_leaves(s, i, &sf->species[of].phenology, day, err))
            return -1;
    }
    return 0;
}

scene *scene_build(const scene_file *sf, const plugin_registry *plugins, const build_options *opt, err_buf *err)
{
    build_options defaults = {0};
    if (!opt) opt = &defaults;
    scene *s = scene_new();
    if (!s) {
        err_nomem(err, "out of memory creating the scene");
        return NULL;
    }
    s->image = sf->image, s->camera = sf->camera, s->sun = sf->sun, s->sky = sf->sky;
    s->earth = sf->earth, s->snow = sf->snow, s->season_day = sf->season.day;
    plugin_call_output out = {.verbose = opt->verbose, .quiet = opt->quiet, .warnings_only = opt->quiet,
                              .threads = opt->threads, .times = opt->times};
    ecology_session *ecology = NULL; /* owned here: the woodland's, kept for the planting plan */
    if (scene_set_site(s, &sf->site, err) || add_materials(s, sf, err) ||
        build_terrain(s, sf, plugins, opt, &out, err) || terrain_near_site(s, sf, err) ||
        scene_build_landcover(s, sf, opt->quiet, err) || scene_build_canopy(s, sf, opt->quiet, err) ||
        scene_ground_camera(s, sf, err) ||
        (!opt->no_plants &&
         (build_species(s, sf, plugins, &out, err) || build_plants(s, sf, err) || scene_build_trees(s, sf, opt, err) ||
          build_woodland(s, sf, plugins, opt, &out, &ecology, err) ||
          scene_build_planting(s, sf, plugins, ecology, opt, err))) ||
        scene_build_objects(s, sf, err) ||
        apply_season(s, sf, err)) {
        ecology_session_free(ecology);
        scene_free(s);
        return NULL;
    }
    ecology_session_free(ecology);
    if (!opt->detail_at_development) ground_departure_report(s, stderr); /* a render's camera and development */
    return s;
}
