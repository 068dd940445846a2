/* lsys_turtle.h — the 3-D turtle that reads a derived string (001 §3; MODELS.md §3) as Lapré's
 * Lparser 2.1 reads it: position P and the frame H (heading), L (left), U (up). The turtle starts
 * at the origin with H = +Z, L = +Y, U = +X (so U = L x H); `+` turns H toward L, `&` pitches H
 * toward U, `<` rolls L toward U, as Lparser's own figures show (reference-outputs/README.md);
 * `$` lays L horizontal and changes the frame's handedness; `t` pitches by e |H_xy|; `~` turns
 * at random; `[ ]` push and pop the whole state; `{ }` collect the vertices that f, z and `.`
 * record (a polygon may span rules and brackets: its vertices are kept apart from the bracket
 * stack). docs/models/tree_lsystem.md lists every command and each departure from Lparser.
 *
 * It draws nothing itself: segments and polygons go to sinks (the mesh builder, the silhouette
 * raster, tests). Lengths are in the file's units.
 *
 * Ownership: the caller owns the string, the config and the sinks; the turtle allocates its
 * stacks and frees them before returning.
 */
#ifndef LSYS_TURTLE_H
#define LSYS_TURTLE_H

#include <stddef.h>
#include <stdint.h>

#include "lsys_status.h"

/* The turtle's orientation. H is a unit vector; L and U are unit and square to H except after
 * `$`, which leaves them |H_xy| long (as Lparser does); U = L x H until `$` makes it H x L. */
typedef struct lsys_frame {
    double h[3], l[3], u[3];
} lsys_frame;

/* Each rotation turns two vectors about the third as it stands (a right-handed turn when that
 * axis is unit, a smaller one when `$` left it shorter) and makes the two unit. Radians. */
/* `+(a)`: H and L turn by -a about U (`-` is a = -angle). */
void lsys_frame_turn(lsys_frame *f, double a);
/* `&(a)`: H and U turn by a about L (`^` is a = -angle). */
void lsys_frame_pitch(lsys_frame *f, double a);
/* `<(a)`: L and U turn by -a about H (`>` is a = -angle). */
void lsys_frame_roll(lsys_frame *f, double a);
/* `$`: L = H x Z, U = H x L, both negated when U points down (always, for a unit H), unit
 * lengths not restored; unchanged when H is vertical. */
void lsys_frame_roll_horizontal(lsys_frame *f);
/* `t(e)`: `&` by e |H_xy| radians (a positive e bends a leaning H further down); unchanged when
 * H is vertical. */
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
    double radius;        /* half the width: max(length * thickness, min_thickness) / 200 */
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
    double min_thickness;      /* smallest width in hundredths of a file unit (Lparser) */
    double base_length;        /* length of F at the start */
    int32_t colour;            /* colour index at the start (Lparser: 2) */
    uint64_t max_segments;     /* limits: exceeding one is an LSYS_ERR_LIMIT naming it */
    uint64_t max_polygons;
    uint32_t max_polygon_vertices; /* vertices held by open polygons at once */
    uint32_t max_depth;        /* nesting of [ ] */
    /* The corners of a tube's end that the bounds take in, as Lparser places them: 8 (a
     * cylinder's ring: radius r along U, U x H and their diagonals), 4 (a block: U +- U x H, each
     * r long), 0 (the axis alone). */
    int tube_corners;
    /* Uniform numbers in [0, 1) for `~`; NULL makes `~` an error. */
    double (*random)(void *ctx);
    void *random_ctx;
} lsys_turtle_config;

typedef struct lsys_turtle_stats {
    uint64_t symbols;          /* commands and variables read (an argument belongs to its symbol) */
    uint64_t segments;         /* drawn segments */
    uint64_t polygons;         /* closed polygons with >= 3 recorded vertices (degenerate ones too) */
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
                   const lsys_sink *sinks, int n_sinks, lsys_turtle_stats *stats, plugin_err *err);

#endif
