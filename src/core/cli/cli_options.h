/* cli_options.h — a command's options as one declarative table: each row names the option, the
 * kind of value it takes (flag, whole number or number in a range, text, path, choice, WxH
 * size, or a parser of the command's own), its help text and where the value goes. One
 * function parses argv against the table and one prints `--help` from the same rows, with the
 * usage line (the synopsis README.md shows) generated from them too. Errors name the command,
 * the option, the value and what would be valid; every one is a usage error (exit status 1). */
#ifndef SYLVA_CLI_OPTIONS_H
#define SYLVA_CLI_OPTIONS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef enum cli_option_type {
    CLI_FLAG,   /* no value: the target (an integer of target_size bytes) becomes 1 */
    CLI_WHOLE,  /* a whole number in [min, max] into an unsigned integer of target_size bytes */
    CLI_NUMBER, /* a number in [low, high] (or (low, high] with CLI_OPEN_LOW) into a double */
    CLI_TEXT,   /* any text, kept as a const char * into argv */
    CLI_PATH,   /* a file or folder, not empty, kept as a const char * */
    CLI_CHOICE, /* one of choices[], its index into an int */
    CLI_SIZE,   /* WIDTHxHEIGHT, each side in [1, CLI_SIZE_MAX], into two uint32_t */
    CLI_CUSTOM, /* parse(cmd, option, value, target) reads it; prints why and gives -1 when bad */
    CLI_ACTION, /* no value: action() is called */
    CLI_HELP    /* no value: the help on stdout, and the command ends with exit status 0 */
} cli_option_type;

enum {
    CLI_REQUIRED = 1, /* the command needs it: shown without brackets in the synopsis */
    CLI_COMMON = 2,   /* taken alike by every scene command (-q, -v, -h, ...): not in the synopsis */
    CLI_OPEN_LOW = 4, /* CLI_NUMBER: low itself is refused */
    CLI_DEFAULT = 8   /* CLI_NUMBER: the help adds "(default X)" from the target's value */
};

typedef struct cli_option {
    const char *names;  /* every spelling, ", "-separated, short first: "-o, --output" */
    cli_option_type type;
    const char *value;  /* the value's name in the help: "N", "FILE", "WxH"; NULL for none */
    const char *help;   /* one paragraph; the help printer wraps it */
    void *target;       /* where the value goes (see the types); NULL for an action or help */
    size_t target_size; /* bytes of an integer target */
    void *target2;      /* CLI_SIZE: the height (target: the width) */
    uint64_t min, max;  /* CLI_WHOLE */
    double low, high;   /* CLI_NUMBER */
    const char *unit;   /* CLI_NUMBER: "metres", "a number" */
    const char *const *choices; /* CLI_CHOICE: NULL-terminated */
    int (*parse)(const char *cmd, const char *option, const char *value, void *target); /* CLI_CUSTOM */
    void (*action)(void); /* CLI_ACTION */
    int *given;         /* may be NULL: counts the times the option is given */
    unsigned flags;     /* CLI_REQUIRED, CLI_COMMON, CLI_OPEN_LOW, CLI_DEFAULT */
} cli_option;

/* Rows, written beside the variables they fill. */
#define CLI_OPT_FLAG(n, var, h) {.names = n, .type = CLI_FLAG, .help = h, .target = &(var), .target_size = sizeof(var)}
#define CLI_OPT_WHOLE(n, v, var, lo, hi, h) \
    {.names = n, .type = CLI_WHOLE, .value = v, .help = h, .target = &(var), .target_size = sizeof(var), .min = lo, .max = hi}
#define CLI_OPT_NUMBER(n, v, u, var, lo, hi, fl, h) \
    {.names = n, .type = CLI_NUMBER, .value = v, .unit = u, .help = h, .target = &(var), .low = lo, .high = hi, .flags = fl}
#define CLI_OPT_TEXT(n, v, var, h) {.names = n, .type = CLI_TEXT, .value = v, .help = h, .target = &(var)}
#define CLI_OPT_PATH(n, v, var, h) {.names = n, .type = CLI_PATH, .value = v, .help = h, .target = &(var)}
#define CLI_OPT_CHOICE(n, var, list, h) {.names = n, .type = CLI_CHOICE, .help = h, .target = &(var), .choices = list}
#define CLI_OPT_SIZE(n, w, ht, h) {.names = n, .type = CLI_SIZE, .value = "WxH", .help = h, .target = &(w), .target2 = &(ht)}
/* -h, --help, the last row of every table. */
#define CLI_OPT_HELP {.names = "-h, --help", .type = CLI_HELP, .help = "this text", .flags = CLI_COMMON}
/* The rows every command on a scene file takes: -q, --allow-gdal-virtual, -v (into the
 * build_options bo), then -h. */
