/* chunk_check.h — the chunks of a PNG or a binary glTF (GLB) file walked before the library
 * that reads it sees it: libpng and Assimp allocate the length a chunk states before they find
 * that the file ends sooner, so a damaged length (up to 4 GiB) in a file of a few hundred bytes
 * became an allocation of that size. Each chunk's length is checked against the bytes that
 * follow it; nothing is read beyond the chunk headers, nothing is allocated past the call. */
#ifndef SYLVA_CHUNK_CHECK_H
#define SYLVA_CHUNK_CHECK_H

#include <stdio.h>

#include "util/err.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 0 when the file open as f (read from its start; name names it in messages) does not start
 * with the PNG signature, or when every chunk up to IEND fits in the file; -1 with err set
 * ("name: ...", ERR_INPUT) naming the first chunk that states more bytes than the file holds, or
 * saying where the file ends when it ends before its IEND chunk (the reader would otherwise ask
 * for bytes past the end in the middle of decoding). io/png_read_check.h calls it. */
int png_check_stream(FILE *f, const char *name, err_buf *err);

/* The same for a file that starts with the GLB magic "glTF" (whatever its extension): its
 * chunks (JSON, BIN) after the 12-byte header. */
int glb_check(const char *path, err_buf *err);

#ifdef __cplusplus
}
#endif

#endif
