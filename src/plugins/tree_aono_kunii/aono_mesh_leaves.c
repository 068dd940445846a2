/* aono_mesh_leaves.c — leaf quads on the outermost branches: where along the branch, round it
 * and at what angle each leaf stands, with its blade turned to face the sky. */
#include <math.h>

#include "aono_mesh.h"
#include "vec3.h"

#define AONO_DEG (3.14159265358979323846 / 180.0)
#define AONO_GOLDEN_ANGLE 137.50776405003785 /* degrees between successive leaves round a branch */

/* Two unit vectors p, q completing unit d to an orthonormal frame. */
static void basis(const double d[3], double p[3], double q[3])
{
    double a[3] = {fabs(d[0]) < 0.9 ? 1.0 : 0.0, fabs(d[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    vec3_cross(d, a, p);
    vec3_normalize(p, 1e-12);
    vec3_cross(d, p, q);
}

/* One leaf: stalk at `at`, pointing along unit L, blade across unit W. */
static void emit_leaf(aono_mesh_buffer *b, const aono_config *cfg, const double at[3], const double L[3],
                      const double W[3], int32_t mat)
{
    double N[3], len = cfg->leaf_length, half = 0.5 * cfg->leaf_length;
    vec3_cross(W, L, N);
    double c[4][3];
    for (int i = 0; i < 3; i++) {
        c[0][i] = at[i] - half * W[i];
        c[1][i] = at[i] + half * W[i];
        c[2][i] = at[i] + half * W[i] + len * L[i];
        c[3][i] = at[i] - half * W[i] + len * L[i];
    }
    static const double uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    uint32_t first = b->nv;
    for (int k = 0; k < 4; k++) aono_mesh_vertex(b, c[k], N, uv[k][0], uv[k][1]);
    aono_mesh_triangle(b, first, first + 1, first + 2, mat);
    aono_mesh_triangle(b, first, first + 2, first + 3, mat);
}

/* Turns v about unit axis k by angle a (radians), in place (Rodrigues). */
static void turn(double v[3], const double k[3], double a)
{
    double kv[3], c = cos(a), s = sin(a), kd = vec3_dot(k, v);
    vec3_cross(k, v, kv);
    for (int i = 0; i < 3; i++) v[i] = v[i] * c + kv[i] * s + k[i] * kd * (1.0 - c);
}

/* Leaves on segment sg: leaf_count per reference length, the fraction drawn at random so that
 * the expected count is exact. */
static uint32_t leaves_on(const aono_config *cfg, const aono_segment *sg, double u)
{
    double x = cfg->leaf_count * sg->length / cfg->leaf_reference_length;
    double whole = floor(x + 1e-9);
    return (uint32_t)whole + (u < x - whole);
}

int aono_mesh_leaves(const aono_config *cfg, const aono_skeleton *s, int32_t leaf, const aono_env *env,
                     aono_mesh_buffer *b, plugin_err *err)
{
    if (!cfg->leaf_count) return SYLVA_OK;
    uint32_t first_level = s->levels + 1 > cfg->leaf_levels ? s->levels + 1 - cfg->leaf_levels : 1;
    static const double up[3] = {0.0, 0.0, 1.0};
    double jitter = cfg->leaf_jitter * AONO_DEG;
    uint64_t total = 0;
    for (uint32_t k = 0; k < s->n; k++) {
        const aono_segment *sg = &s->seg[k];
        if (sg->level < first_level) continue;
        sylva_rng rng;
        env->stream(env->ctx, &rng, "tree_aono_kunii.leaves", sg->node);
        uint32_t count = leaves_on(cfg, sg, env->uniform(&rng));
        total += count;
        if (total > AONO_MAX_LEAVES)
            return plugin_fail(err, SYLVA_ERR_LIMIT, "the tree would carry more than %u leaves (the plugin's limit); "
                               "lower leaf_count or leaf_levels", AONO_MAX_LEAVES);
        int rc = aono_mesh_reserve(b, 4 * count, 2 * count);
        if (rc == -2)
            return plugin_fail(err, SYLVA_ERR_LIMIT,
                               "the tree's leaves need more than %u vertices or %u triangles (the host's "
                               "per-mesh limits); lower leaf_count or leaf_levels",
                               AONO_MESH_MAX_VERTICES, AONO_MESH_MAX_TRIANGLES);
        if (rc) return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory building the tree's leaves");
        double d[3] = {sg->tip[0] - sg->base[0], sg->tip[1] - sg->base[1], sg->tip[2] - sg->base[2]};
        double len = vec3_length(d), p[3], q[3];
        if (vec3_normalize(d, 1e-12)) continue;
        basis(d, p, q);
        double turn0 = 360.0 * env->uniform(&rng);
        for (uint32_t n = 0; n < count; n++) {
            double u = env->uniform(&rng);
            double t = cfg->leaf_placement == AONO_LEAVES_TIP ? 1.0 - 0.15 * u : 0.2 + 0.8 * (n + u) / count;
            double psi = (turn0 + n * AONO_GOLDEN_ANGLE) * AONO_DEG;
            double a = cfg->leaf_angle * AONO_DEG + jitter * (2.0 * env->uniform(&rng) - 1.0);
            double roll = jitter * (2.0 * env->uniform(&rng) - 1.0);
            double r = sg->radius_base + (sg->radius_tip - sg->radius_base) * t;
            double out[3], L[3], W[3], at[3];
            for (int i = 0; i < 3; i++) out[i] = cos(psi) * p[i] + sin(psi) * q[i];
            for (int i = 0; i < 3; i++) {
                L[i] = cos(a) * d[i] + sin(a) * out[i];
                at[i] = sg->base[i] + t * len * d[i] + r * out[i];
            }
            vec3_cross(L, up, W);
            if (vec3_normalize(W, 1e-12)) vec3_cross(L, out, W), vec3_normalize(W, 1e-12);
            turn(W, L, roll);
            emit_leaf(b, cfg, at, L, W, leaf);
        }
    }
    return SYLVA_OK;
}
