/* cli_parts.h — a command's MPI job (cli_mpi.h) given to a product's pipeline as the parts of
 * its run (util/run_parts.h), and the exit status when the pipeline fails. */
#ifndef SYLVA_CLI_PARTS_H
#define SYLVA_CLI_PARTS_H

#include "cli/cli_mpi.h"
#include "util/run_parts.h"

typedef struct cli_parts {
    run_parts parts; /* what the pipeline is given */
    cli_mpi *m;
    int status;      /* set when an agreement found a failure: the job's exit status */
} cli_parts;

/* Fills p for the job m (the rank is the part). */
void cli_parts_of(cli_parts *p, cli_mpi *m);
/* The exit status of a pipeline that failed: the job's when an agreement decided it (its
 * message already printed), else err's after printing it ("sylva CMD: ..."). */
int cli_parts_fail(cli_parts *p, err_buf *err);

#endif
