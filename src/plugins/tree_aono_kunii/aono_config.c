/* aono_config.c — reads the validated parameters into an aono_config and checks what the schema
 * cannot express: the number of angles and ratios a pattern needs, the monopodial leader's
 * angle, the fitted angle laws, the derived ratios (23)–(24), parameters that the chosen
 * methods would never read, the segment count, and the leaf material's energy balance. */
#include "aono_config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "aono_ratio.h"
#include "tree_look.h"

static const char *const pattern_names[] = {"dichotomous", "monopodial", "ternary", "stochastic"};

uint64_t aono_segment_bound(uint32_t children, uint32_t levels)
{
    uint64_t total = 1, layer = 1;
    for (uint32_t k = 0; k < levels; k++) {
        if (layer > UINT64_MAX / children) return UINT64_MAX;
        layer *= children;
        if (total > UINT64_MAX - layer) return UINT64_MAX;
        total += layer;
    }
    return total;
}

void aono_config_release(aono_config *cfg)
{
    if (!cfg) return;
    free(cfg->controllers);
    free(cfg->file);
    cfg->controllers = NULL, cfg->n_controllers = 0, cfg->file = NULL;
}

static void vec3(plugin_params *p, const char *name, double out[3])
{
    const sylva_value *v = plugin_param(p, name);
    for (int k = 0; k < 3; k++) out[k] = v->list[k];
}

/* A parameter that the chosen settings never read is refused, so that a scene never seems to
 * say something the tree ignores. */
static int refuse_unread(plugin_params *p, const char *name, int unread, const char *why, plugin_err *err)
{
    if (unread && plugin_param_given(p, name))
        return plugin_fail_param(err, p->block, name, "%s is not read %s; remove it or change that setting", name, why);
    return SYLVA_OK;
}

static int read_structure(plugin_params *p, aono_config *c, plugin_err *err)
{
    c->levels = (uint32_t)plugin_param_int(p, "levels");
    c->pattern = (aono_pattern)plugin_param_int(p, "pattern");
    c->lvt = (uint32_t)plugin_param_int(p, "lvt") - 1;
    c->ternary_probability = plugin_param_real(p, "ternary_probability");
    c->n_children = c->pattern == AONO_TERNARY || c->pattern == AONO_STOCHASTIC ? 3 : 2;
    if (p->status) return p->status;
    int rc = refuse_unread(p, "lvt", c->pattern != AONO_MONOPODIAL, "unless pattern is monopodial", err);
    if (!rc) rc = refuse_unread(p, "ternary_probability", c->pattern != AONO_STOCHASTIC,
                                "unless pattern is stochastic", err);
    if (rc) return rc;
    uint64_t worst = aono_segment_bound(c->n_children, c->levels);
    if (worst > AONO_MAX_SEGMENTS) {
        uint32_t fit = 0;
        while (fit < c->levels && aono_segment_bound(c->n_children, fit + 1) <= AONO_MAX_SEGMENTS) fit++;
        return plugin_fail_param(err, p->block, "levels",
                                 "%u levels of %s branching make up to %llu segments, more than the %u this "
                                 "plugin builds; use at most %u levels with this pattern",
                                 c->levels, pattern_names[c->pattern], (unsigned long long)worst,
                                 AONO_MAX_SEGMENTS, fit);
    }
    c->trunk_length = plugin_param_real(p, "trunk_length");
    c->height = plugin_param_real(p, "height");
    c->crown_diameter = plugin_param_real(p, "crown_diameter");
    c->rko = plugin_param_real(p, "rko");
    return p->status;
}

static int read_angles(plugin_params *p, aono_config *c, plugin_err *err)
{
    const sylva_value *fi = plugin_param(p, "fi");
    if (p->status) return p->status;
    if (fi->len != c->n_children)
        return plugin_fail_param(err, p->block, "fi", "pattern %s has %u children, so fi needs %u angles FI(i); got %u",
                                 pattern_names[c->pattern], c->n_children, c->n_children, fi->len);
    for (uint32_t i = 0; i < c->n_children; i++)
        c->fi[i] = (aono_angle_law){.kind = AONO_LAW_CONSTANT, .c = fi->list[i]};
    const sylva_value *laws = plugin_param(p, "fi_laws");
    for (uint32_t k = 0; k < laws->len; k++) {
        plugin_params item = plugin_params_in(p, &laws->items[k]);
        uint32_t child = (uint32_t)plugin_param_int(&item, "child") - 1;
        const sylva_value *pts = plugin_param(&item, "points");
        aono_law_kind kind = (aono_law_kind)(plugin_param_int(&item, "law") + 1);
        if (p->status) return p->status;
        if (child >= c->n_children)
            return plugin_fail_param(err, item.block, "child", "fi_laws[%u]: pattern %s has children 1 to %u, not %u", k,
                                     pattern_names[c->pattern], c->n_children, child + 1);
        if (c->fi[child].kind != AONO_LAW_CONSTANT)
            return plugin_fail_param(err, item.block, "child", "fi_laws[%u]: child %u already has a law; give one law "
                                     "per child", k, child + 1);
        char why[400];
        if (aono_law_fit(kind, pts->list, pts->len, &c->fi[child], why, sizeof why))
            return plugin_fail_param(err, item.block, "points", "fi_laws[%u]: %s", k, why);
    }
    if (c->pattern == AONO_MONOPODIAL) {
        const aono_angle_law *lead = &c->fi[c->lvt];
        if (lead->kind != AONO_LAW_CONSTANT || lead->c != 0.0)
            return plugin_fail_param(err, p->block, lead->kind != AONO_LAW_CONSTANT ? "fi_laws" : "fi",
                                     "in the monopodial pattern child LVT = %u continues its mother's direction, "
                                     "so its angle FI(%u) must be the constant 0; give 0 there (or choose "
                                     "pattern dichotomous)",
                                     c->lvt + 1, c->lvt + 1);
    }
    c->sf = plugin_param_real(p, "sf");
    c->del = plugin_param_real(p, "del");
    c->del_mode = (aono_del_mode)plugin_param_int(p, "del_mode");
    c->gamma = plugin_param_real(p, "gamma");
    return p->status;
}

