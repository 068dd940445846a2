/* commands.h — one function per `sylva` command; argv[0] is the command name. Each returns the
 * process exit status and prints its results on stdout, messages on stderr. */
#ifndef SYLVA_CLI_COMMANDS_H
#define SYLVA_CLI_COMMANDS_H

/* `sylva plugins [--describe NAME]`: lists the plugins found (and the modules that could not be
 * used), or describes one plugin and its parameter schema. Exit status: 0 done, 1 usage error,
 * 2 no plugin called NAME, 4 out of memory. */
int cmd_plugins(int argc, char **argv);

/* `sylva render SCENE [options]`: renders to EXR and PNG (see cmd_render.c for options and
 * exit codes). */
int cmd_render(int argc, char **argv);
int cmd_export_pov(int argc, char **argv); /* `sylva export-pov SCENE`: POV-Ray 3.7 scene files (cmd_export_pov.c) */
int cmd_crosscheck(int argc, char **argv); /* `sylva crosscheck SCENE`: sylva vs POV-Ray, report (cmd_crosscheck.c) */
int cmd_simulate(int argc, char **argv); /* `sylva simulate SCENE`: the ecology alone, year by year (cmd_simulate.c) */
int cmd_factors(int argc, char **argv);  /* `sylva factors SCENE -o DIR`: the ecology's terrain factor maps (cmd_factors.c) */
int cmd_tree_stats(int argc, char **argv); /* `sylva tree-stats SCENE SPECIES`: a tree species' models in figures (cmd_tree_stats.c) */

#endif
