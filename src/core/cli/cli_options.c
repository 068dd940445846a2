/* cli_options.c — one parser and one help printer for every command's option table
 * (cli_options.h). */
#include "cli/cli_options.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_args.h"
#include "cli/cli_status.h"
#include "site/proj_network.h"
#include "util/file_check.h"

#define HELP_WIDTH 90     /* columns the help is wrapped to */
#define NAMES_COLUMN 24   /* widest names column; longer names put their help on the next line */

void cli_allow_gdal_virtual(void)
{
    file_allow_gdal_virtual(1);
    proj_network_allow(1);
}

int cli_operand_scene(void *ctx, const char *cmd, const char *arg)
{
    if (!arg) return *(const char **)ctx ? 0 : -1;
    return cli_scene_argument(cmd, arg, ctx);
}

int cli_options_status(int parsed)
{
    return parsed == CLI_PARSE_HELP ? EXIT_OK : EXIT_USAGE;
}

/* Whether `a` (up to len bytes) is one of the row's spellings. */
static int row_named(const cli_option *o, const char *a, size_t len)
{
    for (const char *s = o->names; *s;) {
        size_t l = strcspn(s, ",");
        if (l == len && !strncmp(s, a, len)) return 1;
        s += l;
        while (*s == ',' || *s == ' ') s++;
    }
    return 0;
}

static int takes_value(const cli_option *o)
{
    return o->type != CLI_FLAG && o->type != CLI_ACTION && o->type != CLI_HELP;
}

/* The row `a` names, with *inline_value set for "--name=VALUE". */
static const cli_option *find_row(const cli_command_spec *spec, const char *a, const char **inline_value)
{
    *inline_value = NULL;
    const char *eq = !strncmp(a, "--", 2) ? strchr(a, '=') : NULL;
    for (size_t k = 0; k < spec->n_options; k++) {
        const cli_option *o = &spec->options[k];
        if (row_named(o, a, strlen(a))) return o;
        if (eq && takes_value(o) && row_named(o, a, (size_t)(eq - a))) {
            *inline_value = eq + 1;
            return o;
        }
    }
    return NULL;
}

static void store_uint(void *target, size_t size, uint64_t v)
{
    switch (size) {
    case 1: *(uint8_t *)target = (uint8_t)v; break;
    case 2: *(uint16_t *)target = (uint16_t)v; break;
    case 4: *(uint32_t *)target = (uint32_t)v; break;
    default: *(uint64_t *)target = v; break;
    }
}

/* "a, b or c" into out. */
static void choice_list(const char *const *choices, const char *join, const char *last, char *out, size_t n)
{
    size_t used = 0;
    out[0] = '\0';
    for (size_t k = 0; choices[k] && used < n; k++)
        used += (size_t)snprintf(out + used, n - used, "%s%s", k == 0 ? "" : choices[k + 1] ? join : last, choices[k]);
}

static int parse_number(const char *cmd, const char *opt, const cli_option *o, const char *s)
{
    char *end;
    double v = strtod(s, &end);
    int open = o->flags & CLI_OPEN_LOW;
    if (end == s || *end || !isfinite(v) || !(open ? v > o->low : v >= o->low) || !(v <= o->high)) {
        if (open)
            fprintf(stderr, "sylva %s: %s must be %s in (%g, %g], got '%s'\n", cmd, opt, o->unit, o->low, o->high, s);
        else
            fprintf(stderr, "sylva %s: %s expects %s from %g to %g, got '%s'\n", cmd, opt, o->unit, o->low, o->high, s);
        return -1;
    }
    *(double *)o->target = v;
    return 0;
}

static int parse_choice(const char *cmd, const char *opt, const cli_option *o, const char *s)
{
    for (int k = 0; o->choices[k]; k++)
        if (!strcmp(o->choices[k], s)) {
            *(int *)o->target = k;
            return 0;
        }
    char list[256];
    choice_list(o->choices, ", ", " or ", list, sizeof list);
    fprintf(stderr, "sylva %s: %s expects %s, got '%s'\n", cmd, opt, list, s);
    return -1;
}

/* Reads value s of row o, typed as opt. Returns 0, or -1 after printing why. */
static int parse_value(const char *cmd, const char *opt, const cli_option *o, const char *s)
{
    uint64_t v;
    switch (o->type) {
    case CLI_WHOLE:
        if (cli_parse_u64(cmd, opt, s, o->min, o->max, &v)) return -1;
        store_uint(o->target, o->target_size, v);
        return 0;
    case CLI_NUMBER: return parse_number(cmd, opt, o, s);
    case CLI_CHOICE: return parse_choice(cmd, opt, o, s);
    case CLI_SIZE: return cli_parse_size(cmd, opt, s, o->target, o->target2);
    case CLI_CUSTOM: return o->parse(cmd, opt, s, o->target);
    case CLI_PATH:
        if (!*s) {
            fprintf(stderr, "sylva %s: %s expects a path, got ''\n", cmd, opt);
            return -1;
        }
        /* fall through */
    default: *(const char **)o->target = s; return 0;
    }
}

