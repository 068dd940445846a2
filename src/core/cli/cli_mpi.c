/* cli_mpi.c — the ranks of an MPI job: joining it, agreeing on failures, gathering rows on
 * rank 0 (cli_mpi.h). Built without MPI (SYLVA_MPI undefined), a command is always rank 0 of
 * 1, and refuses to run as one of several processes of a job. */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include "cli/cli_mpi.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_status.h"
#include "render/render.h"

#ifdef SYLVA_MPI
#include <fcntl.h>
#include <mpi.h>
#include <sched.h>
#include <unistd.h>
#endif

/* The size of the job a launcher started this process in, from its environment (Open MPI's
 * mpirun, or a PMI launcher such as MPICH's or Slurm's); 0 when no launcher started it. */
static long launched_ranks(void)
{
    const char *names[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"};
    for (size_t k = 0; k < sizeof names / sizeof *names; k++) {
        const char *v = getenv(names[k]);
        if (v && *v) return strtol(v, NULL, 10);
    }
    return getenv("PMIX_RANK") ? 1 : 0; /* a PMIx launcher that does not say the size */
}

#ifndef SYLVA_MPI

int cli_mpi_begin(cli_mpi *m, const char *cmd, int argc, char **argv)
{
    *m = (cli_mpi){.cmd = cmd, .ranks = 1, .real_stderr = -1};
    long n = launched_ranks();
    if (n <= 1) return EXIT_OK;
    const char *r = getenv("OMPI_COMM_WORLD_RANK");
    if (!r) r = getenv("PMI_RANK");
    if (!r || !strcmp(r, "0"))
        fprintf(stderr, "sylva %s: started as one of %ld processes of an MPI job, but this sylva was built "
                "without MPI (SYLVA_MPI off): run it without mpirun, or rebuild it with Open MPI installed "
                "(docs/mpi.md)\n", cmd, n);
    return EXIT_USAGE;
}

int cli_mpi_agree(cli_mpi *m, int status)
{
    return status;
}

int cli_mpi_end(cli_mpi *m, int status)
{
    return status;
}

int cli_mpi_gather_rows(cli_mpi *m, const cli_rows *arrays, unsigned n_arrays, uint32_t first_row, uint32_t rows,
                        uint32_t band, err_buf *err)
{
    return 0;
}

void cli_mpi_sum(cli_mpi *m, uint64_t *v, unsigned n)
{
}

int cli_mpi_same_scene(cli_mpi *m, const scene *s, err_buf *err)
{
    return 0;
}

#else

/* FNV-1a over the arguments, each with its terminating NUL. */
static uint64_t arguments_hash(int argc, char **argv)
{
    uint64_t h = 1469598103934665603ull;
    for (int i = 0; i < argc; i++)
        for (const char *c = argv[i];; c++) {
            h = (h ^ (unsigned char)*c) * 1099511628211ull;
            if (!*c) break;
        }
    return h;
}

/* Worker threads for a rank: the cores it may run on, shared with the ranks beside it on this
 * machine when the launcher bound none of them to fewer cores. */
static unsigned rank_threads(void)
{
    MPI_Comm local;
    int beside = 1;
    if (MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local) == MPI_SUCCESS) {
        MPI_Comm_size(local, &beside);
        MPI_Comm_free(&local);
    }
    unsigned online = render_default_threads(), usable = online;
    cpu_set_t set;
    if (!sched_getaffinity(0, sizeof set, &set) && CPU_COUNT(&set) > 0) usable = (unsigned)CPU_COUNT(&set);
    unsigned share = online / (unsigned)(beside > 0 ? beside : 1);
    unsigned n = usable < share ? usable : share;
    return n ? n : 1;
}

/* Ranks other than 0: stdout to /dev/null, stderr into a temporary file (replayed if this rank
 * is the one whose failure ends the job). */