static int read_ratios(plugin_params *p, aono_config *c, plugin_err *err)
{
    c->ri_method = (aono_ri_method)plugin_param_int(p, "ri_method");
    if (p->status) return p->status;
    int rc = refuse_unread(p, "ri", c->ri_method != AONO_RI_CONSTANT, "unless ri_method is constant", err);
    if (!rc) rc = refuse_unread(p, "ri_range", c->ri_method != AONO_RI_RANDOM,
                                "unless ri_method is random", err);
    if (!rc) rc = refuse_unread(p, "crown_diameter", c->ri_method != AONO_RI_DIMENSIONS,
                                "unless ri_method is dimensions", err);
    if (!rc) rc = refuse_unread(p, "height", c->ri_method != AONO_RI_DIMENSIONS,
                                "unless ri_method is dimensions", err);
    if (!rc) rc = refuse_unread(p, "rko",
                                c->ri_method != AONO_RI_DIMENSIONS || c->pattern != AONO_DICHOTOMOUS,
                                "unless ri_method is dimensions and pattern dichotomous", err);
    if (rc) return rc;
    if (c->ri_method == AONO_RI_CONSTANT) {
        const sylva_value *ri = plugin_param(p, "ri");
        if (p->status) return p->status;
        if (ri->len != c->n_children)
            return plugin_fail_param(err, p->block, "ri", "pattern %s has %u children, so ri needs %u ratios RI(i); "
                                     "got %u", pattern_names[c->pattern], c->n_children, c->n_children, ri->len);
        for (uint32_t i = 0; i < c->n_children; i++) c->ri[i] = ri->list[i];
    } else if (c->ri_method == AONO_RI_DIMENSIONS) {
        char why[400];
        if (aono_ratios_from_dimensions(c->pattern, c->lvt, c->height, c->trunk_length, c->crown_diameter,
                                        c->rko, c->ri, why, sizeof why))
            return plugin_fail_param(err, p->block, c->trunk_length >= c->height ? "trunk_length" : "crown_diameter",
                                     "%s", why);
    } else {
        const sylva_value *range = plugin_param(p, "ri_range");
        c->ri_range[0] = range->list[0], c->ri_range[1] = range->list[1];
        if (p->status) return p->status;
        if (c->ri_range[0] > c->ri_range[1])
            return plugin_fail_param(err, p->block, "ri_range", "ri_range [%g, %g] is empty; give [low, high] with "
                                     "low <= high, both in (0, 1)", c->ri_range[0], c->ri_range[1]);
    }
    return SYLVA_OK;
}

static int read_deviations(plugin_params *p, aono_config *c, plugin_err *err)
{
    vec3(p, "deviation", c->deviation);
    c->preserve_length = (int)plugin_param_int(p, "preserve_length");
    const sylva_value *list = plugin_param(p, "controllers");
    if (p->status || !list->len) return p->status;
    c->controllers = calloc(list->len, sizeof *c->controllers); /* owned by cfg */
    if (!c->controllers) return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for %u controllers", list->len);
    for (uint32_t i = 0; i < list->len; i++) {
        plugin_params item = plugin_params_in(p, &list->items[i]);
        aono_controller *ctl = &c->controllers[i];
        const sylva_value *pos = plugin_param(&item, "position");
        for (int k = 0; k < 3; k++) ctl->q[k] = pos->list[k];
        ctl->fac = plugin_param_real(&item, "fac");
        if (p->status) return p->status;
        ctl->line = pos->line ? pos->line : item.block->line;
        ctl->column = pos->line ? pos->column : item.block->column;
        if (ctl->fac == 0.0)
            return plugin_fail_param(err, item.block, "fac", "controllers[%u]: fac 0 neither attracts nor repels; give "
                                     "fac > 0 for an attractor or fac < 0 for an inhibitor", i);
        c->n_controllers++;
    }
    return SYLVA_OK;
}

