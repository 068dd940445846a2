/* cli_outputs.c — every file a scene reads listed with the output guard, and the outputs a
 * command names checked against them and against each other. */
#include "cli/cli_outputs.h"

#include <stdio.h>

#include "cli/cli_status.h"
#include "io/output_guard.h"

#define READ_BY_SCENE "a file the scene reads"

/* The PATH values of a plugin's or a section's block, nested groups included. */
static int add_params(const sylva_params *p, err_buf *err)
{
    for (uint32_t i = 0; p && i < p->n; i++) {
        const sylva_value *v = &p->values[i];
        switch (p->spec[i].type) {
        case SYLVA_P_PATH:
            if (v->s && output_guard_add(v->s, READ_BY_SCENE, err)) return -1;
            break;
        case SYLVA_P_GROUP:
            if (add_params(v->group, err)) return -1;
            break;
        case SYLVA_P_GROUP_LIST:
            for (uint32_t k = 0; v->items && k < v->len; k++)
                if (add_params(&v->items[k], err)) return -1;
            break;
        default: break;
        }
    }
    return 0;
}

static int add_object(const object_spec *o, err_buf *err)
{
    return (o->model_path && output_guard_add(o->model_path, READ_BY_SCENE, err)) ||
           (o->file && output_guard_add(o->file, "a layout the scene reads", err)) ? -1 : 0;
}

/* Every file sf reads: itself, its includes and the files its sections and plugin blocks name. */
static int add_scene_files(const scene_file *sf, err_buf *err)
{
    if (output_guard_add(sf->path, "the scene file", err)) return -1;
    for (uint32_t i = 0; i < sf->n_includes; i++)
        if (output_guard_add(sf->includes[i], "a species file the scene includes", err)) return -1;
    if (add_params(sf->terrain.params, err) || add_params(sf->ecology.params, err)) return -1;
    for (uint32_t i = 0; i < sf->n_species; i++)
        if (add_params(sf->species[i].params, err) || add_params(sf->species[i].ecology, err)) return -1;
    for (uint32_t i = 0; i < sf->n_objects; i++)
        if (add_object(&sf->objects[i], err)) return -1;
    for (uint32_t g = 0; g < sf->n_groups; g++)
        for (uint32_t i = 0; i < sf->groups[g].n_parts; i++)
            if (add_object(&sf->groups[g].parts[i], err)) return -1;
    for (uint32_t i = 0; i < sf->n_materials; i++)
        if (sf->materials[i].texture_path && output_guard_add(sf->materials[i].texture_path, READ_BY_SCENE, err))
            return -1;
    const char *named[] = {sf->plants_file, sf->photo.file, sf->photo.control_points};
    for (int i = 0; i < 3; i++)
        if (named[i] && output_guard_add(named[i], READ_BY_SCENE, err)) return -1;
    return 0;
}

int cli_outputs_check(const char *cmd, const scene_file *sf, const cli_file *inputs, uint32_t n_inputs,
                      const cli_file *outputs, uint32_t n_outputs)
{
    err_buf err = {{0}};
    if (sf && add_scene_files(sf, &err)) return cli_fail(cmd, &err, ERR_NOMEM);
    for (uint32_t i = 0; i < n_inputs; i++) {
        char what[64];
        snprintf(what, sizeof what, "the file %s reads", inputs[i].option);
        if (inputs[i].path && output_guard_add(inputs[i].path, what, &err)) return cli_fail(cmd, &err, ERR_NOMEM);
    }
    for (uint32_t i = 0; i < n_outputs; i++) {
        const cli_file *o = &outputs[i];
        if (!o->path) continue;
        if (output_guard_check(o->path, &err)) {
            if (o->option[0] == '-') err_prefix(&err, "%s: ", o->option); /* not for a default name */
            return cli_fail(cmd, &err, ERR_USAGE);
        }
        for (uint32_t k = 0; k < i; k++)
            if (outputs[k].path && output_guard_same_file(outputs[k].path, o->path))
                return cli_failf(cmd, ERR_USAGE, "%s '%s' and %s '%s' are the same file; give each output its own "
                                 "name", outputs[k].option, outputs[k].path, o->option, o->path);
    }
    return EXIT_OK;
}
