/* wp_params.h — the species parameters of Weber & Penn's tree model as Arbaro 1.9 reads them
 * (with the shamanDevel fork's texture names and Helios' extras), their defaults, ranges and
 * places: one table, wp_param_table, that both species readers (wp_species_read.h) follow. */
#ifndef WP_PARAMS_H
#define WP_PARAMS_H

#include <stddef.h>

#define WP_LEVELS 4        /* per-level parameters: levels 0 (trunk) to 3 */
#define WP_NAME_MAX 64     /* species names and leaf-shape names, with the terminating NUL */
#define WP_PATH_MAX 128    /* texture file names of the shamanDevel fork */

/* The parameters of one stem level (Arbaro's nLength ... nBranchDist with n = the level). */
typedef struct wp_level {
    double length, length_v, taper;
    double seg_splits, split_angle, split_angle_v;
    int curve_res;
    double curve, curve_back, curve_v;
    double down_angle, down_angle_v, rotate, rotate_v;
    int branches;
    double branch_dist;
} wp_level;

/* A species: every value has its default until a reader sets it. */
typedef struct wp_params {
    char species[WP_NAME_MAX];
    int shape, levels, lobes, leaves, leaf_distrib, base_splits;
    double scale, scale_v, zscale, zscale_v, base_size, base_split_size;
    double trunk_scale, trunk_scale_v; /* Arbaro's 0Scale, 0ScaleV */
    double ratio, ratio_power, lobe_depth, flare;
    char leaf_shape[WP_NAME_MAX];
    double leaf_scale, leaf_scale_x, leaf_bend, leaf_stem_len, leaf_quality, smooth;
    double attraction_up, prune_ratio, prune_width, prune_width_peak, prune_power_low, prune_power_high;
    char bark_texture[WP_PATH_MAX], leaf_texture[WP_PATH_MAX];
    double leaf_texture_rotation;
    wp_level level[WP_LEVELS];
} wp_params;

typedef enum wp_type { WP_INT, WP_FLOAT, WP_TEXT } wp_type;

/* One row of the table. A per-level row (per_level = 1) is named with a leading 'n' that
 * Arbaro's files replace by the level's digit (nLength -> 0Length) and Helios' files keep,
 * giving one value per level; its offset is into wp_level, otherwise into wp_params. */
typedef struct wp_param_def {
    const char *name;
    wp_type type;
    int per_level;
    double deflt[WP_LEVELS]; /* [0] for a general row; unused for text */
    double min, max;         /* inclusive bounds (+-INFINITY: none) */
    size_t offset;
    size_t text_size;        /* WP_TEXT: the field's size */
    const char *text_deflt;  /* WP_TEXT: the default */
    const char *section;     /* where the paper (or the program that added it) places it */
    const char *meaning;
} wp_param_def;

extern const wp_param_def wp_param_table[];
extern const size_t wp_param_count;

/* Every value of *p set to its default. */
void wp_params_defaults(wp_params *p);

/* The row named `name` ("nLength" style for per-level rows), or NULL. */
const wp_param_def *wp_param_find(const char *name);

/* The row an Arbaro name stands for ("0Length" -> nLength with *level = 0; "Shape" -> Shape
 * with *level = -1), or NULL. */
const wp_param_def *wp_param_find_arbaro(const char *name, int *level);

/* Whether Arbaro reads row d's value for `level` of a tree with `levels` levels: general rows
 * always; per-level rows for the stem levels below `levels`, and at level `levels` (the leaves'
 * level) only the ones that place leaves (nDownAngle, nDownAngleV, nRotate, nRotateV,
 * nBranchDist). */
int wp_param_used(const wp_param_def *d, int levels, int level);

/* Where `def`'s value for `level` (ignored for a general row) lives in *p. */
void *wp_param_slot(const wp_param_def *def, wp_params *p, int level);

/* The table row nearest to `name` as a likely misspelling (Arbaro spelling when `arbaro`),
 * written to out (size n) or "" when none is near. */
void wp_param_nearest(const char *name, int arbaro, char *out, size_t n);

#endif
