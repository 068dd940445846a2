/* vessel_config.c — the preset-then-overrides reading of a tree_vessel scene block (the schema
 * is vessel_schema.c). A preset (vessel_presets.c) and a scene
 * block are read by the same code: a preset becomes a block that gives every key, its own value
 * or else the schema's default. */
#include "vessel_config.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "tree_look.h"
#include "vessel_presets.h"
#include "vessel_texture.h"

static const sylva_value *given(plugin_params *params, const char *key)
{
    const sylva_value *v = plugin_param(params, key);
    return v->is_set ? v : NULL;
}

static void read_real(plugin_params *params, const char *key, double *dst)
{
    const sylva_value *v = given(params, key);
    if (v) *dst = v->r;
}

static void read_colour(plugin_params *params, const char *key, float *dst)
{
    const sylva_value *v = given(params, key);
    if (v && v->list && v->len == 3)
        for (int k = 0; k < 3; k++) dst[k] = (float)v->list[k];
}

static int read_polyline(plugin_params *params, const vessel_polyline_rule *rule,
                         double x_max, vessel_polyline *dst, plugin_err *err)
{
    const sylva_value *v = given(params, rule->key);
    if (!v) return 0;
    return vessel_polyline_set(dst, v->list, v->len, x_max, rule->y_min, rule->y_max, rule->key,
                               err);
}

/* Copies the keys `params` gives onto *out. Returns 0, or -1 with err set (a name the schema
 * lacks: params->status is set instead, and what was read is not to be used). */
static int read_given(plugin_params *params, vessel_params *out, plugin_err *err)
{
    const sylva_value *v;
    if ((v = given(params, "vessels"))) {
        if (v->i < 1 || v->i > VESSEL_MAX_VESSELS)
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "vessels", "'vessels' (S) is %lld; a tree needs 1 to %u "
                               "vessels in its trunk", (long long)v->i, VESSEL_MAX_VESSELS);
        out->vessels = (uint32_t)v->i;
    }
    read_real(params, "trunk_length", &out->trunk_length);
    read_real(params, "thickness", &out->thickness);
    read_real(params, "gravicentralism", &out->gravicentralism);
    read_real(params, "phyllotaxis", &out->phyllotaxis);
    read_real(params, "leaf_size", &out->leaf_size);
    if ((v = given(params, "leaf_density"))) {
        if (v->i < 0 || v->i > VESSEL_MAX_LEAF_DENSITY)
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "leaf_density", "'leaf_density' is %lld; valid values are 0 "
                               "to %u leaves per branch", (long long)v->i, VESSEL_MAX_LEAF_DENSITY);
        out->leaf_density = (uint32_t)v->i;
    }
    if ((v = given(params, "leaf_type"))) out->leaf_type = (vessel_leaf_type)v->i;
    if ((v = given(params, "leaf_spray"))) out->leaf_spray = (uint32_t)v->i;
    char why[PLUGIN_ERR_MAX - 64];
    if ((v = given(params, "leaf"))) {
        int named = tree_look_leaf(v->s, VESSEL_LEAF_TEXTURE_SIZE, &out->leaf, why, sizeof why);
        if (named < 0) return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "leaf", "'leaf': %s", why);
        out->leaf_preset = named == TREE_LOOK_USER_MAPS ? -1 : named;
    }
    /* a bark preset brings its own angle unless bark_angle is given too */
    const sylva_value *bark = given(params, "bark"), *angle = given(params, "bark_angle");
    if (bark) out->bark_preset = (bark_fractal_preset)bark->i;
    if ((bark || angle) &&
        tree_look_bark((int)out->bark_preset, angle ? angle->r : NAN, &out->bark, why, sizeof why))
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, angle ? "bark_angle" : "bark", "'%s': %s",
                           angle ? "bark_angle" : "bark", why);
    read_colour(params, "bark_color", out->bark_albedo);
    read_colour(params, "leaf_color", out->leaf_albedo);
    read_colour(params, "leaf_transmittance", out->leaf_transmittance);
    if ((v = given(params, "sides"))) {
        if (v->i < VESSEL_MIN_SIDES || v->i > VESSEL_MAX_SIDES)
            return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "sides", "'sides' is %lld; branch cones have %u to %u sides",
                               (long long)v->i, VESSEL_MIN_SIDES, VESSEL_MAX_SIDES);
        out->sides = (uint32_t)v->i;
    }
    for (int k = 0; k < VESSEL_LOCALS; k++)
        if (read_polyline(params, &vessel_rules_g[k], VESSEL_ORDER_G_MAX, &out->by_g[k], err) ||
            read_polyline(params, &vessel_rules_w[k], VESSEL_ORDER_W_MAX, &out->by_w[k], err))
            return -1;
    read_real(params, "wind_sway", &out->wind_sway);
    read_real(params, "wind_strength", &out->wind_strength);
    if ((v = given(params, "wind_direction")) && v->list && v->len == 3)
        for (int k = 0; k < 3; k++) out->wind_direction[k] = v->list[k];
    read_real(params, "flexibility", &out->flexibility);
    read_real(params, "wind_time", &out->wind_time);
    return 0;
}

static int64_t choice_index(const sylva_param_spec *spec, const char *s)
{
    for (int64_t k = 0; s && spec->choices && spec->choices[k]; k++)
        if (!strcmp(spec->choices[k], s)) return k;
    return -1;
}

int vessel_preset_get(vessel_preset which, vessel_params *out)
{
    if ((unsigned)which >= VESSEL_PRESETS) return -1;
    const sylva_preset *preset = &vessel_presets[which];
    sylva_value values[VESSEL_SCHEMA_COUNT];
    for (uint32_t k = 0; k < VESSEL_SCHEMA_COUNT; k++) {
        const sylva_param_spec *spec = &vessel_schema[k];
        sylva_value v = {.is_set = 1, .r = spec->def, .i = (int64_t)spec->def, .s = spec->def_str,
                         .list = spec->def_list, .len = spec->def_len};
        for (uint32_t j = 0; j < preset->n_values; j++) {
            const sylva_preset_value *pv = &preset->values[j];
            if (strcmp(pv->param, spec->name)) continue;
            v = (sylva_value){.is_set = 1, .r = pv->r, .i = (int64_t)pv->r, .s = pv->s,
                              .list = pv->list, .len = pv->len};
        }
        if (spec->type == SYLVA_P_ENUM) v.i = choice_index(spec, v.s);
        if (!strcmp(spec->name, "bark_angle")) v.is_set = 0; /* a preset's bark keeps its own angle */
        values[k] = v;
    }
    values[0].i = which; /* the preset key itself */
    sylva_params block = {.spec = vessel_schema, .n = VESSEL_SCHEMA_COUNT, .values = values};
    plugin_params r = plugin_params_open(NULL, NULL, &block); /* the plugin's own block: no host */
    plugin_err err = {0};
    memset(out, 0, sizeof *out);
    return read_given(&r, out, &err) || r.status ? -1 : 0;
}

int vessel_config_read(plugin_params *params, vessel_params *out, plugin_err *err)
{
    const sylva_value *preset = plugin_param(params, "preset");
    if (params->status) return params->status;
    if (vessel_preset_get((vessel_preset)preset->i, out))
        return plugin_fail_key(err, SYLVA_ERR_PARAM, NULL, "preset", "unknown preset; the presets are beech, spruce, "
                           "weeping_willow and maple");
    int rc = read_given(params, out, err);
    if (params->status) return params->status;
    if (rc) return -1;
    return vessel_params_check(out, err);
}
