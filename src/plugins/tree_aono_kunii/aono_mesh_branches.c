/* aono_mesh_branches.c — bark geometry: tapered tubes, mitred rings shared between a mother and
 * her continuation, open bases of side branches buried at the joint, caps on free ends. */
#include <math.h>
#include <stdlib.h>

#include "aono_mesh.h"
#include "vec3.h"

#define AONO_TWO_PI 6.28318530717958647692

/* What the builder remembers of a segment for its children. */
typedef struct ring_memo {
    double dir[3];     /* unit direction of the segment */
    double ref[3];     /* unit vector at u = 0 of its rings, perpendicular to dir */
    double v_tip;      /* v at its tip ring */
    uint32_t tip_ring; /* first vertex of its tip ring */
} ring_memo;

/* The rotation taking unit a to unit b by the smallest angle, applied to v (a·b > −1). */
static void rotate_between(const double a[3], const double b[3], const double v[3], double out[3])
{
    double k[3], kv[3];
    vec3_cross(a, b, k);
    vec3_cross(k, v, kv);
    double c = vec3_dot(a, b), f = vec3_dot(k, v) / (1.0 + c);
    for (int i = 0; i < 3; i++) out[i] = v[i] * c + kv[i] + k[i] * f;
}

/* A unit vector perpendicular to d, as close to `hint` as possible. */
static void perpendicular(const double d[3], const double hint[3], double out[3])
{
    double h = vec3_dot(hint, d);
    for (int i = 0; i < 3; i++) out[i] = hint[i] - h * d[i];
    if (!vec3_normalize(out, 1e-12)) return;
    double axis[3] = {fabs(d[0]) < 0.9 ? 1.0 : 0.0, fabs(d[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    h = vec3_dot(axis, d);
    for (int i = 0; i < 3; i++) out[i] = axis[i] - h * d[i];
    vec3_normalize(out, 1e-12);
}

uint32_t aono_ring_sides(const aono_config *cfg, double radius)
{
    double s = round(cfg->sides * radius / cfg->trunk_radius);
    if (s < cfg->min_sides) s = cfg->min_sides;
    if (s > cfg->sides) s = cfg->sides;
    return (uint32_t)s;
}

/* The direction at u = j / sides around axis d from ref. */
static void ring_dir(const double d[3], const double ref[3], uint32_t j, uint32_t sides, double e[3])
{
    double side[3], th = AONO_TWO_PI * j / sides;
    vec3_cross(d, ref, side);
    for (int i = 0; i < 3; i++) e[i] = cos(th) * ref[i] + sin(th) * side[i];
}

/* A ring perpendicular to d at centre c; returns its first vertex. */
static uint32_t emit_ring(aono_mesh_buffer *b, const double c[3], const double d[3], const double ref[3],
                          double r, uint32_t sides, double v)
{
    uint32_t first = b->nv;
    for (uint32_t j = 0; j <= sides; j++) {
        double e[3], p[3];
        ring_dir(d, ref, j % sides, sides, e);
        for (int i = 0; i < 3; i++) p[i] = c[i] + r * e[i];
        aono_mesh_vertex(b, p, e, (double)j / sides, v);
    }
    return first;
}

/* The mitre ring at joint c between direction a and its continuation bd: each point of the
 * circle of radius r about a, moved along a into the plane bisecting a and bd. */
static uint32_t emit_mitre_ring(aono_mesh_buffer *b, const double c[3], const double a[3], const double bd[3],
                                const double ref[3], double r, uint32_t sides, double v)
{
    double n[3] = {a[0] + bd[0], a[1] + bd[1], a[2] + bd[2]};
    vec3_normalize(n, 1e-12);
    double an = vec3_dot(a, n);
    uint32_t first = b->nv;
    for (uint32_t j = 0; j <= sides; j++) {
        double e[3], e2[3], p[3], nrm[3];
        ring_dir(a, ref, j % sides, sides, e);
        double t = -r * vec3_dot(e, n) / an;
        rotate_between(a, bd, e, e2);
        for (int i = 0; i < 3; i++) p[i] = c[i] + r * e[i] + t * a[i], nrm[i] = e[i] + e2[i];
        vec3_normalize(nrm, 1e-12);
        aono_mesh_vertex(b, p, nrm, (double)j / sides, v);
    }
    return first;
}

/* Triangles between ring A (na sides, base) and ring B (nb sides, further along), advancing
 * along whichever ring is behind in u. Counter-clockwise seen from outside. */
static void stitch(aono_mesh_buffer *b, uint32_t A, uint32_t na, uint32_t B, uint32_t nb, int32_t mat)
{
    uint32_t i = 0, j = 0;
    while (i < na || j < nb) {
        if (j == nb || (i < na && (uint64_t)(i + 1) * nb <= (uint64_t)(j + 1) * na)) {
            aono_mesh_triangle(b, A + i, A + i + 1, B + j, mat);
            i++;
        } else {
            aono_mesh_triangle(b, A + i, B + j + 1, B + j, mat);
            j++;
        }
    }
}

/* A fan closing ring R at centre c, facing along `facing` (+1: along d, −1: against it). */
static void cap(aono_mesh_buffer *b, uint32_t R, uint32_t sides, const double c[3], const double d[3],
                int facing, double v, int32_t mat)
{
    double n[3] = {facing * d[0], facing * d[1], facing * d[2]};
    uint32_t centre = aono_mesh_vertex(b, c, n, 0.5, v);
    for (uint32_t j = 0; j < sides; j++) {
        if (facing > 0) aono_mesh_triangle(b, centre, R + j, R + j + 1, mat);
        else aono_mesh_triangle(b, centre, R + j + 1, R + j, mat);
    }
}

static int mesh_failed(int rc, plugin_err *err)
{
    if (rc == -2)
        return plugin_fail(err, SYLVA_ERR_LIMIT,
                           "the tree's bark needs more than %u vertices or %u triangles (the host's per-mesh "
                           "limits); lower levels or sides", AONO_MESH_MAX_VERTICES, AONO_MESH_MAX_TRIANGLES);
    return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory building the tree's bark");
}

int aono_mesh_branches(const aono_config *cfg, const aono_skeleton *s, int32_t bark, aono_mesh_buffer *b,
                       plugin_err *err)
{
    ring_memo *memo = malloc((size_t)(s->n ? s->n : 1) * sizeof *memo); /* owned here */
    if (!memo) return mesh_failed(-1, err);
    int rc = 0;
    for (uint32_t k = 0; k < s->n && !rc; k++) {
        const aono_segment *sg = &s->seg[k];
        ring_memo *me = &memo[k];
        double len = 0.0;
        for (int i = 0; i < 3; i++) me->dir[i] = sg->tip[i] - sg->base[i];
        len = vec3_length(me->dir);
        vec3_normalize(me->dir, 1e-12);
        uint32_t nb = aono_ring_sides(cfg, sg->radius_base), nt = aono_ring_sides(cfg, sg->radius_tip);
        if ((rc = aono_mesh_reserve(b, nb + nt + 4, nb + 2 * nt + nb))) break;
        uint32_t base_ring;
        double v0;
        if (sg->continues) {
            const ring_memo *pm = &memo[sg->parent];
            rotate_between(pm->dir, me->dir, pm->ref, me->ref);
            perpendicular(me->dir, me->ref, me->ref); /* removes rounding drift */
            base_ring = pm->tip_ring;
            v0 = pm->v_tip;
        } else {
            static const double east[3] = {1.0, 0.0, 0.0};
            perpendicular(me->dir, sg->parent == AONO_NONE ? east : memo[sg->parent].dir, me->ref);
            v0 = 0.0;
            base_ring = emit_ring(b, sg->base, me->dir, me->ref, sg->radius_base, nb, v0);
            /* the trunk's foot, and a side branch of a mother that nothing continues (its base
             * then reaches past her capped end), are closed */
            if (sg->parent == AONO_NONE || s->seg[sg->parent].continuation == AONO_NONE)
                cap(b, base_ring, nb, sg->base, me->dir, -1, v0, bark);
        }
        me->v_tip = v0 + len / (AONO_TWO_PI * 0.5 * (sg->radius_base + sg->radius_tip));
        if (sg->continuation != AONO_NONE) {
            const aono_segment *ch = &s->seg[sg->continuation];
            double cd[3];
            for (int i = 0; i < 3; i++) cd[i] = ch->tip[i] - ch->base[i];
            vec3_normalize(cd, 1e-12);
            me->tip_ring = emit_mitre_ring(b, sg->tip, me->dir, cd, me->ref, sg->radius_tip, nt, me->v_tip);
            stitch(b, base_ring, nb, me->tip_ring, nt, bark);
        } else {
            me->tip_ring = emit_ring(b, sg->tip, me->dir, me->ref, sg->radius_tip, nt, me->v_tip);
            stitch(b, base_ring, nb, me->tip_ring, nt, bark);
            cap(b, me->tip_ring, nt, sg->tip, me->dir, +1, me->v_tip, bark);
        }
    }
    free(memo);
    return rc ? mesh_failed(rc, err) : SYLVA_OK;
}
