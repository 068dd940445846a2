/* commands.c — the table of `sylva` commands (commands.h). */
#include "cli/commands.h"

#include <string.h>

const sylva_command sylva_commands[] = {
    {"render", cmd_render, "SCENE", "render a scene file to EXR and PNG"},
    {"plugins", cmd_plugins, "", "list the plugins found (and problems with broken ones)"},
    {"export-pov", cmd_export_pov, "SCENE", "write a scene (or one species) as POV-Ray 3.7 scene files"},
    {"crosscheck", cmd_crosscheck, "SCENE", "render with sylva (verification mode) and POV-Ray, compare, report"},
    {"simulate", cmd_simulate, "SCENE", "run the scene's ecology alone: plants, statistics, saved state"},
    {"factors", cmd_factors, "SCENE", "write the ecology's terrain factor maps (-o DIR)"},
    {"tree-stats", cmd_tree_stats, "SCENE SPECIES", "a tree species' variants: segments, leaves, bounds, D_B"},
    {"ztv", cmd_ztv, "SCENE -o DIR", "map where the development can be seen from (GeoTIFF, PNG maps, summary)"},
    {"montage", cmd_montage, "SCENE -o DIR", "render the development into the scene's photograph (montage, wireline, sheet)"},
    {"study", cmd_study, "SCENE -o DIR", "every viewpoint's existing, proposed and wireline views from one build"},
    {"probe", cmd_probe, "SCENE E N", "the ground at a point (height, slope, aspect, water) and what stands there"},
    {NULL, NULL, NULL, NULL},
};

const sylva_command *sylva_command_find(const char *name)
{
    for (const sylva_command *c = sylva_commands; c->name; c++)
        if (!strcmp(c->name, name)) return c;
    return NULL;
}
