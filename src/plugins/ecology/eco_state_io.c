/* eco_state_io.c — saving a run to a file and loading it back to continue.
 *
 * The file holds what changes during a run — the year, and per species the seeds, the carried
 * fraction of a seedling, the fifteen random streams (key and counter) and every living plant
 * with all its fields — plus a fingerprint of what does not (the terrain factors, the growth
 * area, the species' names and parameters), so that a state is only ever continued on the run
 * that saved it. Layout: "SYLVAECO", format version, a byte-order mark, the fingerprint, then
 * the body, then an FNV-1a checksum of the body; numbers in the machine's byte order (the mark
 * refuses another). It is written to a new temporary file beside the target (a random name
 * created exclusively, never through a symbolic link), synced, and renamed into place, so a
 * failed save never leaves a half-written file and a planted link redirects nothing.
 */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "eco_sim.h"

#define ECO_STATE_MAGIC "SYLVAECO"
#define ECO_STATE_VERSION 2u /* 2: the edge band's stream */
#define ECO_BYTE_ORDER 0x01020304u

typedef struct state_file {
    FILE *f;
    uint64_t sum;      /* FNV-1a of the body so far */
    int failed;
    uint64_t offset;   /* reading: bytes read so far */
    uint64_t need;     /* reading: the size of the part the file ended in, once failed */
    char part[128];    /* reading: what is being read, for messages */
} state_file;

static void put(state_file *w, const void *data, size_t n)
{
    const unsigned char *b = data;
    for (size_t i = 0; i < n; i++) w->sum = (w->sum ^ b[i]) * 0x100000001b3ull;
    if (!w->failed && fwrite(data, 1, n, w->f) != n) w->failed = 1;
}

/* Reads n bytes, or marks r failed where the file ends (r->offset, r->need and r->part then say
 * where and in what). */
static void get(state_file *r, void *data, size_t n)
{
    if (r->failed || fread(data, 1, n, r->f) != n) {
        if (!r->failed) r->need = n;
        r->failed = 1;
        memset(data, 0, n);
        return;
    }
    r->offset += n;
    const unsigned char *b = data;
    for (size_t i = 0; i < n; i++) r->sum = (r->sum ^ b[i]) * 0x100000001b3ull;
}

/* Names the part read next, printf-style, for the message should the file end inside it. */
static void reading(state_file *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void reading(state_file *r, const char *fmt, ...)
{
    if (r->failed) return; /* the part the file ended in stays named */
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->part, sizeof r->part, fmt, ap);
    va_end(ap);
}

/* The file ended inside the part r was reading: what it holds, and what was expected there. */
static int cut_short(const char *path, const state_file *r, uint64_t size, plugin_err *err)
{
    return plugin_fail(err, SYLVA_ERR_PARAM,
                       "%s: the ecology state is cut short: the file holds %llu bytes and ends inside %s (bytes %llu "
                       "to %llu); it was not saved whole (save the run again)",
                       path, (unsigned long long)size, r->part, (unsigned long long)r->offset + 1,
                       (unsigned long long)(r->offset + r->need));
}

static void put_plant(state_file *w, const eco_plant *p)
{
    put(w, &p->x, sizeof p->x), put(w, &p->y, sizeof p->y), put(w, &p->z, sizeof p->z);
    put(w, &p->h, sizeof p->h), put(w, &p->r, sizeof p->r), put(w, &p->power, sizeof p->power);
    put(w, &p->v, sizeof p->v), put(w, &p->t_max, sizeof p->t_max), put(w, &p->rotation, sizeof p->rotation);
    put(w, p->fav, sizeof p->fav), put(w, &p->age, sizeof p->age), put(w, &p->patch, sizeof p->patch);
    put(w, &p->dominated, sizeof p->dominated);
}

static void get_plant(state_file *r, eco_plant *p, uint32_t q, const char *species)
{
    reading(r, "plant %u of '%s'", q, species);
    get(r, &p->x, sizeof p->x), get(r, &p->y, sizeof p->y), get(r, &p->z, sizeof p->z);
    get(r, &p->h, sizeof p->h), get(r, &p->r, sizeof p->r), get(r, &p->power, sizeof p->power);
    get(r, &p->v, sizeof p->v), get(r, &p->t_max, sizeof p->t_max), get(r, &p->rotation, sizeof p->rotation);
    get(r, p->fav, sizeof p->fav), get(r, &p->age, sizeof p->age), get(r, &p->patch, sizeof p->patch);
    get(r, &p->dominated, sizeof p->dominated);
}

