/* plugin_presets.c — a descriptor's presets (ABI 1.1): checked against the schema when the
 * plugin is loaded, and printed for `sylva plugins --describe` from the same tables the plugin
 * starts from, so the help shows the values the plugin really uses. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "plugin/plugin_host.h"

#define PRESET_MAX 256        /* presets in one descriptor */
#define PRESET_MAX_VALUES 256 /* values in one preset */

static const sylva_param_spec *spec_named(const sylva_plugin *d, const char *name)
{
    for (uint32_t k = 0; name && k < d->n_params; k++)
        if (!strcmp(d->params[k].name, name)) return &d->params[k];
    return NULL;
}

static uint32_t choice_count(const sylva_param_spec *p)
{
    uint32_t n = 0;
    while (p->choices && p->choices[n]) n++;
    return n;
}

/* What is wrong with one value for its spec, or "" when nothing is. */
static void value_fault(const sylva_param_spec *p, const sylva_preset_value *v, char *why,
                        size_t cap)
{
    char a[32];
    why[0] = '\0';
    switch (p->type) {
    case SYLVA_P_BOOL:
        if (v->r != 0 && v->r != 1) snprintf(why, cap, "a bool is 0 or 1, not %g", v->r);
        return;
    case SYLVA_P_INT:
    case SYLVA_P_REAL:
        if (p->type == SYLVA_P_INT && v->r != floor(v->r))
            snprintf(why, cap, "%s is not a whole number", plugin_number_format(a, v->r));
        else if (!plugin_value_in_range(p, v->r))
            snprintf(why, cap, "%s is outside the parameter's range",
                     plugin_number_format(a, v->r));
        return;
    case SYLVA_P_ENUM:
        for (uint32_t k = 0; v->s && p->choices && p->choices[k]; k++)
            if (!strcmp(p->choices[k], v->s)) return;
        snprintf(why, cap, "'%s' is not one of its choices", v->s ? v->s : "NULL");
        return;
    case SYLVA_P_STRING:
    case SYLVA_P_PATH:
        if (!v->s) snprintf(why, cap, "the string is NULL");
        return;
    case SYLVA_P_VEC3:
    case SYLVA_P_LIST:
    case SYLVA_P_POLYLINE: {
        uint32_t per = p->type == SYLVA_P_POLYLINE ? 2 : 1;
        if (!v->list || (p->type == SYLVA_P_VEC3 && v->len != 3) ||
            (p->type != SYLVA_P_VEC3 &&
             (v->len < p->min_len || (p->max_len && v->len > p->max_len)))) {
            snprintf(why, cap, "%u %s is not a length the parameter takes", v->len,
                     p->type == SYLVA_P_POLYLINE ? "points" : "elements");
            return;
        }
        for (uint32_t k = 0; k < v->len; k++) {
            double y = v->list[per * k + per - 1];
            if (!plugin_value_in_range(p, y)) {
                snprintf(why, cap, "element %u, %s, is outside the parameter's range", k,
                         plugin_number_format(a, y));
                return;
            }
            if (per == 2 && (isnan(v->list[2 * k]) ||
                             (k && v->list[2 * k] < v->list[2 * k - 2]))) {
                snprintf(why, cap, "point %u's x is not at or after the point before it", k);
                return;
            }
        }
        return;
    }
    default:
        snprintf(why, cap, "a %s parameter cannot take a preset value",
                 plugin_param_type_name(p->type));
        return;
    }
}

