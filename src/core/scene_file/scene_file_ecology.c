/* scene_file_ecology.c — the ecology section: its plugin and that plugin's parameters; the
 * plugin also names the section of each species that holds the species' ecology block. */
#include "scene_file/scene_file_loader.h"

int sf_read_ecology(loader *L, const ynode *node, uint32_t line, uint32_t column)
{
    L->species_section = "ecology";
    if (!node || ynode_is_null(node)) return 0;
    param_scope scope = {L->file, L->dir, "ecology", NULL, 0, line, column};
    if (node->kind != YNODE_MAPPING)
        return sf_located(L->err, L->file, node->line, node->column,
                          "'ecology' must be a mapping (plugin: NAME and the plugin's keys), got %s",
                          ynode_kind_phrase(node));
    const ynode_pair *pp = ynode_get_pair(node, "plugin");
    if (!pp)
        return sf_located(L->err, L->file, node->line, node->column,
                          "missing required key 'plugin' in 'ecology' (the ecology plugin to use)");
    const sylva_plugin *d;
    const char *name;
    if (sf_find_plugin(L, &scope, pp, sf_host_key(&host_schema_ecology, "plugin"), SYLVA_KIND_ECOLOGY, &d,
                       &name))
        return -1;
    const sylva_params *host, *params;
    if (sf_validate_shared(L, node, &scope, host_schema_ecology.params, host_schema_ecology.n_params,
                           d->params, d->n_params, NULL, &host, &params))
        return -1;
    L->ecology = d;
    if (d->species_section) L->species_section = d->species_section;
    L->sf->ecology.plugin = name;
    L->sf->ecology.params = params;
    L->sf->ecology.line = node->line, L->sf->ecology.column = node->column;
    return 0;
}