/* Whether every CLI_REQUIRED row was given (counted in given[]) and the operands are complete. */
static int complete(const cli_command_spec *spec, const int *given)
{
    for (size_t k = 0; k < spec->n_options; k++)
        if ((spec->options[k].flags & CLI_REQUIRED) && !given[k]) return 0;
    return !spec->operand(spec->ctx, spec->name, NULL);
}

int cli_options_parse(const cli_command_spec *spec, int argc, char **argv)
{
    int given[CLI_OPTIONS_MAX] = {0};
    if (spec->n_options > CLI_OPTIONS_MAX) return CLI_PARSE_BAD;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *val;
        const cli_option *o = find_row(spec, a, &val);
        if (!o) {
            if (spec->operand(spec->ctx, spec->name, a)) return CLI_PARSE_BAD;
            continue;
        }
        char opt[64]; /* the option as typed, without "=VALUE" */
        snprintf(opt, sizeof opt, "%.*s", val ? (int)(val - 1 - a) : (int)strlen(a), a);
        if (o->type == CLI_HELP) {
            cli_options_help(spec, stdout);
            return CLI_PARSE_HELP;
        }
        if (o->type == CLI_FLAG) store_uint(o->target, o->target_size, 1);
        else if (o->type == CLI_ACTION) o->action();
        else {
            if (!val && i + 1 < argc) val = argv[++i];
            if (!val) {
                fprintf(stderr, "sylva %s: %s needs a value (%s %s)\n", spec->name, opt, opt, o->value ? o->value : "");
                return CLI_PARSE_BAD;
            }
            if (parse_value(spec->name, opt, o, val)) return CLI_PARSE_BAD;
        }
        if (o->given) (*o->given)++;
        given[o - spec->options]++;
    }
    if (!complete(spec, given)) {
        cli_options_help(spec, stderr);
        return CLI_PARSE_BAD;
    }
    return CLI_PARSED;
}

/* The value's name in the synopsis and the help: "N", or a choice's "a|b|c". */
static void value_name(const cli_option *o, char *out, size_t n)
{
    if (o->type == CLI_CHOICE) choice_list(o->choices, "|", "|", out, n);
    else snprintf(out, n, "%s", takes_value(o) && o->value ? o->value : "");
}

void cli_options_synopsis(const cli_command_spec *spec, char *out, size_t n)
{
    size_t used = (size_t)snprintf(out, n, "sylva %s%s%s", spec->name, *spec->operands ? " " : "", spec->operands);
    for (size_t k = 0; k < spec->n_options && used < n; k++) {
        const cli_option *o = &spec->options[k];
        if (o->flags & CLI_COMMON) continue;
        char v[256];
        value_name(o, v, sizeof v);
        int req = o->flags & CLI_REQUIRED;
        used += (size_t)snprintf(out + used, n - used, " %s%.*s%s%s%s", req ? "" : "[", (int)strcspn(o->names, ","),
                                 o->names, *v ? " " : "", v, req ? "" : "]");
    }
}

/* Prints text from column `indent` (the first line already there), wrapped at HELP_WIDTH. */
static void wrap(FILE *out, const char *text, int indent)
{
    int col = indent;
    for (const char *s = text; *s;) {
        size_t w = strcspn(s, " ");
        if (col > indent && col + 1 + (int)w > HELP_WIDTH) {
            fprintf(out, "\n%*s", indent, "");
            col = indent;
        } else if (col > indent) {
            fputc(' ', out), col++;
        }
        fwrite(s, 1, w, out);
        col += (int)w;
        s += w;
        while (*s == ' ') s++;
    }
    fputc('\n', out);
}

void cli_options_help(const cli_command_spec *spec, FILE *out)
{
    char line[2048];
    cli_options_synopsis(spec, line, sizeof line);
    fprintf(out, "usage: %s\n%s\n%s\n", line, spec->about, spec->options_title ? spec->options_title : "options:");
    int column = 0;
    for (size_t k = 0; k < spec->n_options; k++) {
        char v[256];
        value_name(&spec->options[k], v, sizeof v);
        int w = (int)(strlen(spec->options[k].names) + (*v ? 1 + strlen(v) : 0));
        if (w > column && w + 4 <= NAMES_COLUMN) column = w;
    }
    column += 4; /* two spaces before, two after */
    for (size_t k = 0; k < spec->n_options; k++) {
        const cli_option *o = &spec->options[k];
        char v[256], help[1024];
        value_name(o, v, sizeof v);
        int w = fprintf(out, "  %s%s%s", o->names, *v ? " " : "", v);
        if (w + 2 > column) fprintf(out, "\n%*s", column, "");
        else fprintf(out, "%*s", column - w, "");
        snprintf(help, sizeof help, "%s", o->help);
        if (o->flags & CLI_DEFAULT)
            snprintf(help + strlen(help), sizeof help - strlen(help), " (default %g)", *(const double *)o->target);
        wrap(out, help, column);
    }
    if (spec->epilogue) fprintf(out, "\n%s", spec->epilogue);
}
