/* host_schema.h — the host's own scene-file sections as static parameter schemas.
 *
 * The scene loader validates the host's sections with these tables exactly as it validates a
 * plugin's block with the plugin's table, and docs/scene-file.md and `sylva plugins --describe`
 * are written from the same tables, so help and checks cannot drift apart. Rules that tie keys
 * together (look_at or direction, fov or focal_length, grid or plugin, ...) are the loader's
 * (scene_file.c); each table states the per-key facts: type, default, range, unit, help.
 *
 * Tables are static const data; nothing here allocates.
 */
#ifndef SYLVA_HOST_SCHEMA_H
#define SYLVA_HOST_SCHEMA_H

#include <stdint.h>

#include "plugin/plugin_host.h"
#include "scene_file/scene_file_spec.h"
#include "sylva/plugin.h"

typedef struct host_schema {
    const char *name;     /* as the docs name it: "image", "plants item", "shape box" */
    const char *help;     /* one sentence on the section */
    const sylva_param_spec *params;
    uint32_t n_params;
} host_schema;

extern const host_schema host_schema_image;
extern const host_schema host_schema_site;
extern const host_schema host_schema_position;     /* a position in map coordinates (a mapping) */
extern const host_schema host_schema_camera;
extern const host_schema host_schema_sun;
extern const host_schema host_schema_sky;
extern const host_schema host_schema_earth;
extern const host_schema host_schema_snow;          /* snow: on the procedural ground */
extern const host_schema host_schema_ground_cover;
extern const host_schema host_schema_ztv;
extern const host_schema host_schema_ztv_target; /* one entry of ztv: targets: */
extern const host_schema host_schema_photo;
extern const host_schema host_schema_study;        /* study: what `sylva study` renders */
extern const host_schema host_schema_landcover;    /* landcover: the site's land-cover map */
extern const host_schema host_schema_canopy;       /* canopy: the site's canopy heights */
extern const host_schema host_schema_material;     /* one entry of materials: */
extern const host_schema host_schema_terrain;      /* terrain's host keys */
extern const host_schema host_schema_species;      /* a species' host keys */
extern const host_schema host_schema_phenology;    /* a species' phenology: block */
extern const host_schema host_schema_blossom;      /* its blossom: block */
extern const host_schema host_schema_plant;        /* one item of plants: */
extern const host_schema host_schema_plants_file;  /* plants: {file: ...} */
extern const host_schema host_schema_trees;        /* trees: a survey's trees */
extern const host_schema host_schema_planting;     /* planting: a planting plan */
extern const host_schema host_schema_planting_item; /* one block, belt, tree or felling of it */
extern const host_schema host_schema_object;       /* one item of objects: (without shape keys) */
extern const host_schema host_schema_object_model; /* one item of objects: with model: */
extern const host_schema host_schema_object_group; /* one item of objects: with group: */
extern const host_schema host_schema_ecology;      /* ecology's host keys */
extern const host_schema host_schema_shape_box;
extern const host_schema host_schema_shape_sphere;
extern const host_schema host_schema_shape_quad;
extern const host_schema host_schema_shape_disk;
extern const host_schema host_schema_shape_mesh;

/* Every host schema above, in the order the docs list them; NULL past the end. */
const host_schema *host_schema_at(uint32_t i);

/* The keys of one built-in shape (size, radius, ...). */
const host_schema *host_schema_shape(shape_kind kind);

/* Top-level section names of a scene file, NULL-terminated. */
extern const char *const host_sections[];

/* The first parameter of a plugin's table whose name the host keeps for itself (one of
 * plugin_reserved_keys, or species_section when not NULL), or NULL when there is none. */
const char *host_reserved_key_clash(const sylva_param_spec *params, uint32_t n,
                                    const char *species_section);

/* Choice names, in enum order: shape_kind, sky_model, and sylva_bsdf - 1. */
extern const char *const host_shape_names[];
extern const char *const host_sky_models[];
extern const char *const host_material_types[];
extern const char *const host_model_up_axes[]; /* model_up order: file, y, z */
extern const char *const host_study_products[]; /* study_product order */
extern const char *const host_study_frames[];   /* study_frame order */
extern const char *const host_stock_sizes[];    /* planting stock: whip, feathered, standard */
extern const char *const host_planting_coordinates[]; /* planting coordinates: local, map */

/* Image size limit (width and height), pixels. */
#define HOST_IMAGE_MAX_SIZE 16384

#endif
