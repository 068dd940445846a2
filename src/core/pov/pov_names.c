/* pov_names.c — identifiers and comment text for the POV-Ray exporter. */
#include "pov/pov_names.h"

#include <stdio.h>
#include <string.h>

static int is_alnum(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

void pov_clean_name(const char *name, char out[POV_CLEAN_MAX + 1])
{
    size_t n = 0;
    int gap = 0;
    for (const char *p = name ? name : ""; *p && n < POV_CLEAN_MAX; p++) {
        if (!is_alnum(*p)) {
            gap = 1;
            continue;
        }
        if (gap && n > 0) {
            out[n++] = '_';
            if (n == POV_CLEAN_MAX) break;
        }
        gap = 0;
        out[n++] = *p;
    }
    while (n > 0 && out[n - 1] == '_') n--;
    out[n] = '\0';
    if (n == 0) {
        memcpy(out, "Unnamed", 8);
        return;
    }
    if (out[0] >= 'a' && out[0] <= 'z') out[0] = (char)(out[0] - 'a' + 'A');
}

void pov_material_identifier(const scene *s, uint32_t index, char out[POV_IDENT_MAX])
{
    char clean[POV_CLEAN_MAX + 1];
    pov_clean_name(index < s->n_materials ? s->materials[index].name : NULL, clean);
    snprintf(out, POV_IDENT_MAX, "M%u_%s", index, clean);
}

void pov_object_identifier(const scene *s, uint32_t index, char out[POV_IDENT_MAX])
{
    char clean[POV_CLEAN_MAX + 1];
    pov_clean_name(index < s->n_objects ? s->objects[index].name : NULL, clean);
    snprintf(out, POV_IDENT_MAX, "O%u_%s", index, clean);
}

void pov_model_identifier(const scene *s, uint32_t index, char out[POV_IDENT_MAX])
{
    char clean[POV_CLEAN_MAX + 1];
    pov_clean_name(index < s->n_models ? s->models[index].name : NULL, clean);
    snprintf(out, POV_IDENT_MAX, "D%u_%s", index, clean);
}

void pov_prototype_identifier(const scene *s, uint32_t p, char out[POV_IDENT_MAX])
{
    uint32_t sp = p < s->n_prototypes ? s->prototypes[p].species : 0;
    uint32_t variant = p < s->n_prototypes ? s->prototypes[p].variant : 0;
    char clean[POV_CLEAN_MAX + 1], other[POV_CLEAN_MAX + 1];
    pov_clean_name(sp < s->n_species ? s->species[sp].name : NULL, clean);
    int shared = 0;
    for (uint32_t j = 0; j < s->n_species && !shared; j++) {
        if (j == sp) continue;
        pov_clean_name(s->species[j].name, other);
        shared = !strcmp(clean, other);
    }
    int digit = clean[0] >= '0' && clean[0] <= '9';
    int reserved = (clean[0] == 'M' || clean[0] == 'O' || clean[0] == 'D') && clean[1] >= '0' && clean[1] <= '9';
    const char *prefix = digit || reserved ? "S__" : "";
    if (shared)
        snprintf(out, POV_IDENT_MAX, "%s%s__%u_%u", prefix, clean, sp, variant);
    else
        snprintf(out, POV_IDENT_MAX, "%s%s_%u", prefix, clean, variant);
}

void pov_comment_text(const char *text, char *out, size_t n)
{
    if (!n) return;
    size_t k = 0;
    for (const char *p = text ? text : ""; *p && k + 1 < n; p++) {
        unsigned char c = (unsigned char)*p;
        out[k++] = c < 0x20 || c == 0x7f ? '?' : (char)c;
    }
    out[k] = '\0';
}
