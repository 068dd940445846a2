/* obj_check.h — an OBJ file's material library references checked before Assimp reads it.
 * Assimp 5.2 hands every file a model refers to through a filter that tidies the path, and that
 * filter reads past the end of a path ending with "://" (a "mtllib file://" line crashed the
 * program) or consisting of two backslashes alone. The file is read as Assimp's OBJ reader splits
 * it into statements (a line ends at '\n', '\r', '\f' or a NUL byte; a backslash before a line end
 * continues it past the next '\n', and the byte after that '\n' joins the statement whatever it is,
 * a backslash or a line end too), a piece at a time; nothing is allocated past the call. */
#ifndef SYLVA_OBJ_CHECK_H
#define SYLVA_OBJ_CHECK_H

#include "util/err.h"

/* 0 when no mtllib statement of the OBJ file at path names a library ending with "://" or
 * starting with two backslashes, and the file does not end with a backslash (Assimp takes one
 * there for a continuation into the end of its buffer and drops it, so "mtllib file://\" reached
 * the filter as "file://"); -1 with err set ("path:line: ...", ERR_INPUT) naming the first that
 * does, or when the file cannot be read. */
int obj_check(const char *path, err_buf *err);

#endif
