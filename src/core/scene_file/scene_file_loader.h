/* scene_file_loader.h — the scene loader's state and what its files share; internal to the
 * scene_file*.c files (the public interface is scene_file.h). Each concern has its own file:
 *
 *   scene_file.c            the file as a whole: its sections in order, load and free, lookups
 *   scene_file_messages.c   messages at file:line:column, unknown names with suggestions
 *   scene_file_keys.c       keys two schemas share, host keys, vectors and strings
 *   scene_file_site.c       the site section: CRS and origin of the local frame
 *   scene_file_position.c   positions in local metres or map coordinates
 *   scene_file_settings.c   image, camera, sun, sky
 *   scene_file_materials.c  materials, and references to them by name
 *   scene_file_plugins.c    the plugin a block names
 *   scene_file_ecology.c    the ecology section
 *   scene_file_terrain.c    the terrain section
 *   scene_file_shapes.c     built-in shapes (of species and objects)
 *   scene_file_includes.c   gathering species across included files
 *   scene_file_species.c    each species' keys, plugin or shape, ecology block
 *   scene_file_plants.c     the plants section
 *   scene_file_trees.c      the trees section (a tree survey)
 *   scene_file_groups.c     the groups section (parts placed as one object)
 *   scene_file_objects.c    the objects section, and one object entry (also a group's part)
 *   scene_file_layout.c     a layout CSV of placements
 *   scene_file_landcover.c  the landcover section: the site's land-cover map
 *   scene_file_communities.c  the landcover section's plant communities
 *   scene_file_canopy.c     the canopy section: the site's canopy heights
 *   scene_file_study.c      the study section: what `sylva study` renders
 *   scene_file_points.c     a study's points file of viewpoints
 *   scene_file_digest.c     the digest of what every render of the scene reads
 *
 * Every function returns 0, or -1 with L->err set (a message located in the file). Everything
 * allocated lives in L->a, the scene_file's arena, except the scene_file's name indexes.
 */
#ifndef SYLVA_SCENE_FILE_LOADER_H
#define SYLVA_SCENE_FILE_LOADER_H

#include "params/validate.h"
#include "params/yaml_doc.h"
#include "plugin/plugin_host.h"
#include "scene_file/host_schema.h"
#include "scene_file/scene_file_spec.h"
#include "site/site_frame.h"
#include "util/arena.h"

#define INCLUDE_MAX_DEPTH 16

/* A species as found in the scene file or an included file, before validation. */
typedef struct species_entry {
    const char *name;
    const ynode *node;
    uint32_t line, column;  /* of the name */
    const char *file, *dir; /* the file that defines it, for messages and paths */
} species_entry;

typedef struct included_file {
    const char *real;       /* canonical path */
    const char *file;       /* as named in messages */
    uint32_t line, column;  /* where it was included (0 for the scene file itself) */
    const char *from;       /* the including file */
} included_file;

typedef struct loader {
    arena *a;
    const plugin_registry *reg;
    err_buf *err;
    scene_file *sf;
    const char *file, *dir;      /* the scene file: name in messages, absolute folder */
    const ynode *root;

    species_entry *entries;      /* entry i becomes sf->species[i]; sf->species_names indexes them */
    uint32_t n_entries, cap_entries;
    included_file chain[INCLUDE_MAX_DEPTH + 1]; /* the include chain from the scene file down */
    uint32_t chain_len;
    included_file *seen;         /* every file read so far */
    uint32_t n_seen, cap_seen;

    site_frame *site;            /* the site's CRS, or NULL without a site section; owned (freed
                                    when loading ends) */
    const sylva_plugin *ecology; /* NULL: the scene has no ecology block */
    const char *species_section; /* the ecology plugin's species_section, or "ecology" */
    unsigned flags;              /* SCENE_FILE_* of scene_file_load_with */
} loader;

