/* pov_names.h — sylva's names as POV-Ray identifiers and as comment text.
 *
 * A clean name keeps letters and digits, turns every other run of characters into one
 * underscore, drops underscores at either end, keeps at most POV_CLEAN_MAX characters and
 * starts upper-case (POV-Ray's keywords are all lower-case, so no identifier is a keyword).
 * Identifiers:
 *   materials   M<index>_<clean>          objects   O<index>_<clean>
 *   models      D<index>_<clean> (the meshes objects share)
 *   prototypes  <Species>_<variant>, where <Species> is the clean species name, prefixed "S__"
 *               when it would start with a digit or look like a material or object name, and
 *               suffixed "__<index>" when another species cleans up to the same name.
 * A clean name never holds "__", so these never collide with one another nor with the fixed
 * names Terrain, Water and Sylva_*. Nothing here allocates. */
#ifndef SYLVA_POV_NAMES_H
#define SYLVA_POV_NAMES_H

#include <stddef.h>
#include <stdint.h>

#include "scene/scene.h"

#define POV_CLEAN_MAX 24
#define POV_IDENT_MAX 64 /* bytes of an identifier buffer, NUL included */

/* The clean form of name (NULL or empty: "Unnamed"); out holds POV_CLEAN_MAX + 1 bytes. */
void pov_clean_name(const char *name, char out[POV_CLEAN_MAX + 1]);

void pov_material_identifier(const scene *s, uint32_t index, char out[POV_IDENT_MAX]);
void pov_object_identifier(const scene *s, uint32_t index, char out[POV_IDENT_MAX]);
void pov_model_identifier(const scene *s, uint32_t index, char out[POV_IDENT_MAX]);
/* The identifier of prototype p ("Oak_0" for variant 0 of species "oak"). */
void pov_prototype_identifier(const scene *s, uint32_t p, char out[POV_IDENT_MAX]);

/* text with control characters (bytes below 0x20 and 0x7f) replaced by '?', cut to fit out's
 * n bytes, for use inside a // comment or a "..." in one. */
void pov_comment_text(const char *text, char *out, size_t n);

#endif
