/* wp_fixture.c — a tree_weber_penn block validated and read through the real host (wp_fixture.h). */
#include "wp_fixture.h"

#include <stdio.h>
#include <string.h>

#include "params/validate.h"
#include "params/yaml_doc.h"
#include "plugin_params.h"
#include "tree_weber_penn.h"
#include "wp_schema.h"

static int fixture_start(wp_fixture *f, const char *dir)
{
    memset(f, 0, sizeof *f);
    f->scene = scene_new();
    f->arena = arena_new();
    if (!f->scene || !f->arena) return err_set(&f->err, "out of memory");
    host_init(&f->host, f->scene, dir, 1, "tree plugin 'tree_weber_penn' for species 'test'", &f->err);
    f->host.quiet = 1;
    return 0;
}

/* Validates the block `map` of file `file` (folder `dir`) and reads it. */
static int fixture_read(wp_fixture *f, const ynode *map, const char *file, const char *dir)
{
    static const char *const host_keys[] = {"plugin", "variants"};
    param_scope scope = {.file = file, .dir = dir, .where = "species.test", .host_keys = host_keys,
                         .n_host_keys = 2, .line = 1, .column = 1};
    if (params_validate(f->arena, map, wp_schema, WP_SCHEMA_COUNT, &scope, &f->params, &f->err)) {
        f->params = NULL;
        return -1;
    }
    plugin_params r = plugin_params_open(host_api_table(), &f->host, f->params);
    plugin_err err = {0};
    return wp_config_read(&r, &f->cfg, &err) ? plugin_params_report(&r, &err) : 0;
}

int wp_fixture_open(wp_fixture *f, const char *yaml, const char *dir)
{
    if (fixture_start(f, dir)) return -1;
    yaml_doc doc;
    if (yaml_doc_parse(f->arena, yaml, strlen(yaml), "test.yaml", &doc, &f->err)) return -1;
    return fixture_read(f, doc.root, "test.yaml", dir);
}

int wp_fixture_open_species(wp_fixture *f, const char *path, const char *name)
{
    static char dir[4096];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash) *slash = '\0';
    else snprintf(dir, sizeof dir, ".");
    if (fixture_start(f, dir)) return -1;
    yaml_doc doc;
    if (yaml_doc_load(f->arena, path, NULL, &doc, &f->err)) return -1;
    const ynode *block = ynode_get(ynode_get(doc.root, "species"), name);
    if (!block) return err_set(&f->err, "%s: no species '%s'", path, name);
    return fixture_read(f, block, path, dir);
}

int wp_fixture_create(wp_fixture *f)
{
    if (!f->params) return err_set(&f->err, "the block was not validated");
    return wp_plugin()->create(host_api_table(), &f->host, f->params, &f->state);
}

int wp_fixture_generate(wp_fixture *f, double age, uint32_t variant, uint32_t n_variants, mesh **out, double *height)
{
    *out = mesh_new();
    if (!*out) return err_set(&f->err, "out of memory");
    sylva_tree_request req = {.size = sizeof req, .age = age, .variant = variant, .n_variants = n_variants,
                              .seed = f->host.seed};
    sylva_tree_out o = {.size = sizeof o, .mesh = *out};
    int rc = wp_plugin()->generate(f->state, host_api_table(), &f->host, &req, &o);
    if (height) *height = o.height;
    return rc;
}

void wp_fixture_close(wp_fixture *f)
{
    if (f->state) wp_plugin()->destroy(f->state);
    host_release(&f->host);
    scene_free(f->scene);
    arena_free(f->arena);
    memset(f, 0, sizeof *f);
}
