/* scene_file_keys.c — reading keys: a mapping whose keys two schemas share (a species' host
 * keys and its tree plugin's, an object's keys and its shape's) validated in two passes that
 * each skip the other's keys, a host key's spec by name, vectors copied out of values, and
 * strings formatted into the loader's arena. */
#include "scene_file/scene_file_loader.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

const char *sf_arena_printf(arena *a, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0) return NULL;
    char *s = arena_alloc(a, (size_t)n + 1);
    if (!s) return NULL;
    va_start(ap, fmt);
    vsnprintf(s, (size_t)n + 1, fmt, ap);
    va_end(ap);
    return s;
}

/* Names of a schema's keys followed by extra names, NULL entries dropped. */
static const char **key_names(arena *a, const sylva_param_spec *spec, uint32_t n,
                              const char *const *extra, uint32_t n_extra, uint32_t *count)
{
    const char **names = arena_alloc(a, ((size_t)n + n_extra + 1) * sizeof *names);
    if (!names) return NULL;
    uint32_t k = 0;
    for (uint32_t i = 0; i < n; i++) names[k++] = spec[i].name;
    for (uint32_t i = 0; i < n_extra; i++)
        if (extra[i]) names[k++] = extra[i];
    *count = k;
    return names;
}

/* Validates a mapping that two schemas share: `own` (host keys) and `other` (a plugin's or a
 * shape's keys), plus an optional extra key owned by neither (the species' ecology block). */
int sf_validate_shared(loader *L, const ynode *map, const param_scope *base,
                       const sylva_param_spec *own, uint32_t n_own,
                       const sylva_param_spec *other, uint32_t n_other, const char *extra,
                       const sylva_params **own_out, const sylva_params **other_out)
{
    uint32_t n1, n2;
    const char **other_keys = key_names(L->a, other, n_other, &extra, 1, &n1);
    const char **own_keys = key_names(L->a, own, n_own, &extra, 1, &n2);
    if (!other_keys || !own_keys) return sf_out_of_memory(L);
    param_scope s1 = *base, s2 = *base;
    s1.host_keys = other_keys, s1.n_host_keys = n1;
    s2.host_keys = own_keys, s2.n_host_keys = n2;
    if (params_validate(L->a, map, own, n_own, &s1, own_out, L->err)) return -1;
    return params_validate(L->a, map, other, n_other, &s2, other_out, L->err);
}

void sf_copy3(double out[3], const sylva_value *v)
{
    for (int k = 0; k < 3; k++) out[k] = v->list[k];
}

double sf_length3(const double v[3]) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/* The spec of one host key (tables are static; every name asked for exists). */
const sylva_param_spec *sf_host_key(const host_schema *schema, const char *name)
{
    for (uint32_t k = 0; k < schema->n_params; k++)
        if (!strcmp(schema->params[k].name, name)) return &schema->params[k];
    return &schema->params[0];
}
