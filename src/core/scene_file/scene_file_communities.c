/* scene_file_communities.c — the landcover: section's plant communities: for a kind or a class
 * of ground, the scene's species that grow on it, their shares, the plants per hectare and the
 * range of their heights; and the area and grid they are planted on. Each community is checked
 * here, each fault at its key; the plants are placed when the scene is built
 * (scene_build/scene_communities.c). */
#include "scene_file/scene_file_loader.h"

#include <string.h>

#include "scene/land_cover.h"
#include "scene_file/scene_file.h"

/* The species names of a community (separated by spaces or commas) into c->species. */
static int read_species(loader *L, const sylva_value *v, landcover_community *c)
{
    const char *p = v->s;
    while (*p) {
        size_t skip = strspn(p, " ,\t"), len;
        p += skip;
        if (!*p) break;
        len = strcspn(p, " ,\t");
        if (c->n_species == COMMUNITY_MAX_SPECIES)
            return sf_located(L->err, L->file, v->line, v->column, "a community holds at most %u species; '%s' "
                              "names more", COMMUNITY_MAX_SPECIES, v->s);
        const char *name = sf_arena_printf(L->a, "%.*s", (int)len, p);
        if (!name) return sf_out_of_memory(L);
        int index = scene_file_species_index(L->sf, name);
        if (index < 0) {
            const char **names = arena_alloc(L->a, ((size_t)L->sf->n_species + 1) * sizeof *names);
            if (!names) return sf_out_of_memory(L);
            for (uint32_t i = 0; i < L->sf->n_species; i++) names[i] = L->sf->species[i].name;
            sylva_value named = *v;
            named.s = name;
            return sf_unknown_name(L, L->file, &named, "species", "species", "landcover.communities", names,
                                   L->sf->n_species);
        }
        c->species[c->n_species++] = (uint32_t)index;
        p += len;
    }
    if (!c->n_species)
        return sf_located(L->err, L->file, v->line, v->column, "a community needs at least one species: species: "
                          "\"pine juniper\" names the scene's species");
    return 0;
}

/* The shares (given, as many as species; or equal), normalised to sum to 1. */
static int read_shares(loader *L, const sylva_value *v, landcover_community *c)
{
    if (v->is_set && v->len != c->n_species)
        return sf_located(L->err, L->file, v->line, v->column, "'shares' gives %u numbers for %u species; give "
                          "one share per species, in the order of species", v->len, c->n_species);
    double sum = 0;
    for (uint32_t i = 0; i < c->n_species; i++) sum += c->share[i] = v->is_set ? v->list[i] : 1.0;
    for (uint32_t i = 0; i < c->n_species; i++) c->share[i] /= sum;
    return 0;
}

/* What ground the community grows on: exactly one of kind and code, never the same twice. */
static int read_ground(loader *L, const sylva_params *item, const landcover_community *done, uint32_t n,
                       landcover_community *c)
{
    const sylva_value *kind = sylva_param(item, "kind"), *code = sylva_param(item, "code");
    if (kind->is_set == code->is_set)
        return sf_located(L->err, L->file, item->line, item->column, "a community grows on one kind of ground "
                          "or one class: give kind: (forest, shrub, grass, ...) or code: (the map's code), %s",
                          kind->is_set ? "not both" : "one of them");
    c->kind = kind->is_set ? (int)kind->i : -1;
    c->code = code->i;
    const sylva_value *at = kind->is_set ? kind : code;
    for (uint32_t k = 0; k < n; k++)
        if (done[k].kind == c->kind && (c->kind >= 0 || done[k].code == c->code))
            return sf_located(L->err, L->file, at->line, at->column, "the %s %s has two communities; give one "
                              "(a community may hold several species)", kind->is_set ? "kind" : "class",
                              kind->is_set ? land_kind_names[c->kind] : sf_arena_printf(L->a, "%lld", (long long)c->code));
    return 0;
}

static int read_community(loader *L, const sylva_params *item, const landcover_community *done, uint32_t n,
                          landcover_community *c)
{
    *c = (landcover_community){.line = item->line, .column = item->column};
    if (read_ground(L, item, done, n, c) || read_species(L, sylva_param(item, "species"), c) ||
        read_shares(L, sylva_param(item, "shares"), c))
        return -1;
    const sylva_value *height = sylva_param(item, "height");
    c->density = sylva_param_real(item, "density");
    c->height[0] = height->list[0], c->height[1] = height->list[1];
    if (c->height[0] > c->height[1])
        return sf_located(L->err, L->file, height->line, height->column, "'height' [%g, %g] runs downward; give "
                          "[lowest, tallest]", c->height[0], c->height[1]);
    return 0;
}

/* The area the communities are planted in: a box with its west below its east, its south below
 * its north. */
static int read_area(loader *L, const sylva_params *p, landcover_spec *lc)
{
    const sylva_value *area = sylva_param(p, "plant_area");
    lc->plant_spacing = sylva_param_real(p, "plant_spacing");
    lc->plant_edge = sylva_param_real(p, "plant_edge");
    if (!area->is_set) return 0;
    const double *a = area->list;
    if (!(a[0] < a[2] && a[1] < a[3]))
        return sf_located(L->err, L->file, area->line, area->column, "'plant_area' [%g, %g, %g, %g] is empty; give "
                          "[west, south, east, north] in the site's map coordinates", a[0], a[1], a[2], a[3]);
    memcpy(lc->plant_area, a, sizeof lc->plant_area);
    lc->has_plant_area = 1;
    return 0;
}

int sf_read_communities(loader *L, const sylva_params *p, landcover_spec *lc)
{
    const sylva_value *v = sylva_param(p, "communities");
    if (read_area(L, p, lc)) return -1;
    if (!v->len) return 0;
    landcover_community *c = arena_alloc(L->a, v->len * sizeof *c);
    if (!c) return sf_out_of_memory(L);
    for (uint32_t i = 0; i < v->len; i++)
        if (read_community(L, &v->items[i], c, i, &c[i])) return -1;
    lc->communities = c, lc->n_communities = v->len;
    return 0;
}
