/* scene_file_includes.c — gathering the species of the scene file and of the files it
 * includes (`include:` inside `species:`), in file order: each name defined once, each file
 * included once, no include cycles, nesting at most INCLUDE_MAX_DEPTH files. */
#include "scene_file/scene_file_loader.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int add_entry(loader *L, const ynode_pair *pr, const char *file, const char *dir)
{
    int64_t first = name_index_add(&L->sf->species_names, pr->key, L->n_entries);
    if (first < 0) return sf_out_of_memory(L);
    if (first != L->n_entries) {
        const species_entry *e = &L->entries[first];
        return sf_located(L->err, file, pr->key_line, pr->key_column,
                          "species '%s' is defined twice; it was first defined at %s:%u:%u", pr->key,
                          e->file, e->line, e->column);
    }
    if (L->n_entries == L->cap_entries) {
        uint32_t cap = L->cap_entries ? 2 * L->cap_entries : 16;
        species_entry *e = arena_alloc(L->a, (size_t)cap * sizeof *e);
        if (!e) return sf_out_of_memory(L);
        if (L->n_entries) memcpy(e, L->entries, (size_t)L->n_entries * sizeof *e);
        L->entries = e, L->cap_entries = cap;
    }
    L->entries[L->n_entries++] = (species_entry){pr->key, pr->value, pr->key_line, pr->key_column,
                                                 file, dir};
    return 0;
}

const char *sf_folder_of(arena *a, const char *path)
{
    const char *slash = strrchr(path, '/');
    if (!slash) return arena_strdup(a, ".");
    if (slash == path) return arena_strdup(a, "/");
    return arena_strndup(a, path, (size_t)(slash - path));
}

/* Reads one included file (named by the scalar `item`) and collects its species. */
static int include_file(loader *L, const ynode *item, const char *file, const char *dir)
{
    if (item->kind != YNODE_SCALAR || ynode_is_null(item) || !item->text[0])
        return sf_located(L->err, file, item->line, item->column,
                          "'include' takes file names (a string or a list of strings), got %s",
                          ynode_kind_phrase(item));
    const char *rel = item->text;
    const char *path = param_resolve_path(L->a, dir, rel);
    /* messages name the file as the user would reach it from the scene file's location */
    const char *shown_dir = strchr(file, '/') ? sf_folder_of(L->a, file) : NULL;
    const char *shown = rel[0] == '/' || !shown_dir ? arena_strdup(L->a, rel)
                                                    : param_resolve_path(L->a, shown_dir, rel);
    if (!path || !shown) return sf_out_of_memory(L);
    char *real = realpath(path, NULL); /* malloc'ed; copied into the arena and freed below */
    if (!real)
        return sf_located(L->err, file, item->line, item->column, "cannot include '%s': %s", rel,
                          strerror(errno));
    const char *canon = arena_strdup(L->a, real);
    free(real);
    if (!canon) return sf_out_of_memory(L);

    for (uint32_t i = 0; i < L->chain_len; i++)
        if (!strcmp(L->chain[i].real, canon)) {
            char trail[1024];
            size_t used = 0;
            for (uint32_t k = i; k < L->chain_len && used < sizeof trail; k++)
                used += (size_t)snprintf(trail + used, sizeof trail - used, "%s includes ",
                                         L->chain[k].file);
            return sf_located(L->err, file, item->line, item->column,
                              "include cycle: %s%s again", trail, L->chain[i].file);
        }
    for (uint32_t i = 0; i < L->n_seen; i++)
        if (!strcmp(L->seen[i].real, canon))
            return sf_located(L->err, file, item->line, item->column,
                              "'%s' is already included (at %s:%u:%u); include a file once", rel,
                              L->seen[i].from, L->seen[i].line, L->seen[i].column);
    if (L->chain_len > INCLUDE_MAX_DEPTH)
        return sf_located(L->err, file, item->line, item->column,
                          "includes nest deeper than the limit of %d files", INCLUDE_MAX_DEPTH);

    if (L->n_seen == L->cap_seen) {
        uint32_t cap = L->cap_seen ? 2 * L->cap_seen : 8;
        included_file *s = arena_alloc(L->a, (size_t)cap * sizeof *s);
        if (!s) return sf_out_of_memory(L);
        if (L->n_seen) memcpy(s, L->seen, (size_t)L->n_seen * sizeof *s);
        L->seen = s, L->cap_seen = cap;
    }
    included_file inc = {canon, shown, item->line, item->column, file};
    L->seen[L->n_seen++] = inc;

    yaml_doc doc;
    int rc = yaml_doc_load(L->a, path, shown, &doc, L->err);
    if (rc == YAML_DOC_UNREADABLE)
        return err_prefix(L->err, "%s:%u:%u: cannot include '%s': ", file, item->line,
                          item->column, rel);
    if (rc) return -1;
    if (!doc.root || doc.root->kind != YNODE_MAPPING)
        return sf_located(L->err, shown, doc.root ? doc.root->line : 1,
                          doc.root ? doc.root->column : 1,
                          "an included species file must hold a mapping with a 'species:' section, "
                          "got %s",
                          ynode_kind_phrase(doc.root));
    for (uint32_t i = 0; i < doc.root->n_pairs; i++) {
        const ynode_pair *pr = &doc.root->pairs[i];
        if (strcmp(pr->key, "species"))
            return sf_located(L->err, shown, pr->key_line, pr->key_column,
                              "an included file holds only a 'species:' section; '%s' belongs in "
                              "the scene file", pr->key);
    }
    const ynode *species = ynode_get(doc.root, "species");
    if (!species)
        return sf_located(L->err, shown, doc.root->line, doc.root->column,
                          "an included species file must hold a 'species:' section");
    const char *inc_dir = sf_folder_of(L->a, canon);
    if (!inc_dir) return sf_out_of_memory(L);
    L->chain[L->chain_len++] = inc;
    rc = sf_collect_species(L, species, shown, inc_dir);
    L->chain_len--;
    return rc;
}

/* Gathers the species of one `species:` mapping, expanding `include:` where it stands. */
int sf_collect_species(loader *L, const ynode *map, const char *file, const char *dir)
{
    if (ynode_is_null(map)) return 0;
    if (map->kind != YNODE_MAPPING)
        return sf_located(L->err, file, map->line, map->column,
                          "'species' must be a mapping of names to species (beech: {plugin: ...}), "
                          "got %s", ynode_kind_phrase(map));
    for (uint32_t i = 0; i < map->n_pairs; i++) {
        const ynode_pair *pr = &map->pairs[i];
        if (strcmp(pr->key, "include")) {
            if (!pr->key[0])
                return sf_located(L->err, file, pr->key_line, pr->key_column,
                                  "a species needs a name, got an empty key");
            if (add_entry(L, pr, file, dir)) return -1;
            continue;
        }
        const ynode *inc = pr->value;
        if (inc->kind == YNODE_SEQUENCE) {
            for (uint32_t k = 0; k < inc->n_items; k++)
                if (include_file(L, inc->items[k], file, dir)) return -1;
        } else if (include_file(L, inc, file, dir)) {
            return -1;
        }
    }
    return 0;
}
