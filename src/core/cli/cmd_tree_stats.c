/* cmd_tree_stats.c — `sylva tree-stats SCENE SPECIES`: builds one tree species' age variants as
 * `sylva render` does and prints what each model is: recursion level, symbols, segments,
 * leaves, branches, triangles, height and bounding box, the box-counting dimension D_B of its
 * silhouette (002 eq. 3) and, where the branch-number law chose the level, the law's D and N2
 * (002 eq. 6). The figures come from the plugin's optional "sylva.tree_stats.v1" interface;
 * a plugin without it is reported as such. */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_options.h"
#include "cli/cli_status.h"
#include "cli/commands.h"
#include "plugin/plugin_host.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "scene_build/plugin_call.h"
#include "scene_file/scene_file.h"

static const char tree_stats_about[] =
    "Builds the age variants of SPECIES (a tree-plugin species of SCENE) as `sylva render`\n"
    "would and prints, for each: age, recursion level, symbols, segments, leaves, branches,\n"
    "triangles, height and bounding box in metres, the box-counting dimension D_B of its\n"
    "silhouette, and the branch-number law's D and target branch count N2 where the law chose\n"
    "the level.\n";

static const char tree_stats_epilogue[] =
    "exit status: 0 done, 1 usage, 2 bad scene, unknown species or plugin failure,\n"
    "4 out of memory or internal error\n";

/* The operands: the scene, then the species. */
typedef struct tree_stats_operands {
    const char *scene_path, *species_name;
} tree_stats_operands;

static int tree_stats_operand(void *ctx, const char *cmd, const char *a)
{
    tree_stats_operands *t = ctx;
    if (!a) return t->scene_path && t->species_name ? 0 : -1;
    if (a[0] == '-' || !t->scene_path) return cli_scene_argument(cmd, a, &t->scene_path);
    if (t->species_name) {
        fprintf(stderr, "sylva %s: one scene and one species; '%s' is extra\n", cmd, a);
        return -1;
    }
    t->species_name = a;
    return 0;
}

static void print_row(uint32_t variant, const sylva_tree_stats *st)
{
    char law[64] = "-";
    if (st->target_branches > 0) snprintf(law, sizeof law, "%.4g (D %.3f)", st->target_branches, st->law_dimension);
    printf("%-7u %-6.3f %-5u %-11llu %-9llu %-8llu %-8llu %-16s %-10llu %-8.3f [%.2f %.2f %.2f]..[%.2f %.2f %.2f]  %.3f\n",
           variant, st->age, st->recursion, (unsigned long long)st->symbols, (unsigned long long)st->segments,
           (unsigned long long)st->leaves, (unsigned long long)st->branches, law, (unsigned long long)st->triangles,
           st->height, st->bbox_min[0], st->bbox_min[1], st->bbox_min[2], st->bbox_max[0], st->bbox_max[1],
           st->bbox_max[2], st->box_dimension);
}

/* Builds and prints the variants through the scene build's plugin call, so the figures describe
 * the models a render uses. Returns 0, or -1 with err set. */