/* --- messages (scene_file_messages.c) --- */
int sf_located(err_buf *err, const char *file, uint32_t line, uint32_t column, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
int sf_out_of_memory(loader *L);
/* node must be a list (a YAML sequence), as `example` shows. */
int sf_expect_list(loader *L, const ynode *node, const char *section, const char *example);
/* "a, b, c" into buf (cut when long). */
void sf_name_list(const char *const *names, uint32_t n, char *buf, size_t size);
/* v names no defined `kind` ("material", "species"; plural: "materials"). */
int sf_unknown_name(loader *L, const char *file, const sylva_value *v, const char *kind, const char *plural,
                    const char *where, const char *const *defined, uint32_t n_defined);

/* --- keys (scene_file_keys.c) --- */
const char *sf_arena_printf(arena *a, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Validates a mapping that two schemas share: `own` (host keys) and `other` (a plugin's or a
 * shape's keys), plus an optional extra key owned by neither (the species' ecology block). */
int sf_validate_shared(loader *L, const ynode *map, const param_scope *base, const sylva_param_spec *own,
                       uint32_t n_own, const sylva_param_spec *other, uint32_t n_other, const char *extra,
                       const sylva_params **own_out, const sylva_params **other_out);
void sf_copy3(double out[3], const sylva_value *v);
double sf_length3(const double v[3]);
/* The spec of one host key (tables are static; every name asked for exists). */
const sylva_param_spec *sf_host_key(const host_schema *schema, const char *name);

/* --- references and plugins --- */
/* Checks that a material key names a defined material; *out is the name or NULL when unset. */
int sf_material_ref(loader *L, const char *file, const sylva_value *v, const char *where, const char **out);
/* Looks up the plugin named in map's `plugin:` key (spec: the host table's `plugin` entry). */
int sf_find_plugin(loader *L, const param_scope *scope, const ynode_pair *pair, const sylva_param_spec *plugin_spec,
                   sylva_kind kind, const sylva_plugin **out, const char **name_out);
/* Fills a shape_spec from validated shape keys. */
int sf_read_shape(loader *L, const char *file, shape_kind kind, const sylva_params *p, const ynode *map,
                  shape_spec *s);

/* --- includes (scene_file_includes.c) --- */
/* The folder of path, in the arena ("." when it has none). */
const char *sf_folder_of(arena *a, const char *path);
/* Gathers the species of one `species:` mapping into L->entries, expanding `include:`. */
int sf_collect_species(loader *L, const ynode *map, const char *file, const char *dir);

/* --- positions (scene_file_position.c) --- */
/* A position as a scene file gives it: [x, y, z] or [x, y] in local metres, or a mapping in map
 * coordinates {easting: E, northing: N} or {longitude: L, latitude: B}, with `height: h` or
 * `height_above_ground: a` or neither (which needs a site: section). Map coordinates become local
 * ones here: local = map - site origin. */
typedef struct sf_position {
    int given;              /* 0: the key is absent; local holds the spec's default */
    double local[3];        /* local metres; local[2] is 0 unless has_height */
    int has_height;         /* 1: local[2] is the height; 0: no height, or one above ground */
    double above_ground;    /* height_above_ground when given, else NaN */
    uint32_t line, column;  /* of the value (of the mapping holding the key when absent) */
} sf_position;

/* Reads the key `spec->name` of the mapping `map` as a position. spec is the key's entry in a
 * host table (sf_host_key): the list form is checked against it (its min_len/max_len say whether
 * a height may be given: max_len 2 refuses heights in every form), SYLVA_PARAM_REQUIRED makes an
 * absent key an error, and its default fills an absent one. `where` names the block in messages
 * ("camera", "objects[2]"). Returns 0 or -1 with L->err set at the offending value. The key must
 * be left out of the validation of `map` (sf_keys_without). */
int sf_read_position(loader *L, const ynode *map, const sylva_param_spec *spec, const char *where,
                     sf_position *out);
/* The keys of `schema` without those named in `drop` (the position keys, read with
 * sf_read_position), as a table in L's arena; NULL when out of memory (L->err set). Validate the
 * mapping against it with `drop` as the scope's host keys. */
const sylva_param_spec *sf_keys_without(loader *L, const host_schema *schema, const char *const *drop,
                                        uint32_t n_drop, uint32_t *n_out);

/* --- the sections, in the order they are read --- */
int sf_read_image(loader *L);
int sf_read_site(loader *L);
int sf_read_camera(loader *L);
int sf_read_sun(loader *L);
int sf_read_sky(loader *L);
int sf_read_earth(loader *L); /* after the site: its default depends on it */
int sf_read_ground_cover(loader *L);
int sf_read_snow(loader *L); /* after the terrain: snow needs its procedural ground */
int sf_read_season(loader *L); /* scene_file_season.c: the season: key */
/* A species' phenology: block (value v of its host keys) into *out (scene_file_season.c). */
int sf_read_phenology(loader *L, const char *file, const char *species, const sylva_value *v, phenology *out);
int sf_read_materials(loader *L, const ynode *node);
int sf_read_ecology(loader *L, const ynode *node, uint32_t line, uint32_t column);
int sf_read_terrain(loader *L, const ynode *node, uint32_t line, uint32_t column);
int sf_read_species(loader *L, const ynode *node);
int sf_read_plants(loader *L, const ynode *node);
int sf_read_trees(loader *L, const ynode_pair *section); /* scene_file_trees.c; NULL: none */
int sf_read_planting(loader *L, const ynode_pair *section); /* scene_file_planting.c; NULL: none */
/* study.years (v: the key's value) into the study's years; with a planting plan and no key, year 1
 * in winter and year 15 in summer (scene_file_study_years.c). */
int sf_read_study_years(loader *L, const sylva_value *v);
int sf_read_groups(loader *L, const ynode *node);
int sf_read_objects(loader *L, const ynode *node);
int sf_read_ztv(loader *L); /* after the objects: its targets name their developments */
int sf_read_photo(loader *L);
int sf_read_landcover(loader *L); /* scene_file_landcover.c; after the site */
/* The landcover: section's communities, plant_area and plant_spacing (p: the section's keys) into
 * lc; scene_file_communities.c, after the species. */
int sf_read_communities(loader *L, const sylva_params *p, landcover_spec *lc);
int sf_read_canopy(loader *L);    /* scene_file_canopy.c; after the site */
/* The index of the development named `name` in L->sf->developments, added when new; -1 with
 * L->err set (out of memory, or more than SCENE_MAX_DEVELOPMENTS). */
int sf_development_index(loader *L, const char *name, const char *file, uint32_t line, uint32_t column);

/* --- objects (scene_file_objects.c) --- */
/* Reads one objects entry (a shape, a model or a group) into o. part: 1 for a group's part,
 * which is a shape or a model at an [x, y, z] of the group's frame. *layout is the entry's
 * layout CSV path (resolved), or NULL. */
int sf_read_object(loader *L, const ynode *item, const char *where, int part, object_spec *o,
                   const char **layout);

/* --- layouts (scene_file_layout.c) --- */
typedef struct layout_row {
    const char *id;
    double xy[2];               /* local metres (map coordinates less the site origin) */
    int has_heading, has_height;
    double heading_deg, height_above_ground;
    uint32_t line;
} layout_row;
/* Reads the CSV at path (shown: its name in messages) into rows in the arena. */
int sf_read_layout(loader *L, const char *path, const char *shown, layout_row **rows, uint32_t *n);
/* The text file at path, whole and NUL-terminated, in the arena (*len its bytes); NULL with
 * L->err set (shown: its name in messages). */
char *sf_read_text_file(loader *L, const char *path, const char *shown, size_t *len);

/* The scene file's digest into L->sf->digest, once every section is read (scene_file_digest.c). */
int sf_digest(loader *L);

/* --- the study (scene_file_study.c, scene_file_points.c) --- */
int sf_read_study(loader *L); /* after the camera, its viewpoints and the objects */
/* The viewpoints of a points file (a CSV by its name, else a point layer OGR reads; layer NULL:
 * its only one) appended to L->sf->study.points, each eye_height above the ground unless the
 * point gives its height, and facing the development unless it gives a heading. */
int sf_read_points(loader *L, const char *path, const char *shown, const char *layer, double eye_height);

#endif