static int read_geometry(plugin_params *p, aono_config *c, plugin_err *err)
{
    c->trunk_radius = plugin_param_real(p, "trunk_radius");
    c->radius_reduction = plugin_param_real(p, "radius_reduction");
    c->lateral_radius_ratio = plugin_param_real(p, "lateral_radius_ratio");
    c->sides = (uint32_t)plugin_param_int(p, "sides");
    c->min_sides = (uint32_t)plugin_param_int(p, "min_sides");
    if (p->status) return p->status;
    if (c->min_sides > c->sides)
        return plugin_fail_param(err, p->block, "min_sides", "min_sides %u is more than the trunk's sides %u; give "
                                 "min_sides <= sides", c->min_sides, c->sides);
    c->leaf_count = (uint32_t)plugin_param_int(p, "leaf_count");
    c->leaf_length = plugin_param_real(p, "leaf_length");
    c->leaf_placement = (aono_leaf_placement)plugin_param_int(p, "leaf_placement");
    c->leaf_levels = (uint32_t)plugin_param_int(p, "leaf_levels");
    c->leaf_angle = plugin_param_real(p, "leaf_angle");
    c->leaf_jitter = plugin_param_real(p, "leaf_jitter");
    vec3(p, "leaf_color", c->leaf_color);
    vec3(p, "leaf_transmittance", c->leaf_transmittance);
    vec3(p, "bark_color", c->bark_color);
    if (p->status) return p->status;
    static const char *const leaf_keys[] = {"leaf", "leaf_length", "leaf_placement",
                                            "leaf_levels", "leaf_angle", "leaf_jitter", "leaf_color",
                                            "leaf_transmittance"};
    for (size_t k = 0; k < sizeof leaf_keys / sizeof leaf_keys[0]; k++) {
        int rc = refuse_unread(p, leaf_keys[k], c->leaf_count == 0, "when leaf_count is 0", err);
        if (rc) return rc;
    }
    for (int k = 0; k < 3; k++)
        if (c->leaf_color[k] + c->leaf_transmittance[k] > 1.0)
            return plugin_fail_param(err, p->block, "leaf_transmittance",
                                     "leaf_color + leaf_transmittance is %g in channel %d; a leaf cannot scatter "
                                     "more light than it receives, so keep the sum at most 1",
                                     c->leaf_color[k] + c->leaf_transmittance[k], k);
    const char *leaf = plugin_param_str(p, "leaf");
    const sylva_value *angle = plugin_param(p, "bark_angle");
    int bark = (int)plugin_param_int(p, "bark");
    if (p->status) return p->status;
    char why[PLUGIN_ERR_MAX - 64];
    if (c->leaf_count && tree_look_leaf(leaf, AONO_LEAF_TEXTURE_SIZE, &c->leaf, why, sizeof why) < 0)
        return plugin_fail_param(err, p->block, "leaf", "%s", why);
    if (tree_look_bark(bark, angle->is_set ? angle->r : NAN, &c->bark, why, sizeof why))
        return plugin_fail_param(err, p->block, angle->is_set ? "bark_angle" : "bark", "%s", why);
    /* Leaves go by length: leaf_count on a branch of the mean outermost length H0 R̄^n, as many
     * per metre elsewhere. The full-grown tree's expected count (every branching with its most
     * children; read_structure has bounded the branch count) must stay within the limit. */
    double mean_ratio = 0.0;
    for (uint32_t i = 0; i < c->n_children; i++)
        mean_ratio += c->ri_method == AONO_RI_RANDOM ? 0.5 * (c->ri_range[0] + c->ri_range[1]) : c->ri[i];
    mean_ratio /= c->n_children;
    c->leaf_reference_length = c->trunk_length * pow(mean_ratio, (double)c->levels);
    double expected = 0.0, layer = 1.0;
    for (uint32_t k = 1; k <= c->levels; k++) {
        layer *= c->n_children;
        if (k + c->leaf_levels > c->levels) expected += layer * c->leaf_count * pow(mean_ratio, (double)k - c->levels);
    }
    if (expected > AONO_MAX_LEAVES)
        return plugin_fail_param(err, p->block, "leaf_count", "%u leaves per outermost branch on the outermost %u levels "
                                 "make some %.0f leaves, more than the %u this plugin builds; lower leaf_count, "
                                 "leaf_levels or levels", c->leaf_count, c->leaf_levels, expected, AONO_MAX_LEAVES);
    return SYLVA_OK;
}

int aono_config_read(plugin_params *params, aono_config *cfg, plugin_err *err)
{
    memset(cfg, 0, sizeof *cfg);
    int rc = read_structure(params, cfg, err);
    if (!rc) rc = read_angles(params, cfg, err);
    if (!rc) rc = read_ratios(params, cfg, err);
    if (!rc) rc = read_deviations(params, cfg, err);
    if (!rc) rc = read_geometry(params, cfg, err);
    if (!rc && params->block->file && !(cfg->file = strdup(params->block->file)))
        rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the scene file's name");
    if (rc) aono_config_release(cfg);
    return rc;
}
