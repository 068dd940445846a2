/* atomic_file.c — unique temporaries beside the target, the fsync-and-rename commit, and the
 * registry of live temporaries that SIGINT/SIGTERM clean up. The signal handler uses only
 * async-signal-safe calls (unlink, sigaction, raise) and reads only slots that are complete. */
#include "io/atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdint.h>
#include <string.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "io/output_guard.h"

/* --- the registry of live temporaries -------------------------------------------------------- */

#define REGISTRY_SLOTS 64
enum { SLOT_FREE = 0, SLOT_BUSY = 1, SLOT_LIVE = 2 };

static struct {
    atomic_int state;
    char path[ATOMIC_PATH_MAX];
} registry[REGISTRY_SLOTS];

static atomic_int handlers_installed;
static struct sigaction previous_int, previous_term;

static void remove_temporaries_and_reraise(int sig)
{
    for (int i = 0; i < REGISTRY_SLOTS; i++)
        if (atomic_load(&registry[i].state) == SLOT_LIVE) unlink(registry[i].path);
    sigaction(sig, sig == SIGINT ? &previous_int : &previous_term, NULL);
    raise(sig);
}

/* Installs the handler for a signal whose action is the default one (an ignored signal stays
 * ignored; a program's own handler is left alone). */
static void install_handlers(void)
{
    int expected = 0;
    if (!atomic_compare_exchange_strong(&handlers_installed, &expected, 1)) return;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = remove_temporaries_and_reraise;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGINT);
    sigaddset(&sa.sa_mask, SIGTERM);
    struct sigaction old;
    if (sigaction(SIGINT, NULL, &old) == 0 && old.sa_handler == SIG_DFL) {
        previous_int = old;
        sigaction(SIGINT, &sa, NULL);
    }
    if (sigaction(SIGTERM, NULL, &old) == 0 && old.sa_handler == SIG_DFL) {
        previous_term = old;
        sigaction(SIGTERM, &sa, NULL);
    }
}

static int registry_add(const char *path)
{
    install_handlers();
    for (int i = 0; i < REGISTRY_SLOTS; i++) {
        int expected = SLOT_FREE;
        if (!atomic_compare_exchange_strong(&registry[i].state, &expected, SLOT_BUSY)) continue;
        memcpy(registry[i].path, path, strlen(path) + 1);
        atomic_store(&registry[i].state, SLOT_LIVE);
        return i;
    }
    return -1; /* every slot in use: this temporary is not cleaned up on a signal */
}

static void registry_remove(int slot)
{
    if (slot < 0) return;
    atomic_store(&registry[slot].state, SLOT_BUSY);
    registry[slot].path[0] = '\0';
    atomic_store(&registry[slot].state, SLOT_FREE);
}

/* --- names ------------------------------------------------------------------------------------ */

/* Twelve letters or digits from the kernel's random source (the clock and a counter when that
 * is unavailable; O_EXCL still guards against a clash). */
static void random_tag(char tag[13])
{
    static const char alphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    static atomic_uint counter;
    unsigned char bytes[12];
    if (getrandom(bytes, sizeof bytes, GRND_NONBLOCK) != (ssize_t)sizeof bytes) {
        struct timespec ts;
        clock_gettime(CLOCK_REALTIME, &ts);
        uint64_t x = (uint64_t)ts.tv_nsec ^ ((uint64_t)ts.tv_sec << 30) ^
                     ((uint64_t)getpid() << 16) ^ atomic_fetch_add(&counter, 1);
        for (int i = 0; i < 12; i++) {
            x ^= x >> 12, x ^= x << 25, x ^= x >> 27;
            bytes[i] = (unsigned char)((x * 0x2545F4914F6CDD1DULL) >> 56);
        }
    }
    for (int i = 0; i < 12; i++) tag[i] = alphabet[bytes[i] % (sizeof alphabet - 1)];
    tag[12] = '\0';
}