#define CLI_OPTS_SCENE_COMMON(bo)                                                                              \
    {.names = "-q, --quiet", .type = CLI_FLAG, .target = &(bo).quiet, .target_size = sizeof((bo).quiet),       \
     .flags = CLI_COMMON, .help = "no progress or information lines (warnings and errors still print)"},       \
    {.names = "--allow-gdal-virtual", .type = CLI_ACTION, .action = cli_allow_gdal_virtual, .flags = CLI_COMMON, \
     .help = "let the scene name GDAL virtual paths, URLs and connection strings (these may reach the "         \
             "network; refused otherwise)"},                                                                   \
    {.names = "-v, --verbose", .type = CLI_FLAG, .target = &(bo).verbose, .target_size = sizeof((bo).verbose), \
     .flags = CLI_COMMON, .help = "plugin debug messages"},                                                    \
    CLI_OPT_HELP

/* Help shared by the commands that take these options. */
#define CLI_HELP_VIEWPOINT "the view from the scene's viewpoint NAME (its viewpoints: section) instead of its camera"
#define CLI_HELP_SEASON                                                                                       \
    "the plants on season S (spring, summer, autumn, winter) or date YYYY-MM-DD, instead of the scene's "    \
    "season: key"

/* --year N: the scene's planting plan N years after planting (into the build_options bo). */
#define CLI_OPT_YEAR(bo)                                                                                      \
    {.names = "--year", .type = CLI_NUMBER, .value = "N", .unit = "years", .target = &(bo).planting_years,     \
     .low = 0, .high = 10000, .given = &(bo).planting_shown,                                                  \
     .help = "the planting plan (planting:) N years after planting: its plants grown to their age then and "  \
             "its fellings made (default: the scene as it stands before the plan)"}

/* A command's table and the text around it in its help. */
typedef struct cli_command_spec {
    const char *name;          /* "render" */
    const char *operands;      /* in the synopsis after the name: "SCENE", "SCENE E N" */
    const char *about;         /* the paragraphs between the usage line and the options */
    const char *options_title; /* "options:" when NULL */
    const cli_option *options;
    size_t n_options;
    const char *epilogue;      /* after the options: notes and the exit statuses */
    /* Every argument that is not an option of the table, in order: returns 0, or -1 after
     * printing why (an unknown option, an extra operand). ctx is the spec's. Last, with arg
     * NULL: 0 when the operands are complete, -1 (printing nothing) when one is missing. */
    int (*operand)(void *ctx, const char *cmd, const char *arg);
    void *ctx;
} cli_command_spec;

/* The results of cli_options_parse besides 0. */
enum { CLI_PARSED = 0, CLI_PARSE_HELP = -1, CLI_PARSE_BAD = -2 };

/* The most rows a table may have. */
#define CLI_OPTIONS_MAX 32

/* Parses argv[1..argc) (argv[0]: the command) against spec: options as `--name VALUE` or
 * `--name=VALUE`, the rest to spec->operand. Returns CLI_PARSED; CLI_PARSE_HELP after printing
 * the help on stdout (-h); CLI_PARSE_BAD after printing "sylva CMD: ..." on stderr, or the help
 * on stderr when a required option or an operand is missing. A command returns
 * cli_options_status(result) for the last two. */
int cli_options_parse(const cli_command_spec *spec, int argc, char **argv);
/* EXIT_OK for CLI_PARSE_HELP, EXIT_USAGE for CLI_PARSE_BAD. */
int cli_options_status(int parsed);

/* The help: the usage line (cli_options_synopsis), about, the options, epilogue. */
void cli_options_help(const cli_command_spec *spec, FILE *out);
/* "sylva CMD OPERANDS [-o FILE] [--spp N] ...": every row not CLI_COMMON, the required ones
 * without brackets. Written into out (n bytes, cut short when longer). */
void cli_options_synopsis(const cli_command_spec *spec, char *out, size_t n);

/* The operand handler of a command that takes one scene file: ctx is a const char ** that gets
 * it (cli_scene_argument). */
int cli_operand_scene(void *ctx, const char *cmd, const char *arg);
/* --allow-gdal-virtual: GDAL virtual paths, URLs and connection strings, and PROJ's network. */
void cli_allow_gdal_virtual(void);

#endif
