/* scene_file.h — a scene file, read and validated, before any plugin runs.
 *
 * scene_file_load() parses the YAML (libyaml), checks every key against the host's section
 * schemas (host_schema.h) and every plugin block against that plugin's schema (looked up in the
 * plugin registry by name), fills defaults, resolves relative paths against the scene file's
 * folder and merges included species files. Any problem stops loading with
 * "file:line:column: message" in err.
 *
 * The record it returns, and what each section holds, is scene_file_spec.h.
 */
#ifndef SYLVA_SCENE_FILE_H
#define SYLVA_SCENE_FILE_H

#include "scene_file/scene_file_spec.h"
#include "util/err.h"

struct plugin_registry;

/* Reads and validates `path`. plugins may be NULL only for scenes that name no plugin.
 * Returns a new scene_file (caller frees with scene_file_free) or NULL with err set. */
scene_file *scene_file_load(const char *path, const struct plugin_registry *plugins, err_buf *err);

/* Flags of scene_file_load_with. */
#define SCENE_FILE_NO_CAMERA 1u /* the camera: section may be left out: for a command that draws no
                                   picture (ztv, probe) */
#define SCENE_FILE_QUIET 2u     /* no info lines on stderr (what the loader chose for a left-out
                                   key, e.g. the site's UTM zone): a command's -q */
/* scene_file_load with flags (0: as scene_file_load). */
scene_file *scene_file_load_with(const char *path, const struct plugin_registry *plugins, unsigned flags,
                                 err_buf *err);
void scene_file_free(scene_file *sf); /* accepts NULL */

/* Makes the viewpoint named `name` the scene's camera (before the scene is built). Returns 0, or
 * -1 with err (ERR_USAGE) naming the viewpoints there are. */
int scene_file_use_viewpoint(scene_file *sf, const char *name, err_buf *err);

/* Shows the plants on the day text names (a season's name or a date YYYY-MM-DD, as the season:
 * key takes) instead of the scene's own season (before the scene is built). Returns 0, or -1
 * with err (ERR_USAGE) saying what would be valid. */
int scene_file_use_season(scene_file *sf, const char *text, err_buf *err);

/* Reads the viewpoints of a points file (docs/study.md: a CSV, or a point layer OGR reads, from
 * `layer` or its only one) in place of the study: section's points (before the scene is built).
 * path is as given on the command line. Returns 0, or -1 with err (ERR_INPUT) at the file's
 * line and column. */
int scene_file_read_points(scene_file *sf, const char *path, const char *layer, err_buf *err);

/* A viewpoint's number on the study's sheets, maps, layers and index: its place among the
 * scene's viewpoints, then the points file's, from 1 (the same whatever order a study renders
 * them in); 0 for a viewpoint of neither list. */
uint32_t scene_file_viewpoint_number(const scene_file *sf, const scene_viewpoint *v);

/* Where the development stands (local x, y): the mean position of the objects marked
 * `development`, else of the ztv: section's targets. 0, or -1 when the scene names neither. */
int scene_file_development_place(const scene_file *sf, double at[2]);

/* The DTM the terrain's plugin block names (its `dtm` path, resolved), or NULL. */
const char *scene_file_dtm_path(const scene_file *sf);

/* Index of a material or species by name, or -1 (a hash lookup). */
int scene_file_material_index(const scene_file *sf, const char *name);
int scene_file_species_index(const scene_file *sf, const char *name);

#endif
