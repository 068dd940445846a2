/* lsys_turtle.c — interpretation of a derived string: one pass over the bytes, a switch per
 * symbol, a stack of turtle states for `[ ]` and a separate vertex stack for `{ }`. Limits on
 * segments, polygons, polygon vertices and nesting are checked before anything grows. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lsys_symbols.h"
#include "lsys_turtle.h"

#define DEG (M_PI / 180.0)
#define DEFAULT_TROPISM 0.2    /* `t` without an argument (Lparser 2.1 manual) */
#define BARE_RANDOM_TURN 6.0   /* `~` without an argument turns up to this many radians (Lparser) */
#define MAX_COLOUR_INDEX 65535 /* colour indices are clamped to [0, this] */

typedef struct turtle_state {
    double pos[3];
    lsys_frame frame;
    double length;     /* F length */
    double angle;      /* standard angle, degrees */
    double thickness;  /* percent of the segment length */
    int32_t colour;
    lsys_joint joint;
} turtle_state;

typedef struct turtle {
    const lsys_turtle_config *cfg;
    const lsys_sink *sinks;
    int n_sinks;
    lsys_turtle_stats st;
    plugin_err *err;
    turtle_state cur;
    turtle_state *stack;        /* owned */
    uint32_t depth, cap;
    double *pv;                 /* owned: vertices of open polygons, xyz */
    uint32_t npv, cap_pv;
    uint32_t *pstart;           /* owned: first vertex of each open polygon */
    uint32_t npoly, cap_poly;
} turtle;

/* Grows the bounds by p +- r[k] along each axis. */
static void grow_bounds(turtle *t, const double p[3], const double r[3])
{
    if (!t->st.has_bounds) {
        for (int k = 0; k < 3; k++) t->st.lo[k] = p[k] - r[k], t->st.hi[k] = p[k] + r[k];
        t->st.has_bounds = 1;
        return;
    }
    for (int k = 0; k < 3; k++) {
        if (p[k] - r[k] < t->st.lo[k]) t->st.lo[k] = p[k] - r[k];
        if (p[k] + r[k] > t->st.hi[k]) t->st.hi[k] = p[k] + r[k];
    }
}

/* Grows the bounds by the corners of both ends of the tube p0..p1 of radius r (cfg->tube_corners
 * of them, around U made square to the axis). */
static void grow_tube_bounds(turtle *t, const double p0[3], const double p1[3], double r)
{
    static const double none[3] = {0.0, 0.0, 0.0};
    grow_bounds(t, p0, none);
    grow_bounds(t, p1, none);
    int corners = t->cfg->tube_corners;
    if (corners != 4 && corners != 8) return;
    double a[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]}, e2[3], e3[3];
    const double *u = t->cur.frame.u;
    double na = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]), nu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if (!(na > 0.0) || !(nu > 0.0)) return;
    for (int k = 0; k < 3; k++) a[k] /= na, e2[k] = u[k] / nu;
    e3[0] = a[1] * e2[2] - a[2] * e2[1], e3[1] = a[2] * e2[0] - a[0] * e2[2], e3[2] = a[0] * e2[1] - a[1] * e2[0];
    double n3 = sqrt(e3[0] * e3[0] + e3[1] * e3[1] + e3[2] * e3[2]);
    if (!(n3 > 0.0)) return;
    /* Offsets (i, j) along (e2, e3): a block's four corners, or a ring's eight vertices. */
    static const double square[4][2] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
    const double h = sqrt(0.5);
    const double ring[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {h, h}, {h, -h}, {-h, h}, {-h, -h}};
    for (int c = 0; c < corners; c++) {
        double i = corners == 4 ? square[c][0] : ring[c][0], j = corners == 4 ? square[c][1] : ring[c][1];
        double q0[3], q1[3];
        for (int k = 0; k < 3; k++) {
            double o = r * (i * e2[k] + j * e3[k] / n3);
            q0[k] = p0[k] + o, q1[k] = p1[k] + o;
        }
        grow_bounds(t, q0, none);
        grow_bounds(t, q1, none);
    }
}

