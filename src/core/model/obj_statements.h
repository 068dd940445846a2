/* obj_statements.h — an OBJ file as sylva hands it to Assimp: its point ("p") and line ("l")
 * statements read as comments. sylva reads no points or lines (they are dropped after reading),
 * and Assimp 5.2's OBJ reader writes past the end of a mesh's vertex, normal and texture
 * coordinate arrays when a line statement lists a single vertex: it counts no vertex for it but
 * stores one, so the corner a later line statement duplicates lands one element beyond the
 * arrays. With every such statement a comment, that code never runs.
 *
 * Assimp starts a statement at the file's first byte and after every line end ('\n', '\r', '\f'
 * or a NUL byte; a line continued with a backslash resumes after a '\n'), and reads one whose
 * first byte is 'p' or 'l' as a point or line statement whatever follows. That byte becomes '#',
 * Assimp's comment: the file keeps its size and every offset, so it can be changed as it is read.
 */
#ifndef SYLVA_OBJ_STATEMENTS_H
#define SYLVA_OBJ_STATEMENTS_H

#include <stddef.h>

/* Turns into '#' every byte of buf[0..n) that starts a point or line statement; before is the
 * byte before buf[0] in the file, or -1 when buf starts the file. */
void obj_points_lines_as_comments(char *buf, size_t n, int before);

#endif
