/* wp_params.c — the table of Weber-Penn species parameters: names, types, defaults and ranges as
 * Arbaro 1.9's Params.registerParams() gives them, the shamanDevel fork's texture names, and
 * Helios' ZScale, ZScaleV and BaseSplitSize; lookup by either file format's spelling. */
#include "wp_params.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define INF INFINITY
#define IMAX ((double)INT_MAX)
#define IMIN ((double)INT_MIN)
#define GEN(nm, ty, field, d, lo, hi, sec, what) \
    { nm, ty, 0, { d, 0, 0, 0 }, lo, hi, offsetof(wp_params, field), 0, NULL, sec, what }
#define LVL(nm, ty, field, d0, d1, d2, d3, lo, hi, sec, what) \
    { nm, ty, 1, { d0, d1, d2, d3 }, lo, hi, offsetof(wp_level, field), 0, NULL, sec, what }
#define TXT(nm, field, d, sec, what) \
    { nm, WP_TEXT, 0, { 0 }, 0, 0, offsetof(wp_params, field), sizeof(((wp_params *)0)->field), d, sec, what }

const wp_param_def wp_param_table[] = {
    TXT("Species", species, "default", "Arbaro", "the species' name"),
    GEN("Shape", WP_INT, shape, 0, 0, 8, "Shape",
        "tree shape: 0 conical, 1 spherical, 2 hemispherical, 3 cylindrical, 4 tapered cylindrical, 5 flame, "
        "6 inverse conical, 7 tend flame, 8 envelope"),
    GEN("Levels", WP_INT, levels, 3, 0, 9, "Recursion", "levels of recursion (stem levels; the last bears leaves)"),
    GEN("Scale", WP_FLOAT, scale, 10, 1e-6, INF, "Size", "average tree size in metres"),
    GEN("ScaleV", WP_FLOAT, scale_v, 0, 0, INF, "Size", "variation of tree size in metres"),
    GEN("ZScale", WP_FLOAT, zscale, 1, 0, INF, "Size (Helios)", "additional vertical scale (not in the paper; unused)"),
    GEN("ZScaleV", WP_FLOAT, zscale_v, 0, 0, INF, "Size (Helios)", "variation of ZScale (unused)"),
    GEN("BaseSize", WP_FLOAT, base_size, 0.25, 0, 1, "Shape", "fraction of the trunk without branches"),
    GEN("0BaseSplits", WP_INT, base_splits, 0, 0, IMAX, "Splitting", "clones made at the trunk's base"),
    GEN("BaseSplitSize", WP_FLOAT, base_split_size, 0, 0, 1, "Splitting (Helios)", "where the base splits are (Helios)"),
    GEN("Ratio", WP_FLOAT, ratio, 0.05, 1e-6, INF, "Radius", "trunk radius to trunk length"),
    GEN("RatioPower", WP_FLOAT, ratio_power, 1, -INF, INF, "Radius", "how child radii fall with level"),
    GEN("Flare", WP_FLOAT, flare, 0.5, -1, INF, "Flare", "widening of the trunk's base"),
    GEN("Lobes", WP_INT, lobes, 0, 0, IMAX, "Lobes", "lobes of the trunk's cross section"),
    GEN("LobeDepth", WP_FLOAT, lobe_depth, 0, 0, INF, "Lobes", "depth of the lobes"),
    GEN("Leaves", WP_INT, leaves, 0, IMIN, IMAX, "Leaves", "leaves per stem of the last level (negative: fans)"),
    TXT("LeafShape", leaf_shape, "0", "Leaves", "leaf shape id or name"),
    GEN("LeafScale", WP_FLOAT, leaf_scale, 0.2, 1e-6, INF, "Leaves", "leaf length in metres"),
    GEN("LeafScaleX", WP_FLOAT, leaf_scale_x, 0.5, 1e-6, INF, "Leaves", "leaf width to length"),
    GEN("LeafBend", WP_FLOAT, leaf_bend, 0.3, 0, 1, "Leaf orientation", "how far leaves turn to the light"),
    GEN("LeafStemLen", WP_FLOAT, leaf_stem_len, 0.5, -INF, INF, "Leaves (Arbaro)", "leaf stalk length to leaf length"),
    GEN("LeafDistrib", WP_INT, leaf_distrib, 4, 0, 8, "Leaves (Arbaro)", "shape id of the leaves' distribution along a stem"),
    GEN("LeafQuality", WP_FLOAT, leaf_quality, 1, 1e-6, 1, "Quality (Arbaro)", "leaf count reduction"),
    GEN("Smooth", WP_FLOAT, smooth, 0.5, 0, 1, "Quality (Arbaro)", "mesh smoothness"),
    GEN("AttractionUp", WP_FLOAT, attraction_up, 0, -INF, INF, "Vertical attraction", "upward pull on stems"),
    GEN("PruneRatio", WP_FLOAT, prune_ratio, 0, 0, 1, "Pruning", "how much of the envelope pruning acts"),
    GEN("PruneWidth", WP_FLOAT, prune_width, 0.5, 0, 1, "Pruning", "width of the envelope to its height"),
    GEN("PruneWidthPeak", WP_FLOAT, prune_width_peak, 0.5, 0, 1, "Pruning", "height of the envelope's widest point"),
    GEN("PrunePowerLow", WP_FLOAT, prune_power_low, 0.5, 0, INF, "Pruning", "curvature of the envelope below its peak"),
    GEN("PrunePowerHigh", WP_FLOAT, prune_power_high, 0.5, 0, INF, "Pruning", "curvature of the envelope above its peak"),
    GEN("0Scale", WP_FLOAT, trunk_scale, 1, 1e-6, INF, "Size", "trunk radius scale"),
    GEN("0ScaleV", WP_FLOAT, trunk_scale_v, 0, 0, INF, "Size", "variation of 0Scale"),
    TXT("BarkTexture", bark_texture, "", "Texture (shamanDevel)", "bark image file name"),
    TXT("LeafTexture", leaf_texture, "", "Texture (shamanDevel)", "leaf image file name"),
    GEN("LeafTextureRotation", WP_FLOAT, leaf_texture_rotation, 0, -360, 360, "Texture (shamanDevel)",
        "leaf image rotation in degrees"),
    LVL("nLength", WP_FLOAT, length, 1, 0.5, 0.5, 0.5, 1e-7, INF, "Length", "stem length to parent (level 0: to Scale)"),
    LVL("nLengthV", WP_FLOAT, length_v, 0, 0, 0, 0, 0, INF, "Length", "variation of nLength"),
    LVL("nTaper", WP_FLOAT, taper, 1, 1, 1, 1, 0, 2.99999999, "Taper", "radius taper: 0-1 cone, 1-2 spherical, 2-3 periodic"),
    LVL("nSegSplits", WP_FLOAT, seg_splits, 0, 0, 0, 0, 0, INF, "Splitting", "clones per segment"),
    LVL("nSplitAngle", WP_FLOAT, split_angle, 0, 0, 0, 0, 0, 180, "Splitting", "angle between clones in degrees"),
    LVL("nSplitAngleV", WP_FLOAT, split_angle_v, 0, 0, 0, 0, 0, 180, "Splitting", "variation of nSplitAngle"),
    LVL("nCurveRes", WP_INT, curve_res, 3, 3, 1, 1, 1, IMAX, "Curvature", "segments per stem"),
    LVL("nCurve", WP_FLOAT, curve, 0, 0, 0, 0, -INF, INF, "Curvature", "stem curvature in degrees"),
    LVL("nCurveBack", WP_FLOAT, curve_back, 0, 0, 0, 0, -INF, INF, "Curvature", "curvature of the stem's upper half"),
    LVL("nCurveV", WP_FLOAT, curve_v, 0, 0, 0, 0, -90, INF, "Curvature", "variation of nCurve (negative: helix)"),
    LVL("nDownAngle", WP_FLOAT, down_angle, 0, 30, 30, 30, -179.9999999, 179.999999, "Child stems",
        "angle from the parent stem in degrees"),
    LVL("nDownAngleV", WP_FLOAT, down_angle_v, 0, 0, 0, 0, -179.9999999, 179.9999999, "Child stems",
        "variation of nDownAngle (negative: by position)"),
    LVL("nRotate", WP_FLOAT, rotate, 0, 120, 120, 120, -360, 360, "Child stems", "angle about the parent to the previous child"),
    LVL("nRotateV", WP_FLOAT, rotate_v, 0, 0, 0, 0, -360, 360, "Child stems", "variation of nRotate"),
    LVL("nBranches", WP_INT, branches, 1, 10, 5, 5, 0, IMAX, "Child stems", "child stems per stem"),
    LVL("nBranchDist", WP_FLOAT, branch_dist, 0, 1, 1, 1, 0, 1, "Child stems (Arbaro)", "distribution of whorls along a stem"),
};
const size_t wp_param_count = sizeof wp_param_table / sizeof wp_param_table[0];

