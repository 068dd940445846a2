/* commands.h — the `sylva` commands: one function per command, and the table the command line
 * dispatches from and lists in `sylva --help`. argv[0] is the command name; each function
 * returns the process exit status (cli_status.h) and prints its results on stdout, messages on
 * stderr. Each command's --help gives its options. */
#ifndef SYLVA_CLI_COMMANDS_H
#define SYLVA_CLI_COMMANDS_H

int cmd_render(int argc, char **argv);     /* cmd_render.c */
int cmd_plugins(int argc, char **argv);    /* cmd_plugins.c */
int cmd_export_pov(int argc, char **argv); /* cmd_export_pov.c */
int cmd_crosscheck(int argc, char **argv); /* cmd_crosscheck.c */
int cmd_simulate(int argc, char **argv);   /* cmd_simulate.c */
int cmd_factors(int argc, char **argv);    /* cmd_factors.c */
int cmd_tree_stats(int argc, char **argv); /* cmd_tree_stats.c */
int cmd_probe(int argc, char **argv);      /* cmd_probe.c */
int cmd_ztv(int argc, char **argv);        /* cmd_ztv.c */
int cmd_montage(int argc, char **argv);    /* cmd_montage.c */
int cmd_study(int argc, char **argv);      /* cmd_study.c */

typedef struct sylva_command {
    const char *name;                 /* as typed after `sylva` */
    int (*run)(int argc, char **argv);
    const char *synopsis;             /* arguments for `sylva --help`, e.g. "SCENE SPECIES" */
    const char *summary;              /* one line for `sylva --help` */
} sylva_command;

/* Every command, in the order `sylva --help` lists them; the last entry's name is NULL. */
extern const sylva_command sylva_commands[];

/* The command called `name`, or NULL. */
const sylva_command *sylva_command_find(const char *name);

#endif