static int record_vertex(turtle *t)
{
    if (!t->npoly) return LSYS_OK;
    if (t->npv >= t->cfg->max_polygon_vertices)
        return plugin_fail(t->err, LSYS_ERR_LIMIT,
                         "open polygons hold more than max_polygon_vertices = %u vertices; close polygons "
                         "with '}' sooner or raise max_polygon_vertices",
                         t->cfg->max_polygon_vertices);
    if (t->npv == t->cap_pv) {
        uint32_t cap = t->cap_pv ? t->cap_pv * 2 : 64;
        if (cap > t->cfg->max_polygon_vertices) cap = t->cfg->max_polygon_vertices;
        double *g = realloc(t->pv, (size_t)cap * 3 * sizeof *g);
        if (!g) return plugin_fail(t->err, LSYS_ERR_NOMEM, "out of memory for polygon vertices");
        t->pv = g, t->cap_pv = cap;
    }
    memcpy(t->pv + 3 * (size_t)t->npv, t->cur.pos, sizeof t->cur.pos);
    t->npv++;
    return LSYS_OK;
}

static int move(turtle *t, double d, int draw, int record)
{
    turtle_state *c = &t->cur;
    double p0[3] = {c->pos[0], c->pos[1], c->pos[2]};
    for (int k = 0; k < 3; k++) c->pos[k] += d * c->frame.h[k];
    if (!isfinite(c->pos[0] + c->pos[1] + c->pos[2]))
        return plugin_fail(t->err, LSYS_ERR_LIMIT,
                         "the turtle moved beyond finite coordinates (a length grew without bound); check "
                         "the length modifiers ' \" and the arguments of F, Z, f, z, g");
    if (draw && d != 0.0) {
        if (t->st.segments >= t->cfg->max_segments)
            return plugin_fail(t->err, LSYS_ERR_LIMIT,
                             "the L-system draws more than max_segments = %llu segments; lower the recursion "
                             "level or raise max_segments",
                             (unsigned long long)t->cfg->max_segments);
        t->st.segments++;
        /* Width: thickness percent of the length, at least min_thickness / 100 file units. */
        double width = fabs(d) * c->thickness / 100.0, floor = t->cfg->min_thickness / 100.0;
        /* A segment near the largest double (F(1e308)) overflows the product; the same width
         * then comes from the percentage first. */
        if (!isfinite(width)) width = fabs(d) * (c->thickness / 100.0);
        if (!isfinite(width))
            return plugin_fail(t->err, LSYS_ERR_LIMIT,
                               "a segment of %g units at thickness %g %% is wider than finite numbers; "
                               "check the arguments of F and the thickness modifiers ! and #",
                               fabs(d), c->thickness);
        double r = 0.5 * (width > floor ? width : floor);
        lsys_segment seg = {.p0 = {p0[0], p0[1], p0[2]}, .p1 = {c->pos[0], c->pos[1], c->pos[2]},
                            .frame = &c->frame, .radius = r, .colour = c->colour, .joint = &c->joint};
        grow_tube_bounds(t, p0, c->pos, r);
        for (int i = 0; i < t->n_sinks; i++)
            if (t->sinks[i].segment && t->sinks[i].segment(t->sinks[i].ctx, &seg)) return LSYS_ERR_SINK;
    }
    return record ? record_vertex(t) : LSYS_OK;
}

static int joint_end(turtle *t, lsys_joint *j)
{
    if (!j->open) return LSYS_OK;
    for (int i = 0; i < t->n_sinks; i++)
        if (t->sinks[i].joint_end && t->sinks[i].joint_end(t->sinks[i].ctx, j)) return LSYS_ERR_SINK;
    j->open = 0;
    return LSYS_OK;
}

static int push(turtle *t)
{
    if (t->depth >= t->cfg->max_depth)
        return plugin_fail(t->err, LSYS_ERR_LIMIT,
                         "brackets [ ] nest deeper than %u levels (the nesting limit); the string has "
                         "unbalanced '[' or an extreme recursion level",
                         t->cfg->max_depth);
    if (t->depth == t->cap) {
        uint32_t cap = t->cap ? t->cap * 2 : 64;
        if (cap > t->cfg->max_depth) cap = t->cfg->max_depth;
        turtle_state *g = realloc(t->stack, (size_t)cap * sizeof *g);
        if (!g) return plugin_fail(t->err, LSYS_ERR_NOMEM, "out of memory for the bracket stack");
        t->stack = g, t->cap = cap;
    }
    t->stack[t->depth++] = t->cur;
    if (t->depth > t->st.depth) t->st.depth = t->depth;
    t->cur.joint.open = 0; /* a branch starts a tube of its own */
    return LSYS_OK;
}

static int pop(turtle *t)
{
    if (!t->depth) {
        t->st.stray_pops++;
        return LSYS_OK;
    }
    int rc = joint_end(t, &t->cur.joint);
    if (rc) return rc;
    t->cur = t->stack[--t->depth];
    return LSYS_OK;
}

