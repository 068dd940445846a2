/* name_list.h — names separated by spaces or commas ("existing, proposed", "north east,west"),
 * as a scene file's keys that name several things and the command line's lists give them. */
#ifndef SYLVA_NAME_LIST_H
#define SYLVA_NAME_LIST_H

#include <stddef.h>

/* The next name of *text: its length, with *name at its first character and *text moved past
 * it; 0 when none is left. */
size_t name_list_next(const char **text, const char **name);

#endif
