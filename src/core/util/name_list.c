/* name_list.c — the names of a list separated by spaces or commas (name_list.h). */
#include "util/name_list.h"

#include <string.h>

#define NAME_LIST_SEPARATORS " ,\t"

size_t name_list_next(const char **text, const char **name)
{
    const char *p = *text + strspn(*text, NAME_LIST_SEPARATORS);
    size_t len = strcspn(p, NAME_LIST_SEPARATORS);
    *name = p, *text = p + len;
    return len;
}
