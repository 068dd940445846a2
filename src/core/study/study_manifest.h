/* study_manifest.h — the record a study keeps beside each product's PNG and EXR
 * (DIR/VIEWPOINT/PRODUCT_FRAME.manifest): what made them, as lines of text: the sylva version,
 * the scene's digest (scene_file_spec.h: every section but the cameras and the study), the
 * viewpoint's camera, the product, the frame, its size and samples. A product whose two files
 * are there and whose record says what this run would write is up to date, and a rerun keeps it:
 * an interrupted study goes on where it stopped, and a changed scene or setting renders anew
 * only what it changes.
 *
 * The record is written after the product's files (atomically, io/atomic_file.h), so a product
 * cut short leaves no record that vouches for it. */
#ifndef SYLVA_STUDY_MANIFEST_H
#define SYLVA_STUDY_MANIFEST_H

#include <stddef.h>
#include <stdint.h>

#include "scene/scene_settings.h"
#include "util/err.h"

#define STUDY_MANIFEST_MAX 2048

/* What one product's record says. */
typedef struct study_record {
    uint64_t scene_digest;
    const char *viewpoint;
    const camera_settings *camera; /* the viewpoint's, with the frame's lens */
    const char *product, *frame;
    uint32_t width, height, spp;   /* spp: the samples per pixel rendered with */
    uint64_t seed;
    uint32_t season_day;           /* the day the plants are shown on (--season may change it) */
    const char *extra;             /* more lines the product depends on (a sheet's page), or NULL */
} study_record;

/* The record's text into out (STUDY_MANIFEST_MAX bytes). */
void study_manifest_text(const study_record *r, char out[STUDY_MANIFEST_MAX]);

/* 1 when png and exr are regular files and the record at path holds exactly text. */
int study_manifest_current(const char *path, const char *text, const char *png, const char *exr);

/* Writes text to path atomically. Returns 0, or -1 with err set. */
int study_manifest_write(const char *path, const char *text, err_buf *err);

#endif