/* Creates a new temporary file beside `path` for writing: a name no file has (O_EXCL) with a
 * random part, never opened through a symbolic link (O_NOFOLLOW), mode 0666 less the umask as
 * fopen would give. Returns the descriptor, or -1 with errno set and err filled. */
static int create_temporary(const char *path, char *tmp, size_t n, plugin_err *err)
{
    static atomic_uint counter;
    for (int attempt = 0; attempt < 64; attempt++) {
        uint32_t random = 0;
        if (getentropy(&random, sizeof random)) random = (uint32_t)attempt * 0x9e3779b9u;
        unsigned c = atomic_fetch_add(&counter, 1);
        if ((size_t)snprintf(tmp, n, "%s.tmp-%ld-%u-%08x", path, (long)getpid(), c, random) >= n) {
            plugin_fail(err, SYLVA_ERR_IO, "%s: the path is too long to save the ecology state", path);
            errno = ENAMETOOLONG;
            return -1;
        }
        int fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST) {
            if (fd < 0) plugin_fail(err, SYLVA_ERR_IO, "%s: cannot write the ecology state: %s", path, strerror(errno));
            return fd;
        }
    }
    plugin_fail(err, SYLVA_ERR_IO, "%s: cannot write the ecology state: no free temporary name beside it", path);
    errno = EEXIST;
    return -1;
}

int eco_sim_save(const eco_sim *s, const char *path, plugin_err *err)
{
    char tmp[4096];
    int fd = create_temporary(path, tmp, sizeof tmp, err);
    if (fd < 0) return SYLVA_ERR_IO;
    FILE *f = fdopen(fd, "wb");
    if (!f) {
        int e = errno;
        close(fd);
        unlink(tmp);
        return plugin_fail(err, SYLVA_ERR_IO, "%s: cannot write the ecology state: %s", path, strerror(e));
    }
    state_file w = {f, 0, 0};
    uint32_t version = ECO_STATE_VERSION, order = ECO_BYTE_ORDER;
    if (fwrite(ECO_STATE_MAGIC, 1, 8, f) != 8 || fwrite(&version, 4, 1, f) != 1 || fwrite(&order, 4, 1, f) != 1 ||
        fwrite(&s->fingerprint, 8, 1, f) != 1)
        w.failed = 1;
    w.sum = 0xcbf29ce484222325ull;
    put(&w, &s->n_species, sizeof s->n_species);
    put(&w, &s->year, sizeof s->year);
    for (uint32_t j = 0; j < s->n_species; j++) {
        uint32_t len = (uint32_t)strlen(s->names[j]);
        put(&w, &len, sizeof len);
        put(&w, s->names[j], len);
        put(&w, &s->seeds[j], sizeof s->seeds[j]);
        put(&w, &s->carry[j], sizeof s->carry[j]);
        for (int q = 0; q < ECO_N_STREAMS; q++) {
            const sylva_rng *r = &s->rng[(size_t)j * ECO_N_STREAMS + q];
            put(&w, &r->key, sizeof r->key);
            put(&w, &r->counter, sizeof r->counter);
        }
        put(&w, &s->pop[j].n, sizeof s->pop[j].n);
        for (uint32_t q = 0; q < s->pop[j].n; q++) put_plant(&w, &s->pop[j].plants[q]);
    }
    uint64_t sum = w.sum;
    if (!w.failed && fwrite(&sum, 8, 1, f) != 1) w.failed = 1;
    /* On the disk before it takes the final name, so a crash leaves the old file or the new. */
    int e = 0;
    if (!w.failed && (fflush(f) || fsync(fileno(f)))) w.failed = 1, e = errno;
    if (fclose(f) && !w.failed) w.failed = 1, e = errno;
    if (!w.failed && rename(tmp, path)) w.failed = 1, e = errno;
    if (w.failed) {
        unlink(tmp);
        return plugin_fail(err, SYLVA_ERR_IO, "%s: cannot write the ecology state: %s", path, strerror(e ? e : EIO));
    }
    return SYLVA_OK;
}

