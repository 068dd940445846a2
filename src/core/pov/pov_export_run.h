/* pov_export_run.h — `sylva export-pov`'s pipeline on a built scene: the whole scene, or one
 * species (found by name, its variant checked), written as POV-Ray files, with the note and
 * the closing line the command prints on stderr. */
#ifndef SYLVA_POV_EXPORT_RUN_H
#define SYLVA_POV_EXPORT_RUN_H

#include "pov/pov_write.h"

typedef struct pov_export_request {
    pov_export_options scene;  /* for the whole scene; its source is set from `source` */
    const char *out;           /* OUT.pov (or, for a species, OUT.inc) */
    const char *source;        /* the scene file's name, for the header comments */
    const char *species;       /* NULL: the whole scene; else the one species to write */
    int32_t variant;           /* with species: -1 every variant, else the one */
    int quiet;                 /* no note or closing line */
    double scene_seconds;      /* to load and build the scene, for the closing line */
} pov_export_request;

/* Writes what r asks for. Returns 0, or -1 with err set and its kind stated (ERR_INPUT: no such
 * species or variant; ERR_OUTPUT: a file not written). */
int pov_export_run(const scene *s, const pov_export_request *r, err_buf *err);

#endif
