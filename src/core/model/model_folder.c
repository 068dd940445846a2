/* model_folder.c — references a model makes, checked against its folder, and the Assimp file
 * system that opens only what the check allows (model_folder.h). Paths are compared after
 * they are made absolute and free of "." and "..", and once more as the kernel resolves them
 * (realpath), so neither ".." nor a symbolic link leads out. */
#include "model/model_folder.h"

#include "model/obj_statements.h"
#include "util/file_check.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char why_absolute[] = "is an absolute path";
static const char why_climbs[] = "climbs out of the model's folder";
static const char why_link[] = "leads out of the model's folder through a symbolic link";

/* Removes ".", ".." and repeated '/' from the absolute path p, in place ("/.." stays "/"). */
static void path_normalise(char *p)
{
    char *out = p; /* p[0] is '/' */
    const char *in = p;
    while (*in) {
        while (*in == '/') in++;
        if (!*in) break;
        const char *end = strchr(in, '/');
        size_t n = end ? (size_t)(end - in) : strlen(in);
        if (n == 1 && in[0] == '.') {
        } else if (n == 2 && in[0] == '.' && in[1] == '.') {
            while (out > p && *--out != '/') {}
        } else {
            *out++ = '/';
            memmove(out, in, n);
            out += n;
        }
        in += n;
    }
    if (out == p) *out++ = '/';
    *out = '\0';
}

/* 1 when the absolute, normalised path p is root or lies below it. */
static int path_inside(const char *root, const char *p)
{
    size_t n = strlen(root);
    if (n == 1) return 1; /* root is "/" */
    return !strncmp(p, root, n) && (p[n] == '/' || p[n] == '\0');
}

/* The reason ref (relative to the folder base, reaching file) is refused, or NULL. */
static const char *escape(const model_folder *mf, const char *base, const char *ref, const char *file)
{
    if (!strncmp(ref, "file://", 7)) ref += 7;
    int drive = ((ref[0] >= 'A' && ref[0] <= 'Z') || (ref[0] >= 'a' && ref[0] <= 'z')) && ref[1] == ':' &&
                (ref[2] == '/' || ref[2] == '\\'); /* C:\tex.png */
    if (ref[0] == '/' || ref[0] == '\\' || drive) return why_absolute;
    char lexical[2 * MODEL_FOLDER_PATH_MAX + 2];
    int n = snprintf(lexical, sizeof lexical, "%s/%s", base, ref);
    if (n < 0 || (size_t)n >= sizeof lexical) return why_climbs; /* cannot be shown inside */
    for (char *c = lexical; *c; c++)
        if (*c == '\\') *c = '/';
    path_normalise(lexical);
    if (!path_inside(mf->root, lexical)) return why_climbs;
    char real[PATH_MAX];
    if (realpath(file, real) && !path_inside(mf->root, real)) return why_link;
    return NULL;
}

static int refusal(const model_folder *mf, const char *ref, const char *why, err_buf *err)
{
    return err_fail(err, ERR_INPUT,
                    "%s: the model refers to the file '%s', which %s; a model's files must lie in %s and "
                    "below (an object's model_root: names a wider folder)",
                    mf->model, ref, why, mf->root);
}

int model_folder_init(model_folder *mf, const char *model, const char *root, err_buf *err)
{
    memset(mf, 0, sizeof *mf);
    mf->model = model;
    const char *slash = strrchr(model, '/');
    mf->prefix_len = slash ? (size_t)(slash - model) + 1 : 0;
    char dir[MODEL_FOLDER_PATH_MAX];
    if (mf->prefix_len >= sizeof dir) return err_fail(err, ERR_INPUT, "%s: the model's path is too long", model);
    if (slash) snprintf(dir, sizeof dir, "%.*s", (int)(slash - model), model);
    else snprintf(dir, sizeof dir, ".");
    if (!dir[0]) snprintf(dir, sizeof dir, "/");
    char real[PATH_MAX];
    if (!realpath(dir, real) || strlen(real) >= sizeof mf->dir)
        return err_fail(err, ERR_INPUT, "%s: cannot find the model's folder: %s", model, strerror(errno));
    memcpy(mf->dir, real, strlen(real) + 1);
    if (!root) {
        memcpy(mf->root, mf->dir, sizeof mf->root);
        return 0;
    }
    if (!realpath(root, real) || strlen(real) >= sizeof mf->root)
        return err_fail(err, ERR_INPUT, "%s: model_root '%s' cannot be used: %s", model, root, strerror(errno));
    memcpy(mf->root, real, strlen(real) + 1);
    if (!path_inside(mf->root, mf->dir))
        return err_fail(err, ERR_INPUT, "%s: the model does not lie in its model_root %s; give a folder that holds it",
                        model, mf->root);
    return 0;
}

int model_folder_check(const model_folder *mf, const char *ref, const char *file, err_buf *err)
{
    const char *why = escape(mf, mf->dir, ref, file);
    return why ? refusal(mf, ref, why, err) : 0;
}

int model_folder_refusal(const model_folder *mf, err_buf *err)
{
    if (mf->out_of_memory) return err_nomem(err, "%s: out of memory opening the model's files", mf->model);
    return mf->refused[0] ? refusal(mf, mf->refused, mf->refused_why, err) : 0;
}

/* --- the Assimp file system ------------------------------------------------------------------- */

/* A file Assimp opened: the stream, and for the OBJ model file the byte before the next one read
 * (model/obj_statements.h needs it). */
typedef struct folder_file {
    FILE *s;
    int obj;          /* 1: point and line statements are read as comments */
    long next;        /* the offset after the last byte read, or -1 */
    int last;         /* that byte */
} folder_file;