static int run_species(const scene_file *sf, const species_spec *sp, const plugin_registry *reg,
                       uint32_t n_variants, double only_age, int verbose, err_buf *err)
{
    scene *sc = scene_new(); /* owned: holds the meshes' materials while they are measured */
    if (!sc) return err_nomem(err, "out of memory");
    plugin_call c;
    plugin_call_output out = {.verbose = verbose, .quiet = 1};
    if (plugin_call_open_tree(&c, sf, sp, sc, reg, &out, err)) {
        scene_free(sc);
        return -1;
    }
    const sylva_plugin *desc = c.plugin->desc;
    const sylva_tree_stats_v1 *ext = desc->extension ? desc->extension(SYLVA_TREE_STATS_V1) : NULL;
    int rc = 0;
    if (!ext || ext->size < offsetof(sylva_tree_stats_v1, last_stats) + sizeof ext->last_stats || !ext->last_stats) {
        rc = err_at(err, ERR_INPUT, sf->path, sp->line, sp->column,
                    "tree plugin '%s' (%s) does not report statistics (no \"%s\" interface)", sp->plugin,
                    c.plugin->file, SYLVA_TREE_STATS_V1);
        goto done;
    }
    printf("species %s: plugin %s (%s)\n", sp->name, sp->plugin, c.plugin->file);
    printf("%-7s %-6s %-5s %-11s %-9s %-8s %-8s %-16s %-10s %-8s %-36s  %s\n", "variant", "age", "level", "symbols",
           "segments", "leaves", "branches", "N2 eq.6", "triangles", "height", "bounding box (m)", "D_B");
    uint32_t count = only_age > 0 ? 1 : n_variants;
    for (uint32_t v = 0; v < count && !rc; v++) {
        mesh *m = mesh_new();
        if (!m) {
            rc = err_nomem(err, "out of memory");
            break;
        }
        tree_variant tv = {.index = v, .count = count, .age = only_age};
        sylva_tree_stats st = {.size = sizeof st};
        if (!(rc = plugin_call_tree(&c, &tv, m, err))) {
            if (ext->last_stats(c.state, &st))
                rc = plugin_call_refuse(&c, "last_stats", ERR_PLUGIN, err, "gave no statistics for variant %u", v);
            else
                print_row(v, &st);
        }
        mesh_free(m);
    }
done:
    plugin_call_close(&c);
    scene_free(sc);
    return rc;
}

int cmd_tree_stats(int argc, char **argv)
{
    uint64_t variants = 0;
    double age = 0;
    int verbose = 0;
    const cli_option options[] = {
        CLI_OPT_WHOLE("--variants", "N", variants, 1, 64, "build N age variants (ages 1/N, 2/N, ..., 1) instead of "
                      "the species'"),
        CLI_OPT_NUMBER("--age", "A", "a number", age, 0, 1, CLI_OPEN_LOW, "build one model at normalised age A in "
                       "(0, 1]"),
        {.names = "-v, --verbose", .type = CLI_FLAG, .target = &verbose, .target_size = sizeof verbose,
         .flags = CLI_COMMON, .help = "plugin debug messages"},
        CLI_OPT_HELP,
    };
    tree_stats_operands ops = {0};
    const cli_command_spec spec = {"tree-stats", "SCENE SPECIES", tree_stats_about, NULL, options,
                                   sizeof options / sizeof *options, tree_stats_epilogue, tree_stats_operand, &ops};
    int parsed = cli_options_parse(&spec, argc, argv);
    if (parsed) return cli_options_status(parsed);
    const char *scene_path = ops.scene_path, *species_name = ops.species_name;
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open(&err);
    if (!reg) return cli_fail("tree-stats", &err, ERR_INTERNAL);
    int rc = EXIT_OK;
    const species_spec *sp = NULL;
    scene_file *sf = scene_file_load(scene_path, reg, &err);
    if (!sf) {
        rc = cli_fail(NULL, &err, ERR_INPUT);
        goto done;
    }
    for (uint32_t i = 0; i < sf->n_species; i++)
        if (!strcmp(sf->species[i].name, species_name)) sp = &sf->species[i];
    if (!sp) {
        char names[ERR_MSG_MAX / 2] = "";
        for (uint32_t i = 0, used = 0; i < sf->n_species && used < sizeof names; i++)
            used += (uint32_t)snprintf(names + used, sizeof names - used, " %s", sf->species[i].name);
        rc = cli_failf("tree-stats", ERR_INPUT, "%s has no species '%s'; its species are:%s", scene_path,
                       species_name, sf->n_species ? names : " (none)");
        goto done;
    }
    if (!sp->plugin) {
        err_at(&err, ERR_INPUT, sf->path, sp->line, sp->column,
               "species '%s' is a built-in shape, not a tree plugin's model", sp->name);
        rc = cli_fail("tree-stats", &err, ERR_INPUT);
        goto done;
    }
    if (run_species(sf, sp, reg, variants ? (uint32_t)variants : sp->variants, age, verbose, &err))
        rc = cli_fail("tree-stats", &err, ERR_PLUGIN);
done:
    scene_file_free(sf);
    plugin_registry_free(reg);
    return rc;
}
