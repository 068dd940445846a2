/* wp_fixture.c — a tree_weber_penn block validated and read through the real host (wp_fixture.h). */
#include "wp_fixture.h"

#include <string.h>

#include "params/validate.h"
#include "params/yaml_doc.h"
#include "plugin_params.h"
#include "wp_schema.h"

int wp_fixture_open(wp_fixture *f, const char *yaml, const char *dir)
{
    memset(f, 0, sizeof *f);
    f->scene = scene_new();
    f->arena = arena_new();
    if (!f->scene || !f->arena) return err_set(&f->err, "out of memory");
    host_init(&f->host, f->scene, dir, 1, "tree plugin 'tree_weber_penn' for species 'test'", &f->err);
    f->host.quiet = 1;
    yaml_doc doc;
    if (yaml_doc_parse(f->arena, yaml, strlen(yaml), "test.yaml", &doc, &f->err)) return -1;
    static const char *const host_keys[] = {"plugin", "variants"};
    param_scope scope = {.file = "test.yaml", .dir = dir, .where = "species.test", .host_keys = host_keys,
                         .n_host_keys = 2, .line = 1, .column = 1};
    if (params_validate(f->arena, doc.root, wp_schema, WP_SCHEMA_COUNT, &scope, &f->params, &f->err)) {
        f->params = NULL;
        return -1;
    }
    plugin_params r = plugin_params_open(host_api_table(), &f->host, f->params);
    plugin_err err = {0};
    return wp_config_read(&r, &f->cfg, &err) ? plugin_params_report(&r, &err) : 0;
}

void wp_fixture_close(wp_fixture *f)
{
    host_release(&f->host);
    scene_free(f->scene);
    arena_free(f->arena);
    memset(f, 0, sizeof *f);
}
