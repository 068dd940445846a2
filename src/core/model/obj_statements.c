/* obj_statements.c — point and line statements of an OBJ file turned into comments
 * (model/obj_statements.h). */
#include "model/obj_statements.h"

/* Where Assimp's OBJ reader ends a line. */
static int line_end(int c)
{
    return c == '\n' || c == '\r' || c == '\f' || c == '\0';
}

void obj_points_lines_as_comments(char *buf, size_t n, int before)
{
    int prev = before;
    for (size_t i = 0; i < n; i++) {
        int c = (unsigned char)buf[i];
        if ((prev < 0 || line_end(prev)) && (c == 'p' || c == 'l')) buf[i] = '#';
        prev = c;
    }
}
