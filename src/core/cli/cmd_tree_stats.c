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
#include "cli/commands.h"
#include "plugin/plugin_host.h"
#include "scene/host.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "scene/scene_build.h"
#include "scene/scene_file.h"

static void tree_stats_usage(FILE *out)
{
    fprintf(out,
            "usage: sylva tree-stats SCENE SPECIES [options]\n"
            "Builds the age variants of SPECIES (a tree-plugin species of SCENE) as `sylva render`\n"
            "would and prints, for each: age, recursion level, symbols, segments, leaves, branches,\n"
            "triangles, height and bounding box in metres, the box-counting dimension D_B of its\n"
            "silhouette, and the branch-number law's D and target branch count N2 where the law chose\n"
            "the level.\n\n"
            "options:\n"
            "  --variants N   build N age variants (ages 1/N, 2/N, ..., 1) instead of the species'\n"
            "  --age A        build one model at normalised age A in (0, 1]\n"
            "  -v, --verbose  plugin debug messages\n"
            "  -h, --help     this text\n\n"
            "exit status: 0 done, 1 usage, 2 bad scene, unknown species or plugin failure,\n"
            "4 out of memory or internal error\n");
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

/* Builds and prints the variants; returns the exit status. */
static int run_species(const scene_file *sf, const species_spec *sp, const loaded_plugin *lp, uint32_t n_variants,
                       double only_age, int verbose)
{
    const sylva_tree_stats_v1 *ext = lp->desc->extension ? lp->desc->extension(SYLVA_TREE_STATS_V1) : NULL;
    if (!ext || ext->size < offsetof(sylva_tree_stats_v1, last_stats) + sizeof ext->last_stats || !ext->last_stats) {
        fprintf(stderr, "sylva tree-stats: tree plugin '%s' (%s) does not report statistics (no \"%s\" interface)\n",
                sp->plugin, lp->file, SYLVA_TREE_STATS_V1);
        return EXIT_INPUT;
    }
    scene *sc = scene_new();
    if (!sc) {
        fprintf(stderr, "sylva tree-stats: out of memory\n");
        return EXIT_INTERNAL;
    }
    err_buf err = {{0}};
    char context[200];
    snprintf(context, sizeof context, "tree plugin '%s' for species '%s'", sp->plugin, sp->name);
    /* The same seeds as the scene build, so the figures describe the models a render uses. */
    sylva_host h;
    host_init(&h, sc, sf->dir, scene_species_seed(sf, sp->name, 0), context, &err);
    h.verbose = verbose, h.quiet = 1, h.kind = SYLVA_KIND_TREE;
    const sylva_host_api *api = host_api_table();
    void *state = NULL;
    int rc = lp->desc->create(api, &h, sp->params, &state);
    if (rc) {
        fprintf(stderr, "%s:%u:%u: %s (%s): create failed: %s\n", sf->path, sp->line, sp->column, context, lp->file,
                err.msg[0] ? err.msg : "no reason given");
        host_release(&h);
        scene_free(sc);
        return EXIT_INPUT;
    }
    printf("species %s: plugin %s (%s)\n", sp->name, sp->plugin, lp->file);
    printf("%-7s %-6s %-5s %-11s %-9s %-8s %-8s %-16s %-10s %-8s %-36s  %s\n", "variant", "age", "level", "symbols",
           "segments", "leaves", "branches", "N2 eq.6", "triangles", "height", "bounding box (m)", "D_B");
    int status = EXIT_OK;
    uint32_t count = only_age > 0 ? 1 : n_variants;
    for (uint32_t v = 0; v < count && status == EXIT_OK; v++) {
        mesh *m = mesh_new();
        if (!m) {
            fprintf(stderr, "sylva tree-stats: out of memory\n");
            status = EXIT_INTERNAL;
            break;
        }
        h.seed = scene_species_seed(sf, sp->name, v);
        sylva_tree_request req = {.size = sizeof req, .age = only_age > 0 ? only_age : (double)(v + 1) / count,
                                  .variant = v, .n_variants = count, .lod = 0, .seed = h.seed};
        sylva_tree_out out = {.size = sizeof out, .mesh = m};
        err_clear(&err);
        rc = lp->desc->generate(state, api, &h, &req, &out);
        sylva_tree_stats st = {.size = sizeof st};
        if (rc) {
            fprintf(stderr, "%s:%u:%u: %s (%s): generate failed for variant %u: %s\n", sf->path, sp->line, sp->column,
                    context, lp->file, v, err.msg[0] ? err.msg : "no reason given");
            status = EXIT_INPUT;
        } else if (ext->last_stats(state, &st)) {
            fprintf(stderr, "sylva tree-stats: %s gave no statistics for variant %u\n", context, v);
            status = EXIT_INPUT;
        } else {
            print_row(v, &st);
        }
        mesh_free(m);
    }
    lp->desc->destroy(state);
    host_release(&h);
    scene_free(sc);
    return status;
}

int cmd_tree_stats(int argc, char **argv)
{
    const char *scene_path = NULL, *species_name = NULL;
    uint64_t variants = 0;
    double age = 0;
    int verbose = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            tree_stats_usage(stdout);
            return EXIT_OK;
        } else if (!strcmp(a, "--variants")) {
            if (!val) goto missing;
            if (cli_parse_u64("tree-stats", a, val, 1, 64, &variants)) return EXIT_USAGE;
            i++;
        } else if (!strcmp(a, "--age")) {
            if (!val) goto missing;
            char *end = NULL;
            age = strtod(val, &end);
            if (!end || *end || !(age > 0 && age <= 1)) {
                fprintf(stderr, "sylva tree-stats: --age must be a number in (0, 1], got '%s'\n", val);
                return EXIT_USAGE;
            }
            i++;
        } else if (!strcmp(a, "-v") || !strcmp(a, "--verbose")) {
            verbose = 1;
        } else if (a[0] == '-') {
            fprintf(stderr, "sylva tree-stats: unknown option '%s' (see sylva tree-stats --help)\n", a);
            return EXIT_USAGE;
        } else if (!scene_path) {
            scene_path = a;
        } else if (!species_name) {
            species_name = a;
        } else {
            fprintf(stderr, "sylva tree-stats: one scene and one species; '%s' is extra\n", a);
            return EXIT_USAGE;
        }
        continue;
    missing:
        fprintf(stderr, "sylva tree-stats: %s needs a value\n", a);
        return EXIT_USAGE;
    }
    if (!scene_path || !species_name) {
        tree_stats_usage(stderr);
        return EXIT_USAGE;
    }
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open(&err);
    if (!reg) {
        fprintf(stderr, "sylva tree-stats: %s\n", err.msg);
        return EXIT_INTERNAL;
    }
    int rc = EXIT_INPUT;
    scene_file *sf = scene_file_load(scene_path, reg, &err);
    if (!sf) {
        fprintf(stderr, "%s\n", err.msg);
        goto done;
    }
    const species_spec *sp = NULL;
    for (uint32_t i = 0; i < sf->n_species; i++)
        if (!strcmp(sf->species[i].name, species_name)) sp = &sf->species[i];
    if (!sp) {
        fprintf(stderr, "sylva tree-stats: %s has no species '%s'; its species are:", scene_path, species_name);
        for (uint32_t i = 0; i < sf->n_species; i++) fprintf(stderr, " %s", sf->species[i].name);
        fprintf(stderr, "%s\n", sf->n_species ? "" : " (none)");
        goto done;
    }
    if (!sp->plugin) {
        fprintf(stderr, "%s:%u:%u: species '%s' is a built-in shape, not a tree plugin's model\n", sf->path, sp->line,
                sp->column, sp->name);
        goto done;
    }
    const loaded_plugin *lp = plugin_registry_find(reg, sp->plugin, SYLVA_KIND_TREE, &err);
    if (!lp) {
        fprintf(stderr, "%s:%u:%u: %s\n", sf->path, sp->line, sp->column, err.msg);
        goto done;
    }
    rc = run_species(sf, sp, lp, variants ? (uint32_t)variants : sp->variants, age, verbose);
done:
    scene_file_free(sf);
    plugin_registry_free(reg);
    return rc;
}
