/* scene_file_messages.c — how the scene loader says what is wrong: a message at
 * file:line:column, running out of memory, a section that is not a list, and an unknown name
 * with the nearest defined one or the list of defined ones. */
#include "scene_file/scene_file_loader.h"

#include <stdarg.h>
#include <stdio.h>

int sf_located(err_buf *err, const char *file, uint32_t line, uint32_t column,
               const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    err_vat(err, ERR_INPUT, file, line, column, fmt, ap);
    va_end(ap);
    return -1;
}

int sf_out_of_memory(loader *L)
{
    return err_nomem(L->err, "%s: out of memory while loading", L->file);
}

int sf_expect_list(loader *L, const ynode *node, const char *section, const char *example)
{
    if (node->kind == YNODE_SEQUENCE) return 0;
    return sf_located(L->err, L->file, node->line, node->column,
                      "'%s' must be a list (%s), got %s", section, example, ynode_kind_phrase(node));
}

/* A list of names for messages: "a, b, c" (cut when long). */
void sf_name_list(const char *const *names, uint32_t n, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (uint32_t k = 0; k < n && used < size; k++)
        used += (size_t)snprintf(buf + used, size - used, "%s%s", k ? ", " : "", names[k]);
}

/* An unknown name of a `kind` ("material", "species") among the defined ones. */
int sf_unknown_name(loader *L, const char *file, const sylva_value *v, const char *kind,
                    const char *plural, const char *where, const char *const *defined,
                    uint32_t n_defined)
{
    const char *near = param_nearest_name(v->s, defined, n_defined);
    if (near)
        return sf_located(L->err, file, v->line, v->column,
                          "unknown %s '%s' in '%s'; did you mean '%s'?", kind, v->s, where, near);
    if (!n_defined)
        return sf_located(L->err, file, v->line, v->column,
                          "unknown %s '%s' in '%s'; the scene defines no %s", kind, v->s, where,
                          plural);
    char list[1024];
    sf_name_list(defined, n_defined, list, sizeof list);
    return sf_located(L->err, file, v->line, v->column, "unknown %s '%s' in '%s'; defined %s are %s",
                      kind, v->s, where, plural, list);
}
