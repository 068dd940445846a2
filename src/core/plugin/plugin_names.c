/* plugin_names.c — well-formed names and the kinds' names (plugin_names.h). */
#include "plugin/plugin_names.h"

#include <stddef.h>

int plugin_name_is_valid(const char *name)
{
    if (!name || !(name[0] >= 'a' && name[0] <= 'z')) return 0;
    size_t n = 1;
    for (; name[n] && n <= PLUGIN_NAME_MAX; n++) {
        char c = name[n];
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return 0;
    }
    return n <= PLUGIN_NAME_MAX;
}

const char *plugin_kind_name(sylva_kind kind)
{
    switch (kind) {
    case SYLVA_KIND_TERRAIN: return "terrain";
    case SYLVA_KIND_TREE: return "tree";
    case SYLVA_KIND_ECOLOGY: return "ecology";
    }
    return "unknown";
}