/* A plant read from a file is checked before the run uses it. */
static int plant_is_valid(const eco_sim *s, const eco_plant *p)
{
    const eco_terrain *t = &s->terrain;
    double v[9] = {p->x, p->y, p->z, p->h, p->r, p->power, p->v, p->t_max, p->rotation};
    for (int i = 0; i < 9; i++)
        if (!isfinite(v[i])) return 0;
    for (int i = 0; i < 5; i++)
        if (!(p->fav[i] >= 0 && p->fav[i] <= 1)) return 0;
    return p->patch < (uint64_t)t->ni * t->nk && p->h >= 0 && p->h <= 1 && p->r >= 0 && p->dominated <= 1 &&
           eco_patch_of(t, p->x, p->y) >= 0;
}

int eco_sim_load(eco_sim *s, const char *path, plugin_err *err)
{
    FILE *f = fopen(path, "rb");
    if (!f) return plugin_fail(err, SYLVA_ERR_IO, "%s: cannot read the ecology state: %s", path, strerror(errno));
    struct stat st;
    uint64_t size = fstat(fileno(f), &st) ? 0 : (uint64_t)st.st_size;
    char magic[8];
    uint32_t version = 0, order = 0;
    uint64_t fingerprint = 0;
    int rc = SYLVA_OK;
    eco_population *pop = NULL;
    double *seeds = NULL, *carry = NULL;
    sylva_rng *rng = NULL;
    /* the header, outside the checksum */
    state_file r = {f, 0, 0, 0, 0, ""};
    reading(&r, "the mark %s", ECO_STATE_MAGIC);
    size_t got = fread(magic, 1, 8, f);
    if (got == 8) r.offset = 8;
    else r.failed = 1, r.need = 8;
    if (memcmp(magic, ECO_STATE_MAGIC, got)) {
        rc = plugin_fail(err, SYLVA_ERR_PARAM, "%s: not a sylva ecology state (it does not start with %s)", path,
                         ECO_STATE_MAGIC);
        goto done;
    }
    reading(&r, "the format version and byte-order mark");
    get(&r, &version, 4), get(&r, &order, 4);
    reading(&r, "the fingerprint of the scene that saved it");
    get(&r, &fingerprint, 8);
    if (r.failed) {
        rc = cut_short(path, &r, size, err);
        goto done;
    }
    if (version != ECO_STATE_VERSION || order != ECO_BYTE_ORDER) {
        rc = plugin_fail(err, SYLVA_ERR_PARAM,
                         "%s: an ecology state of format %u%s; this sylva reads format %u in its own byte order", path,
                         version, order == ECO_BYTE_ORDER ? "" : " in another byte order", ECO_STATE_VERSION);
        goto done;
    }
    if (fingerprint != s->fingerprint) {
        rc = plugin_fail(err, SYLVA_ERR_PARAM,
                         "%s: the state was saved from another terrain, growth area, species list or species "
                         "parameters; continue it with the scene that saved it",
                         path);
        goto done;
    }
    r.sum = 0xcbf29ce484222325ull; /* the body */
    uint32_t n_species = 0, year = 0;
    reading(&r, "the species count and year");
    get(&r, &n_species, sizeof n_species);
    get(&r, &year, sizeof year);
    if (r.failed) {
        rc = cut_short(path, &r, size, err);
        goto done;
    }
    if (n_species != s->n_species) {
        rc = plugin_fail(err, SYLVA_ERR_PARAM,
                         "%s: the state holds %u species, the scene %u; continue it with the scene that saved it", path,
                         n_species, s->n_species);
        goto done;
    }
    uint32_t ns = n_species ? n_species : 1;
    pop = calloc(ns, sizeof *pop);
    seeds = calloc(ns, sizeof *seeds);
    carry = calloc(ns, sizeof *carry);
    rng = calloc((size_t)ns * ECO_N_STREAMS, sizeof *rng);
    if (!pop || !seeds || !carry || !rng) {
        rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory loading %s", path);
        goto done;
    }
    uint64_t living = 0;
    for (uint32_t j = 0; j < n_species && !r.failed; j++) {
        uint32_t len = 0;
        const char *name = s->names[j];
        reading(&r, "the name of species %u ('%s' in the scene)", j, name);
        get(&r, &len, sizeof len);
        char *stored = !r.failed && len == strlen(name) ? malloc(len + 1) : NULL;
        if (stored) {
            get(&r, stored, len);
            stored[len] = '\0';
        }
        int same = stored && !strcmp(stored, name);
        free(stored);
        if (r.failed) break;
        if (!same) {
            rc = plugin_fail(err, SYLVA_ERR_PARAM,
                             "%s: species %u of the state is not the scene's '%s'; continue it with the scene "
                             "that saved it",
                             path, j, name);
            goto done;
        }
        reading(&r, "the seeds of '%s'", name);
        get(&r, &seeds[j], sizeof seeds[j]);
        get(&r, &carry[j], sizeof carry[j]);
        if (!r.failed && !(isfinite(seeds[j]) && seeds[j] >= 0 && carry[j] >= 0 && carry[j] < 1)) {
            rc = plugin_fail(err, SYLVA_ERR_PARAM, "%s: the seeds of '%s' are damaged (a value out of range)", path,
                             name);
            goto done;
        }
        for (int q = 0; q < ECO_N_STREAMS; q++) {
            sylva_rng *g = &rng[(size_t)j * ECO_N_STREAMS + q];
            reading(&r, "random stream %d of '%s'", q, name);
            get(&r, &g->key, sizeof g->key);
            get(&r, &g->counter, sizeof g->counter);
        }
        uint32_t n = 0;
        reading(&r, "the plant count of '%s'", name);
        get(&r, &n, sizeof n);
        living += n;
        if (r.failed || living > s->config.max_plants) {
            if (!r.failed)
                rc = plugin_fail(err, SYLVA_ERR_PARAM, "%s: the state holds more than max_plants = %llu living plants",
                                 path, (unsigned long long)s->config.max_plants);
            break;
        }
        pop[j].plants = malloc((n ? n : 1) * sizeof *pop[j].plants);
        if (!pop[j].plants) {
            rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the %u plants of '%s' in %s", n, name, path);
            goto done;
        }
        pop[j].cap = n ? n : 1;
        for (uint32_t q = 0; q < n && !r.failed; q++) {
            get_plant(&r, &pop[j].plants[q], q, name);
            if (!r.failed && !plant_is_valid(s, &pop[j].plants[q])) {
                rc = plugin_fail(err, SYLVA_ERR_PARAM, "%s: plant %u of '%s' is damaged (a value out of range)", path,
                                 q, name);
                goto done;
            }
            pop[j].n = q + 1;
        }
    }
    if (rc) goto done;
    uint64_t body = r.sum, sum = 0;
    reading(&r, "the checksum");
    get(&r, &sum, sizeof sum);
    if (r.failed) {
        rc = cut_short(path, &r, size, err);
        goto done;
    }
    if (fgetc(f) != EOF) {
        rc = plugin_fail(err, SYLVA_ERR_PARAM,
                         "%s: the ecology state ends with its checksum at byte %llu, but the file holds %llu bytes; "
                         "something was added after it (save the run again)",
                         path, (unsigned long long)r.offset, (unsigned long long)size);
        goto done;
    }
    if (sum != body) {
        rc = plugin_fail(err, SYLVA_ERR_PARAM,
                         "%s: the ecology state is damaged: it is whole (%llu bytes), but its checksum does not "
                         "match what it holds (save the run again)", path, (unsigned long long)size);
        goto done;
    }
    /* Everything read and checked: the run takes it over. */
    for (uint32_t j = 0; j < s->n_species; j++) {
        free(s->pop[j].plants);
        s->pop[j] = pop[j];
        pop[j].plants = NULL;
    }
    free(s->seeds), free(s->carry), free(s->rng);
    s->seeds = seeds, s->carry = carry, s->rng = rng;
    seeds = carry = NULL, rng = NULL;
    s->year = year;
done:
    for (uint32_t j = 0; pop && j < s->n_species; j++) free(pop[j].plants);
    free(pop), free(seeds), free(carry), free(rng);
    fclose(f);
    return rc;
}
