/* cli_parts.c — the MPI job as the parts of a pipeline's run (cli_parts.h). */
#include "cli/cli_parts.h"

#include "cli/cli_status.h"

static int same_scene(void *job, const void *s, err_buf *err)
{
    return cli_mpi_same_scene(((cli_parts *)job)->m, s, err);
}

/* A failing rank prints its failure (kept aside on ranks > 0) before the agreement. */
static int agree(void *job, int failed, err_buf *err)
{
    cli_parts *p = job;
    int status = failed ? cli_fail(p->m->cmd, err, ERR_INTERNAL) : EXIT_OK;
    p->status = cli_mpi_agree(p->m, status);
    return p->status ? -1 : 0;
}

static int gather_rows(void *job, const run_rows *arrays, unsigned n_arrays, uint32_t first_row, uint32_t rows,
                       uint32_t band, err_buf *err)
{
    return cli_mpi_gather_rows(((cli_parts *)job)->m, arrays, n_arrays, first_row, rows, band, err);
}

static void sum(void *job, uint64_t *v, unsigned n)
{
    cli_mpi_sum(((cli_parts *)job)->m, v, n);
}

void cli_parts_of(cli_parts *p, cli_mpi *m)
{
    *p = (cli_parts){.parts = {.part = m->rank, .parts = m->ranks, .job = p, .same_scene = same_scene,
                               .agree = agree, .gather_rows = gather_rows, .sum = sum},
                     .m = m};
}

int cli_parts_fail(cli_parts *p, err_buf *err)
{
    return p->status ? p->status : cli_fail(p->m->cmd, err, ERR_INTERNAL);
}