static int polygon_begin(turtle *t)
{
    if (t->npoly == t->cap_poly) {
        uint32_t cap = t->cap_poly ? t->cap_poly * 2 : 16;
        if (cap > t->cfg->max_depth) cap = t->cfg->max_depth;
        if (t->npoly >= cap)
            return plugin_fail(t->err, LSYS_ERR_LIMIT, "polygons { } nest deeper than %u levels (the nesting limit)",
                             t->cfg->max_depth);
        uint32_t *g = realloc(t->pstart, (size_t)cap * sizeof *g);
        if (!g) return plugin_fail(t->err, LSYS_ERR_NOMEM, "out of memory for the polygon stack");
        t->pstart = g, t->cap_poly = cap;
    }
    t->pstart[t->npoly++] = t->npv;
    return LSYS_OK;
}

/* Drops vertices that repeat their predecessor (the closing f of a leaf returns to the first
 * vertex; `{.` records the start twice). Returns the count kept. */
static uint32_t drop_repeats(double *v, uint32_t n)
{
    uint32_t k = 0;
    for (uint32_t i = 0; i < n; i++) {
        double *p = v + 3 * i;
        if (k) {
            double *q = v + 3 * (k - 1);
            double d = fabs(p[0] - q[0]) + fabs(p[1] - q[1]) + fabs(p[2] - q[2]);
            double s = fabs(p[0]) + fabs(p[1]) + fabs(p[2]) + 1e-300;
            if (d <= 1e-9 * s) continue;
        }
        memmove(v + 3 * k, p, 3 * sizeof *v);
        k++;
    }
    while (k > 1) {
        double *p = v, *q = v + 3 * (k - 1);
        double d = fabs(p[0] - q[0]) + fabs(p[1] - q[1]) + fabs(p[2] - q[2]);
        double s = fabs(p[0]) + fabs(p[1]) + fabs(p[2]) + 1e-300;
        if (d > 1e-9 * s) break;
        k--;
    }
    return k;
}

static int polygon_end(turtle *t)
{
    if (!t->npoly) {
        t->st.stray_polygon_ends++;
        return LSYS_OK;
    }
    uint32_t start = t->pstart[--t->npoly];
    /* Three recorded vertices make a polygon, as in Lparser, even when they coincide; the sinks
     * get it only when three distinct ones remain. A polygon closed before any vertex was stored
     * has no vertex buffer at all (pv is NULL). */
    uint32_t recorded = t->npv - start;
    uint32_t n = recorded ? drop_repeats(t->pv + 3 * (size_t)start, recorded) : 0;
    if (recorded >= 3) {
        if (t->st.polygons >= t->cfg->max_polygons)
            return plugin_fail(t->err, LSYS_ERR_LIMIT,
                             "the L-system draws more than max_polygons = %llu polygons; lower the recursion "
                             "level or raise max_polygons",
                             (unsigned long long)t->cfg->max_polygons);
        t->st.polygons++;
        const double *v = t->pv + 3 * (size_t)start;
        static const double none[3] = {0.0, 0.0, 0.0};
        for (uint32_t i = 0; i < n; i++) grow_bounds(t, v + 3 * i, none);
        for (int i = 0; n >= 3 && i < t->n_sinks; i++)
            if (t->sinks[i].polygon && t->sinks[i].polygon(t->sinks[i].ctx, v, n, t->cur.colour))
                return LSYS_ERR_SINK;
    }
    t->npv = start;
    return LSYS_OK;
}

/* Turns, pitches and rolls by three uniform angles in [-a, a], a in radians. */
static void random_turn(turtle *t, double a)
{
    const lsys_turtle_config *cfg = t->cfg;
    double r1 = cfg->random(cfg->random_ctx), r2 = cfg->random(cfg->random_ctx), r3 = cfg->random(cfg->random_ctx);
    lsys_frame_turn(&t->cur.frame, (2.0 * r1 - 1.0) * a);
    lsys_frame_pitch(&t->cur.frame, (2.0 * r2 - 1.0) * a);
    lsys_frame_roll(&t->cur.frame, (2.0 * r3 - 1.0) * a);
}

