/* refusing_plugins.c — two test plugins that fail on purpose, so the command-line tests can
 * check that a plugin's failure reads the same from every command and ends with the exit
 * status of its kind:
 *   refusing_tree     builds a one-triangle model per variant (and reports its statistics)
 *                     until variant `refuse_variant`, where generate() fails with a sentence
 *                     naming the request it got (variant, age, seed), or with SYLVA_ERR_NOMEM
 *                     when `out_of_memory` is set;
 *   refusing_ecology  whose create() refuses its `tag` through param_error, naming the first
 *                     number of its random stream (so the sentence shows the seed it was given).
 */
#include <stdlib.h>

#include "sylva/plugin.h"

typedef struct refusing_tree {
    int64_t refuse_variant;
    int out_of_memory;
    sylva_tree_stats last; /* of the last model built */
    int built;
} refusing_tree;

static const sylva_param_spec tree_params[] = {
    {.name = "refuse_variant", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .def = 0,
     .min = 0, .max = 64, .help = "The variant whose generate() fails."},
    {.name = "out_of_memory", .type = SYLVA_P_BOOL, .def = 0,
     .help = "Fail as when an allocation fails (SYLVA_ERR_NOMEM) instead of refusing the request."},
};

static int tree_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params, void **state)
{
    (void)api, (void)host;
    refusing_tree *t = calloc(1, sizeof *t);
    if (!t) return SYLVA_ERR_NOMEM;
    t->refuse_variant = sylva_param_int(params, "refuse_variant");
    t->out_of_memory = (int)sylva_param_int(params, "out_of_memory");
    *state = t;
    return SYLVA_OK;
}

static int tree_generate(void *state, const sylva_host_api *api, sylva_host *host, const void *request, void *out)
{
    refusing_tree *t = state;
    const sylva_tree_request *req = request;
    sylva_tree_out *o = out;
    if (req->variant == (uint64_t)t->refuse_variant) {
        if (t->out_of_memory) {
            api->error(host, "out of memory for variant %u (on purpose)", req->variant);
            return SYLVA_ERR_NOMEM;
        }
        return api->error(host, "variant %u of %u at age %.6g with seed %016llx refused on purpose", req->variant,
                          req->n_variants, req->age, (unsigned long long)req->seed);
    }
    float h = (float)(10.0 * req->age);
    const float pos[9] = {-1, 0, 0, 1, 0, 0, 0, 0, h};
    const uint32_t tri[3] = {0, 1, 2};
    int rc = api->mesh_append(host, o->mesh, pos, NULL, NULL, 3, tri, NULL, 1);
    if (rc) return rc;
    o->height = h;
    t->last = (sylva_tree_stats){.size = sizeof t->last, .age = req->age, .triangles = 1, .height = h,
                                 .bbox_min = {-1, 0, 0}, .bbox_max = {1, 0, h}};
    t->built = 1;
    return SYLVA_OK;
}

static int tree_last_stats(void *state, sylva_tree_stats *out)
{
    const refusing_tree *t = state;
    if (!t->built) return SYLVA_ERR_PARAM;
    uint32_t size = out->size < sizeof *out ? out->size : (uint32_t)sizeof *out;
    sylva_tree_stats copy = t->last;
    copy.size = out->size;
    for (uint32_t i = 0; i < size; i++) ((unsigned char *)out)[i] = ((const unsigned char *)&copy)[i];
    return SYLVA_OK;
}

static const sylva_tree_stats_v1 tree_stats = {.size = sizeof tree_stats, .last_stats = tree_last_stats};

static const void *tree_extension(const char *id)
{
    const char *a = id, *b = SYLVA_TREE_STATS_V1;
    while (*a && *a == *b) a++, b++;
    return *a == *b ? &tree_stats : NULL;
}

static void tree_destroy(void *state) { free(state); }

static const sylva_param_spec ecology_params[] = {
    {.name = "tag", .type = SYLVA_P_INT, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX, .def = 1, .min = 0,
     .max = 100, .help = "Any value; create() refuses every one."},
};

static int ecology_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params, void **state)
{
    *state = NULL;
    sylva_rng r;
    api->rng_init(host, &r, "refusal", 0);
    return api->param_error(host, params, "tag", "tag %lld refused on purpose; first number of the stream %016llx",
                            (long long)sylva_param_int(params, "tag"), (unsigned long long)api->rng_u64(&r));
}

static int ecology_generate(void *state, const sylva_host_api *api, sylva_host *host, const void *request, void *out)
{
    (void)state, (void)request, (void)out;
    return api->error(host, "refusing_ecology: generate() ran although create() failed");
}

static void ecology_destroy(void *state) { (void)state; }

static const sylva_plugin plugins[] = {
    {.size = sizeof(sylva_plugin), .abi_major = SYLVA_ABI_MAJOR, .abi_minor = SYLVA_ABI_MINOR,
     .param_spec_size = sizeof(sylva_param_spec), .kind = SYLVA_KIND_TREE, .name = "refusing_tree",
     .summary = "A tree whose generate() fails at one variant (for tests).", .version = "1.0",
     .params = tree_params, .n_params = 2, .create = tree_create, .generate = tree_generate,
     .destroy = tree_destroy, .extension = tree_extension},
    {.size = sizeof(sylva_plugin), .abi_major = SYLVA_ABI_MAJOR, .abi_minor = SYLVA_ABI_MINOR,
     .param_spec_size = sizeof(sylva_param_spec), .kind = SYLVA_KIND_ECOLOGY, .name = "refusing_ecology",
     .summary = "An ecology whose create() always fails (for tests).", .version = "1.0",
     .params = ecology_params, .n_params = 1, .create = ecology_create, .generate = ecology_generate,
     .destroy = ecology_destroy},
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    return index < sizeof plugins / sizeof plugins[0] ? &plugins[index] : NULL;
}
