/* ply_check.h — checks that a PLY file is whole before Assimp reads it: Assimp 5.2's PLY reader
 * loops forever, aborts or crashes on a header without end_header or a body shorter than the
 * header declares, and aborts on a face that lists no vertices, so model_import asks this first. It reads the header and walks the body
 * (binary: every scalar and list; ASCII: every number, each item on a line of its own as Assimp
 * reads it) without keeping any of it. Where Assimp would read the header otherwise than the PLY
 * format says without failing (an element it does not know, whose items it takes for none,
 * before one it knows; a property after an obj_info line, which it drops), the file is refused.
 *
 * Nothing is allocated past the call; the file is read into memory for the walk and freed. */
#ifndef SYLVA_PLY_CHECK_H
#define SYLVA_PLY_CHECK_H

#include "util/err.h"

/* 0 when the file's header is well formed, its body holds every element item it declares and
 * no face lists zero vertices; -1 with err set ("path:line: what is wrong", ERR_INPUT) otherwise. */
int ply_check(const char *path, err_buf *err);

#endif
