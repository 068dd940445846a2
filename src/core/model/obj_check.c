/* obj_check.c — the material libraries an OBJ file names, checked before Assimp reads it
 * (model/obj_check.h). */
#include "model/obj_check.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

/* Where Assimp's OBJ reader ends a line. */
static int line_end(int c)
{
    return c == '\n' || c == '\r' || c == '\f' || c == '\0';
}

/* One statement as it is read: its first bytes (enough to tell an mtllib statement), then for an
 * mtllib statement its library's first two and last three bytes. */
typedef struct statement {
    char head[8];
    size_t n_head;
    int library;       /* 1: an mtllib statement, its library being read */
    size_t n_ref;      /* bytes of the library read so far */
    char first[2], last[3];
    int ended;         /* 1: a line end inside the statement ended its keyword or its library, and
                        * Assimp reads nothing of it after that */
    unsigned long line; /* the physical line it starts on */
} statement;

/* 1 when the statement read so far names a library Assimp's path filter reads past. */
static int unsafe(const statement *s)
{
    if (!s->library || !s->n_ref) return 0;
    int colon_slashes = s->n_ref >= 3 && !memcmp(s->last, "://", 3);
    int unc = s->n_ref == 2 && s->first[0] == '\\' && s->first[1] == '\\';
    return colon_slashes || unc;
}

/* Takes byte c of the statement's text (continuations joined). A line end reaches here only as
 * the byte after a continuation, which Assimp's reader copies into the statement as it is. */
static void statement_add(statement *s, char c)
{
    if (s->ended) return;
    if (line_end((unsigned char)c)) {
        s->ended = 1;
        return;
    }
    if (s->library) {
        if (!s->n_ref && (c == ' ' || c == '\t')) return; /* the spaces before the name */
        if (s->n_ref < 2) s->first[s->n_ref] = c;
        memmove(s->last, s->last + 1, 2), s->last[2] = c;
        s->n_ref++;
        return;
    }
    if (s->n_head < sizeof s->head) s->head[s->n_head++] = c;
    if (s->n_head == 7 && !memcmp(s->head, "mtllib", 6) && (c == ' ' || c == '\t')) s->library = 1;
}

int obj_check(const char *path, err_buf *err)
{
    FILE *f = fopen(path, "rb");
    if (!f) return err_fail(err, ERR_INPUT, "%s: cannot read the model: %s", path, strerror(errno));
    char buf[65536];
    statement s = {.line = 1};
    unsigned long line = 1;
    /* skipping: a continuation, up to its '\n'; literal: the byte after that '\n', which the reader
     * takes into the statement whatever it is */
    int backslash = 0, skipping = 0, literal = 0, found = 0, rc = 0;
    size_t got;
    while (!found && (got = fread(buf, 1, sizeof buf, f)) > 0) {
        for (size_t i = 0; i < got && !found; i++) {
            char c = buf[i];
            if (c == '\n') line++;
            if (skipping) {
                skipping = c != '\n';
                literal = !skipping;
                continue;
            }
            if (literal) {
                literal = 0;
                statement_add(&s, c);
                continue;
            }
            if (backslash) {
                backslash = 0;
                if (line_end((unsigned char)c)) { /* a continuation: the statement goes on after the '\n' */
                    skipping = c != '\n';
                    literal = !skipping;
                    continue;
                }
                statement_add(&s, '\\');
            }
            if (c == '\\') {
                backslash = 1;
                continue;
            }
            if (line_end((unsigned char)c)) {
                if ((found = unsafe(&s))) break;
                s = (statement){.line = line};
                continue;
            }
            statement_add(&s, c);
        }
    }
    if (ferror(f)) rc = err_fail(err, ERR_INPUT, "%s: cannot read the model: a read error", path);
    else if (backslash && !found)
        rc = err_fail(err, ERR_INPUT, "%s:%lu: the file ends with a backslash, which Assimp's OBJ reader takes for a "
                      "line continued past the end of the file; end the file without it", path, line);
    else if (unsafe(&s))
        rc = err_fail(err, ERR_INPUT, "%s:%lu: the material library's name %s; name a file beside the model "
                      "(materials.mtl)", path, s.line,
                      s.n_ref == 2 ? "is two backslashes" : "ends with \"://\"");
    fclose(f);
    return rc;
}
