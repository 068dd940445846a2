/* ecology_entry.c — the module's one exported symbol: the `ecology` plugin's descriptor. */
#include "eco_plugin.h"

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index == 0 ? &eco_descriptor : (const sylva_plugin *)0;
}
