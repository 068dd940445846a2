/* lsys_turtle.h — the 3-D turtle that reads a derived string (001 §3; MODELS.md §3): position P
 * and the orthonormal frame H (heading), L (left), U (up) with U = H x L; the rotations of
 * 001 Table 2 right-multiply [H L U] by R_U, R_L, R_H; `$` rolls L horizontal (001 eq. 2);
 * `t` bends H toward T = (0, 0, -1) by e |H x T| (001 eq. 3); `~` turns at random; `[ ]`
 * push and pop the whole state; `{ }` collect polygon vertices (a polygon may span rules and
 * brackets: its vertices are kept apart from the bracket stack).
 *
 * The turtle starts at the origin with H = +Z, L = +Y, U = -X (right-handed, as the Lparser 2.1
 * manual states). It draws nothing itself: segments and polygons go to sinks (the mesh builder,
 * the silhouette raster, tests). Lengths are in the file's units.
 *
 * Ownership: the caller owns the string, the config and the sinks; the turtle allocates its
 * stacks and frees them before returning.
 */
#ifndef LSYS_TURTLE_H
#define LSYS_TURTLE_H

#include <stddef.h>
#include <stdint.h>

#include "lsys_error.h"

/* The turtle's orientation: three orthonormal vectors, U = H x L. */
typedef struct lsys_frame {
    double h[3], l[3], u[3];
} lsys_frame;

/* [H L U] <- [H L U] R_U(a): turn about U (`+` is a = +angle, `-` is -angle). Radians. */
void lsys_frame_turn(lsys_frame *f, double a);
/* [H L U] <- [H L U] R_L(a): pitch about L (`&` +angle, `^` -angle). */
void lsys_frame_pitch(lsys_frame *f, double a);
/* [H L U] <- [H L U] R_H(a): roll about H (`<` +angle, `>` -angle). */
void lsys_frame_roll(lsys_frame *f, double a);
/* `$` (001 eq. 2): L = V x H / |V x H| with V = (0, 0, -1), U = H x L; unchanged when H is
 * vertical (V x H vanishes). */
void lsys_frame_roll_horizontal(lsys_frame *f);
/* `t(e)` (001 eq. 3): rotates the frame about H x T by e |H x T| radians, T = (0, 0, -1); a
 * positive e bends H down, a negative one up; unchanged when H is vertical. */
void lsys_frame_tropism(lsys_frame *f, double e);

/* The open end of the tube a branch is drawing: where the next segment joins without a gap.
 * Kept in the turtle state (pushed and popped with it) but read and written only by the
 * geometry sink. */
typedef struct lsys_joint {
    double center[3];
    double e1[3], e2[3];  /* the ring's plane: unit, perpendicular, e1 x e2 along the tube */
    double radius;
    double bark_v;        /* the bark texture's v at the ring: metres along the branches from
                           * the model's base over the bark's tile length */
    int32_t colour;       /* colour index of the tube that ends at the ring */
    uint64_t chunk;       /* the sink's output chunk holding the ring's vertices */
    uint32_t first;       /* index of the ring's first vertex in that chunk */
    int open;             /* 1 while a segment may continue from this ring */
} lsys_joint;

/* One drawn segment (F or Z), in file units. */
typedef struct lsys_segment {
    double p0[3], p1[3];  /* start and end */
    const lsys_frame *frame; /* the turtle's frame while drawing */
    double radius;        /* half the width: length * max(thickness, min_thickness) / 200 */
    int32_t colour;       /* colour index */
    lsys_joint *joint;    /* the branch's open end: the sink reads and updates it */
} lsys_segment;

/* A consumer of the turtle's output. Any callback may be NULL. A non-zero return stops the
 * interpretation with LSYS_ERR_SINK (the sink keeps its own message). */
typedef struct lsys_sink {
    void *ctx;
    int (*segment)(void *ctx, const lsys_segment *seg);
    /* A closed polygon: n >= 3 vertices (xyz, file units) in drawing order. */
    int (*polygon)(void *ctx, const double *xyz, uint32_t n, int32_t colour);
    /* A branch ended (`]` or the end of the string) while its joint was open. */
    int (*joint_end)(void *ctx, lsys_joint *joint);
} lsys_sink;

typedef struct lsys_turtle_config {
    double angle_deg;          /* standard angle */
    double thickness;          /* percent of the segment length */
    double min_thickness;      /* percent of the segment length */
    double base_length;        /* length of F at the start */
    int32_t colour;            /* colour index at the start (Lparser: 2) */
    uint64_t max_segments;     /* limits: exceeding one is an LSYS_ERR_LIMIT naming it */
    uint64_t max_polygons;
    uint32_t max_polygon_vertices; /* vertices held by open polygons at once */
    uint32_t max_depth;        /* nesting of [ ] */
    /* How far a tube's corners reach from its axis, in radii (1 for cylinders, sqrt 2 for
     * blocks), for the bounds; 0 counts the axis alone. */
    double tube_reach;
    /* Uniform numbers in [0, 1) for `~`; NULL makes `~` an error. */
    double (*random)(void *ctx);
    void *random_ctx;
} lsys_turtle_config;

typedef struct lsys_turtle_stats {
    uint64_t symbols;          /* commands and variables read (an argument belongs to its symbol) */
    uint64_t segments;         /* drawn segments */
    uint64_t polygons;         /* closed polygons with >= 3 vertices */
    uint64_t stray_pops;       /* `]` with nothing pushed (ignored) */
    uint64_t stray_polygon_ends; /* `}` with no open polygon (ignored) */
    uint64_t open_at_end;      /* `[` and `{` still open at the end of the string */
    uint32_t depth;            /* deepest bracket nesting */
    int has_bounds;            /* 1 when something was drawn */
    double lo[3], hi[3];       /* bounds of the tubes around the segments and of polygon vertices */
} lsys_turtle_stats;

/* Interprets s[0..n) and feeds the n_sinks sinks. Returns LSYS_OK, LSYS_ERR_LIMIT (the
 * sentence names the limit), LSYS_ERR_NOMEM or LSYS_ERR_SINK. stats may be NULL. */
int lsys_interpret(const unsigned char *s, size_t n, const lsys_turtle_config *cfg,
                   const lsys_sink *sinks, int n_sinks, lsys_turtle_stats *stats, lsys_error *err);

#endif
