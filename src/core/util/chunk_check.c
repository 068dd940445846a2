/* chunk_check.c — chunk lengths checked against the file's size (chunk_check.h). A PNG: an
 * 8-byte signature, then chunks of a 4-byte big-endian length, a 4-byte type, the data and a
 * 4-byte CRC, the last of type IEND. A GLB: a 12-byte header starting "glTF", then chunks of a
 * 4-byte little-endian length, a 4-byte type and the data. */
#include "util/chunk_check.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

typedef struct chunked_format {
    const char *name;              /* in messages */
    const unsigned char *magic;    /* the file's first bytes */
    size_t magic_len, first_chunk; /* bytes of the magic; where the first chunk starts */
    int big_endian;
    unsigned trailer;              /* bytes after a chunk's data (the PNG's CRC) */
    const char *last_type;         /* the chunk type that ends the file, or NULL */
} chunked_format;

/* Walks the chunks of the file open as f (from its start; path names it in messages). */
static int walk(FILE *f, const char *path, const chunked_format *fm, err_buf *err)
{
    unsigned char head[16];
    int rc = 0, ended = 0; /* ended: the chunk that ends the file was reached */
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (size < 0 || fseek(f, 0, SEEK_SET) != 0) {
        rc = err_fail(err, ERR_INPUT, "%s: cannot read the file: %s", path, strerror(errno));
    } else if (fread(head, 1, fm->magic_len, f) == fm->magic_len && !memcmp(head, fm->magic, fm->magic_len)) {
        for (uint64_t at = fm->first_chunk; at + 8 <= (uint64_t)size;) {
            if (fseek(f, (long)at, SEEK_SET) != 0 || fread(head, 1, 8, f) != 8) break;
            const unsigned char *b = head;
            uint64_t length = fm->big_endian ? (uint64_t)b[0] << 24 | (uint64_t)b[1] << 16 | (uint64_t)b[2] << 8 | b[3]
                                             : (uint64_t)b[3] << 24 | (uint64_t)b[2] << 16 | (uint64_t)b[1] << 8 | b[0];
            uint64_t left = (uint64_t)size - at - 8;
            if (length + fm->trailer > left) {
                char type[5];
                for (int k = 0; k < 4; k++) type[k] = b[4 + k] >= 0x20 && b[4 + k] < 0x7f ? (char)b[4 + k] : '?';
                type[4] = 0;
                rc = err_fail(err, ERR_INPUT, "%s: the %s is damaged or cut short: chunk '%s' at byte %llu states "
                              "%llu bytes of data, and %llu bytes follow it", path, fm->name, type,
                              (unsigned long long)at, (unsigned long long)length,
                              (unsigned long long)(left >= fm->trailer ? left - fm->trailer : 0));
                break;
            }
            if (fm->last_type && !memcmp(b + 4, fm->last_type, 4)) {
                ended = 1;
                break;
            }
            at += 8 + length + fm->trailer;
        }
        if (!rc && fm->last_type && !ended)
            rc = err_fail(err, ERR_INPUT, "%s: the %s is damaged or cut short: it ends at byte %ld "
                          "without its '%s' chunk", path, fm->name, size, fm->last_type);
    }
    return rc;
}

int png_check_stream(FILE *f, const char *name, err_buf *err)
{
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const chunked_format png = {"PNG", signature, 8, 8, 1, 4, "IEND"};
    return walk(f, name, &png, err);
}

int glb_check(const char *path, err_buf *err)
{
    static const unsigned char magic[4] = {'g', 'l', 'T', 'F'};
    static const chunked_format glb = {"GLB", magic, 4, 12, 0, 0, NULL};
    FILE *f = fopen(path, "rb");
    if (!f) return err_fail(err, ERR_INPUT, "%s: cannot read the file: %s", path, strerror(errno));
    int rc = walk(f, path, &glb, err);
    fclose(f);
    return rc;
}
