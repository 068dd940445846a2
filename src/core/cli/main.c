/* main.c — the `sylva` command: dispatches to one function per command (commands.h). */
#include <stdio.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "sylva/plugin.h"

static void usage(FILE *out)
{
    fprintf(out,
            "usage: sylva COMMAND [options]\n\n"
            "commands:\n"
            "  render SCENE     render a scene file to EXR and PNG\n"
            "  plugins          list the plugins found (and problems with broken ones)\n"
            "  export-pov SCENE write a scene (or one species) as POV-Ray 3.7 scene files\n"
            "  crosscheck SCENE render with sylva (verification mode) and POV-Ray, compare, report\n"
            "  simulate SCENE   run the scene's ecology alone: plants, statistics, saved state\n"
            "  factors SCENE    write the ecology's terrain factor maps (-o DIR)\n"
            "  tree-stats SCENE SPECIES  a tree species' variants: segments, leaves, bounds, D_B\n"
            "  --version        print the version\n"
            "  --help           this text; every command takes --help too\n\n"
            "Plugins are found in SYLVA_PLUGIN_PATH (colon-separated folders), the build tree\n"
            "and the install folder.\n\n"
            "exit status: 0 done, 1 usage, 2 bad scene or plugin failure, 3 output not written,\n"
            "4 out of memory or internal error\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return EXIT_USAGE;
    }
    const char *cmd = argv[1];
    if (!strcmp(cmd, "--help") || !strcmp(cmd, "-h") || !strcmp(cmd, "help")) {
        usage(stdout);
        return EXIT_OK;
    }
    if (!strcmp(cmd, "--version")) {
        printf("sylva %s (plugin ABI %d.%d)\n", SYLVA_VERSION, SYLVA_ABI_MAJOR, SYLVA_ABI_MINOR);
        return EXIT_OK;
    }
    if (!strcmp(cmd, "render")) return cmd_render(argc - 1, argv + 1);
    if (!strcmp(cmd, "plugins")) return cmd_plugins(argc - 1, argv + 1);
    if (!strcmp(cmd, "export-pov")) return cmd_export_pov(argc - 1, argv + 1);
    if (!strcmp(cmd, "crosscheck")) return cmd_crosscheck(argc - 1, argv + 1);
    if (!strcmp(cmd, "simulate")) return cmd_simulate(argc - 1, argv + 1);
    if (!strcmp(cmd, "factors")) return cmd_factors(argc - 1, argv + 1);
    if (!strcmp(cmd, "tree-stats")) return cmd_tree_stats(argc - 1, argv + 1);
    fprintf(stderr, "sylva: unknown command '%s' (commands: render, plugins, export-pov, crosscheck, simulate, factors, tree-stats; see sylva --help)\n", cmd);
    return EXIT_USAGE;
}
