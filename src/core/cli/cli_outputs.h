/* cli_outputs.h — a command's outputs checked against what it reads before anything is
 * written: no output may be the scene file, a file it includes or names (a DTM, a layout, a
 * model, a saved forest, a photograph), a file the command line gives to read (--load), nor
 * another of the outputs. Files are compared by what they are (io/output_guard.h), not by how
 * they are spelled. */
#ifndef SYLVA_CLI_OUTPUTS_H
#define SYLVA_CLI_OUTPUTS_H

#include <stdint.h>

#include "scene_file/scene_file.h"

/* A file the command line names: its path (NULL: not given) and the option that gave it. */
typedef struct cli_file {
    const char *path;
    const char *option; /* "-o", "--save", "--load" */
} cli_file;

/* Lists sf's files and the extra inputs with the output guard, so that no output the command
 * makes later (the files in an output folder, POV-Ray includes) replaces one either, then checks
 * the outputs named now. Returns EXIT_OK, or EXIT_USAGE after printing "sylva CMD: ..." with
 * both files named (the exit status of running out of memory when listing fails). */
int cli_outputs_check(const char *cmd, const scene_file *sf, const cli_file *inputs, uint32_t n_inputs,
                      const cli_file *outputs, uint32_t n_outputs);

#endif
