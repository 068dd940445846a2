/* build_options.h — how a scene is built (scene_build.h) and an ecology run is driven
 * (ecology_session.h): logging, which ground, what to leave out, threads, where times add up.
 * Plain values; the phase_times it points to is the caller's. */
#ifndef SYLVA_BUILD_OPTIONS_H
#define SYLVA_BUILD_OPTIONS_H

#include "util/phase_times.h"

typedef struct build_options {
    int verbose;     /* plugin DEBUG logs */
    int quiet;       /* no progress output, and no plugin INFO logs (warnings still print) */
    int no_ecology;  /* 1: leave the ecology plugin out (a caller that drives it itself) */
    int analysis;    /* 1: a scene for an analysis (ZTV, probe): the ground as surveyed is the
                        terrain too, nothing refined for a camera */
    int detail_at_development; /* 1: the rendered terrain refined around the development (the
                        development objects' mean position, else the ztv targets', else the
                        terrain's centre) instead of the camera: a refined ground that is the same
                        whatever the camera (`ztv --ground refined`) */
    int no_plants;   /* 1: a scene without plants: no species' models, no plants placed (the scene
                        file's, the tree survey's, the woodland's, the planting plan's): an analysis
                        that traces bare earth or a canopy surface, which needs none */
    int planting_shown; /* 1: the planting plan planted and grown planting_years after its year
                        (--year); 0: the scene as it stands before the plan (nothing felled) */
    double planting_years; /* years since planting (>= 0) */
    unsigned threads; /* threads for the tree variants and the plugins' workers; 0: one per processor */
    phase_times *times; /* may be NULL: where the terrain, tree variant and ecology times add up */
} build_options;

#endif
