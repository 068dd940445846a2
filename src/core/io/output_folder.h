/* output_folder.h — the folder a command writes its files into, created when missing. */
#ifndef SYLVA_OUTPUT_FOLDER_H
#define SYLVA_OUTPUT_FOLDER_H

#include "util/err.h"

/* Creates the output folder `dir` when it does not exist (its parent must). Returns 0, or -1
 * with err (ERR_OUTPUT). */
int output_folder_make(const char *dir, err_buf *err);

#endif