static void silence(cli_mpi *m)
{
    fflush(stdout), fflush(stderr);
    int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0) {
        dup2(null, STDOUT_FILENO);
        close(null);
    }
    m->kept = tmpfile();
    if (!m->kept) return; /* the rank's messages then show as they are */
    m->real_stderr = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
    if (m->real_stderr < 0 || dup2(fileno(m->kept), STDERR_FILENO) < 0) {
        if (m->real_stderr >= 0) close(m->real_stderr);
        m->real_stderr = -1;
        fclose(m->kept);
        m->kept = NULL;
    }
}

/* Prints what this rank kept of its stderr on the real one, each line after the rank. */
static void replay(const cli_mpi *m)
{
    if (!m->kept || m->real_stderr < 0) return;
    fflush(stderr);
    rewind(m->kept);
    char line[4096];
    int start = 1;
    while (fgets(line, sizeof line, m->kept)) {
        /* prefix and line in one write: the launcher forwards each write whole, so another
         * rank's message never lands between the two */
        if (start) dprintf(m->real_stderr, "[rank %d of %d] %s", m->rank, m->ranks, line);
        else dprintf(m->real_stderr, "%s", line);
        start = strchr(line, '\n') != NULL;
    }
    if (!start) dprintf(m->real_stderr, "\n");
}

