/* pov_write.h — the POV-Ray 3.7 exporter: a scene graph as scene files that POV-Ray renders to
 * the picture sylva's verification mode computes (render/integrator.h).
 *
 * A scene export to DIR/NAME.pov writes, beside it:
 *   NAME.pov            global settings, camera, sun, sky, the terrain and objects, includes
 *   NAME_materials.inc  one texture per material (pigment, finish, image map)
 *   NAME_terrain.inc    the terrain (and water surface) as mesh2        (when there is terrain)
 *   NAME_objects.inc    each object as a mesh2 in world coordinates     (when there are objects)
 *   NAME_species.inc    each species variant declared once as a mesh2   (when there are species)
 *   NAME_plants.inc     each plant as `object { Species_k matrix <12 numbers> }`
 *   NAME_M<i>_<material>.png  the image of each textured material
 * Coordinates stay sylva's (right-handed, Z up, metres): the camera's `sky` (sylva's up vector)
 * and `right -x*aspect` written before `look_at` make POV-Ray show them unmirrored. POV-Ray
 * looks for include and image files in the folder it runs in: render from DIR.
 *
 * Lighting matches the verification mode term by term: pigment = albedo (times the texture),
 * finish { ambient 1 diffuse 1 }, global ambient_light = sky.ambient, a parallel light of
 * colour sun irradiance x sun colour (POV-Ray's diffuse term has no 1/pi, nor has the
 * verification formula), background = the sky's mean radiance, assumed_gamma 1 (linear).
 * Alpha-masked textures are written with their alpha cut at one half, as sylva tests it; a
 * textured material with a coloured albedo has the albedo multiplied into its image (8-bit
 * sRGB), one with a grey albedo keeps the image as it is and carries the albedo in the finish.
 *
 * Every file is streamed (no file's text is held whole) through a temporary name and renamed
 * into place when complete; NAME.pov is written last. Names become POV-Ray identifiers
 * (letters, digits, underscores, starting with an upper-case letter, at most 40 characters);
 * the original names stay in comments with control characters replaced.
 *
 * Nothing here prints; errors fill err. The scene is only read. */
#ifndef SYLVA_POV_WRITE_H
#define SYLVA_POV_WRITE_H

#include <stdint.h>

#include "pov/pov_names.h"
#include "scene/scene.h"
#include "util/err.h"

typedef struct pov_export_options {
    uint32_t width, height; /* image the camera's aspect and the render command are for; 0: the scene's */
    uint32_t spp;           /* samples the render command's antialiasing matches; 0: the scene's */
    const char *source;     /* the scene file's name for the header comment, or NULL */
} pov_export_options;

typedef struct pov_export_stats {
    uint32_t files;          /* files written (scene files and images) */
    uint64_t bytes;          /* their total size */
    uint64_t instances;      /* plants written */
    uint64_t instance_bytes; /* size of NAME_plants.inc */
    uint64_t skipped;        /* plants left out: empty prototype or singular transform */
} pov_export_stats;

/* Exports the whole scene to pov_path (which must end in ".pov"). o and st may be NULL.
 * Returns 0, or -1 with err set (a file could not be written, a mesh holds a non-finite
 * value, the name holds a quote, backslash or control character); files already renamed into
 * place stay, none is left half-written. */
int pov_export_scene(const scene *s, const char *pov_path, const pov_export_options *o,
                     pov_export_stats *st, err_buf *err);

/* Exports one species for use in another POV-Ray scene: its variants (all when variant < 0)
 * declared as mesh2 objects with their materials, base at the origin, growing along +Z, and a
 * transform Sylva_to_y_up for scenes that keep POV-Ray's usual Y-up axes. path ending in
 * ".inc": that include file alone; ending in ".pov": NAME.inc plus a small scene NAME.pov that
 * shows the variants side by side on a ground plane. Textures are written beside it. Returns 0
 * or -1 with err set (also for a species or variant that does not exist). st may be NULL. */
int pov_export_species(const scene *s, uint32_t species_index, int32_t variant, const char *path,
                       const char *source, pov_export_stats *st, err_buf *err);

#endif
