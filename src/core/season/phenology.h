/* phenology.h — when a species carries its leaves: the scene's season (a named season or a
 * calendar date, as a day of the year) and each species' habit (evergreen or deciduous) with
 * the days its leaves come out and fall. One ecology run serves every season: the season
 * changes only how the plants look (scene_season.h), never which plants stand where.
 *
 * In spring a deciduous species' new leaves are a lighter green for a few weeks after leaf_out,
 * and a species may flower (its blossom: block, drawn by scene_spring.h). */
#ifndef SYLVA_PHENOLOGY_H
#define SYLVA_PHENOLOGY_H

#include <stdint.h>

#include "util/err.h"

/* The day of the year (1..366) each named season stands for: the middle of its quarter in the
 * temperate northern hemisphere (mid-April, mid-July, mid-October, mid-January). */
enum { SEASON_SPRING_DAY = 105, SEASON_SUMMER_DAY = 196, SEASON_AUTUMN_DAY = 288, SEASON_WINTER_DAY = 15 };

typedef struct season_settings {
    uint32_t day;             /* day of the year, 1..366 (SEASON_SUMMER_DAY when not given) */
    const char *text;         /* as written ("winter", "2026-01-20"), or "summer" by default */
    uint32_t line, column;    /* of the value (0 when not given) */
} season_settings;

typedef enum leaf_habit { HABIT_EVERGREEN = 0, HABIT_DECIDUOUS = 1 } leaf_habit;

typedef struct phenology {
    leaf_habit habit;
    uint32_t leaf_out;        /* day of the year the leaves come out (deciduous) */
    uint32_t leaf_fall;       /* day of the year the last leaves have fallen (deciduous) */
    uint32_t colouring;       /* day of the year the leaves start to turn (deciduous; in leaf then) */
    double autumn_color[3];   /* linear RGB the leaves' albedo reaches at leaf_fall */
    double fresh_color[3];    /* linear RGB of the new leaves' albedo at leaf_out (deciduous) */
    uint32_t fresh_days;      /* days after leaf_out until the leaves have their summer colour */
    struct flowering {        /* the blossom: block */
        int given;            /* 0: the species does not flower visibly */
        uint32_t first, last; /* days of the year the flowers are open (last < first: over new year) */
        double color[3], faded_color[3]; /* linear RGB of an open flower and of one at its end */
        double size;          /* metres across an open flower */
        double per_point;     /* flowers per crown point over the season (expected) */
        uint32_t max_per_plant;
        const char *file;     /* where the block is written, for messages at build time */
        uint32_t line, column;
    } blossom;
} phenology;

/* The day of the year of text: spring, summer, autumn, winter, or a date YYYY-MM-DD (the
 * Gregorian calendar, leap years counted). Returns 0 with *day set, or -1 with err naming what
 * would be valid (the caller locates it). */
int season_day_parse(const char *text, uint32_t *day, err_buf *err);

/* 1 when a plant of phenology p carries its leaves on day (evergreens always do; a deciduous
 * plant from leaf_out up to the day before leaf_fall). */
int phenology_in_leaf(const phenology *p, uint32_t day);

/* How far the leaves have turned on day: 0 until colouring (and for evergreens and leafless
 * days), rising linearly to 1 at leaf_fall (days counted round the year's end). */
double phenology_autumn_share(const phenology *p, uint32_t day);

/* How fresh the leaves still are on day: 1 at leaf_out, falling linearly to 0 at fresh_days
 * after it (0 for evergreens, leafless days and fresh_days 0). */
double phenology_fresh_share(const phenology *p, uint32_t day);

/* Days since the blossom's first day when day falls in [first, last] (counted round the year's
 * end), else -1 (and -1 when no blossom is given). */
int phenology_blossom_day(const phenology *p, uint32_t day);

/* The share of a plant's leaves already down on day: 0 for evergreens and while the leaves are
 * green, f^2 while they turn (f = phenology_autumn_share: the leaves colour first and fall ever
 * faster, a quarter down when they are half turned), 1 for a deciduous plant out of leaf. */
double phenology_fallen_share(const phenology *p, uint32_t day);

/* How far a temperate meadow's grass is into its winter rest on day, in [0, 1]: 0 in full growth
 * (10 May to 18 August, days 130..230), rising to 1 as it cures and dies back by late November
 * (day 330), 1 through the winter to 1 March (day 60), falling to 0 as it greens up again. Day 0
 * (no season) is summer's 0. */
double meadow_dormancy(uint32_t day);

#endif
