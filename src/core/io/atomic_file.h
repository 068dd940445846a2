/* atomic_file.h — every output file is written whole or not at all: the bytes go to a new
 * temporary file beside the target, which is flushed to disk and renamed onto the target only
 * when everything has been written.
 *
 * The temporary's name is unpredictable (".<name>.tmp-<random>[.ext]") and it is created with
 * O_CREAT|O_EXCL|O_NOFOLLOW, so a file or symbolic link planted under any name is never opened
 * or followed; only the final rename replaces what stands at the target path. While it is
 * open, the temporary is listed in a registry that a SIGINT/SIGTERM handler empties (unlink,
 * then the default action) so an interrupted run leaves no temporary behind.
 *
 * Files that belong together (a render's PNG and EXR) are committed together: written and
 * flushed first, then renamed one after the other while the run holds a lock file beside them
 * (".<stem>.lock", removed when done), so two runs writing the same outputs at once leave the
 * whole set of one of them, never a PNG of one and an EXR of the other. */
#ifndef SYLVA_ATOMIC_FILE_H
#define SYLVA_ATOMIC_FILE_H

#include <stdio.h>

#include "util/err.h"

#define ATOMIC_PATH_MAX 4096

typedef struct atomic_file {
    char path[ATOMIC_PATH_MAX]; /* the target */
    char tmp[ATOMIC_PATH_MAX];  /* the temporary; "" when none is live */
    int fd;                     /* open on tmp for writing; -1 when closed */
    FILE *stream;               /* stdio stream on fd (atomic_file_open_stream), or NULL */
    int slot;                   /* index in the signal-cleanup registry, or -1 */
} atomic_file;

/* Creates the temporary for path (keeping path's extension, so a format can be told from it)
 * and opens it for writing. Returns 0, or -1 with err set and nothing created. */
int atomic_file_open(atomic_file *af, const char *path, err_buf *err);
/* atomic_file_open, then a buffered stdio stream on the temporary, owned by af (commit or
 * abort closes it). NULL with err set, and nothing created, when either fails. */
FILE *atomic_file_open_stream(atomic_file *af, const char *path, err_buf *err);
/* Flushes the stream, fsyncs, closes and renames the temporary onto the target. On any failure
 * the temporary is removed and err says why. af is closed afterwards either way. */
int atomic_file_commit(atomic_file *af, err_buf *err);
/* Commits the n files af[0..n-1] (open, with targets in one folder and one stem, as out.png and
 * out.exr) as one set: each is flushed, fsynced and closed, then, holding the lock
 * "<folder>/.<stem of af[0]>.lock" (waiting while another run holds it), all are renamed into
 * place. On a failure before the renames every temporary is removed and nothing is replaced.
 * Every af is closed afterwards either way. Returns 0 or -1 with err set. */
int atomic_file_commit_together(atomic_file *af, int n, err_buf *err);
/* Closes and removes the temporary; accepts an af that is already closed or never opened
 * (zeroed). */
void atomic_file_abort(atomic_file *af);

#endif