int plugin_presets_check(const sylva_plugin *d, err_buf *err)
{
    if (!d->preset_param && !d->presets && !d->n_presets) return 0;
    const sylva_param_spec *sel = spec_named(d, d->preset_param);
    if (!sel || sel->type != SYLVA_P_ENUM)
        return err_set(err, "preset_param %s%s%s is not an enum parameter of the schema; it names "
                       "the enum whose choices are the presets", d->preset_param ? "'" : "",
                       d->preset_param ? d->preset_param : "NULL", d->preset_param ? "'" : "");
    uint32_t choices = choice_count(sel);
    if (!d->presets || d->n_presets != choices || d->n_presets > PRESET_MAX)
        return err_set(err, "'%s' has %u choices but the descriptor describes %u presets; give "
                       "one preset per choice, in the choices' order", sel->name, choices,
                       d->presets ? d->n_presets : 0);
    char why[ERR_MSG_MAX / 2];
    for (uint32_t i = 0; i < d->n_presets; i++) {
        const sylva_preset *pr = &d->presets[i];
        if (!pr->name || strcmp(pr->name, sel->choices[i]))
            return err_set(err, "preset %u is called %s%s%s, but choice %u of '%s' is '%s'", i,
                           pr->name ? "'" : "", pr->name ? pr->name : "NULL", pr->name ? "'" : "",
                           i, sel->name, sel->choices[i]);
        if (!pr->help || !pr->help[0])
            return err_set(err, "preset '%s' has no help; say in one sentence what it is",
                           pr->name);
        if ((pr->n_values && !pr->values) || pr->n_values > PRESET_MAX_VALUES)
            return err_set(err, "preset '%s' declares %u values %s", pr->name, pr->n_values,
                           pr->values ? "(too many)" : "but no table");
        for (uint32_t k = 0; k < pr->n_values; k++) {
            const sylva_preset_value *v = &pr->values[k];
            const sylva_param_spec *p = spec_named(d, v->param);
            if (!p || p == sel)
                return err_set(err, "preset '%s': value %u names %s%s%s, which is %s", pr->name, k,
                               v->param ? "'" : "", v->param ? v->param : "NULL",
                               v->param ? "'" : "",
                               p ? "the preset selector itself" : "not a parameter of the schema");
            for (uint32_t j = 0; j < k; j++)
                if (!strcmp(pr->values[j].param, v->param))
                    return err_set(err, "preset '%s': '%s' is given twice", pr->name, v->param);
            value_fault(p, v, why, sizeof why);
            if (why[0]) return err_set(err, "preset '%s': '%s': %s", pr->name, v->param, why);
        }
    }
    return 0;
}

/* The value as a scene file would give it. */
static void format_value(char *buf, size_t cap, const sylva_param_spec *p,
                         const sylva_preset_value *v)
{
    char a[32], b[32];
    size_t len = 0;
    buf[0] = '\0';
#define ADD(...)                                                                                \
    do {                                                                                        \
        if (len < cap) {                                                                        \
            int w_ = snprintf(buf + len, cap - len, __VA_ARGS__);                               \
            len = w_ < 0 ? cap : len + (size_t)w_;                                              \
        }                                                                                       \
    } while (0)
    switch (p->type) {
    case SYLVA_P_BOOL: ADD("%s", v->r != 0 ? "true" : "false"); break;
    case SYLVA_P_INT:
    case SYLVA_P_REAL: ADD("%s", plugin_number_format(a, v->r)); break;
    case SYLVA_P_ENUM: ADD("%s", v->s); break;
    case SYLVA_P_STRING:
    case SYLVA_P_PATH: ADD("\"%s\"", v->s); break;
    case SYLVA_P_POLYLINE:
        ADD("[");
        for (uint32_t k = 0; k < v->len; k++)
            ADD("%s[%s, %s]", k ? ", " : "", plugin_number_format(a, v->list[2 * k]),
                plugin_number_format(b, v->list[2 * k + 1]));
        ADD("]");
        break;
    default:
        ADD("[");
        for (uint32_t k = 0; k < v->len; k++)
            ADD("%s%s", k ? ", " : "", plugin_number_format(a, v->list[k]));
        ADD("]");
        break;
    }
#undef ADD
    if (p->unit && p->type != SYLVA_P_ENUM && p->type != SYLVA_P_BOOL && len + 2 < cap)
        snprintf(buf + len, cap - len, " %s", p->unit);
}

void plugin_presets_print(FILE *out, const sylva_plugin *d, int indent)
{
    if (!d->n_presets || !d->presets) return;
    size_t wname = 0;
    for (uint32_t k = 0; k < d->n_params; k++)
        if (strlen(d->params[k].name) > wname) wname = strlen(d->params[k].name);
    char value[1024];
    for (uint32_t i = 0; i < d->n_presets; i++) {
        const sylva_preset *pr = &d->presets[i];
        fprintf(out, "%*s%s: %s\n", indent, "", pr->name, pr->help);
        for (uint32_t k = 0; k < pr->n_values; k++) {
            const sylva_param_spec *p = spec_named(d, pr->values[k].param);
            if (!p) continue;
            format_value(value, sizeof value, p, &pr->values[k]);
            fprintf(out, "%*s%-*s  %s\n", indent + 4, "", (int)wname, p->name, value);
        }
    }
}
