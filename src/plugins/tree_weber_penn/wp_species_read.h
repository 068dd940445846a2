/* wp_species_read.h — Weber-Penn species files read into wp_params: Arbaro's
 * `<arbaro><species name=...><param name="X" value="V"/>...` (with the shamanDevel fork's extra
 * names) and Helios' `<helios><WeberPennTree label=...><Shape> 6 </Shape>...` library, whose
 * per-level fields are lists of four values and whose own fields (LeafFile, WoodFile,
 * WoodColor, LeafAngleDist) are noted and not used. Unknown names, repeated names, values that
 * are not numbers and values out of range are refused at their place in the file. */
#ifndef WP_SPECIES_READ_H
#define WP_SPECIES_READ_H

#include <stddef.h>

#include "plugin_err.h"
#include "wp_params.h"

#define WP_MAX_SPECIES 1024 /* species in one file */

typedef struct wp_species_list {
    wp_params *items;   /* owned; each named by its species (Arbaro) or label (Helios) */
    size_t count;
    char ignored[256];  /* the Helios-only field names met, comma-separated ("" when none) */
} wp_species_list;

/* Reads buf[0..len), named `file` in messages, into *out (emptied first). Returns 0, or a
 * negative sylva_status with err's sentence set (`file:line:column: ...`) and *out empty. */
int wp_species_read_buffer(const char *file, const char *buf, size_t len, wp_species_list *out, plugin_err *err);

/* The same for the file at `path`. */
int wp_species_read_file(const char *path, wp_species_list *out, plugin_err *err);

/* Frees the list's species and empties it. */
void wp_species_list_free(wp_species_list *list);

/* The species named `name`, or NULL. */
const wp_params *wp_species_find(const wp_species_list *list, const char *name);

#endif
