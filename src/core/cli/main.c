/* main.c — the `sylva` command: dispatches to the command named first, from the table in
 * commands.c, which `sylva --help` lists too. */
#include <stdio.h>
#include <string.h>

#include "cli/cli_status.h"
#include "cli/commands.h"
#include "site/proj_network.h"
#include "sylva/plugin.h"
#include "util/memory_budget.h"

static void usage(FILE *out)
{
    fprintf(out, "usage: sylva COMMAND [options]\n\ncommands:\n");
    for (const sylva_command *c = sylva_commands; c->name; c++) {
        char head[64];
        snprintf(head, sizeof head, "%s%s%s", c->name, c->synopsis[0] ? " " : "", c->synopsis);
        fprintf(out, "  %-26s %s\n", head, c->summary);
    }
    fprintf(out,
            "  %-26s print the version\n"
            "  %-26s this text; every command takes --help too\n\n"
            "Plugins are found in SYLVA_PLUGIN_PATH (colon-separated folders), the build tree\n"
            "and the install folder.\n\n"
            "exit status: 0 done, 1 usage, 2 bad scene or plugin failure, 3 output not written,\n"
            "4 out of memory or internal error\n",
            "--version", "--help");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return EXIT_USAGE;
    }
    const char *name = argv[1];
    if (!strcmp(name, "--help") || !strcmp(name, "-h") || !strcmp(name, "help")) {
        usage(stdout);
        return EXIT_OK;
    }
    if (!strcmp(name, "--version")) {
        printf("sylva %s (plugin ABI %d.%d)\n", SYLVA_VERSION, SYLVA_ABI_MAJOR, SYLVA_ABI_MINOR);
        return EXIT_OK;
    }
    const sylva_command *c = sylva_command_find(name);
    if (c) {
        /* no network through PROJ (grids for a transformation) unless a command allows it */
        proj_network_start();
        err_buf err = {{0}};
        if (memory_limit_check(&err)) return cli_fail(c->name, &err, ERR_USAGE);
        return c->run(argc - 1, argv + 1);
    }
    fprintf(stderr, "sylva: unknown command '%s' (commands:", name);
    for (c = sylva_commands; c->name; c++) fprintf(stderr, "%s %s", c == sylva_commands ? "" : ",", c->name);
    fprintf(stderr, "; see sylva --help)\n");
    return EXIT_USAGE;
}