int cli_mpi_begin(cli_mpi *m, const char *cmd, int argc, char **argv)
{
    *m = (cli_mpi){.cmd = cmd, .ranks = 1, .real_stderr = -1};
    if (launched_ranks() < 1) return EXIT_OK;
    int initialised = 0, provided;
    MPI_Initialized(&initialised);
    if (!initialised) {
        /* only the main thread calls MPI; the worker threads never do */
        if (MPI_Init_thread(NULL, NULL, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
            return cli_failf(cmd, ERR_INTERNAL, "MPI_Init failed: cannot join the MPI job");
        m->mpi = 1;
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &m->rank);
    MPI_Comm_size(MPI_COMM_WORLD, &m->ranks);
    if (m->ranks < 2) return EXIT_OK;
    m->threads = rank_threads();
    if (m->rank) silence(m);
    /* rank 0's hash and its complement; the minimum of each differs from it when some rank's
     * arguments differ */
    uint64_t h = arguments_hash(argc, argv), mine[2] = {h, ~h}, least[2];
    MPI_Allreduce(mine, least, 2, MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD);
    if (least[0] != h || least[1] != ~h) {
        m->decided = 1, m->status = EXIT_USAGE, m->failed_rank = 0;
        if (!m->rank)
            fprintf(stderr, "sylva %s: the %d ranks of the MPI job were not started with the same arguments; "
                    "every rank must run the same command (docs/mpi.md)\n", cmd, m->ranks);
        return EXIT_USAGE;
    }
    return EXIT_OK;
}

int cli_mpi_agree(cli_mpi *m, int status)
{
    if (m->ranks < 2) return status;
    if (m->decided) return m->status;
    /* the lowest failing rank and its status in one number: rank * 256 + status */
    int mine = status ? m->rank * 256 + (status & 255 ? status & 255 : 4) : INT_MAX, first;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == INT_MAX) return EXIT_OK;
    m->decided = 1, m->failed_rank = first / 256, m->status = first % 256;
    if (m->rank && m->rank == m->failed_rank) replay(m);
    return m->status;
}

int cli_mpi_end(cli_mpi *m, int status)
{
    if (m->ranks > 1) status = cli_mpi_agree(m, status);
    if (m->kept) {
        fflush(stderr);
        if (m->real_stderr >= 0) dup2(m->real_stderr, STDERR_FILENO), close(m->real_stderr);
        fclose(m->kept);
    }
    if (m->mpi) MPI_Finalize();
    *m = (cli_mpi){.ranks = 1, .real_stderr = -1};
    return status;
}

/* Rows of [first_row, first_row + rows) that rank r computes. */
static uint32_t rank_rows(const cli_mpi *m, int r, uint32_t first_row, uint32_t rows, uint32_t band)
{
    uint32_t n = 0;
    for (uint32_t y = first_row; y < first_row + rows; y++) n += cli_mpi_row_rank(m, y, band) == r;
    return n;
}

/* Sends or receives n bytes in pieces an int counts. */
#define PIECE (1u << 30)
static void send_bytes(const uint8_t *p, size_t n)
{
    for (size_t at = 0; at < n; at += PIECE)
        MPI_Send(p + at, (int)(n - at < PIECE ? n - at : PIECE), MPI_BYTE, 0, 0, MPI_COMM_WORLD);
}

static void receive_bytes(uint8_t *p, size_t n, int from)
{
    for (size_t at = 0; at < n; at += PIECE)
        MPI_Recv(p + at, (int)(n - at < PIECE ? n - at : PIECE), MPI_BYTE, from, 0, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
}

/* Copies rank r's rows between the arrays and buf (packed row by row, array after array
 * within a row): into buf when pack, out of it otherwise. */
static void move_rows(const cli_mpi *m, int r, const cli_rows *a, unsigned n_arrays, uint32_t first_row, uint32_t rows,
                      uint32_t band, uint8_t *buf, int pack)
{
    for (uint32_t y = first_row; y < first_row + rows; y++) {
        if (cli_mpi_row_rank(m, y, band) != r) continue;
        for (unsigned k = 0; k < n_arrays; k++) {
            uint8_t *row = (uint8_t *)a[k].data + (size_t)(y - first_row) * a[k].row_bytes;
            if (pack) memcpy(buf, row, a[k].row_bytes);
            else memcpy(row, buf, a[k].row_bytes);
            buf += a[k].row_bytes;
        }
    }
}

int cli_mpi_gather_rows(cli_mpi *m, const cli_rows *arrays, unsigned n_arrays, uint32_t first_row, uint32_t rows,
                        uint32_t band, err_buf *err)
{
    if (m->ranks < 2) return 0;
    size_t row_bytes = 0, most = 0;
    for (unsigned k = 0; k < n_arrays; k++) row_bytes += arrays[k].row_bytes;
    for (int r = m->rank ? m->rank : 1; r < (m->rank ? m->rank + 1 : m->ranks); r++) {
        size_t n = rank_rows(m, r, first_row, rows, band) * row_bytes;
        if (n > most) most = n;
    }
    uint8_t *buf = most ? malloc(most) : NULL; /* owned: one rank's rows, packed */
    /* a rank that fails here agrees no more than any failing rank: in cli_mpi_end */
    if (most && !buf) return err_nomem(err, "out of memory for %zu bytes of rows to gather", most);
    if (cli_mpi_agree(m, EXIT_OK)) {
        free(buf);
        err_set(err, "rank %d of the %d ranks failed; the job ends", m->failed_rank, m->ranks);
        err->status = ERR_INTERNAL;
        return -1;
    }
    if (m->rank) {
        move_rows(m, m->rank, arrays, n_arrays, first_row, rows, band, buf, 1);
        send_bytes(buf, rank_rows(m, m->rank, first_row, rows, band) * row_bytes);
    } else {
        for (int r = 1; r < m->ranks; r++) {
            receive_bytes(buf, rank_rows(m, r, first_row, rows, band) * row_bytes, r);
            move_rows(m, r, arrays, n_arrays, first_row, rows, band, buf, 0);
        }
    }
    free(buf);
    return 0;
}

/* FNV-1a, 8 bytes at a time (with the tail byte by byte), continuing from h. */
static uint64_t digest_bytes(uint64_t h, const void *p, size_t n)
{
    const uint8_t *b = p;
    size_t k = 0;
    for (; k + 8 <= n; k += 8) {
        uint64_t w;
        memcpy(&w, b + k, 8);
        h = (h ^ w) * 1099511628211ull;
    }
    for (; k < n; k++) h = (h ^ b[k]) * 1099511628211ull;
    return h;
}

static uint64_t digest_mesh(uint64_t h, const mesh *me)
{
    if (!me) return digest_bytes(h, "", 1);
    h = digest_bytes(h, &me->nv, sizeof me->nv);
    h = digest_bytes(h, &me->nt, sizeof me->nt);
    h = digest_bytes(h, me->pos, (size_t)me->nv * 3 * sizeof(float));
    h = digest_bytes(h, me->nrm, (size_t)me->nv * 3 * sizeof(float));
    h = digest_bytes(h, me->uv, (size_t)me->nv * 2 * sizeof(float));
    h = digest_bytes(h, me->tri, (size_t)me->nt * 3 * sizeof(uint32_t));
    return digest_bytes(h, me->mat, (size_t)me->nt * sizeof(int32_t));
}

/* A digest of what the pixels depend on, field by field (never a struct's padding or pointers). */
static uint64_t scene_digest(const scene *s)
{
    uint64_t h = 1469598103934665603ull;
    const camera_settings *c = &s->camera;
    const double view[] = {c->position[0], c->position[1], c->position[2], c->direction[0], c->direction[1],
                           c->direction[2], c->up[0], c->up[1], c->up[2], c->fov_deg, c->roll_deg};
    h = digest_bytes(h, view, sizeof view);
    for (uint32_t k = 0; k < s->n_materials; k++) {
        const material *mt = &s->materials[k];
        const float v[] = {mt->albedo.x, mt->albedo.y, mt->albedo.z, mt->transmittance.x, mt->transmittance.y,
                           mt->transmittance.z};
        const int32_t i[] = {(int32_t)mt->bsdf, mt->texture, mt->alpha_mask};
        h = digest_bytes(digest_bytes(h, v, sizeof v), i, sizeof i);
    }
    for (uint32_t k = 0; k < s->n_prototypes; k++) h = digest_mesh(h, s->prototypes[k].mesh);
    for (uint32_t k = 0; k < s->n_instances; k++) {
        const instance *in = &s->instances[k];
        const int32_t i[] = {(int32_t)in->prototype, in->development};
        h = digest_bytes(digest_bytes(h, i, sizeof i), &in->xf, sizeof in->xf);
    }
    for (uint32_t k = 0; k < s->n_objects; k++) {
        const object *o = &s->objects[k];
        const int32_t i[] = {o->model, o->development};
        h = digest_bytes(digest_mesh(digest_bytes(h, i, sizeof i), o->mesh), &o->xf, sizeof o->xf);
    }
    for (uint32_t k = 0; k < s->n_models; k++) h = digest_mesh(h, s->models[k].mesh);
    const sylva_heightfield *t = s->terrain;
    if (t) {
        const double at[] = {t->x0, t->y0, t->dx, t->dy};
        h = digest_bytes(digest_bytes(h, at, sizeof at), t->z, (size_t)t->nx * t->ny * sizeof(float));
        for (uint32_t l = 0; l < t->n_levels; l++)
            h = digest_bytes(h, t->levels[l].z, (size_t)t->levels[l].nx * t->levels[l].ny * sizeof(float));
    }
    return h;
}

int cli_mpi_same_scene(cli_mpi *m, const scene *s, err_buf *err)
{
    if (m->ranks < 2) return 0;
    if (cli_mpi_agree(m, EXIT_OK)) {
        err_set(err, "rank %d of the %d ranks failed; the job ends", m->failed_rank, m->ranks);
        err->status = ERR_INTERNAL;
        return -1;
    }
    uint64_t mine = scene_digest(s), rank0 = mine;
    MPI_Bcast(&rank0, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    int other = mine != rank0 ? m->rank : INT_MAX, first;
    MPI_Allreduce(&other, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == INT_MAX) return 0;
    m->decided = 1, m->failed_rank = first, m->status = cli_exit_status(ERR_INPUT);
    err_set(err, "rank %d of the %d ranks built another scene than rank 0 from the same arguments: every rank "
            "must see the same scene file, data and plugins (docs/mpi.md)", first, m->ranks);
    err->status = ERR_INPUT;
    return -1;
}

void cli_mpi_sum(cli_mpi *m, uint64_t *v, unsigned n)
{
    if (m->ranks > 1) MPI_Allreduce(MPI_IN_PLACE, v, (int)n, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
}

#endif
