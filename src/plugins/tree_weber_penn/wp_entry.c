/* wp_entry.c — the module's one exported symbol: the tree_weber_penn descriptor (its operations
 * live in the tree_weber_penn_plugin library, the model in tree_weber_penn_model). */
#include "tree_weber_penn.h"

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? wp_plugin() : (const sylva_plugin *)0;
}