void *wp_param_slot(const wp_param_def *def, wp_params *p, int level)
{
    char *base = def->per_level ? (char *)&p->level[level] : (char *)p;
    return base + def->offset;
}

static void set_default(const wp_param_def *d, wp_params *p, int level)
{
    void *slot = wp_param_slot(d, p, level);
    double v = d->deflt[d->per_level ? level : 0];
    if (d->type == WP_TEXT) snprintf(slot, d->text_size, "%s", d->text_deflt);
    else if (d->type == WP_INT) *(int *)slot = (int)v;
    else *(double *)slot = v;
}

void wp_params_defaults(wp_params *p)
{
    memset(p, 0, sizeof *p);
    for (size_t i = 0; i < wp_param_count; i++) {
        const wp_param_def *d = &wp_param_table[i];
        for (int l = 0; l < (d->per_level ? WP_LEVELS : 1); l++) set_default(d, p, l);
    }
}

const wp_param_def *wp_param_find(const char *name)
{
    for (size_t i = 0; i < wp_param_count; i++)
        if (strcmp(wp_param_table[i].name, name) == 0) return &wp_param_table[i];
    return NULL;
}

const wp_param_def *wp_param_find_arbaro(const char *name, int *level)
{
    *level = -1;
    const wp_param_def *d = wp_param_find(name);
    if (d && !d->per_level) return d;
    if (name[0] < '0' || name[0] > '0' + WP_LEVELS - 1 || strlen(name) >= WP_NAME_MAX) return NULL;
    char generic[WP_NAME_MAX];
    snprintf(generic, sizeof generic, "n%s", name + 1);
    d = wp_param_find(generic);
    if (!d || !d->per_level) return NULL;
    *level = name[0] - '0';
    return d;
}

