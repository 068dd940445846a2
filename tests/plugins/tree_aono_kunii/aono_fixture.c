/* aono_fixture.c — the tree_aono_kunii plugin driven through the real host for tests and
 * benchmarks (see aono_fixture.h). */
#include "aono_fixture.h"

#include <string.h>

#include "tree_aono_kunii.h"
#include "params/validate.h"
#include "params/yaml_doc.h"

static void fixture_stream(void *ctx, sylva_rng *rng, const char *purpose, uint64_t index)
{
    aono_fixture *f = ctx;
    host_api_table()->rng_init(&f->host, rng, purpose, index);
}

static int fixture_start(aono_fixture *f, uint64_t seed)
{
    memset(f, 0, sizeof *f);
    f->scene = scene_new();
    f->arena = arena_new();
    if (!f->scene || !f->arena) return err_set(&f->err, "out of memory");
    host_init(&f->host, f->scene, ".", seed, "tree plugin 'tree_aono_kunii' for species 'test'", &f->err);
    f->host.quiet = 1;
    f->env = (aono_env){.stream = fixture_stream, .uniform = host_api_table()->rng_uniform, .ctx = f};
    return 0;
}

/* Validates the block `map` and runs create(). */
static int fixture_create(aono_fixture *f, const ynode *map, const char *file, const char *where)
{
    static const char *const host_keys[] = {"plugin", "variants"};
    param_scope scope = {.file = file, .dir = ".", .where = where, .host_keys = host_keys, .n_host_keys = 2,
                         .line = 1, .column = 1};
    const sylva_plugin *pl = aono_plugin();
    if (params_validate(f->arena, map, pl->params, pl->n_params, &scope, &f->params, &f->err)) {
        f->params = NULL;
        return -1;
    }
    return pl->create(host_api_table(), &f->host, f->params, &f->state);
}

int aono_fixture_open(aono_fixture *f, const char *yaml, uint64_t seed)
{
    if (fixture_start(f, seed)) return -1;
    yaml_doc doc;
    if (yaml_doc_parse(f->arena, yaml, strlen(yaml), "test.yaml", &doc, &f->err)) return -1;
    return fixture_create(f, doc.root, "test.yaml", "species.test");
}

int aono_fixture_open_species(aono_fixture *f, const char *path, const char *name, uint64_t seed)
{
    if (fixture_start(f, seed)) return -1;
    yaml_doc doc;
    if (yaml_doc_load(f->arena, path, NULL, &doc, &f->err)) return -1;
    const ynode *block = ynode_get(ynode_get(doc.root, "species"), name);
    if (!block) return err_set(&f->err, "%s: no species '%s'", path, name);
    return fixture_create(f, block, path, name);
}

void aono_fixture_close(aono_fixture *f)
{
    if (f->state) aono_plugin()->destroy(f->state);
    host_release(&f->host);
    scene_free(f->scene);
    arena_free(f->arena);
    memset(f, 0, sizeof *f);
}

int aono_fixture_generate(aono_fixture *f, double age, mesh **out, double *height)
{
    *out = mesh_new();
    if (!*out) return err_set(&f->err, "out of memory");
    sylva_tree_request req = {.size = sizeof req, .age = age, .variant = 0, .n_variants = 1, .seed = f->host.seed};
    sylva_tree_out o = {.size = sizeof o, .mesh = *out};
    int rc = aono_plugin()->generate(f->state, host_api_table(), &f->host, &req, &o);
    if (height) *height = o.height;
    return rc;
}

int aono_fixture_config(aono_fixture *f, aono_config *cfg)
{
    plugin_params r = plugin_params_open(host_api_table(), &f->host, f->params);
    return aono_config_read(&r, cfg, &f->fail);
}

int aono_fixture_grow(aono_fixture *f, uint32_t levels, aono_skeleton *skel)
{
    aono_config cfg;
    int rc = aono_fixture_config(f, &cfg);
    if (rc) return rc;
    rc = aono_grow(&cfg, levels, &f->env, skel, &f->fail);
    aono_config_release(&cfg);
    return rc;
}
