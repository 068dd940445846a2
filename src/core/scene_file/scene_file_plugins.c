/* scene_file_plugins.c — finding the plugin a block names (`plugin:` in the terrain, ecology
 * and species blocks) in the registry, by name and kind, and refusing one whose parameter names
 * clash with the host's own keys. Only the plugin's descriptor is read; none of its code runs. */
#include "scene_file/scene_file_loader.h"

/* Looks up the plugin named in map's `plugin:` key (spec: the host table's `plugin` entry). */
int sf_find_plugin(loader *L, const param_scope *scope, const ynode_pair *pair,
                   const sylva_param_spec *plugin_spec, sylva_kind kind,
                   const sylva_plugin **out, const char **name_out)
{
    sylva_value v;
    if (param_value_read(L->a, pair->value, plugin_spec, scope, &v, L->err)) return -1;
    const char *kind_name = plugin_kind_name(kind);
    if (!L->reg)
        return sf_located(L->err, scope->file, v.line, v.column,
                          "%s plugin '%s' cannot be used: no plugins are available (the scene was "
                          "loaded without a plugin registry)",
                          kind_name, v.s);
    err_buf e;
    err_clear(&e);
    const loaded_plugin *lp = plugin_registry_find(L->reg, v.s, kind, &e);
    if (!lp) {
        sf_located(L->err, scope->file, v.line, v.column, "%s", e.msg[0] ? e.msg : "no such plugin");
        if (e.status == ERR_NOMEM) L->err->status = ERR_NOMEM; /* opening the module ran out */
        return -1;
    }
    const sylva_plugin *d = lp->desc;
    const char *clash = host_reserved_key_clash(d->params, d->n_params, L->species_section);
    if (clash)
        return sf_located(L->err, scope->file, v.line, v.column,
                          "%s plugin '%s' (%s) cannot be used: its parameter '%s' has a name the "
                          "host keeps for itself (plugin, material, variants, shape, grid, origin, "
                          "spacing, include, %s); the plugin must rename it",
                          kind_name, v.s, lp->file, clash,
                          L->species_section ? L->species_section : "ecology");
    *out = d;
    *name_out = v.s;
    return 0;
}
