/* run_parts.h — how one run is split between the processes of a job (an MPI job, say): the
 * part this process computes and the collective steps a product's pipeline takes with the
 * others, given by the command that started the job. A process alone is part 0 of 1 and every
 * step is immediate. The pipeline (ztv/ztv_study.h, render/render_pipeline.h) knows nothing of
 * how the parts talk. */
#ifndef SYLVA_RUN_PARTS_H
#define SYLVA_RUN_PARTS_H

#include <stddef.h>
#include <stdint.h>

#include "util/err.h"

/* Row r of an array covering rows [first_row, first_row + rows) starts at data + (r - first_row)
 * * row_bytes. */
typedef struct run_rows {
    void *data;
    size_t row_bytes;
} run_rows;

typedef struct run_parts {
    int part, parts; /* this process computes part `part` of `parts` (0 of 1 alone) */
    void *job;       /* the callbacks' own */
    /* Collective: checks that every part built the same scene (s: a const scene *). Returns 0,
     * or -1 with err set. */
    int (*same_scene)(void *job, const void *s, err_buf *err);
    /* Collective: every part says whether its steps so far failed (err: why); returns 0 when
     * none did, else -1, the failure then reported and the job's outcome decided by the job. */
    int (*agree)(void *job, int failed, err_buf *err);
    /* Collective: part 0's arrays get the rows [first_row, first_row + rows) the other parts
     * computed (interleaved bands of `band` rows). Returns 0, or -1 with err set. */
    int (*gather_rows)(void *job, const run_rows *arrays, unsigned n_arrays, uint32_t first_row, uint32_t rows,
                       uint32_t band, err_buf *err);
    /* Collective, right after an agreement that found no failure: v[i] becomes the sum over the
     * parts. */
    void (*sum)(void *job, uint64_t *v, unsigned n);
} run_parts;

#endif
