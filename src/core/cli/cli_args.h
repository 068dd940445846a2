/* cli_args.h — strict parsing of command-line numbers, sizes and the scene argument, with
 * messages that name the option and what would be valid; the scene file's stem for default
 * output names. */
#ifndef SYLVA_CLI_ARGS_H
#define SYLVA_CLI_ARGS_H

#include <stddef.h>
#include <stdint.h>

#include "util/err.h"

/* Parses an unsigned integer in [lo, hi]; prints "sylva OPTION: ..." and returns -1 when bad. */
int cli_parse_u64(const char *cmd, const char *opt, const char *s, uint64_t lo, uint64_t hi, uint64_t *out);
/* An argument of a command that takes one scene file: an unknown option or a second file is
 * reported ("sylva CMD: ...") and gives -1; otherwise *scene_path is set and 0 returned. */
int cli_scene_argument(const char *cmd, const char *arg, const char **scene_path);
/* The scene file's name without its folder and extension ("scenes/a.yaml" gives "a"), written
 * into out between prefix and suffix. Returns -1 when that does not fit in n bytes. */
int cli_scene_stem(const char *scene_path, const char *prefix, const char *suffix, char *out, size_t n);
/* The largest side of an image --size takes. */
#define CLI_SIZE_MAX 16384u
/* Parses "WxH" with each side in [1, CLI_SIZE_MAX]; a side too long for any integer type is
 * refused as out of range, never wrapped. */
int cli_parse_size(const char *cmd, const char *opt, const char *s, uint32_t *w, uint32_t *h);

#endif