/* "<dir>/.<stem>.tmp-<tag><ext>" for path "<dir>/<stem><ext>". */
static int temp_name(const char *path, char *tmp, size_t n)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    if (!dot || dot == base) dot = base + strlen(base);
    char tag[13];
    random_tag(tag);
    int k = snprintf(tmp, n, "%.*s.%.*s.tmp-%s%s", (int)(base - path), path, (int)(dot - base),
                     base, tag, dot);
    return k < 0 || (size_t)k >= n ? -1 : 0;
}

/* --- the file --------------------------------------------------------------------------------- */

/* -1 with err when something other than a file or a symbolic link stands at path: the commit
 * renames over what is there, and would put a file in place of a device (/dev/null), a FIFO, a
 * socket or a folder. A link is replaced, never followed. */
static int not_a_file_to_replace(const char *path, err_buf *err)
{
    struct stat st;
    if (lstat(path, &st) != 0 || S_ISREG(st.st_mode) || S_ISLNK(st.st_mode)) return 0;
    const char *what = S_ISDIR(st.st_mode) ? "a folder" : S_ISCHR(st.st_mode) ? "a character device"
                     : S_ISBLK(st.st_mode) ? "a block device" : S_ISFIFO(st.st_mode) ? "a FIFO (named pipe)"
                     : S_ISSOCK(st.st_mode) ? "a socket" : "not a regular file";
    return err_set(err, "%s: is %s; an output replaces the file it names, so name a regular file (or a new one)",
                   path, what);
}

int atomic_file_open(atomic_file *af, const char *path, err_buf *err)
{
    memset(af, 0, sizeof *af);
    af->fd = -1, af->slot = -1;
    size_t len = path ? strlen(path) : 0;
    if (!len) return err_set(err, "no output file was named");
    if (len >= sizeof af->path || len + 32 >= sizeof af->tmp)
        return err_set(err, "%s: output path is too long", path);
    if (path[len - 1] == '/') return err_set(err, "%s: names a folder, not an output file", path);
    if (output_guard_check(path, err)) return -1;
    if (not_a_file_to_replace(path, err)) return -1;
    memcpy(af->path, path, len + 1);
    for (int attempt = 0; attempt < 100; attempt++) {
        if (temp_name(path, af->tmp, sizeof af->tmp))
            return err_set(err, "%s: output path is too long", path);
        af->fd = open(af->tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (af->fd >= 0) break;
        if (errno != EEXIST) {
            int e = errno;
            af->tmp[0] = '\0';
            return err_set(err, "%s: cannot create the output file: %s (the folder must exist "
                           "and be writable)", path, strerror(e));
        }
    }
    if (af->fd < 0) {
        af->tmp[0] = '\0';
        return err_set(err, "%s: cannot create a temporary file beside it: every name tried "
                       "exists", path);
    }
    af->slot = registry_add(af->tmp);
    return 0;
}

FILE *atomic_file_open_stream(atomic_file *af, const char *path, err_buf *err)
{
    if (atomic_file_open(af, path, err)) return NULL;
    af->stream = fdopen(af->fd, "w");
    if (!af->stream) {
        err_set(err, "%s: cannot write: %s", af->path, strerror(errno));
        atomic_file_abort(af);
    }
    return af->stream;
}

/* Closes stream and descriptor; returns 0 or the first errno met. */
static int close_all(atomic_file *af)
{
    int e = 0;
    if (af->stream) {
        if (fflush(af->stream) != 0 || ferror(af->stream)) e = errno ? errno : EIO;
        if (!e && fsync(af->fd) != 0) e = errno;
        if (fclose(af->stream) != 0 && !e) e = errno ? errno : EIO;
    } else if (af->fd >= 0) {
        if (fsync(af->fd) != 0) e = errno;
        if (close(af->fd) != 0 && !e) e = errno;
    }
    af->stream = NULL, af->fd = -1;
    return e;
}

static void forget_temporary(atomic_file *af)
{
    registry_remove(af->slot);
    af->slot = -1;
    af->tmp[0] = '\0';
}

int atomic_file_commit(atomic_file *af, err_buf *err)
{
    if (!af->tmp[0]) return err_set(err, "%s: the output file is not open", af->path);
    int e = close_all(af);
    if (e) {
        unlink(af->tmp);
        forget_temporary(af);
        return err_set(err, "%s: writing failed: %s", af->path, strerror(e));
    }
    if (rename(af->tmp, af->path) != 0) {
        e = errno;
        unlink(af->tmp);
        forget_temporary(af);
        return err_set(err, "%s: cannot move the finished file into place: %s", af->path,
                       strerror(e));
    }
    forget_temporary(af);
    return 0;
}

/* --- files committed together ------------------------------------------------------------------ */

/* "<dir>/.<stem>.lock" for "<dir>/<stem><ext>". */
static int lock_name(const char *path, char *out, size_t n)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    if (!dot || dot == base) dot = base + strlen(base);
    int k = snprintf(out, n, "%.*s.%.*s.lock", (int)(base - path), path, (int)(dot - base), base);
    return k < 0 || (size_t)k >= n ? -1 : 0;
}