int wp_param_used(const wp_param_def *d, int levels, int level)
{
    static const char *const leaf_level[] = { "nDownAngle", "nDownAngleV", "nRotate", "nRotateV", "nBranchDist" };
    if (!d->per_level || level < levels) return 1;
    if (level > levels) return 0;
    for (size_t i = 0; i < sizeof leaf_level / sizeof leaf_level[0]; i++)
        if (strcmp(d->name, leaf_level[i]) == 0) return 1;
    return 0;
}

/* Levenshtein's distance between two names of under WP_NAME_MAX bytes (longer ones: far). */
static size_t name_distance(const char *a, const char *b)
{
    size_t na = strlen(a), nb = strlen(b), row[WP_NAME_MAX + 1];
    if (na > WP_NAME_MAX || nb > WP_NAME_MAX) return (size_t)-1;
    for (size_t j = 0; j <= nb; j++) row[j] = j;
    for (size_t i = 1; i <= na; i++) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= nb; j++) {
            size_t up = row[j], best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best) best = up + 1;
            if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
            diag = up;
            row[j] = best;
        }
    }
    return row[nb];
}

/* The spelling of row d that a file uses: Arbaro puts the level's digit (that of `name`, or 0)
 * in place of a per-level row's 'n'. */
static void spelling(const wp_param_def *d, const char *name, int arbaro, char *out, size_t n)
{
    char digit = (name[0] >= '0' && name[0] <= '3') ? name[0] : '0';
    if (arbaro && d->per_level) snprintf(out, n, "%c%s", digit, d->name + 1);
    else snprintf(out, n, "%s", d->name);
}

void wp_param_nearest(const char *name, int arbaro, char *out, size_t n)
{
    size_t limit = strlen(name) / 3 < 2 ? 2 : strlen(name) / 3, best = limit + 1;
    out[0] = '\0';
    for (size_t i = 0; i < wp_param_count; i++) {
        char cand[WP_NAME_MAX + 2];
        spelling(&wp_param_table[i], name, arbaro, cand, sizeof cand);
        size_t dist = name_distance(name, cand);
        if (dist < best) {
            best = dist;
            snprintf(out, n, "%s", cand);
        }
    }
}
