/* test_cli_options.c — one option table parsed and printed (cli/cli_options.h): each kind of
 * value reaches its target, `--name=VALUE` reads as `--name VALUE`, a bad value, a missing
 * value, a missing required option and a missing operand are refused, and the synopsis lists
 * the rows that are not common to every command. */
#include <string.h>

#include "harness.h"

#include "cli/cli_options.h"

typedef struct values {
    const char *scene, *out;
    uint32_t spp, width, height;
    uint64_t seed;
    int seed_given, flat, choice;
    double radius;
} values;

static const char *const colours[] = {"red", "green", "blue", NULL};

/* Parses the words of `line` (at most 16) with a table over v; v starts zeroed, choice -1. */
static int parse(const char *line, values *v)
{
    memset(v, 0, sizeof *v);
    v->choice = -1;
    const cli_option options[] = {
        {.names = "-o, --output", .type = CLI_PATH, .value = "DIR", .target = &v->out, .flags = CLI_REQUIRED,
         .help = "folder"},
        CLI_OPT_WHOLE("--spp", "N", v->spp, 1, 64, "samples"),
        {.names = "--seed", .type = CLI_WHOLE, .value = "N", .target = &v->seed, .target_size = sizeof v->seed,
         .max = UINT64_MAX, .given = &v->seed_given, .help = "seed"},
        CLI_OPT_SIZE("--size", v->width, v->height, "size"),
        CLI_OPT_NUMBER("--radius", "M", "metres", v->radius, 0, 10, CLI_OPEN_LOW, "radius"),
        CLI_OPT_CHOICE("--colour", v->choice, colours, "colour"),
        CLI_OPT_FLAG("--flat", v->flat, "flat"),
        CLI_OPT_HELP,
    };
    const cli_command_spec spec = {"test", "SCENE", "about\n", NULL, options, sizeof options / sizeof *options,
                                   "end\n", cli_operand_scene, &v->scene};
    char copy[256], *argv[17] = {"test"};
    int argc = 1;
    snprintf(copy, sizeof copy, "%s", line);
    for (char *w = strtok(copy, " "); w && argc < 17; w = strtok(NULL, " ")) argv[argc++] = w;
    static char synopsis[256];
    cli_options_synopsis(&spec, synopsis, sizeof synopsis);
    CHECK(!strcmp(synopsis, "sylva test SCENE -o DIR [--spp N] [--seed N] [--size WxH] [--radius M] "
                            "[--colour red|green|blue] [--flat]"));
    return cli_options_parse(&spec, argc, argv);
}

TEST(each_kind_reaches_its_target)
{
    values v;
    CHECK_INT(parse("a.yaml -o out --spp=8 --seed 0 --size 3x2 --radius 2.5 --colour blue --flat", &v), CLI_PARSED);
    CHECK(v.scene && !strcmp(v.scene, "a.yaml"));
    CHECK(v.out && !strcmp(v.out, "out"));
    CHECK_INT(v.spp, 8);
    CHECK_INT(v.seed_given, 1);
    CHECK_INT(v.width, 3);
    CHECK_INT(v.height, 2);
    CHECK_NEAR(v.radius, 2.5, 0);
    CHECK_INT(v.choice, 2);
    CHECK_INT(v.flat, 1);
    CHECK_INT(parse("a.yaml --output=out", &v), CLI_PARSED);
    CHECK_INT(v.seed_given, 0);
    CHECK_INT(v.choice, -1);
}

TEST(bad_lines_are_refused)
{
    values v;
    CHECK_INT(parse("a.yaml -o out --spp 65", &v), CLI_PARSE_BAD);      /* out of range */
    CHECK_INT(parse("a.yaml -o out --radius 0", &v), CLI_PARSE_BAD);    /* the open end */
    CHECK_INT(parse("a.yaml -o out --colour pink", &v), CLI_PARSE_BAD); /* not a choice */
    CHECK_INT(parse("a.yaml -o out --size 3x", &v), CLI_PARSE_BAD);
    CHECK_INT(parse("a.yaml -o out --spp", &v), CLI_PARSE_BAD);         /* no value */
    CHECK_INT(parse("a.yaml -o", &v), CLI_PARSE_BAD);
    CHECK_INT(parse("a.yaml -o ", &v), CLI_PARSE_BAD);
    CHECK_INT(parse("a.yaml", &v), CLI_PARSE_BAD);                      /* -o required */
    CHECK_INT(parse("-o out", &v), CLI_PARSE_BAD);                      /* no scene */
    CHECK_INT(parse("a.yaml b.yaml -o out", &v), CLI_PARSE_BAD);        /* two scenes */
    CHECK_INT(parse("a.yaml -o out --sppp 3", &v), CLI_PARSE_BAD);      /* unknown option */
    CHECK_INT(parse("--help", &v), CLI_PARSE_HELP);
    CHECK_INT(cli_options_status(CLI_PARSE_HELP), 0);
    CHECK_INT(cli_options_status(CLI_PARSE_BAD), 1);
}

TEST_LIST(TEST_CASE(each_kind_reaches_its_target), TEST_CASE(bad_lines_are_refused))
