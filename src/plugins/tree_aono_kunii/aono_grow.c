/* aono_grow.c — grows the skeleton level by level: for every mother, its children's angles,
 * divergences and lengths, their tips in the mother's frame (16)–(19), the deviations (25), and
 * which child continues the mother (for the joint geometry and the radii). */
#include "aono_grow.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aono_frame.h"

#define AONO_TWO_PI 6.28318530717958647692
#define AONO_CONTROLLER_EPS 1e-6 /* metres: a tip this close to a controller has no direction */

void aono_skeleton_release(aono_skeleton *s)
{
    if (!s) return;
    free(s->seg);
    memset(s, 0, sizeof *s);
}

double aono_child_angle(const aono_config *cfg, uint32_t child, uint32_t level)
{
    if (cfg->pattern == AONO_MONOPODIAL && child == cfg->lvt) return 0.0;
    return aono_law_eval(&cfg->fi[child], (double)level);
}

double aono_child_azimuth(const aono_config *cfg, uint32_t child, uint32_t level)
{
    double del = cfg->del_mode == AONO_DEL_SPIRAL ? cfg->del * level : cfg->del;
    if (child == 0) return del;
    if (child == 1) return del + cfg->gamma;
    return del + 180.0 + 0.5 * cfg->gamma;
}

int aono_deviate(const aono_config *cfg, const double pb[3], double rho, double p[3], uint32_t *which)
{
    double q[3] = {p[0] + cfg->deviation[0], p[1] + cfg->deviation[1], p[2] + cfg->deviation[2]};
    for (uint32_t i = 0; i < cfg->n_controllers; i++) {
        const aono_controller *c = &cfg->controllers[i];
        double d[3] = {c->q[0] - p[0], c->q[1] - p[1], c->q[2] - p[2]};
        double D = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]); /* D(i) */
        if (!(D > AONO_CONTROLLER_EPS)) {
            *which = i;
            return -1;
        }
        for (int k = 0; k < 3; k++) q[k] += c->fac * d[k] / D;
    }
    if (cfg->preserve_length) {
        double v[3] = {q[0] - pb[0], q[1] - pb[1], q[2] - pb[2]};
        double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        /* A deviation that cancels the branch exactly leaves no direction: keep the undeviated tip. */
        if (!(len > 1e-12 * rho)) return 0;
        for (int k = 0; k < 3; k++) q[k] = pb[k] + rho * v[k] / len;
    }
    p[0] = q[0], p[1] = q[1], p[2] = q[2];
    return 0;
}

/* A standard normal deviate from two uniforms (Box–Muller). */
static double normal_deviate(const aono_env *env, sylva_rng *rng)
{
    double u1 = env->uniform(rng), u2 = env->uniform(rng);
    return sqrt(-2.0 * log(1.0 - u1)) * cos(AONO_TWO_PI * u2);
}

static int reserve(aono_skeleton *s, uint64_t need, plugin_err *err)
{
    if (need > AONO_MAX_SEGMENTS)
        return plugin_fail(err, SYLVA_ERR_LIMIT, "the tree would have more than %u segments (the plugin's limit); "
                           "lower levels or choose a pattern with fewer children", AONO_MAX_SEGMENTS);
    if (need <= s->cap) return SYLVA_OK;
    uint64_t cap = s->cap ? s->cap : 64;
    while (cap < need) cap *= 2;
    if (cap > AONO_MAX_SEGMENTS) cap = AONO_MAX_SEGMENTS;
    aono_segment *seg = realloc(s->seg, (size_t)cap * sizeof *seg);
    if (!seg)
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for %llu branch segments", (unsigned long long)cap);
    s->seg = seg, s->cap = (uint32_t)cap;
    return SYLVA_OK;
}

