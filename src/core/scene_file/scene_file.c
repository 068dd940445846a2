/* scene_file.c — reading a scene file into a scene_file: sections, cross-references, includes.
 *
 * The YAML tree (yaml_doc) is checked section by section against the host's schemas
 * (host_schema) and each plugin block against its plugin's schema (plugin_registry_find); keys
 * of a mapping that two schemas share (a species' host keys and its tree plugin's keys, an
 * object's keys and its shape's keys) are validated in two passes, each skipping the other's
 * keys. Rules between keys (look_at or direction, grid or plugin, material names, species
 * names) are checked here, each at the location of the key that breaks them. No plugin code
 * beyond the registry's descriptor lookup runs.
 *
 * Sections are read in a fixed order: image, site, camera, sun, sky, materials, ecology,
 * terrain, species (with includes), plants, trees, planting, groups, objects, earth, then ztv, ground cover,
 * snow, season, photo, landcover, canopy and study — the site before every position, materials
 * before their users, the ecology before the species blocks it defines, species before plants,
 * the earth after the site (its default follows it), the study after the viewpoints and the
 * objects (a point of its points file faces the development).
 */
#include "scene_file/scene_file_loader.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "scene_file/scene_estimate.h"
#include "scene_file/scene_file.h"

int scene_file_material_index(const scene_file *sf, const char *name)
{
    return sf ? (int)name_index_find(&sf->material_names, name) : -1;
}

int scene_file_species_index(const scene_file *sf, const char *name)
{
    if (!sf) return -1;
    int64_t i = name_index_find(&sf->species_names, name);
    return i < sf->n_species ? (int)i : -1; /* while loading, entries not yet read are no species */
}

static int check_sections(loader *L)
{
    uint32_t n = 0;
    while (host_sections[n]) n++;
    for (uint32_t i = 0; i < L->root->n_pairs; i++) {
        const ynode_pair *pr = &L->root->pairs[i];
        uint32_t k = 0;
        while (k < n && strcmp(host_sections[k], pr->key)) k++;
        if (k < n) continue;
        const char *near = param_nearest_name(pr->key, host_sections, n);
        if (near)
            return sf_located(L->err, L->file, pr->key_line, pr->key_column,
                              "unknown section '%s'; did you mean '%s'?", pr->key, near);
        char list[512];
        sf_name_list(host_sections, n, list, sizeof list);
        return sf_located(L->err, L->file, pr->key_line, pr->key_column,
                          "unknown section '%s'; sections are %s", pr->key, list);
    }
    return 0;
}

static int load(loader *L, const char *path)
{
    scene_file *sf = L->sf;
    char *real = realpath(path, NULL); /* malloc'ed; copied and freed here */
    if (!real) return err_set(L->err, "%s: cannot open: %s", path, strerror(errno));
    const char *canon = arena_strdup(L->a, real);
    free(real);
    if (!canon || !(sf->dir = sf_folder_of(L->a, canon))) return sf_out_of_memory(L);
    L->dir = sf->dir;

    yaml_doc doc;
    if (yaml_doc_load(L->a, path, path, &doc, L->err)) return -1;
    L->file = doc.file;
    if (!doc.root)
        return sf_located(L->err, L->file, 1, 1,
                          "the scene file is empty; it needs at least a 'camera:' section with a "
                          "'position'");
    if (doc.root->kind != YNODE_MAPPING)
        return sf_located(L->err, L->file, doc.root->line, doc.root->column,
                          "a scene file must be a mapping of sections (image:, camera:, terrain:, "
                          "...), got %s", ynode_kind_phrase(doc.root));
    L->root = doc.root;
    L->chain[0] = (included_file){canon, L->file, 0, 0, NULL};
    L->chain_len = 1;

    if (check_sections(L) || sf_read_image(L) || sf_read_site(L) || sf_read_camera(L) || sf_read_sun(L) ||
        sf_read_sky(L) ||
        sf_read_materials(L, ynode_get(L->root, "materials")))
        return -1;
    const ynode_pair *eco = ynode_get_pair(L->root, "ecology");
    const ynode_pair *ter = ynode_get_pair(L->root, "terrain");
    if (sf_read_ecology(L, eco ? eco->value : NULL, eco ? eco->key_line : 0,
                        eco ? eco->key_column : 0) ||
        sf_read_terrain(L, ter ? ter->value : NULL, ter ? ter->key_line : 0,
                        ter ? ter->key_column : 0) ||
        sf_read_species(L, ynode_get(L->root, "species")) ||
        sf_read_plants(L, ynode_get(L->root, "plants")) ||
        sf_read_trees(L, ynode_get_pair(L->root, "trees")) ||
        sf_read_planting(L, ynode_get_pair(L->root, "planting")) ||
        sf_read_groups(L, ynode_get(L->root, "groups")) ||
        sf_read_objects(L, ynode_get(L->root, "objects")) || sf_read_earth(L) || sf_read_ztv(L) ||
        sf_read_ground_cover(L) || sf_read_snow(L) || sf_read_season(L) ||
        sf_read_photo(L) || sf_read_landcover(L) || sf_read_canopy(L) || sf_read_study(L))
        return -1;
    if (scene_estimate_check(L->sf, L->err)) return -1; /* before any mesh is built */
    if (L->sf->ecology.plugin && L->sf->terrain.source == TERRAIN_NONE)
        return sf_located(L->err, L->file, L->sf->ecology.line, L->sf->ecology.column,
                          "the ecology plugin '%s' places plants on the terrain, but the scene has no "
                          "'terrain:' section; add one (grid: ... or plugin: ...)", L->sf->ecology.plugin);
    return 0;
}

scene_file *scene_file_load(const char *path, const struct plugin_registry *plugins, err_buf *err)
{
    return scene_file_load_with(path, plugins, 0, err);
}

scene_file *scene_file_load_with(const char *path, const struct plugin_registry *plugins, unsigned flags,
                                 err_buf *err)
{
    err_clear(err);
    if (!path || !path[0]) {
        err_set(err, "no scene file was named");
        return NULL;
    }
    arena *a = arena_new();
    scene_file *sf = a ? arena_alloc(a, sizeof *sf) : NULL;
    if (!sf || !(sf->path = arena_strdup(a, path))) {
        arena_free(a);
        err_nomem(err, "%s: out of memory while loading", path);
        return NULL;
    }
    sf->arena = a;
    loader L = {.a = a, .reg = plugins, .err = err, .sf = sf, .file = path, .flags = flags};
    int rc = load(&L, path);
    site_frame_free(L.site);
    if (!rc && L.n_seen && !(sf->includes = arena_alloc(a, (size_t)L.n_seen * sizeof *sf->includes)))
        rc = sf_out_of_memory(&L);
    for (uint32_t i = 0; !rc && i < L.n_seen; i++) sf->includes[sf->n_includes++] = L.seen[i].real;
    if (!rc) rc = sf_digest(&L);
    if (rc) {
        scene_file_free(sf);
        return NULL;
    }
    return sf;
}

void scene_file_free(scene_file *sf)
{
    if (!sf) return;
    name_index_free(&sf->material_names);
    name_index_free(&sf->species_names);
    arena_free(sf->arena); /* sf itself lives in its arena */
}
