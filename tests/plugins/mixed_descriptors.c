/* mixed_descriptors.c — a test module with many descriptors, each checking one rule of the
 * host's descriptor checks. Index 0 (an ecology plugin with a species schema) and the last index
 * (a plugin from a newer ABI minor with a longer descriptor) are valid and must be listed; every
 * other index has exactly one flaw and must give exactly one problem naming its index. */
#include <stddef.h>

#include "sylva/plugin.h"

static int mixed_create(const sylva_host_api *api, sylva_host *host, const sylva_params *params,
                        void **state)
{
    *state = NULL;
    return SYLVA_OK;
}

static int mixed_generate(void *state, const sylva_host_api *api, sylva_host *host,
                          const void *request, void *out)
{
    ((sylva_ecology_out *)out)->n_plants = 0;
    return SYLVA_OK;
}

static void mixed_destroy(void *state) { (void)state; }

static const sylva_param_spec mixed_params[] = {
    {.name = "density", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN, .def = 0.01,
     .min = 0.0, .unit = "1/m2", .help = "Plants per square metre."},
};

static const char *const mixed_shade_choices[] = {"tolerant", "intolerant", NULL};
static const sylva_param_spec mixed_species_params[] = {
    {.name = "shade", .type = SYLVA_P_ENUM, .def_str = "tolerant", .choices = mixed_shade_choices,
     .help = "Whether the species grows under other trees."},
    {.name = "max_slope", .type = SYLVA_P_REAL, .flags = SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_HAS_MAX,
     .def = 30.0, .min = 0.0, .max = 90.0, .unit = "deg", .help = "Steepest ground it grows on."},
};

static const sylva_param_spec mixed_reserved_params[] = {
    {.name = "spacing", .type = SYLVA_P_REAL, .def = 1.0, .unit = "m",
     .help = "Collides with the host's own terrain key."},
};

/* Fields every entry shares, and the three that some entries change on purpose. */
#define MIXED_COMMON                                                                          \
    .abi_major = SYLVA_ABI_MAJOR, .param_spec_size = sizeof(sylva_param_spec),                 \
    .version = "1.0", .generate = mixed_generate, .destroy = mixed_destroy
#define MIXED_SIZE .size = sizeof(sylva_plugin)
#define MIXED_MINOR .abi_minor = SYLVA_ABI_MINOR
#define MIXED_CREATE .create = mixed_create
#define MIXED_BASE MIXED_COMMON, MIXED_SIZE, MIXED_MINOR, MIXED_CREATE

/* A descriptor as a later minor would write it: sylva_plugin followed by a field this host does
 * not know. */
typedef struct mixed_future_plugin {
    sylva_plugin base;
    const char *later_field;
} mixed_future_plugin;

static const mixed_future_plugin mixed_future = {
    .base = {MIXED_COMMON, MIXED_CREATE, .size = sizeof(mixed_future_plugin),
             .abi_minor = SYLVA_ABI_MINOR + 5,
             .kind = SYLVA_KIND_TERRAIN, .name = "mixed_future",
             .summary = "Valid: written against a newer minor, with a longer descriptor."},
    .later_field = "ignored by this host",
};

static const sylva_plugin mixed[] = {
    /* 0: valid */
    {MIXED_BASE, .kind = SYLVA_KIND_ECOLOGY, .name = "mixed_ecology",
     .summary = "Valid: an ecology plugin with a species schema.", .params = mixed_params,
     .n_params = 1, .species_section = "ecology", .species_params = mixed_species_params,
     .n_species_params = 2},
    /* 1: unknown kind */
    {MIXED_BASE, .kind = (sylva_kind)7, .name = "mixed_kind", .summary = "Kind 7."},
    /* 2: no create */
    {MIXED_COMMON, MIXED_SIZE, MIXED_MINOR, .kind = SYLVA_KIND_TERRAIN, .name = "mixed_nocreate",
     .summary = "No create."},
    /* 3: species section badly named */
    {MIXED_BASE, .kind = SYLVA_KIND_ECOLOGY, .name = "mixed_section",
     .summary = "Species section 'Ecology'.", .species_section = "Ecology",
     .species_params = mixed_species_params, .n_species_params = 2},
    /* 4: species schema on a terrain plugin */
    {MIXED_BASE, .kind = SYLVA_KIND_TERRAIN, .name = "mixed_terrain_species",
     .summary = "Terrain with species params.", .species_section = "ecology",
     .species_params = mixed_species_params, .n_species_params = 2},
    /* 5: the name of index 0 again */
    {MIXED_BASE, .kind = SYLVA_KIND_TERRAIN, .name = "mixed_ecology", .summary = "Duplicate."},
    /* 6: a summary of two lines */
    {MIXED_BASE, .kind = SYLVA_KIND_TERRAIN, .name = "mixed_summary",
     .summary = "First line.\nSecond line."},
    /* 7: a size too small to hold the version */
    {MIXED_COMMON, MIXED_MINOR, MIXED_CREATE, .size = 8, .kind = SYLVA_KIND_TERRAIN,
     .name = "mixed_tiny", .summary = "Size 8."},
    /* 8: a size that stops before the operations */
    {MIXED_COMMON, MIXED_MINOR, MIXED_CREATE, .size = offsetof(sylva_plugin, create),
     .kind = SYLVA_KIND_TERRAIN, .name = "mixed_short", .summary = "Size short of the operations."},
    /* 9: a parameter named like a host key */
    {MIXED_BASE, .kind = SYLVA_KIND_TERRAIN, .name = "mixed_reserved",
     .summary = "A parameter called 'spacing'.", .params = mixed_reserved_params, .n_params = 1},
    /* 10: a species section named like a host key */
    {MIXED_BASE, .kind = SYLVA_KIND_ECOLOGY, .name = "mixed_section_reserved",
     .summary = "Species section 'shape'.", .species_section = "shape",
     .species_params = mixed_species_params, .n_species_params = 2},
};

SYLVA_EXPORT const sylva_plugin *sylva_plugin_get(uint32_t index)
{
    if (index < sizeof mixed / sizeof mixed[0]) return &mixed[index];
    return index == sizeof mixed / sizeof mixed[0] ? &mixed_future.base : NULL;
}
