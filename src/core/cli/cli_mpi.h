/* cli_mpi.h — a command run as one rank of an MPI job (docs/mpi.md). `mpirun -np N sylva render`
 * and `mpirun -np N sylva ztv` split the frame's bands or the map's rows between the ranks;
 * every rank loads and builds the whole scene itself, computes its rows, and rank 0 gathers
 * the rows and writes the one output, byte for byte the one a single process writes.
 *
 * Started without a launcher (no mpirun), or in a build without MPI (SYLVA_MPI off), a command
 * is rank 0 of 1 and nothing here calls MPI: the run is the plain one.
 *
 * Every rank runs the same command and takes the same steps. Ranks other than 0 print nothing:
 * their stdout goes nowhere, their stderr is kept aside in a temporary file. Before any exchange
 * of rows the ranks agree on how their steps ended (cli_mpi_agree), so a failure on any rank
 * ends every rank with one exit status and one message — rank 0's own, or else the first
 * failing rank's kept stderr, marked with its rank — and never leaves a rank waiting.
 *
 * Ownership: cli_mpi_begin fills a cli_mpi that cli_mpi_end releases (and finalises MPI). */
#ifndef SYLVA_CLI_MPI_H
#define SYLVA_CLI_MPI_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "scene/scene.h"
#include "util/err.h"
#include "util/run_parts.h"

typedef struct cli_mpi {
    const char *cmd;     /* the command's name, for messages */
    int rank, ranks;     /* 0 of 1 outside a job */
    unsigned threads;    /* worker threads for a rank given no --threads; 0: one per core */
    int mpi;             /* 1: this process initialised MPI */
    int decided;         /* 1: an agreement found a failure; no rank agrees again */
    int status;          /* the job's exit status once decided */
    int failed_rank;     /* the first failing rank once decided */
    int real_stderr;     /* ranks > 0: stderr's own descriptor (stderr is then `kept`); else -1 */
    FILE *kept;          /* ranks > 0: what the rank wrote on stderr; owned */
} cli_mpi;

/* Joins the MPI job this process was started in, if any: initialises MPI, checks that every
 * rank was given the same arguments, sets the worker threads of a rank from the cores it may
 * use and the ranks beside it on this machine, and silences ranks other than 0. Returns
 * EXIT_OK, or an exit status after printing why (a build without MPI started by mpirun as one
 * of several, different arguments). cli_mpi_end follows in every case. */
int cli_mpi_begin(cli_mpi *m, const char *cmd, int argc, char **argv);

/* Collective: every rank gives the exit status of its steps so far (0: all went well) and gets
 * the job's: 0 when every rank's was 0, else rank 0's, else the first failing rank's, whose kept
 * messages it prints then, each line marked with its rank. After a failure no further agreement
 * is made. Outside a job, returns status. */
int cli_mpi_agree(cli_mpi *m, int status);
/* A rank that fails makes one agreement more, at most: its next one (or cli_mpi_end's) meets the
 * one the others make before their next exchange, and decides. */

/* Ends the command: agrees on status unless a failure was already agreed on, releases m,
 * finalises MPI, and returns the exit status this process ends with (the job's). */
int cli_mpi_end(cli_mpi *m, int status);

/* Rows of an array to gather (util/run_parts.h). */
typedef run_rows cli_rows;

/* The rank that computes row y of a split whose bands are `band` rows tall (interleaved: band k
 * belongs to rank k modulo ranks). */
static inline int cli_mpi_row_rank(const cli_mpi *m, uint32_t y, uint32_t band)
{
    return m->ranks > 1 ? (int)(y / band % (uint32_t)m->ranks) : 0;
}

/* Collective, for the ranks whose steps all went well so far (a rank that failed goes on to
 * cli_mpi_end, whose agreement meets this one's): agrees that every rank is ready, then copies
 * into rank 0's arrays the rows [first_row, first_row + rows) that the other ranks computed
 * (cli_mpi_row_rank with band); rank 0's own rows and the other ranks' arrays are left as they
 * are. Returns 0, or -1 with err set: this rank ran out of memory for the exchange, or another
 * rank failed (the job's status is then decided, cli_mpi_end returns it). Outside a job,
 * returns 0. */
int cli_mpi_gather_rows(cli_mpi *m, const cli_rows *arrays, unsigned n_arrays, uint32_t first_row, uint32_t rows,
                        uint32_t band, err_buf *err);

/* Collective, for the ranks whose steps all went well so far (as cli_mpi_gather_rows): agrees
 * that every rank is ready, then checks that every rank built the same scene s, from a digest of
 * its camera, materials, meshes, placements and terrain (ranks on several machines that do not
 * see the same files would otherwise make one picture of several scenes). Returns 0, or -1 with
 * err set: another rank failed, or some rank built another scene than rank 0 (the job then ends
 * with exit status 2). Outside a job, returns 0. */
int cli_mpi_same_scene(cli_mpi *m, const scene *s, err_buf *err);

/* Collective, right after an agreement that found no failure: v[i] becomes the sum over the
 * ranks. Outside a job, leaves v. */
void cli_mpi_sum(cli_mpi *m, uint64_t *v, unsigned n);

#endif