static FILE *stream_of(struct aiFile *f) { return ((folder_file *)(void *)f->UserData)->s; }

/* The byte before offset at in ff's stream (-1 at the start); the stream is left at `at`. */
static int byte_before(folder_file *ff, long at)
{
    if (at <= 0) return -1;
    if (at == ff->next) return ff->last;
    int c = fseek(ff->s, at - 1, SEEK_SET) == 0 ? fgetc(ff->s) : EOF;
    fseek(ff->s, at, SEEK_SET);
    return c == EOF ? '\n' : c; /* unreadable: taken as a line end, so a statement there is a comment */
}

static size_t file_read(struct aiFile *f, char *buf, size_t size, size_t count)
{
    folder_file *ff = (folder_file *)(void *)f->UserData;
    if (!ff->obj) return fread(buf, size, count, ff->s);
    long at = ftell(ff->s);
    int before = byte_before(ff, at);
    size_t got = fread(buf, size, count, ff->s), bytes = got * size;
    obj_points_lines_as_comments(buf, bytes, before);
    if (bytes) ff->next = at + (long)bytes, ff->last = (unsigned char)buf[bytes - 1]; /* '#' or not, no line end */
    return got;
}

static size_t file_write(struct aiFile *f, const char *buf, size_t size, size_t count)
{
    (void)f, (void)buf, (void)size, (void)count;
    return 0; /* opened for reading only */
}

static size_t file_tell(struct aiFile *f)
{
    long at = ftell(stream_of(f));
    return at < 0 ? 0 : (size_t)at;
}

static size_t file_size(struct aiFile *f)
{
    FILE *s = stream_of(f);
    long at = ftell(s), end = -1;
    if (at >= 0 && fseek(s, 0, SEEK_END) == 0) end = ftell(s);
    if (at >= 0) fseek(s, at, SEEK_SET);
    return end < 0 ? 0 : (size_t)end;
}

static enum aiReturn file_seek(struct aiFile *f, size_t offset, enum aiOrigin origin)
{
    int whence = origin == aiOrigin_SET ? SEEK_SET : origin == aiOrigin_CUR ? SEEK_CUR : SEEK_END;
    if (offset > LONG_MAX) return aiReturn_FAILURE;
    return fseek(stream_of(f), (long)offset, whence) == 0 ? aiReturn_SUCCESS : aiReturn_FAILURE;
}

static void file_flush(struct aiFile *f) { (void)f; }

/* 1 when ref is one of the places Assimp's file system guesses for a file that did not open: an
 * absolute name found within the path it asked for then. */
static int guess(const model_folder *mf, const char *ref)
{
    return (ref[0] == '/' || ref[0] == '\\') && mf->failed[0] && strstr(mf->failed, ref);
}

/* Opens path for Assimp when it is the model or a file its folder allows; a refusal is kept. */
static struct aiFile *folder_open(struct aiFileIO *io, const char *path, const char *mode)
{
    model_folder *mf = (model_folder *)(void *)io->UserData;
    if (!path || strpbrk(mode, "wa+")) return NULL;
    const char *ref = NULL; /* as the model names the file; NULL for the model itself */
    if (strcmp(path, mf->model)) {
        /* Assimp joins a reference to the model's folder as the model names it */
        int joined = mf->prefix_len && !strncmp(path, mf->model, mf->prefix_len);
        ref = joined ? path + mf->prefix_len : path;
        if (guess(mf, ref)) return NULL; /* absolute: refused, and not the model's */
        char cwd[MODEL_FOLDER_PATH_MAX];
        const char *base = joined || !mf->prefix_len ? mf->dir : getcwd(cwd, sizeof cwd);
        const char *why = base ? escape(mf, base, ref, path) : why_climbs;
        if (why) {
            if (!mf->refused[0]) snprintf(mf->refused, sizeof mf->refused, "%s", ref), mf->refused_why = why;
            snprintf(mf->failed, sizeof mf->failed, "%s", path);
            return NULL;
        }
    }
    err_buf why_not = {{0}}; /* not passed on: a file that does not open is said as missing */
    int fd = file_open_regular(path, NULL, &why_not); /* a folder or FIFO is no file to read */
    FILE *s = fd >= 0 ? fdopen(fd, "rb") : NULL;
    if (fd >= 0 && !s) close(fd);
    if (!s) {
        if (ref && !mf->missing[0]) snprintf(mf->missing, sizeof mf->missing, "%s", ref);
        snprintf(mf->failed, sizeof mf->failed, "%s", path);
        return NULL;
    }
    struct aiFile *f = calloc(1, sizeof *f);     /* freed by folder_close */
    folder_file *ff = calloc(1, sizeof *ff);     /* freed by folder_close */
    if (!f || !ff) {
        fclose(s);
        free(f), free(ff);
        mf->out_of_memory = 1;
        return NULL;
    }
    *ff = (folder_file){.s = s, .obj = mf->obj_points_lines && !strcmp(path, mf->model), .next = -1};
    f->ReadProc = file_read, f->WriteProc = file_write, f->TellProc = file_tell;
    f->FileSizeProc = file_size, f->SeekProc = file_seek, f->FlushProc = file_flush;
    f->UserData = (aiUserData)(void *)ff;
    return f;
}

static void folder_close(struct aiFileIO *io, struct aiFile *f)
{
    (void)io;
    if (!f) return;
    fclose(stream_of(f));
    free(f->UserData);
    free(f);
}

struct aiFileIO model_folder_io(model_folder *mf)
{
    return (struct aiFileIO){.OpenProc = folder_open, .CloseProc = folder_close,
                             .UserData = (aiUserData)(void *)mf};
}
