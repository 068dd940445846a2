/* blossom.h — flowers on a species' plants as a particle system (docs/models/leaves_bark_blossom.md,
 * Blossom by a particle system).
 *
 * Each plant of the species is a source of particles. A particle is born on one of its crown
 * points (the centres of the prototype's leaf-material triangles; for a prototype without leaves,
 * the centres of its triangles in the upper half of its height) on a random day of the blossom
 * season, lives a random number of days and is then deleted. While it lives it drifts from its
 * crown point at a random constant velocity (p(t) = p0 + v (t - t_birth)), grows from a bud to
 * an open flower, and its colour moves from the open colour towards the faded one, each with its
 * own random share. For a still the system is sampled at one day: every particle alive that day
 * becomes a small two-sided disc, an instance of the species' petal prototype placed in the
 * plant's frame (composed with the plant instance's transform, its scale taken out so that sizes
 * are metres in the world).
 *
 * The petal prototypes form one species "blossom <species>" with BLOSSOM_COLOURS variants, the
 * same disc in a ramp of colours from the open to the faded colour; a particle takes the variant
 * nearest its colour. The petals are flagged as ground cover (no canopy, no crown proxy): they
 * are not plants.
 *
 * Every number is a hash of the seed, the plant's instance index and the particle's number, and
 * the plants are visited in instance order, so the same scene and seed give the same petals
 * whatever the thread count. */
#ifndef SYLVA_BLOSSOM_H
#define SYLVA_BLOSSOM_H

#include <stdint.h>

#include "scene/scene.h"
#include "util/err.h"
#include "util/vec3.h"

#define BLOSSOM_COLOURS 8u   /* petal variants along the colour ramp */
#define BLOSSOM_DISC_SIDES 8u /* a petal disc is an octagon */

typedef struct blossom_params {
    double first_day, last_day;        /* days of the year: births fall uniformly in [first, last) */
    double lifetime_min, lifetime_max; /* days a flower lives, uniform in [min, max] */
    double per_point;                  /* flowers per crown point over the season (expected) */
    uint32_t max_per_plant;            /* flowers per plant over the season at most */
    double speed_max;                  /* metres per day: drift speed uniform in [0, max] */
    double size_min, size_max;         /* metres: radius of an open flower, uniform in [min, max] */
    double bud_size;                   /* share of the full radius at birth, (0, 1] */
    double opening;                    /* share of the lifetime spent opening, (0, 1] */
    double aspect_min;                 /* a flower's second radius is [aspect_min, 1] of its first */
    float colour_open[3];              /* linear RGB of a flower that has just opened */
    float colour_faded[3];             /* linear RGB at the end of its life */
    double colour_jitter;              /* [0, 1]: share of a flower's colour that is random, not age */
    uint64_t max_instances;            /* petals one blossom_add adds at most (a clear error beyond) */
} blossom_params;

/* One particle's random draws (its state over its whole life). */
typedef struct blossom_particle {
    uint32_t point;      /* index of its crown point */
    double birth;        /* day */
    double lifetime;     /* days */
    vec3 velocity;       /* metres per day, in the plant's frame */
    vec3 normal;         /* unit normal of its disc, in the plant's frame */
    double size;         /* metres: radius when open */
    double aspect;       /* second radius / first */
    double tint;         /* [0, 1): its random colour share */
} blossom_particle;

/* A particle sampled at a day. */
typedef struct blossom_state {
    int alive;           /* birth <= day < birth + lifetime */
    double age;          /* (day - birth) / lifetime, in [0, 1) when alive */
    vec3 offset;         /* metres from its crown point: v (day - birth) */
    double radius;       /* metres */
    double colour;       /* [0, 1]: 0 the open colour, 1 the faded one */
} blossom_state;

typedef struct blossom_report {
    uint32_t plants;     /* plants of the species visited */
    uint64_t particles;  /* born over the whole season */
    uint64_t petals;     /* alive at the day: instances added */
} blossom_report;

/* Cherry-like defaults: white-pink flowers about 1.5 cm across in a season of days 100-120. */
void blossom_params_default(blossom_params *p);

/* 0, or -1 with err naming the first field out of range and what would be valid. */
int blossom_params_check(const blossom_params *p, err_buf *err);

/* The draws of particle k of the plant with instance index `plant` over n_points crown points
 * (n_points > 0). */
void blossom_particle_draw(const blossom_params *p, uint64_t seed, uint32_t plant, uint32_t k,
                           uint32_t n_points, blossom_particle *out);

/* Particle q sampled at `day`. */
blossom_state blossom_particle_at(const blossom_params *p, const blossom_particle *q, double day);

/* The linear RGB of colour position c in [0, 1] (0 open, 1 faded). */
vec3 blossom_colour(const blossom_params *p, double c);

/* The number of particles plant `plant` bears over the season with n_points crown points. */
uint32_t blossom_particle_count(const blossom_params *p, uint64_t seed, uint32_t plant, uint32_t n_points);

/* The crown points of prototype `proto` (its frame): *pts an owned array of 3 * *n floats the
 * caller frees (NULL when *n is 0). Returns 0, or -1 with err set (out of memory). */
int blossom_crown_points(const scene *s, uint32_t proto, float **pts, uint32_t *n, err_buf *err);

/* Adds the petals alive on `day` on every plant (instance) of `plant_species` that is in s now: the
 * petal species and its prototypes, then one instance per living particle. Returns 0, or -1
 * with err set (bad parameters, species out of range, max_instances passed, out of memory); on
 * error s may hold the petal species and some of its instances. rep may be NULL. */
int blossom_add(scene *s, uint32_t plant_species, const blossom_params *p, double day, uint64_t seed,
                blossom_report *rep, err_buf *err);

#endif
