/* cmd_plugins.c — `sylva plugins`: which plugins this host can use, and what each one takes.
 *
 * The listing opens every module of the search path; it goes to stdout, and modules that could
 * not be used are reported on stderr, one line each, so a script reading the list is not
 * confused by them. `--describe` opens only the module that provides the plugin and prints from
 * its own schema and presets, the tables the scene loader validates against and the plugin
 * starts from. `--manifest` writes the manifest a module needs to be checked before it is
 * opened (plugin_manifest.h); the build runs it for every module it makes.
 */
#include <stdio.h>
#include <string.h>

#include "cli/cli_options.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "plugin/plugin_host.h"
#include "plugin/plugin_manifest.h"

static const char plugins_about[] =
    "\n"
    "Lists the plugins found in the search path (name, kind, version, summary, file);\n"
    "modules that could not be used are reported on stderr with the reason.\n";

/* The search path and the exit statuses, after the options. */
static void plugins_epilogue(char *out, size_t n)
{
    int tree = plugin_running_from_build_tree();
    snprintf(out, n,
             "Search path, first match wins: the folders of SYLVA_PLUGIN_PATH (colon-separated),\n"
             "%s%s%sthen %s.\n"
             "Exit status: 0 done, 1 usage error, 2 no plugin called NAME or no manifest written,\n"
             "4 out of memory.\n",
             tree ? "then " : "", tree ? SYLVA_PLUGIN_BUILD_DIR : "", tree ? " (this build tree), " : "",
             SYLVA_PLUGIN_INSTALL_DIR);
}

/* Any operand is unknown; the help follows the message. */
static int plugins_operand(void *ctx, const char *cmd, const char *a)
{
    if (!a) return 0;
    fprintf(stderr, "sylva %s: unknown %s '%s'\n", cmd, a[0] == '-' ? "option" : "argument", a);
    cli_options_help(ctx, stderr);
    return -1;
}

static void plugins_list(const plugin_registry *reg)
{
    uint32_t n = plugin_registry_count(reg);
    if (n == 0) {
        printf("no plugins found; searched:");
        for (uint32_t i = 0; i < plugin_registry_folder_count(reg); i++)
            printf("%s %s", i ? "," : "", plugin_registry_folder_at(reg, i));
        printf("\n");
    } else {
        int wname = 4, wkind = 4, wver = 7, wsum = 7; /* at least the headings */
        for (uint32_t i = 0; i < n; i++) {
            const sylva_plugin *d = plugin_registry_at(reg, i)->desc;
            int l = (int)strlen(d->name);
            if (l > wname) wname = l;
            l = (int)strlen(plugin_kind_name(d->kind));
            if (l > wkind) wkind = l;
            l = (int)strlen(d->version);
            if (l > wver) wver = l;
            l = (int)strlen(d->summary);
            if (l > wsum) wsum = l;
        }
        printf("%-*s  %-*s  %-*s  %-*s  %s\n", wname, "NAME", wkind, "KIND", wver, "VERSION", wsum,
               "SUMMARY", "FILE");
        for (uint32_t i = 0; i < n; i++) {
            const loaded_plugin *lp = plugin_registry_at(reg, i);
            printf("%-*s  %-*s  %-*s  %-*s  %s\n", wname, lp->desc->name, wkind,
                   plugin_kind_name(lp->desc->kind), wver, lp->desc->version, wsum,
                   lp->desc->summary, lp->file);
        }
    }
    for (uint32_t i = 0; i < plugin_registry_problem_count(reg); i++)
        fprintf(stderr, "sylva plugins: %s\n", plugin_registry_problem_at(reg, i)->message);
}

static void plugins_describe(const loaded_plugin *lp)
{
    const sylva_plugin *d = lp->desc;
    printf("%s: %s\n", d->name, d->summary);
    printf("  kind     %s\n", plugin_kind_name(d->kind));
    printf("  version  %s\n", d->version);
    printf("  file     %s\n", lp->file);
    printf("  ABI      %u.%u\n", d->abi_major, d->abi_minor);
    printf("\nparameters:\n");
    if (d->n_params) plugin_schema_print(stdout, d->params, d->n_params, 2);
    else printf("  (none)\n");
    if (d->n_presets) {
        printf("\npresets (chosen with `%s`; a key the scene gives replaces the preset's value, "
               "a key the preset does not set keeps its default):\n", d->preset_param);
        plugin_presets_print(stdout, d, 2);
    }
    if (d->kind == SYLVA_KIND_ECOLOGY && d->species_section) {
        printf("\nspecies parameters (each species' `%s` block):\n", d->species_section);
        if (d->n_species_params)
            plugin_schema_print(stdout, d->species_params, d->n_species_params, 2);
        else printf("  (none)\n");
    }
}

int cmd_plugins(int argc, char **argv)
{
    const char *cmd = argc > 0 && argv[0] ? argv[0] : "plugins";
    const char *describe = NULL, *manifest = NULL;
    int n_describe = 0, n_manifest = 0;
    char epilogue[1024];
    plugins_epilogue(epilogue, sizeof epilogue);
    const cli_option options[] = {
        {.names = "--describe", .type = CLI_TEXT, .value = "NAME", .target = &describe, .given = &n_describe,
         .help = "print one plugin's summary, kind, file, parameter schema and presets with their values"},
        {.names = "--manifest", .type = CLI_PATH, .value = "MODULE.so", .target = &manifest, .given = &n_manifest,
         .help = "write MODULE.sylva-plugin beside the module (runs the module's code once: a build step)"},
        CLI_OPT_HELP,
    };
    cli_command_spec spec = {cmd, "", plugins_about, NULL, options, sizeof options / sizeof *options, epilogue,
                             plugins_operand, NULL};
    spec.ctx = &spec;
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    if (n_describe + n_manifest > 1) {
        fprintf(stderr, "sylva %s: %s; give one of --describe NAME and --manifest MODULE\n", cmd,
                n_describe > 1 ? "--describe is given twice" : n_manifest > 1 ? "--manifest is given twice"
                                                             : "--describe and --manifest are both given");
        return EXIT_USAGE;
    }
    if (describe && !describe[0]) {
        fprintf(stderr, "sylva %s: --describe needs a plugin name\n", cmd);
        return EXIT_USAGE;
    }

    err_buf err;
    err_clear(&err);
    if (manifest) {
        if (plugin_manifest_write(manifest, &err) == 0) return EXIT_OK;
        return cli_fail(cmd, &err, ERR_INPUT);
    }
    plugin_registry *reg = plugin_registry_open(&err); /* freed below */
    if (!reg) return cli_fail(cmd, &err, ERR_INTERNAL);
    int status = EXIT_OK;
    if (!describe) {
        if (plugin_registry_load_all(reg, &err)) {
            plugin_registry_free(reg);
            return cli_fail(cmd, &err, ERR_INTERNAL);
        }
        plugins_list(reg);
    } else {
        const loaded_plugin *lp = plugin_registry_find(reg, describe, 0, &err);
        if (lp) {
            plugins_describe(lp);
        } else {
            status = cli_fail(cmd, &err, ERR_INPUT);
        }
    }
    plugin_registry_free(reg);
    return status;
}