static int run(turtle *t, const unsigned char *s, size_t n)
{
    turtle_state *c = &t->cur;
    int rc = LSYS_OK;
    for (size_t i = 0; i < n && !rc;) {
        unsigned char sym = s[i++];
        double arg = 0.0;
        int has_arg = 0;
        if (sym == '(') {
            /* An argument left behind by a rewritten symbol belongs to nothing. */
            size_t g = lsys_arg_group(s + i - 1, n - i + 1, NULL);
            if (g) i += g - 1;
            continue;
        }
        if (i < n && s[i] == '(') {
            size_t g = lsys_arg_group(s + i, n - i, &arg);
            if (g) {
                has_arg = 1, i += g;
                while (i < n && s[i] == '(' && (g = lsys_arg_group(s + i, n - i, NULL))) i += g;
            }
        }
        t->st.symbols++;
        switch (sym) {
        case 'F': rc = move(t, has_arg ? arg : c->length, 1, 0); break;
        case 'Z': rc = move(t, has_arg ? arg : 0.5 * c->length, 1, 0); break;
        case 'f': rc = move(t, has_arg ? arg : c->length, 0, 1); break;
        case 'z': rc = move(t, has_arg ? arg : 0.5 * c->length, 0, 1); break;
        case 'g': rc = move(t, has_arg ? arg : c->length, 0, 0); break;
        case '.': rc = record_vertex(t); break;
        case '+': lsys_frame_turn(&c->frame, (has_arg ? arg : c->angle) * DEG); break;
        case '-': lsys_frame_turn(&c->frame, -(has_arg ? arg : c->angle) * DEG); break;
        case '&': lsys_frame_pitch(&c->frame, (has_arg ? arg : c->angle) * DEG); break;
        case '^': lsys_frame_pitch(&c->frame, -(has_arg ? arg : c->angle) * DEG); break;
        case '<': lsys_frame_roll(&c->frame, (has_arg ? arg : c->angle) * DEG); break;
        case '>': lsys_frame_roll(&c->frame, -(has_arg ? arg : c->angle) * DEG); break;
        case '|': lsys_frame_turn(&c->frame, M_PI); break;
        case '%': lsys_frame_roll(&c->frame, M_PI); break;
        case '$': lsys_frame_roll_horizontal(&c->frame); break;
        case 't': lsys_frame_tropism(&c->frame, has_arg ? arg : DEFAULT_TROPISM); break;
        case '~':
            if (!t->cfg->random) {
                rc = plugin_fail(t->err, LSYS_ERR_SYNTAX, "'~' needs a random stream and none was given");
                break;
            }
            random_turn(t, has_arg ? arg * DEG : BARE_RANDOM_TURN);
            break;
        case '[': rc = push(t); break;
        case ']': rc = pop(t); break;
        case '{': rc = polygon_begin(t); break;
        case '}': rc = polygon_end(t); break;
        case 'c':
            if (has_arg) {
                double v = floor(arg + 0.5);
                c->colour = v < 0 ? 0 : v > MAX_COLOUR_INDEX ? MAX_COLOUR_INDEX : (int32_t)v;
            } else if (c->colour < MAX_COLOUR_INDEX) {
                c->colour++;
            }
            break;
        case '"': c->length = has_arg ? c->length * arg : c->length / 0.9; break;
        case '\'': c->length *= has_arg ? arg : 0.9; break;
        case ';': c->angle = has_arg ? c->angle * arg : c->angle / 0.9; break;
        case ':': c->angle *= has_arg ? arg : 0.9; break;
        case '?': c->thickness = has_arg ? c->thickness * arg : c->thickness / 0.7; break;
        case '!': c->thickness *= has_arg ? arg : 0.7; break;
        default: break; /* rule variables, digits, `_`: no drawing */
        }
    }
    if (rc) return rc;
    /* The end of the string closes every branch that is still open. */
    if ((rc = joint_end(t, &t->cur.joint))) return rc;
    for (uint32_t d = t->depth; d-- > 0;)
        if ((rc = joint_end(t, &t->stack[d].joint))) return rc;
    t->st.open_at_end = t->depth + t->npoly;
    return LSYS_OK;
}

int lsys_interpret(const unsigned char *s, size_t n, const lsys_turtle_config *cfg, const lsys_sink *sinks,
                   int n_sinks, lsys_turtle_stats *stats, plugin_err *err)
{
    turtle t = {.cfg = cfg, .sinks = sinks, .n_sinks = n_sinks, .err = err};
    t.cur.frame = (lsys_frame){.h = {0, 0, 1}, .l = {0, 1, 0}, .u = {1, 0, 0}};
    t.cur.length = cfg->base_length;
    t.cur.angle = cfg->angle_deg;
    t.cur.thickness = cfg->thickness;
    t.cur.colour = cfg->colour;
    int rc = run(&t, s, n);
    free(t.stack);
    free(t.pv);
    free(t.pstart);
    if (stats) *stats = t.st;
    return rc;
}