static double dist(const double a[3], const double b[3])
{
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* Picks the child that continues mother m: the one whose direction turns least from the
 * mother's, if it turns by at most 90 degrees. Then sets the children's radii. */
static void classify_children(const aono_config *cfg, aono_skeleton *s, uint32_t m)
{
    aono_segment *mo = &s->seg[m];
    double md[3], best = 0.0;
    double ml = dist(mo->base, mo->tip);
    for (int k = 0; k < 3; k++) md[k] = (mo->tip[k] - mo->base[k]) / ml;
    mo->continuation = AONO_NONE;
    for (uint32_t c = mo->first_child; c < mo->first_child + mo->n_children; c++) {
        const aono_segment *ch = &s->seg[c];
        double cl = dist(ch->base, ch->tip), cosang = 0.0;
        for (int k = 0; k < 3; k++) cosang += md[k] * (ch->tip[k] - ch->base[k]) / cl;
        if (cosang >= best && (mo->continuation == AONO_NONE || cosang > best)) {
            best = cosang;
            mo->continuation = c;
        }
    }
    for (uint32_t c = mo->first_child; c < mo->first_child + mo->n_children; c++) {
        aono_segment *ch = &s->seg[c];
        ch->continues = c == mo->continuation;
        ch->radius_base = mo->radius_tip * (ch->continues ? 1.0 : cfg->lateral_radius_ratio);
        ch->radius_tip = ch->radius_base * cfg->radius_reduction;
    }
}

static int controller_on_tip(const aono_config *cfg, uint32_t which, uint32_t level, const double p[3],
                             plugin_err *err)
{
    const aono_controller *c = &cfg->controllers[which];
    return plugin_fail(err, SYLVA_ERR_PARAM,
                       "%s:%u:%u: 'position': controller %u at (%g, %g, %g) lies on the tip of a "
                       "level-%u branch at (%g, %g, %g), where the direction (Q - P)/|Q - P| of (25) is "
                       "undefined; move the controller off the branch tips (by more than 1 micrometre)",
                       cfg->file ? cfg->file : "scene", c->line, c->column, which + 1, c->q[0], c->q[1],
                       c->q[2], level, p[0], p[1], p[2]);
}

/* Appends the children of mother m (at level `level`, i.e. the children's level). */
static int branch(const aono_config *cfg, uint32_t level, const aono_env *env, aono_skeleton *s, uint32_t m,
                  plugin_err *err)
{
    sylva_rng rng;
    env->stream(env->ctx, &rng, "tree_aono_kunii.branching", s->seg[m].node);
    uint32_t nc = cfg->n_children;
    if (cfg->pattern == AONO_STOCHASTIC) nc = env->uniform(&rng) < cfg->ternary_probability ? 3 : 2;
    int rc = reserve(s, (uint64_t)s->n + nc, err);
    if (rc) return rc;
    aono_segment *mo = &s->seg[m];
    aono_frame frame;
    if (aono_frame_build(mo->base, mo->tip, &frame))
        return plugin_fail(err, SYLVA_ERR_PARAM, "a level-%u branch has zero length, so its children have no frame",
                           mo->level);
    mo->first_child = s->n;
    mo->n_children = (uint8_t)nc;
    for (uint32_t i = 0; i < nc; i++) {
        double phi = aono_child_angle(cfg, i, level);
        int leader = cfg->pattern == AONO_MONOPODIAL && i == cfg->lvt;
        if (cfg->sf > 0.0 && !leader) phi += cfg->sf * normal_deviate(env, &rng);
        phi = fmin(180.0, fmax(0.0, phi));
        double ratio = cfg->ri[i];
        if (cfg->ri_method == AONO_RI_RANDOM)
            ratio = cfg->ri_range[0] + (cfg->ri_range[1] - cfg->ri_range[0]) * env->uniform(&rng);
        double rho = ratio * mo->length; /* ρ_i = R_i ρ_op */
        double tip[3];
        aono_frame_child(&frame, mo->tip, rho, phi, aono_child_azimuth(cfg, i, level), tip);
        uint32_t which = 0;
        if (aono_deviate(cfg, mo->tip, rho, tip, &which))
            return controller_on_tip(cfg, which, level, tip, err);
        aono_segment *ch = &s->seg[s->n++];
        memset(ch, 0, sizeof *ch);
        memcpy(ch->base, mo->tip, sizeof ch->base);
        memcpy(ch->tip, tip, sizeof ch->tip);
        ch->length = rho;
        ch->node = 4 * mo->node + i + 1;
        ch->parent = m;
        ch->first_child = AONO_NONE;
        ch->continuation = AONO_NONE;
        ch->level = (uint8_t)level;
        ch->child_index = (uint8_t)i;
        if (!(dist(ch->base, ch->tip) > 0.0))
            return plugin_fail(err, SYLVA_ERR_PARAM,
                               "child %u of a level-%u branch came out with zero length after the "
                               "deviations (25); lower deviation or the controllers' fac", i + 1, level - 1);
    }
    classify_children(cfg, s, m);
    return SYLVA_OK;
}

int aono_grow(const aono_config *cfg, uint32_t levels, const aono_env *env, aono_skeleton *out, plugin_err *err)
{
    memset(out, 0, sizeof *out);
    int rc = reserve(out, aono_segment_bound(cfg->pattern == AONO_STOCHASTIC ? 2 : cfg->n_children, levels), err);
    if (rc) goto fail;
    aono_segment *trunk = &out->seg[out->n++];
    memset(trunk, 0, sizeof *trunk);
    trunk->tip[2] = cfg->trunk_length; /* P_A(0, 0, 0), P_B(0, 0, H0) */
    trunk->length = cfg->trunk_length;
    /* A younger tree is the outer part of the full-grown one's radius series: its twigs are as
     * thin as the old tree's, its trunk thinner by one reduction per missing level. */
    trunk->radius_base = cfg->trunk_radius * pow(cfg->radius_reduction, (double)(cfg->levels - levels));
    trunk->radius_tip = trunk->radius_base * cfg->radius_reduction;
    trunk->node = 1;
    trunk->parent = AONO_NONE;
    trunk->first_child = AONO_NONE;
    trunk->continuation = AONO_NONE;
    uint32_t first = 0, end = 1;
    for (uint32_t level = 1; level <= levels; level++) {
        for (uint32_t m = first; m < end; m++)
            if ((rc = branch(cfg, level, env, out, m, err))) goto fail;
        first = end, end = out->n;
        if (env->progress) env->progress(env->ctx, level, levels);
    }
    out->levels = levels;
    return SYLVA_OK;
fail:
    aono_skeleton_release(out);
    return rc;
}
