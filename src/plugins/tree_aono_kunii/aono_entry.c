/* aono_entry.c — the module's one exported symbol: the tree_aono_kunii descriptor (the
 * model and its operations live in the tree_aono_kunii_model library). */
#include "tree_aono_kunii.h"

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? aono_plugin() : (const sylva_plugin *)0;
}