/* An exclusive flock on the lock file `name`, waiting for another holder. A holder removes the
 * file when it is done, so a lock taken on a file that is no longer at `name` is let go and
 * taken again on the new one. Returns the descriptor, or -1 with errno set. */
static int lock_take(const char *name)
{
    for (;;) {
        int fd = open(name, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd < 0) return -1;
        int rc;
        while ((rc = flock(fd, LOCK_EX)) != 0 && errno == EINTR) {}
        struct stat held, named;
        if (rc == 0 && fstat(fd, &held) == 0 && lstat(name, &named) == 0 && held.st_dev == named.st_dev &&
            held.st_ino == named.st_ino)
            return fd;
        int e = errno;
        close(fd);
        if (rc != 0) return errno = e, -1;
    }
}

int atomic_file_commit_together(atomic_file *af, int n, err_buf *err)
{
    int e = 0, failed = 0;
    for (int i = 0; i < n && !e; i++) {
        e = af[i].tmp[0] ? close_all(&af[i]) : EBADF;
        failed = i;
    }
    if (e) {
        for (int i = 0; i < n; i++) atomic_file_abort(&af[i]);
        return err_set(err, "%s: writing failed: %s", af[failed].path, strerror(e));
    }
    char lock[ATOMIC_PATH_MAX + 16];
    int lock_fd = lock_name(af[0].path, lock, sizeof lock) ? (errno = ENAMETOOLONG, -1) : lock_take(lock);
    if (lock_fd < 0) {
        e = errno;
        for (int i = 0; i < n; i++) atomic_file_abort(&af[i]);
        return err_set(err, "%s: cannot take the lock file beside it that keeps runs writing the same outputs "
                       "apart: %s", af[0].path, strerror(e));
    }
    int slot = registry_add(lock); /* an interrupted run removes it with its temporaries */
    int rc = 0;
    for (int i = 0; i < n; i++) {
        if (!rc && rename(af[i].tmp, af[i].path) != 0) {
            e = errno;
            rc = err_set(err, "%s: cannot move the finished file into place: %s", af[i].path, strerror(e));
        }
        if (rc) unlink(af[i].tmp);
        forget_temporary(&af[i]);
    }
    registry_remove(slot);
    unlink(lock);
    close(lock_fd);
    return rc;
}

void atomic_file_abort(atomic_file *af)
{
    if (!af || !af->tmp[0]) return; /* never opened, or already committed or aborted */
    if (af->stream) fclose(af->stream);
    else if (af->fd >= 0) close(af->fd);
    af->stream = NULL, af->fd = -1;
    unlink(af->tmp);
    forget_temporary(af);
}
